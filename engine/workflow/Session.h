#pragma once

#include "calibration/Calibration.h"
#include "common/Error.h"
#include "common/Progress.h"
#include "control/ClosedLoop.h"
#include "data/Batch.h"
#include "data/Cleaning.h"
#include "data/DataSetSummary.h"
#include "data/MappingGuess.h"
#include "data/SiBatch.h"
#include "discovery/Discovery.h"
#include "hybrid/Evaluation.h"
#include "hybrid/HybridModel.h"
#include "hybrid/HybridTraining.h"
#include "hybrid/ResidualDiagnostics.h"
#include "io/ResultFiles.h"
#include "plant/VirtualPlant.h"
#include "training/TrainingScript.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::live {
struct PublishOptions;
struct PublishResult;
struct LiveOptions;
struct LiveResult;
} // namespace drytwin::live

namespace drytwin::workflow {

/// @brief What to load: a batch file or folder (CONTRACT.md §1), an optional column mapping,
/// the cleaning rules. An empty path with only a model path opens a model alone.
struct OpenOptions {
    std::string dataPath;
    std::string mappingPath;
    std::string modelPath; ///< empty: keep the current model (default parameters in a new session)
    data::CleaningOptions cleaning;
    Status validate() const;
};

/// @brief What open() loaded.
struct OpenResult {
    std::shared_ptr<const data::DataSet> dataSet; ///< null when no data path was given
    data::DataSetSummary summary;
    bool modelLoaded = false;
    /// What reading the model file had to assume (hybrid::HybridModel::readNotes).
    std::vector<std::string> modelNotes;
    Ending ending;
};

/// @brief Virtual-plant batches written as batch files (CONTRACT.md §2 `generate`).
struct GenerateOptions {
    plant::PlantOptions plant;
    std::string outFolder;
    std::string truthPath; ///< empty: the hidden truth is not written
    Status validate() const;
};

struct GenerateResult {
    std::vector<std::string> files;
    int samplesPerBatch = 0;
    Ending ending;
};

/// @brief The physics model over every loaded batch, with the session's model.
struct SimulateOptions {
    /// Physics parameters to simulate with instead of the model's (the parameters a calibration
    /// started from, for its before/after plot). A run with them is not kept as the latest
    /// simulation: it is not the model's.
    std::optional<properties::ParameterSet> parameters;
    Status validate() const { return {}; }
};

/// @brief One batch's fit of the simulation on the rows the cleaning keeps.
struct BatchFit {
    std::string id;
    std::size_t rows = 0;
    double maeXOutPct = 0;    ///< % wb
    double maeTOutC = 0;      ///< °C (= K)
    std::size_t keptRows = 0; ///< the rows the MAEs are over (those the cleaning keeps)
};

struct SimulateResult {
    std::vector<physics::SimulationResult> simulations; ///< one per batch, SI units, dry basis
    std::vector<BatchFit> fits;
    Ending ending;
    /// @brief The outlet moisture's MAE over every kept row of every batch [% wb] (each batch
    /// weighted by its kept rows, as the calibration counts its rows); NaN without rows.
    double maeXOutPctAllKeptRows() const;
    /// @brief The outlet temperature's, alike [°C].
    double maeTOutCAllKeptRows() const;
    /// @brief The kept rows those two are over.
    std::size_t keptRows() const;
};

/// @brief Calibration of the session's physics model (paper §IV.B).
/// @brief The parameters a calibration frees unless told otherwise: h_HDT and k_HDT (the paper's
/// two) and the inlet gauge's scatter share phi_X_in_scatter. A measured X_in carries the gauge's
/// scatter, which the PBM would otherwise pass to its outlet prediction and every residual learnt
/// on it would inherit (issue #24, docs/pgrl-cc.md).
std::vector<properties::Param> defaultCalibrationParameters();

struct CalibrateOptions {
    CalibrateOptions() { calibration.freeParameters = defaultCalibrationParameters(); }
    calibration::CalibrationOptions calibration; ///< rows and simulation options are set by the session
    std::size_t subsetStride = 10;               ///< every STRIDE-th kept row ...
    std::size_t subsetCount = 300;               ///< ... the first COUNT of them (0: all)
    Status validate() const;
};

struct CalibrateResult {
    calibration::CalibrationResult calibration;
    properties::ParameterSet startParameters;
    bool droppedResidualModels = false; ///< learnt models were trained on the old parameters
    Ending ending;
};

/// @brief Training of the residual models on the chronological 70 % (Algorithm 1).
struct TrainOptions {
    residual::ResidualOptions residual;
    baselines::LstmOptions lstm;
    hybrid::ModelSelection selection; ///< settings chosen inside the training part (off: as given)
    Status validate() const;
};

struct TrainResult {
    std::shared_ptr<const residual::ResidualModel> pgrlCc;
    std::shared_ptr<const residual::ResidualModel> extInput;
    std::shared_ptr<const baselines::LstmBaseline> lstm;
    bool onDefaultParameters = false; ///< the model held no calibration
    std::vector<hybrid::SelectionCandidate> selection;
    Ending ending;
};

/// @brief Held-out metrics of every model the session holds, with residual diagnostics.
struct EvaluateOptions {
    evaluation::EvaluationOptions evaluation;
    Status validate() const { return evaluation.validate(); }
};

struct EvaluateResult {
    evaluation::EvaluationResult evaluation;
    hybrid::ResidualDiagnostics diagnostics;
    Ending ending;
};

/// @brief Discovery on the loaded data with the session's model (CONTRACT.md §2 `discover`).
struct DiscoverOptions {
    discovery::DiscoveryOptions discovery;
    /// A period when the line ran as it should (a batch file or folder, CONTRACT.md §2
    /// `discover --reference`): the loaded data are then judged by what changed against it.
    /// Read with the session's cleaning rules and @p referenceMappingPath (empty: the contract's
    /// columns). Empty: the loaded data alone.
    std::string referencePath;
    std::string referenceMappingPath;
    bool retrainResidual =
        true; ///< retrain PGRL-CC on the starting and the extended model for the hybrid gain
    Status validate() const { return discovery.validate(); }
};

struct DiscoverResult {
    discovery::DiscoveryResult discovery;
    /// The session's model with the causes added (fitted values and intervals under mechanisms,
    /// h_HDT and k_HDT refitted), the residual models retrained on top. The session's own model is
    /// unchanged until setModel() takes this one ("extend the model").
    hybrid::HybridModel extendedModel;
    bool hasHybrid = false; ///< PGRL-CC one-step held-out MAE on the starting and the extended model
    double hybridMaeMoistureBefore = 0, hybridMaeMoistureAfter = 0;       ///< % wb
    double hybridMaeTemperatureBefore = 0, hybridMaeTemperatureAfter = 0; ///< °C
    /// PGRL-CC on the extended model lost to PGRL-CC on the starting one on the held-out part:
    /// extendedModel is then the starting model (h_HDT, k_HDT refitted) with its residual model.
    bool keptStartingModel = false;
    /// On the same held-out rows: the last measurement held and the PBM with its last error held
    /// (the forecasts PGRL-CC must beat to earn its place).
    io::HybridReferences references;
    Ending ending;
};

/// @brief A closed-loop what-if scenario against the virtual plant (CONTRACT.md §2 `mpc`).
struct MpcOptions {
    std::string scenarioPath; ///< a scenario file; empty: the bundled one named below
    std::string bundledScenario = "paper_like_1000";
    control::ClosedLoopOptions closedLoop;
    Status validate() const { return closedLoop.validate(); }
};

struct MpcResult {
    control::ClosedLoopResult closedLoop;
    Ending ending;
};

/// @brief A scripted training session run headless (CONTRACT.md §2 `training`, docs/training.md).
struct TrainingOptions {
    std::string scriptPath; ///< a session file; a saved session is one
    std::string outFolder;  ///< gets session.json and recording/<scenario>.csv
    Status validate() const;
};

struct TrainingResult {
    training::SavedSession files;
    training::TrainingScore score;
    double endS = 0; ///< the session time the replay ran to
    std::size_t events = 0;
    /// What the replay says beside its score (training::modelDiffersNote: saved with another model).
    std::vector<std::string> notes;
    Ending ending;
};

struct PipelineResult;

/// @brief Everything in order into a folder, with a report (CONTRACT.md §2 `pipeline`).
///
/// Whole or not at all: every file is first written into a hidden staging folder inside
/// outFolder and moved into outFolder only once every stage (and finishInFolder) succeeded; a
/// failed or cancelled run leaves outFolder as it was (a previous report stays whole, not mixed
/// with this run's first stages).
struct PipelineOptions {
    std::string outFolder;
    CalibrateOptions calibrate;
    TrainOptions train;
    EvaluateOptions evaluate;
    DiscoverOptions discover;
    MpcOptions mpc; ///< the bundled paper-like scenario with the trained model
    /// Optional last stage writing more files into the staging folder it is given (the HTML/PDF
    /// report, drawn by the GUI's code the engine does not link); they are moved with the rest.
    /// Returns the files it wrote.
    std::function<Expected<std::vector<std::string>>(const PipelineResult&, const std::string& folder)>
        finishInFolder;
    Status validate() const;
};

/// @brief One finished stage of a pipeline.
struct PipelineStage {
    std::string name; ///< inspect, calibrate, train, evaluate, ablation, report
    std::vector<std::string> files;
    double elapsedSeconds = 0;
};

struct PipelineResult {
    data::DataSetSummary inspect;
    CalibrateResult calibrate;
    TrainResult train;
    EvaluateResult evaluate;
    hybrid::AblationResult ablation;
    DiscoverResult discover;
    MpcResult mpc;
    std::string reportPath;
    /// A saved project's results file these were read from (`drytwin report`); empty when this run
    /// made them.
    std::string resultsFrom;
    std::vector<PipelineStage> stages;
    Ending ending;
};

/// @brief The latest result of each action, for views that show them later.
struct LatestResults {
    std::optional<SimulateResult> simulate;
    std::optional<CalibrateResult> calibrate;
    std::optional<TrainResult> train;
    std::optional<EvaluateResult> evaluate;
    std::optional<hybrid::AblationResult> ablation;
    std::optional<DiscoverResult> discover;
    std::optional<MpcResult> mpc;
};

/// @brief What a user does with DryTwin, one method per action, called alike by the command
/// line and the GUI (ARCHITECTURE.md, workflow layer). Holds the loaded data set (immutable once
/// loaded, shared with whoever shows it), the current model and the latest results.
///
/// Every action takes an options struct and a Progress, and returns a result that says how it
/// ended, or an Error. A failed or cancelled action leaves the session as it was: nothing loaded
/// before is lost. Not thread-safe: one thread at a time calls it (the engine thread in the GUI);
/// the data set and learnt models it hands out are immutable and may be read from any thread.
class Session {
public:
    /// @brief Loads data and/or a model. On any error nothing changes; every rejected file is
    /// listed in the error's causes.
    Expected<OpenResult> open(const OpenOptions& options, const Progress& progress = {});
    /// @brief Runs the virtual plant and writes its batches (and the truth) to files. Leaves
    /// the session's data and model alone.
    Expected<GenerateResult> generate(const GenerateOptions& options, const Progress& progress = {}) const;
    /// @brief Runs the virtual plant and publishes its batches' samples to an MQTT broker at N x
    /// real time (`generate --publish`): the samples generate() would write for the same options.
    /// Leaves the session alone; declared here, defined in live/ (live/LivePublisher.h).
    Expected<live::PublishResult> publish(const live::PublishOptions& options,
                                          const Progress& progress = {}) const;
    /// @brief Follows a running line on an MQTT broker and records its tags as batch files until
    /// the duration ends or progress says stop (`drytwin live`; live/LiveRecorder.h).
    Expected<live::LiveResult> live(const live::LiveOptions& options, const Progress& progress = {}) const;
    /// @brief The loaded data set at a glance, with the cleaning counts.
    Expected<data::DataSetSummary> inspect() const;
    /// @brief A guess at the column mapping of the plant file at @p path from the first rows of
    /// its first 4 MB (the column-mapping dialog's proposal). Touches no session state.
    static Expected<data::MappingGuess> guessMapping(const std::string& path);
    /// @brief The production runs the first @p maxBytes of the plant file at @p path would give
    /// with @p mapping (the dialog's preview; 0: the whole file). Touches no session state.
    static Expected<data::PlantFileRuns>
    previewRuns(const std::string& path, const data::ColumnMapping& mapping, std::size_t maxBytes);
    /// @brief Runs the physics model over every batch.
    Expected<SimulateResult> simulate(const SimulateOptions& options = {}, const Progress& progress = {});
    /// @brief Calibrates the physics parameters; the model takes the result (also when stopped
    /// with StopKeepBest). Learnt residual models, trained on the old parameters, are dropped.
    Expected<CalibrateResult> calibrate(const CalibrateOptions& options = {}, const Progress& progress = {});
    /// @brief Trains PGRL-CC and the two baselines on top of the physics model.
    Expected<TrainResult> train(const TrainOptions& options = {}, const Progress& progress = {});
    /// @brief Held-out metrics of every model the session holds.
    Expected<EvaluateResult> evaluate(const EvaluateOptions& options = {}, const Progress& progress = {});
    /// @brief What the simulation gets wrong, its cause, the extended model and the gain.
    Expected<DiscoverResult> discover(const DiscoverOptions& options = {}, const Progress& progress = {});
    /// @brief The ablation table (paper Table 3) on the current physics parameters.
    Expected<hybrid::AblationResult> ablation(const Progress& progress = {});
    /// @brief Runs a what-if scenario once per controller (an MPC on each prediction model the
    /// session's model holds, and the plant's PI loop). Needs no data: the plant makes its own.
    Expected<MpcResult> mpc(const MpcOptions& options, const Progress& progress = {});
    /// @brief Replays a training session file with the session's model (its MPC controllers)
    /// and writes the session and its recording. Needs no data: the plant makes its own.
    Expected<TrainingResult> training(const TrainingOptions& options, const Progress& progress = {}) const;
    /// @brief inspect, calibrate, train, evaluate, ablation, discover and mpc in order, each result written
    /// to the folder as it is done, then report.md. A failed or cancelled stage keeps the files of the stages
    /// before it.
    Expected<PipelineResult> pipeline(const PipelineOptions& options, const Progress& progress = {});

    /// @brief Saves the current model as a model file (atomically).
    Status saveModel(const std::string& path) const;
    /// @brief Sets one physics parameter after checking it against its bounds.
    Status setParameter(properties::Param param, double value);

    bool hasData() const { return m_dataSet != nullptr; }
    std::shared_ptr<const data::DataSet> dataSet() const { return m_dataSet; }
    /// @brief The loaded batches in SI units, cleaning applied (empty without data).
    const std::vector<data::SiBatch>& siBatches() const { return m_si; }
    const data::CleaningOptions& cleaning() const { return m_cleaning; }
    const hybrid::HybridModel& model() const { return m_model; }
    void setModel(hybrid::HybridModel model) { m_model = std::move(model); }
    const LatestResults& latest() const { return m_latest; }

private:
    /// A reference period read with the session's cleaning rules (a rejected file: its error);
    /// what reading and checking its files noticed (a unit that looks wrong, a gap) into @p notes.
    Expected<std::vector<data::SiBatch>> loadReference(const std::string& path,
                                                       const std::string& mappingPath,
                                                       const Progress& progress,
                                                       std::vector<std::string>& notes) const;

    Status requireData(const std::string& action) const;
    /// The loaded data keep at least one row after cleaning; else why not (BadInput).
    Status requireUsableRows(const std::string& action) const;
    /// Options valid and data loaded: the precondition of every action on the data.
    template <class Options> Status ready(const Options& options, const std::string& action) const;

    std::shared_ptr<const data::DataSet> m_dataSet;
    std::string m_dataPath;
    data::CleaningOptions m_cleaning;
    std::vector<data::SiBatch> m_si;
    hybrid::HybridModel m_model;
    LatestResults m_latest;
};

} // namespace drytwin::workflow
