// What pipeline() runs, in which order, and what it writes: inspect, calibrate, train, evaluate,
// ablation, discover and mpc, each result written to a staging folder as its stage ends, then the
// report; the files are moved into the output folder when every stage is done. A failed stage
// leaves the session's model and the output folder as they were before the pipeline.

#include "workflow/Session.h"

#include "common/AtomicFile.h"
#include "io/ModelFile.h"
#include "io/Report.h"
#include "io/ResultFiles.h"
#include "workflow/session/SessionInternal.h"

#include <filesystem>
#include <vector>

namespace drytwin::workflow {

Expected<PipelineResult> Session::pipeline(const PipelineOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = ready(options, "pipeline"); !st) {
        return st.error();
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(options.outFolder, ec);
    if (ec) {
        return Error{ErrorKind::BadInput, options.outFolder, "cannot create the folder: " + ec.message()};
    }
    // Every file goes into a staging folder inside the output folder (the same file system, so
    // that moving a file is a rename) and is moved out only when the whole run succeeded: a failed
    // or interrupted run leaves the folder's earlier report whole, never half replaced. A staging
    // folder an earlier run left behind (the process killed) is cleared first.
    const fs::path staging = fs::path(options.outFolder) / ".drytwin-pipeline-partial";
    fs::remove_all(staging, ec);
    fs::create_directories(staging, ec);
    if (ec) {
        return Error{ErrorKind::BadInput, staging.string(),
                     "cannot create the staging folder: " + ec.message()};
    }
    const auto in = [&](const char* name) { return (staging / name).string(); };
    // A failed stage leaves the session's model as it was before the pipeline.
    const hybrid::HybridModel modelBefore = m_model;
    const auto failWith = [&](Error e) {
        m_model = modelBefore;
        std::error_code ignored;
        fs::remove_all(staging, ignored);
        return e;
    };
    PipelineResult result;
    auto stageStart = std::chrono::steady_clock::now();
    const auto finishStage = [&](const char* name, std::vector<std::string> files) {
        result.stages.push_back({name, std::move(files), secondsSince(stageStart)});
        stageStart = std::chrono::steady_clock::now();
    };
    const auto write = [&](const std::string& path, const std::string& text) {
        return writeFileAtomically(path, text);
    };

    auto summary = inspect();
    if (!summary) {
        return failWith(summary.error());
    }
    result.inspect = *summary;
    if (auto st = write(in("inspect.json"), io::inspectJson(result.inspect)); !st) {
        return failWith(st.error());
    }
    finishStage("inspect", {in("inspect.json")});

    auto calibrated = calibrate(options.calibrate, progress);
    if (!calibrated) {
        return failWith(calibrated.error());
    }
    result.calibrate = *calibrated;
    if (auto st = saveModel(in("model-calibrated.json")); !st) {
        return failWith(st.error());
    }
    finishStage("calibrate", {in("model-calibrated.json")});

    auto trained = train(options.train, progress);
    if (!trained) {
        return failWith(trained.error());
    }
    result.train = *trained;
    if (auto st = saveModel(in("model.json")); !st) {
        return failWith(st.error());
    }
    finishStage("train", {in("model.json")});

    auto evaluated = evaluate(options.evaluate, progress);
    if (!evaluated) {
        return failWith(evaluated.error());
    }
    result.evaluate = *evaluated;
    if (auto st = write(in("evaluate.json"), io::evaluationJson(evaluated->evaluation)); !st) {
        return failWith(st.error());
    }
    if (auto st = write(in("diagnostics.json"), io::residualDiagnosticsJson(evaluated->diagnostics)); !st) {
        return failWith(st.error());
    }
    finishStage("evaluate", {in("evaluate.json"), in("diagnostics.json")});

    // The ablation trains its own variants on the calibrated physics, from the settings the
    // training chose (it reads them from the trained PGRL-CC).
    const hybrid::HybridModel trainedModel = m_model;
    auto ablated = ablation(progress);
    m_model = trainedModel;
    if (!ablated) {
        return failWith(ablated.error());
    }
    result.ablation = *ablated;
    if (auto st = write(in("ablation.json"), io::ablationJson(*ablated)); !st) {
        return failWith(st.error());
    }
    finishStage("ablation", {in("ablation.json")});

    // Discovery starts from the calibrated physics model (the trained one has the same physics;
    // its PGRL-CC settings are reused when discovery retrains on the extended model); the
    // extended model is written beside the others and does not replace the session's.
    auto discovered = discover(options.discover, progress);
    m_model = trainedModel;
    if (!discovered) {
        return failWith(discovered.error());
    }
    result.discover = *discovered;
    const auto& dd = *discovered;
    if (auto st = write(in("discover.json"),
                        io::discoveryJson(dd.discovery, dd.hasHybrid, dd.hybridMaeMoistureBefore,
                                          dd.hybridMaeMoistureAfter, dd.hybridMaeTemperatureBefore,
                                          dd.hybridMaeTemperatureAfter, dd.keptStartingModel, dd.references));
        !st) {
        return failWith(st.error());
    }
    if (auto st = io::writeModelFile(dd.extendedModel, in("model-extended.json")); !st) {
        return failWith(st.error());
    }
    finishStage("discover", {in("discover.json"), in("model-extended.json")});

    // The bundled closed-loop scenario with the trained model (paper Table 2).
    auto controlled = mpc(options.mpc, progress);
    if (!controlled) {
        return failWith(controlled.error());
    }
    if (controlled->ending.termination == Termination::StoppedKeptBest) {
        return failWith(cancelledError("mpc")); // a pipeline stage is whole or not written
    }
    result.mpc = *controlled;
    if (auto st = write(in("mpc.json"), io::mpcJson(controlled->closedLoop)); !st) {
        return failWith(st.error());
    }
    finishStage("mpc", {in("mpc.json")});

    auto report = io::writePipelineReport(staging.string());
    if (!report) {
        return failWith(report.error());
    }
    result.reportPath = *report;
    std::vector<std::string> reportFiles{*report};
    if (options.finishInFolder) {
        auto more = options.finishInFolder(result, staging.string());
        if (!more) {
            return failWith(more.error());
        }
        reportFiles.insert(reportFiles.end(), more->begin(), more->end());
    }
    finishStage("report", std::move(reportFiles));

    // The run is whole: its files replace the folder's, one rename each.
    const auto finalPath = [&](const std::string& stagedPath) {
        return (fs::path(options.outFolder) / fs::path(stagedPath).filename()).string();
    };
    // The staged files listed first, then moved: a folder is not changed while it is read, and a
    // listing that fails is an error, not a run whose files silently stayed behind.
    std::vector<fs::path> staged;
    for (fs::directory_iterator it(staging, ec), end; !ec && it != end; it.increment(ec)) {
        staged.push_back(it->path());
    }
    if (ec) {
        return failWith(
            Error{ErrorKind::BadInput, staging.string(), "cannot list the finished files: " + ec.message()});
    }
    for (const auto& file : staged) {
        fs::rename(file, fs::path(options.outFolder) / file.filename(), ec);
        if (ec) {
            return failWith(Error{ErrorKind::BadInput,
                                  (fs::path(options.outFolder) / file.filename()).string(),
                                  "cannot move the finished file into place: " + ec.message()});
        }
    }
    fs::remove_all(staging, ec);
    for (auto& stage : result.stages) {
        for (auto& f : stage.files) {
            f = finalPath(f);
        }
    }
    result.reportPath = finalPath(result.reportPath);
    result.ending = {Termination::Completed, "every stage done", secondsSince(t0)};
    return result;
}

} // namespace drytwin::workflow
