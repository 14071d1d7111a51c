#pragma once

#include "common/Progress.h"
#include "data/Cleaning.h"
#include "discovery/Discovery.h"

#include "plant/VirtualPlant.h"

#include <functional>

#include <string>
#include <vector>

namespace drytwin::workflow {
struct PipelineResult;
class Session;
} // namespace drytwin::workflow

namespace drytwin::app {

/// @brief Every option of every subcommand; each handler reads the ones it declared.
struct CommandOptions {
    std::string dataPath;
    std::string mappingPath;
    std::string outPath;
    std::string modelPath;
    std::string jsonPath;
    std::string diagnosticsPath; ///< evaluate: residual ACF, PSD and eigenvalues as JSON
    std::string truthPath;
    std::string scenarioPath;
    std::string scriptPath;               ///< training: the session file to replay
    std::string projectPath;              ///< report: a project saved by the workbench
    std::vector<std::string> controllers; ///< mpc: a subset of the controllers
    unsigned seed = 1;
    int batches = 10;
    int samples = 6300;
    bool demo = false;
    std::string periodic; ///< generate: PERIOD_S:AMPLITUDE_K of a hidden periodic disturbance
    bool drift = false;   ///< generate: unmeasured random-walk drift
    std::string plantKind = "distributed"; ///< generate: distributed | lumped
    std::string sensorMode = "realistic";  ///< generate: realistic | ideal (lumped: also "builtin")
    bool sensorModeGiven = false;
    plant::SensorFaultRates sensorFaults; ///< generate: per channel and hour
    int maxCauses = 3;                    ///< discover
    std::vector<std::string> causes;      ///< discover: only these candidate causes (empty: all)
    std::string referencePath;            ///< discover: a period when the line ran as it should
    std::string referenceMappingPath;     ///< discover: the reference's column mapping
    double falseAlarmRate = discovery::DiscoveryOptions{}.falseAlarmRate;     ///< discover --reference
    double minExplained = discovery::DiscoveryOptions{}.minExplainedFraction; ///< discover
    double fastWindowS = discovery::DiscoveryOptions{}.fastBandWindowS;       ///< discover
    std::vector<std::string> effects;
    std::vector<std::string> onsets; ///< generate: NAME=SECONDS, when a mechanism starts in each batch
    std::vector<std::string> freeParameters;
    std::vector<std::string> bounds;
    int maxEvaluations = 2000;
    std::string subset = "10:300"; ///< calibration rows: every STRIDE-th kept row, the first COUNT
    int horizonSteps = 30;
    int residualLags = 0; ///< 0: chosen by validation inside the training part
    bool noSelect = false;
    int degree = 2;
    int lstmEpochs = 30;
    std::vector<std::string> baseFeatures;
    double ridge = -1; ///< < 0: chosen by validation (or the model's default with --no-select)
    data::CleaningOptions cleaning;
    bool quiet = false;
    Progress progress;
    /// pipeline, report: writes report.html and report.pdf from the run's results (set by main, which has
    /// the GUI's plot code); returns the files written, or an error message.
    std::function<std::vector<std::string>(const workflow::PipelineResult&, const workflow::Session&,
                                           const std::string& folder, std::string& error)>
        renderReport;
    std::string commandLine; ///< the exact command, for the report's reproducibility block
    // The live link (generate --publish, live; issue #73).
    std::string brokerUrl;   ///< generate --publish, live --broker
    double speed = 1;        ///< generate --publish: line seconds per wall-clock second
    std::string topicsPath;  ///< the topic mapping (CONTRACT.md §2)
    std::string topicPrefix; ///< where unmapped tags are (default drytwin/line1)
    std::string mqttUser;
    std::string passwordFile;          ///< the password's only sources: this file or DRYTWIN_MQTT_PASSWORD
    std::string passwordOnCommandLine; ///< refused with a message, never used
    std::string caFile;
    std::string recordFolder;         ///< live --record
    double durationS = 0;             ///< live --duration (0: until Ctrl+C)
    double reorderWindowS = 10;       ///< live: line seconds a sample may come late and still be placed
    double splitGapS = 600;           ///< live: a gap longer than this starts a new batch file
    double liveFalseAlarmRate = 0.01; ///< live --reference: per planned run
    double plannedRunS = 0;           ///< live --reference: 0 = the reference batches' mean length
};

int runInspect(const CommandOptions& o);
int runGenerate(const CommandOptions& o);
int runSimulate(const CommandOptions& o);
int runCalibrate(const CommandOptions& o);
int runEvaluate(const CommandOptions& o);
int runTrain(const CommandOptions& o);
int runAblation(const CommandOptions& o);
int runDiscover(const CommandOptions& o);
int runPipeline(const CommandOptions& o);
int runMpc(const CommandOptions& o);
int runTraining(const CommandOptions& o);
int runReport(const CommandOptions& o);
int runLive(const CommandOptions& o);

} // namespace drytwin::app
