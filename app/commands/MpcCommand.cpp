#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"

#include "common/AtomicFile.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

namespace drytwin::app {

using namespace detail;

int runMpc(const CommandOptions& o) {
    workflow::MpcOptions options;
    // A bare name picks a bundled scenario; anything else is a file.
    if (!o.scenarioPath.empty()) {
        if (control::bundledScenarios().count(o.scenarioPath)) {
            options.bundledScenario = o.scenarioPath;
        } else {
            std::error_code ec;
            const bool bareName = o.scenarioPath.find_first_of("/\\.") == std::string::npos;
            if (bareName && !std::filesystem::exists(o.scenarioPath, ec)) {
                // A bare name that is not bundled: say which are, rather than "cannot open the file".
                std::string names;
                for (const auto& [name, text] : control::bundledScenarios()) {
                    names += (names.empty() ? "" : ", ") + name;
                }
                return fail(Error{ErrorKind::Usage, "--scenario",
                                  "\"" + o.scenarioPath + "\" is neither a bundled scenario (" + names +
                                      ") nor an existing file"});
            }
            options.scenarioPath = o.scenarioPath;
        }
    }
    if (!o.controllers.empty()) {
        options.closedLoop.controllers.clear();
        for (const auto& name : o.controllers) {
            const auto k = control::controllerByName(name);
            if (!k) {
                return fail(
                    Error{ErrorKind::Usage, "--controllers",
                          "\"" + name + "\" is not one of pbm, ext_input_residual, lstm, pgrl_cc, pi"});
            }
            // Named twice is one run (pi,pi ran and printed the PI loop twice).
            if (std::find(options.closedLoop.controllers.begin(), options.closedLoop.controllers.end(), *k) ==
                options.closedLoop.controllers.end()) {
                options.closedLoop.controllers.push_back(*k);
            }
        }
    }
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    if (!session.model().calibration) {
        std::fprintf(stderr,
                     "drytwin mpc: note: %s holds no calibration; the controllers predict with the "
                     "default physics parameters\n",
                     o.modelPath.c_str());
    }
    auto result = session.mpc(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    // Cancelled (Ctrl+C): the runs so far stopped at different points and their scores are not
    // comparable with each other or with a whole run (a PGRL-CC IAE of 20 after 51 of 500
    // decisions read as a result, with exit 0 and the JSON written). Said, nothing written, 130.
    if (result->ending.termination == Termination::StoppedKeptBest) {
        std::fprintf(stderr, "drytwin mpc: stopped before every controller had run the whole scenario; "
                             "nothing written (the scores of part-runs are not comparable)\n");
        return fail(cancelledError("mpc"));
    }
    const auto& r = result->closedLoop;
    std::printf(
        "Scenario %s on DryTwin's virtual %s plant (%s instruments): %d scored steps of 1 s after %d s "
        "of PI warm-up, MPC every %d s, band ±%.2f %% wb\n",
        r.scenario.name.c_str(), std::string(plant::plantKindName(r.scenario.plant)).c_str(),
        std::string(r.scenario.instrumentsName()).c_str(), r.scenario.lengthS, r.scenario.warmupS,
        r.scenario.controlIntervalS, r.scenario.bandPct);
    std::printf("\n%-20s %12s %12s %10s %11s %11s %11s %9s %12s\n", "controller", "IAE [% wb*s]",
                "effort [K^2]", "viol. [%]", "solve med", "solve max", "model med", "fallback",
                "gain [%wb/K]");
    for (const auto& run : r.runs) {
        if (!run.ran) {
            std::printf("%-20s skipped: %s\n", control::controllerName(run.kind), run.skippedReason.c_str());
            continue;
        }
        const auto& m = run.metrics;
        if (run.kind == control::ControllerKind::Pi) {
            std::printf("%-20s %12.1f %12.1f %10.1f %11s %11s %11s %9s\n", "pi (plant's own)", m.iaePctS,
                        m.effortK2, m.violationPct, "-", "-", "-", "-");
        } else {
            std::printf("%-20s %12.1f %12.1f %10.1f %8.2f ms %8.2f ms %8.2f ms %4d/%-4d %12.4f\n",
                        control::controllerName(run.kind), m.iaePctS, m.effortK2, m.violationPct,
                        m.solveMsMedian, m.solveMsMax, m.modelMsMedian, m.fallbacks, m.decisions,
                        m.gainPctPerKMedian);
        }
        if (m.fallbacks > 0) {
            std::printf("%-20s last fallback: %s\n", "", m.lastFallbackReason.c_str());
        }
        if (const auto ratio = run.kind == control::ControllerKind::Pi
                                   ? std::nullopt
                                   : control::mismatchedGainRatio(m.gainPctPerKMedian, r.plantGainPctPerK)) {
            std::printf("%-20s its model's gain is %.2f times the plant's: %s\n", "", *ratio,
                        control::gainMismatchEffect(*ratio).c_str());
        }
    }
    std::printf(
        "\nIAE and violations on the product's true outlet moisture; solve = Ipopt per decision, model = "
        "forecasts and linearisation; gain = the model's steady dX_out/dT_hot (the plant's: %.4f %%/K).\n",
        r.plantGainPctPerK);
    // Only where some model's forecasts were checked (the PI loop alone has none).
    const bool anyChecked = std::any_of(r.runs.begin(), r.runs.end(),
                                        [](const auto& run) { return run.forecastCheck.has_value(); });
    if (anyChecked) {
        std::printf(
            "\nWhy the ranking: each model forecasting the PI run as its MPC would (disturbances held, "
            "same update), MAE of X_out [%% wb]\n%-20s",
            "model");
    }
    bool header = false;
    bool tooShort = false;
    for (const auto& run : r.runs) {
        if (!run.forecastCheck) {
            continue;
        }
        if (!header) {
            for (int h : run.forecastCheck->horizonsS) {
                std::printf(" %9d s", h);
            }
            std::printf("\n");
            header = true;
        }
        std::printf("%-20s", control::controllerName(run.kind));
        for (double m : run.forecastCheck->maePct) {
            if (std::isfinite(m)) {
                std::printf(" %11.4f", m);
            } else {
                std::printf(" %11s", "n/a");
                tooShort = true;
            }
        }
        std::printf("\n");
    }
    if (tooShort) {
        std::printf("n/a: the scenario's PI run is too short to score a forecast that far ahead.\n");
    }
    std::printf("\n%.1f s\n", result->ending.elapsedSeconds);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::mpcJson(r)); !st) {
            return fail(st.error());
        }
    }
    // A controller asked for by name that could not run (a model file without that learnt part)
    // is a failed request, not a result: the table says why, the exit code says it failed.
    if (!o.controllers.empty()) {
        std::string skipped;
        for (const auto& run : r.runs) {
            if (!run.ran && !run.skippedReason.empty()) {
                skipped += (skipped.empty() ? "" : "; ") + std::string(control::controllerName(run.kind)) +
                           ": " + run.skippedReason;
            }
        }
        if (!skipped.empty()) {
            return fail(Error{ErrorKind::BadInput, o.modelPath, "asked for, could not run: " + skipped});
        }
    }
    return 0;
}

} // namespace drytwin::app
