#pragma once

#include "baselines/LstmBaseline.h"
#include "common/Error.h"
#include "common/Progress.h"
#include "data/SiBatch.h"
#include "io/ModelFile.h"
#include "residual/ResidualModel.h"

#include <string>
#include <vector>

namespace drytwin::hybrid {

/// @brief Model-file keys of the residual models (CONTRACT.md §3 model keys).
inline constexpr const char* kPgrlCcKey = "pgrl_cc";
inline constexpr const char* kExtInputKey = "ext_input_residual";
inline constexpr const char* kLstmKey = "lstm";

/// @brief PBM runs of a data set with a model file's parameters and switches.
Expected<std::vector<physics::SimulationResult>> simulatePbm(const std::vector<data::SiBatch>& batches,
                                                             const io::ModelFile& model,
                                                             const properties::ModelSwitches& switches,
                                                             const Progress& progress = {});

/// @brief Views of the training (or test) part of the chronological split.
std::vector<residual::BatchView> splitViews(const std::vector<data::SiBatch>& batches,
                                            const std::vector<physics::SimulationResult>& pbm, bool test,
                                            double trainFraction = 0.7);

/// @brief What `drytwin train` produced.
struct TrainingResult {
    residual::ResidualModel pgrlCc;
    residual::ResidualModel extInput;
    baselines::LstmBaseline lstm;
    double elapsedSeconds = 0;
};

/// @brief Algorithm 1 on the chronological 70 % of the data: the PGRL-CC model, the
/// external-input baseline (same machinery, z = [u, d]) and the black-box LSTM.
Expected<TrainingResult> trainResidualModels(const std::vector<data::SiBatch>& batches,
                                             const io::ModelFile& model,
                                             const residual::ResidualOptions& options = {},
                                             const baselines::LstmOptions& lstmOptions = {},
                                             const Progress& progress = {});

/// @brief The LSTM baseline stored in a model file, if any.
Expected<baselines::LstmBaseline> loadLstm(const io::ModelFile& model, bool& present);

/// @brief Stores the trained models in the model file (kept through later reads and writes).
void storeResidualModels(io::ModelFile& model, const TrainingResult& trained);

/// @brief A residual model stored in a model file under @p key, if any.
Expected<residual::ResidualModel> loadResidualModel(const io::ModelFile& model, const std::string& key,
                                                    bool& present);

/// @brief One row of the ablation table (paper Table 3).
struct AblationRow {
    std::string variant;     ///< "full", "no_aw_clamp", …
    std::string description; ///< as in the paper's remark
    double maeMoisture = 0, r2Moisture = 0, maeTemperature = 0, r2Temperature = 0, ljungBoxPMoisture = 0;
};

/// @brief The six variants of Table 3 and the full model, trained and evaluated one step ahead
/// on the held-out 30 %.
Expected<std::vector<AblationRow>> runAblation(const std::vector<data::SiBatch>& batches,
                                               const io::ModelFile& model, const Progress& progress = {});

/// @brief The ablation table as JSON.
std::string ablationJson(const std::vector<AblationRow>& rows);

} // namespace drytwin::hybrid
