#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"

#include "common/AtomicFile.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace drytwin::app {

using namespace detail;

int runPipeline(const CommandOptions& o) {
    workflow::PipelineOptions options;
    options.outFolder = o.outPath;
    options.evaluate.evaluation.horizonSteps = o.horizonSteps;
    workflow::Session session;
    int rc = 0;
    if (!calibrateOptions(o, options.calibrate, rc) || !trainOptions(o, options.train, rc) ||
        !open(o, session, rc)) {
        return rc;
    }
    // The HTML/PDF report is drawn into the pipeline's staging folder, so that it is moved into
    // the output folder with the rest, or not at all.
    double renderSeconds = 0;
    if (o.renderReport) {
        options.finishInFolder = [&](const workflow::PipelineResult& r,
                                     const std::string& folder) -> Expected<std::vector<std::string>> {
            const auto t0 = std::chrono::steady_clock::now();
            std::string error;
            auto files = o.renderReport(r, session, folder, error);
            renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (!error.empty()) {
                return Error{ErrorKind::BadInput, o.outPath, "the HTML/PDF report: " + error};
            }
            return files;
        };
    }
    auto result = session.pipeline(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& r = *result;
    std::printf("\n== inspect ==\n%zu batch(es), %zu rows; the cleaning rules keep %zu\n",
                r.inspect.batches.size(), r.inspect.rows, r.inspect.cleaning.kept);
    std::printf("\n== calibrate ==\n");
    printCalibration(r.calibrate);
    std::printf("\n== train ==\n");
    printTraining(r.train);
    std::printf("\n== evaluate ==\n");
    printEvaluation(r.evaluate.evaluation);
    std::printf("\n== ablation ==\n");
    printAblation(r.ablation);
    std::printf("\n== discover ==\nverdict %s", r.discover.discovery.verdict.c_str());
    for (const auto& f : r.discover.discovery.findings) {
        std::printf("; %s (%s = %.4g)", f.cause.c_str(),
                    std::string(properties::info(f.parameter).symbol).c_str(), f.value);
    }
    std::printf("\n");
    std::printf("\n== stages ==\n");
    for (const auto& s : r.stages) {
        std::printf("%-10s %7.1f s ", s.name.c_str(), s.elapsedSeconds);
        for (const auto& f : s.files) {
            std::printf(" %s", f.c_str());
        }
        std::printf("\n");
    }
    std::printf("\n== mpc (%s) ==\n", r.mpc.closedLoop.scenario.name.c_str());
    for (const auto& run : r.mpc.closedLoop.runs) {
        if (run.ran) {
            std::printf("%-20s IAE %8.1f %% wb*s, effort %8.1f K^2, violations %5.1f %%\n",
                        control::controllerName(run.kind), run.metrics.iaePctS, run.metrics.effortK2,
                        run.metrics.violationPct);
        }
    }
    std::printf(
        "\nreport %s, with inspect.json, model-calibrated.json, model.json, evaluate.json, ablation.json, "
        "diagnostics.json, discover.json, model-extended.json and mpc.json beside it\n",
        r.reportPath.c_str());
    if (o.renderReport) {
        for (const auto& stage : r.stages) {
            for (const auto& f : stage.files) {
                if (stage.name == "report" && f != r.reportPath) {
                    std::printf("report %s\n", f.c_str());
                }
            }
        }
        std::printf("HTML and PDF report with figures: %.1f s\n", renderSeconds);
    }
    return 0;
}

} // namespace drytwin::app
