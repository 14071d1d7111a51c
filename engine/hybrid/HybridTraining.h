#pragma once

#include "baselines/LstmBaseline.h"
#include "common/Error.h"
#include "common/Progress.h"
#include "data/SiBatch.h"
#include "hybrid/HybridModel.h"
#include "residual/ResidualModel.h"

#include <string>
#include <vector>

namespace drytwin::hybrid {

/// @brief PBM runs of a data set with a model file's parameters and switches.
Expected<std::vector<physics::SimulationResult>> simulatePbm(const std::vector<data::SiBatch>& batches,
                                                             const HybridModel& model,
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
    Ending ending;
};

/// @brief Algorithm 1 on the chronological 70 % of the data: the PGRL-CC model, the
/// external-input baseline (same machinery, z = [u, d]) and the black-box LSTM.
Expected<TrainingResult> trainResidualModels(const std::vector<data::SiBatch>& batches,
                                             const HybridModel& model,
                                             const residual::ResidualOptions& options = {},
                                             const baselines::LstmOptions& lstmOptions = {},
                                             const Progress& progress = {});

/// @brief Puts the trained models into @p model, replacing any it held.
void storeResidualModels(HybridModel& model, TrainingResult&& trained);

/// @brief One row of the ablation table (paper Table 3).
struct AblationRow {
    std::string variant;     ///< "full", "no_aw_clamp", …
    std::string description; ///< as in the paper's remark
    double maeMoisture = 0, r2Moisture = 0, maeTemperature = 0, r2Temperature = 0, ljungBoxPMoisture = 0;
};

/// @brief The ablation table with how its run ended.
struct AblationResult {
    std::vector<AblationRow> rows;
    Ending ending;
};

/// @brief The six variants of Table 3 and the full model, trained and evaluated one step ahead
/// on the held-out 30 %.
Expected<AblationResult> runAblation(const std::vector<data::SiBatch>& batches, const HybridModel& model,
                                     const Progress& progress = {});

} // namespace drytwin::hybrid
