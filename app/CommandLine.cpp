#include "CommandLine.h"

#include "CliProgress.h"
#include "HeadlessCommands.h"

#include "common/LibraryVersions.h"
#include "plant/Mechanisms.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <unistd.h>

namespace drytwin::app {

namespace {

/// The mechanisms' names for the help text (users have the program, not the contract file).
std::string mechanismNames() {
    std::string names;
    for (const auto& m : plant::mechanisms()) {
        names += (names.empty() ? "" : ", ") + std::string(m.name);
    }
    return names;
}

} // namespace

struct CommandLine::Impl {
    CLI::App app{"DryTwin — digital-twin workbench for pneumatic drying lines.\n"
                 "Without a subcommand it opens the GUI; with one it runs headless.",
                 "drytwin"};
    CommandOptions options;
    std::map<CLI::App*, std::function<int(const CommandOptions&)>> handlers;
    CLI::App* selected = nullptr;
    bool quiet = false;
    std::string screenshotPath;
    std::string projectPath;
    std::string language;
    std::string guiModelPath;
    std::string guiMappingPath;
    std::string runActions;
    std::string guiReferencePath;
    std::string trainingSession;
    std::string saveProjectPath;
};

CommandLine::CommandLine() : m_impl(new Impl) {
    auto& app = m_impl->app;
    auto& o = m_impl->options;
    app.set_version_flag("--version", "drytwin " + dryTwinVersion());
    app.allow_extras(); // Qt's own GUI options (-platform, -style ...) pass through
    app.add_option("--data", m_impl->options.dataPath, "GUI: open this batch file or folder at start");
    app.add_flag("-q,--quiet", m_impl->quiet, "no progress on stderr");
    app.add_option(
        "--screenshot", m_impl->screenshotPath,
        "GUI: once the window's work is done, save it to PATH.png, or one PNG per tab into the folder "
        "PATH, then quit");
    app.add_option("--project", m_impl->projectPath, "GUI: open this project file at start");
    app.add_option("--save-project", m_impl->saveProjectPath,
                   "GUI: once the window's work (loading, --run) is done, save the project to this file "
                   "(before --screenshot, which then shows what a reopened project must show)");
    app.add_option("--model", m_impl->guiModelPath, "GUI: open this model file with the data");
    app.add_option("--mapping", m_impl->guiMappingPath,
                   "GUI: read --data's columns with this column-mapping file (a historian export)");
    app.add_option("--training", m_impl->trainingSession,
                   "GUI: reopen this saved training session on the Training tab");
    app.add_option("--reference", m_impl->guiReferencePath,
                   "GUI: compare the data with this reference period (a batch file or folder from a time "
                   "when the line ran as it should) when Discover runs");
    app.add_option("--run", m_impl->runActions,
                   "GUI: after loading, run these actions in order: calibrate, train, evaluate, ablation, "
                   "discover, mpc (e.g. calibrate,train,discover,mpc)");
    app.add_option("--lang", m_impl->language,
                   "GUI: language, en or zh_CN (default: as chosen before, else the "
                   "system's)");
    app.require_subcommand(0, 1);
    app.footer("Exit codes: 0 done; 2 wrong usage; 3 bad input data or model file; 4 numerical failure; "
               "130 cancelled.");

    auto addData = [&](CLI::App* sub, bool required = true) {
        auto* opt = sub->add_option("--data", o.dataPath, "batch file or folder of *.csv batch files");
        if (required) {
            opt->required();
        }
        sub->add_option("--mapping", o.mappingPath,
                        "JSON column mapping {\"<contract column>\": \"<header in the files>\", ...}");
    };
    // The broker's login and the topics, alike on generate --publish and live.
    auto addMqttOptions = [&](CLI::App* sub) {
        sub->add_option(
            "--topics,--mapping", o.topicsPath,
            "topic mapping (JSON): {\"<contract column>\": \"<topic>\", \"batch_id\": \"<topic>\", "
            "\"prefix\": \"<twin's prefix>\"}; unnamed columns are on <topic prefix>/<column>");
        sub->add_option(
            "--topic-prefix", o.topicPrefix,
            "where the line's unmapped tags are: <prefix>/<contract column> (default drytwin/line1)");
        sub->add_option("--user", o.mqttUser, "broker user name");
        sub->add_option(
            "--password-file", o.passwordFile,
            "file whose first line is the broker password (else DRYTWIN_MQTT_PASSWORD; never on the "
            "command line)");
        sub->add_option("--password", o.passwordOnCommandLine)->group(""); // refused with a message
        sub->add_option("--cafile", o.caFile,
                        "TLS (mqtts://): CA certificate(s) to check the broker against");
    };
    auto reg = [&](CLI::App* sub, std::function<int(const CommandOptions&)> handler) {
        sub->allow_extras(false);
        // Also after the subcommand, where a script writes it (`drytwin calibrate -q …` was refused).
        sub->add_flag("-q,--quiet", m_impl->quiet, "no progress on stderr");
        m_impl->handlers[sub] = std::move(handler);
    };

    auto* inspect =
        app.add_subcommand("inspect", "load and validate a data set; print batches, rows, ranges, "
                                      "missing cells and rows the cleaning rules would drop");
    addData(inspect);
    inspect->add_option("--min-xhdt", o.cleaning.minXhdtPct, "cleaning: minimum tube-outlet moisture [% wb]")
        ->capture_default_str();
    inspect->add_option("--min-thdt", o.cleaning.minThdtC, "cleaning: minimum tube-outlet temperature [°C]")
        ->capture_default_str();
    inspect->add_option("--min-feed", o.cleaning.minFeedKgPerHour, "cleaning: minimum feed rate [kg/h]")
        ->capture_default_str();
    inspect->add_option("--json", o.jsonPath, "also write the summary as JSON");
    reg(inspect, runInspect);

    auto* generate = app.add_subcommand(
        "generate",
        "write virtual-plant batches (--out), or publish them live to an MQTT broker (--publish)");
    generate->add_option("--out", o.outPath, "output folder");
    generate->add_option("--seed", o.seed, "random seed")->capture_default_str();
    generate->add_option("--batches", o.batches, "number of batches")->capture_default_str();
    generate->add_option("--samples", o.samples, "samples per batch (1 s apart, at least 200)")
        ->capture_default_str();
    auto* demo = generate->add_flag("--demo", o.demo, "the bundled demo mix of mechanisms and drift");
    generate
        ->add_option("--effect", o.effects,
                     "NAME[=STRENGTH] of a mechanism to hide in the data (" + mechanismNames() +
                         "; docs/mechanisms.md); repeatable")
        ->excludes(demo);
    generate
        ->add_option("--onset", o.onsets,
                     "NAME=SECONDS: the mechanism acts from this time into each batch (a meter window that "
                     "fogs up, a gauge knocked mid-batch); repeatable")
        ->excludes(demo);
    generate->add_option("--truth", o.truthPath, "write the hidden truth (parameters, effects) here");
    generate
        ->add_option("--periodic", o.periodic,
                     "PERIOD_S:AMPLITUDE_K of an unmeasured periodic swing of the drying gas temperature "
                     "(matches no mechanism: discover must report it as unexplained)")
        ->excludes(demo);
    generate
        ->add_flag("--drift", o.drift,
                   "unmeasured slow random-walk drift of the leaf's drying (as in --demo)")
        ->excludes(demo);
    generate
        ->add_option("--plant", o.plantKind,
                     "distributed: the line with a gas phase, residence-time spread, a layered belt and a "
                     "mixed winnower (docs/plant.md); lumped: the plant of the paper's base equations")
        ->check(CLI::IsMember({"distributed", "lumped"}))
        ->capture_default_str();
    generate
        ->add_option("--sensors", o.sensorMode,
                     "realistic: every column through its transmitter (noise, lag, quantisation, spikes, "
                     "stuck values, dropouts; docs/plant.md); ideal: true values; builtin: the lumped "
                     "plant's own small noise (its default)")
        ->check(CLI::IsMember({"realistic", "ideal", "builtin"}))
        ->capture_default_str()
        ->each([&o](const std::string&) { o.sensorModeGiven = true; });
    generate->add_option("--sensor-spikes", o.sensorFaults.spikesPerHour, "spikes per channel and hour")
        ->check(CLI::Range(0.0, 60.0))
        ->capture_default_str();
    generate->add_option("--sensor-stuck", o.sensorFaults.stuckPerHour, "stuck values per channel and hour")
        ->check(CLI::Range(0.0, 60.0))
        ->capture_default_str();
    generate
        ->add_option("--sensor-dropouts", o.sensorFaults.dropoutsPerHour,
                     "dropouts (missing cells) per channel and hour")
        ->check(CLI::Range(0.0, 60.0))
        ->capture_default_str();
    generate->add_option("--publish", o.brokerUrl,
                         "publish the batches' samples live to this MQTT broker (mqtt://host:port, mqtts:// "
                         "with TLS) instead of (or, with --out, after) writing them: one message per column "
                         "and second, {\"t\": <Unix s>, \"v\": <value or null>} (docs/live.md)");
    generate->add_option("--speed", o.speed, "--publish: N x real time (1 = the line's own pace)")
        ->capture_default_str();
    addMqttOptions(generate);
    reg(generate, runGenerate);

    auto* live = app.add_subcommand(
        "live", "follow a running line on an MQTT broker and record its tags as batch files (docs/live.md)");
    live->add_option("--broker", o.brokerUrl, "the broker: mqtt://host:port, or mqtts://host:port with TLS")
        ->required();
    live->add_option("--record", o.recordFolder,
                     "write the stream to this folder as batch files, one per batch id (made if missing; "
                     "existing files are never overwritten)");
    live->add_option("--duration", o.durationS,
                     "end after this many seconds of wall clock (default: at Ctrl+C)")
        ->check(CLI::NonNegativeNumber);
    live->add_option(
            "--reorder-window", o.reorderWindowS,
            "seconds of line time a sample may come after newer ones and still be placed; later ones "
            "are counted late and not recorded")
        ->capture_default_str();
    live->add_option("--split-gap", o.splitGapS,
                     "a stretch without messages longer than this many seconds starts a new batch file; "
                     "shorter gaps are rows of missing cells")
        ->capture_default_str();
    live->add_option(
        "--reference", o.referencePath,
        "a period when the line ran as it should (batch file or folder): the dynamic-PCA monitor "
        "is fitted on it and judges the line second by second; its windows and its alarm are "
        "published under the twin's prefix (<prefix>/monitor, <prefix>/alarm)");
    live->add_option("--false-alarm-rate", o.liveFalseAlarmRate,
                     "with --reference: the chance of an alarm over one planned run of a healthy line")
        ->capture_default_str();
    live->add_option("--planned-run", o.plannedRunS,
                     "with --reference: the run length [s] the false-alarm rate holds over (default: the "
                     "reference batches' mean)");
    live->add_option("--model", o.modelPath, "the twin's model file (not yet in this version)");
    addMqttOptions(live);
    reg(live, runLive);

    auto* simulate =
        app.add_subcommand("simulate", "run a model over data; write predictions and proxy states");
    addData(simulate);
    simulate->add_option("--model", o.modelPath, "model file (default: the paper's default parameters)");
    simulate->add_option("--out", o.outPath, "output CSV")->required();
    reg(simulate, runSimulate);

    auto* calibrate = app.add_subcommand("calibrate", "calibrate the physics model; write a model file");
    addData(calibrate);
    calibrate->add_option("--model", o.modelPath, "start from this model file");
    calibrate->add_option("--out", o.outPath, "model file to write")->required();
    calibrate->add_option("--free", o.freeParameters,
                          "parameters to fit (default h_HDT k_HDT phi_X_in_scatter)");
    calibrate
        ->add_option("--subset", o.subset,
                     "calibration rows STRIDE:COUNT, every STRIDE-th kept row, the first COUNT "
                     "(paper: 10:300; 1:0 for every row)")
        ->capture_default_str();
    calibrate->add_option("--bound", o.bounds,
                          "NAME=LOWER:UPPER search range of a free parameter; repeatable");
    calibrate->add_option("--seed", o.seed, "random seed of the global search")->capture_default_str();
    calibrate->add_option("--max-evaluations", o.maxEvaluations, "cap on model evaluations")
        ->capture_default_str();
    reg(calibrate, runCalibrate);

    auto* train = app.add_subcommand("train", "learn the PGRL-CC residual model on a calibrated model");
    addData(train);
    train->add_option("--model", o.modelPath, "calibrated model file")->required();
    train->add_option("--out", o.outPath, "model file to write")->required();
    train
        ->add_option("--lags", o.residualLags,
                     "measured residual lags in the lifted state (default: chosen among 16, 32 and 60 by "
                     "multi-step validation inside the training part)")
        ->check(CLI::Range(1, 600));
    train->add_option("--degree", o.degree, "polynomial dictionary degree (1-3)")->capture_default_str();
    train->add_option("--base", o.baseFeatures,
                      "base features of the orthogonal projection (Eq. 27), e.g. 1 T_amb X_HDT^2; "
                      "default: the constant and linear terms");
    train->add_option("--ridge", o.ridge,
                      "ridge weight lambda_A = lambda_B = lambda_E per unit of total weight (default: chosen "
                      "among 1e-4 and 1e-3 by validation)");
    train->add_flag("--no-select", o.noSelect,
                    "take the settings as given (lags 8, ridge 1e-4, with P_perp) instead of choosing lags, "
                    "ridge and P_perp by multi-step validation inside the training part");
    train->add_option("--lstm-epochs", o.lstmEpochs, "training epochs of the LSTM baseline")
        ->capture_default_str();
    train->add_option("--seed", o.seed, "seed of the LSTM baseline")->capture_default_str();
    reg(train, runTrain);

    auto* evaluate = app.add_subcommand("evaluate", "metrics on the held-out part of the data");
    addData(evaluate);
    evaluate->add_option("--model", o.modelPath, "model file")->required();
    evaluate->add_option("--json", o.jsonPath, "write the metrics as JSON (what they mean: docs/pgrl-cc.md)");
    evaluate->add_option("--diagnostics", o.diagnosticsPath,
                         "write residual ACF, PSD and the eigenvalues of A (before/after) as JSON");
    evaluate->add_option("--horizon", o.horizonSteps, "multi-step horizon [steps]")
        ->check(CLI::Range(1, 3600))
        ->capture_default_str();
    reg(evaluate, runEvaluate);

    auto* discover = app.add_subcommand("discover", "find what the simulation gets wrong and name the cause");
    addData(discover);
    discover->add_option(
        "--model", o.modelPath,
        "model file to start from (default: the paper's parameters, h_HDT and k_HDT fitted first)");
    discover->add_option("--json", o.jsonPath,
                         "write the findings as JSON (what they mean: docs/discovery.md)");
    discover->add_option(
        "--out-model", o.outPath,
        "write the model for forecasting here: the physics extended by the named causes with "
        "PGRL-CC retrained on it, or the starting model where that forecasts worse (said)");
    discover->add_option("--max-causes", o.maxCauses, "causes added one at a time, at most")
        ->capture_default_str();
    discover
        ->add_option("--min-explained", o.minExplained,
                     "share of the held-out squared error left, or of its fast part, that a cause must "
                     "remove to be named")
        ->capture_default_str();
    discover
        ->add_option("--causes", o.causes,
                     "only these candidate causes (comma-separated, of " + mechanismNames() +
                         "; default: all eleven): ask about one suspect")
        ->delimiter(',');
    discover->add_option("--reference", o.referencePath,
                         "a period when the line ran as it should (batch file or folder): judge the data "
                         "by what changed against it (detection, onset, cause)");
    discover->add_option("--reference-mapping", o.referenceMappingPath,
                         "column mapping of the reference's files (default: --mapping's)");
    discover
        ->add_option("--false-alarm-rate", o.falseAlarmRate,
                     "with --reference: the chance that each detector flags a data set as changed when "
                     "nothing changed")
        ->capture_default_str();
    discover
        ->add_option("--fast-window", o.fastWindowS,
                     "seconds: the error's fast part is the error about its centred moving average over "
                     "this window, per batch (0: judge the whole error only)")
        ->capture_default_str();
    reg(discover, runDiscover);

    auto* mpc = app.add_subcommand("mpc", "closed-loop what-if scenario, one row per controller model");
    addData(mpc);
    mpc->add_option("--model", o.modelPath, "model file")->required();
    mpc->add_option("--scenario", o.scenarioPath,
                    "scenario file (docs/mpc.md); default: the bundled paper_like_1000, or a bundled name");
    mpc->add_option("--controllers", o.controllers,
                    "comma-separated subset of pbm, ext_input_residual, lstm, pgrl_cc, pi (default: all)")
        ->delimiter(',');
    mpc->add_option("--json", o.jsonPath, "write the results as JSON");
    reg(mpc, runMpc);

    auto* ablation = app.add_subcommand("ablation", "the ablation table of the paper's Table 3");
    addData(ablation);
    ablation->add_option("--model", o.modelPath, "calibrated model file (default: default parameters)");
    ablation->add_option("--json", o.jsonPath, "write the table as JSON");
    reg(ablation, runAblation);

    auto* training =
        app.add_subcommand("training", "replay a training session file headless (docs/training.md)");
    training->add_option("--script", o.scriptPath, "session file: events to replay, or a saved session")
        ->required()
        ->check(CLI::ExistingFile);
    training->add_option("--out", o.outPath, "folder for session.json and recording/*.csv")->required();
    training->add_option("--model", o.modelPath,
                         "model file for MPC controllers (default: the paper's parameters)");
    reg(training, runTraining);

    auto* pipeline = app.add_subcommand("pipeline", "everything above in order, with a report");
    addData(pipeline);
    pipeline->add_option("--out", o.outPath, "report folder")->required();
    reg(pipeline, runPipeline);

    auto* report = app.add_subcommand(
        "report", "the pipeline's HTML and PDF report from a saved project's results, re-running nothing");
    // Not CLI11's ExistingFile check: a missing project is bad input (exit 3), named by the reader.
    report->add_option("--project", o.projectPath, "project file (.dtproj) saved by the workbench")
        ->required();
    report->add_option("--data", o.dataPath,
                       "the project's data where they are now, when moved (must be the batches and rows "
                       "the results were made on)");
    report->add_option("--mapping", o.mappingPath, "their column mapping (default: the project's)");
    report
        ->add_option("--out", o.outPath,
                     "report folder (made if missing; its report.html and report.pdf are replaced)")
        ->required();
    reg(report, runReport);
}

CommandLine::~CommandLine() {
    delete m_impl;
}

namespace {

/// Why a file cannot be written at @p path (its folder missing or not writable, or it is a
/// folder), or "" when it can.
std::string unwritableReason(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        return "is a folder; give a file name";
    }
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) {
        folder = ".";
    }
    if (!fs::is_directory(folder, ec)) {
        return fs::exists(folder, ec) ? "'" + folder.string() + "' is a file, not a folder"
                                      : "the folder '" + folder.string() + "' does not exist";
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        return "the folder '" + folder.string() + "' is not writable";
    }
    if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0) {
        return "the file exists and is not writable";
    }
    return {};
}

/// Why a folder a command writes into cannot be made or written at @p path (a file there, the
/// folder or the nearest folder above it that exists not writable), or "" when it can.
std::string unwritableFolderReason(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path folder = fs::absolute(fs::path(path), ec);
    if (ec) {
        return {};
    }
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
        return "is a file, not a folder";
    }
    // The folder itself, or the nearest one above it that exists (where it would be made).
    while (!fs::exists(folder, ec) && folder.has_parent_path() && folder.parent_path() != folder) {
        folder = folder.parent_path();
    }
    if (!fs::is_directory(folder, ec)) {
        return "'" + folder.string() + "' is a file, not a folder";
    }
    if (::access(folder.c_str(), W_OK) != 0) {
        return "the folder '" + folder.string() + "' is not writable";
    }
    return {};
}

} // namespace

ParsedCommandLine CommandLine::parse(int argc, char** argv) {
    ParsedCommandLine result;
    try {
        m_impl->app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        result.exitNow = true;
        const int rc = m_impl->app.exit(e);
        // CLI11 returns 0 for --help/--version; every other parse error is wrong usage.
        result.exitCode = rc == 0 ? 0 : 2;
        return result;
    }
    for (auto* sub : m_impl->app.get_subcommands()) {
        m_impl->selected = sub;
    }
    // A file the command will write, checked before the work: an unwritable path found only after
    // minutes of computing loses them (folders made by generate, training and pipeline excepted).
    if (m_impl->selected) {
        const std::string name = m_impl->selected->get_name();
        const bool writesFolder =
            name == "generate" || name == "training" || name == "pipeline" || name == "report";
        for (const auto& [flag, path] :
             {std::pair<const char*, const std::string*>{"--out", &m_impl->options.outPath},
              {"--json", &m_impl->options.jsonPath},
              {"--diagnostics", &m_impl->options.diagnosticsPath},
              {"--record", &m_impl->options.recordFolder}}) {
            if (path->empty()) {
                continue;
            }
            // The same for a folder the command makes: wrong usage (2), as for a file, not bad
            // input data (3), which a newcomer got from generate and pipeline.
            const bool folder =
                (writesFolder && std::string(flag) == "--out") || std::string(flag) == "--record";
            const std::string why = folder ? unwritableFolderReason(*path) : unwritableReason(*path);
            if (!why.empty()) {
                std::fprintf(stderr, "drytwin: error: %s %s: %s\n",
                             name == "discover" && std::string(flag) == "--out" ? "--out-model" : flag,
                             path->c_str(), why.c_str());
                result.exitNow = true;
                result.exitCode = 2;
                return result;
            }
        }
    }
    if (!m_impl->selected) {
        // Extras are for Qt's own options (-platform ...); a bare word is a mistyped subcommand.
        for (const auto& extra : m_impl->app.remaining()) {
            if (!extra.empty() && extra[0] != '-') {
                std::fprintf(stderr, "drytwin: unknown subcommand '%s'; see drytwin --help\n", extra.c_str());
                result.exitNow = true;
                result.exitCode = 2;
                return result;
            }
        }
        result.gui = true;
        result.guiDataPath = m_impl->options.dataPath;
        result.screenshotPath = m_impl->screenshotPath;
        result.projectPath = m_impl->projectPath;
        result.language = m_impl->language;
        result.modelPath = m_impl->guiModelPath;
        result.mappingPath = m_impl->guiMappingPath;
        result.runActions = m_impl->runActions;
        result.referencePath = m_impl->guiReferencePath;
        result.trainingSession = m_impl->trainingSession;
        result.saveProjectPath = m_impl->saveProjectPath;
    }
    m_impl->options.quiet = m_impl->quiet;
    return result;
}

void CommandLine::setReportRenderer(
    std::function<std::vector<std::string>(const workflow::PipelineResult&, const workflow::Session&,
                                           const std::string&, std::string&)>
        renderer,
    std::string commandLine) {
    m_impl->options.renderReport = std::move(renderer);
    m_impl->options.commandLine = std::move(commandLine);
}

int CommandLine::run() {
    if (!m_impl->selected) {
        return 2;
    }
    installInterruptHandler();
    m_impl->options.progress = makeCliProgress(m_impl->quiet);
    return m_impl->handlers.at(m_impl->selected)(m_impl->options);
}

} // namespace drytwin::app
