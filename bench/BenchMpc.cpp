// The closed-loop benchmark of issue #12: the bundled 1,000-step scenario with all five
// controllers (wall time, Ipopt time per decision), then the same scenario over further seeds of
// its disturbances and noise, so that the ranking is not one seed's.
//   bench_mpc MODEL_FILE [SEEDS] [distributed|lumped]   (MODEL_FILE: e.g. the pipeline's model.json;
//   the plant: the scenario's own, distributed since issue #22, unless named)
//   Environment: BENCH_MPC_FIRST_SEED (default the scenario's, 11), BENCH_MPC_MOVE_WEIGHT,
//   BENCH_MPC_RESIDUAL_ALONG_PREVIOUS_PLAN (the hybrids' residual as before 2026-11-28).
#include "control/BundledScenarios.h"
#include "control/ClosedLoop.h"
#include "io/ModelFile.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace drytwin;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: bench_mpc MODEL_FILE [SEEDS] [distributed|lumped] [moving-correction]\n");
        return 2;
    }
    auto model = io::readModelFile(argv[1]);
    if (!model) {
        std::fprintf(stderr, "bench_mpc: %s\n", model.error().message().c_str());
        return 3;
    }
    const int seeds = argc > 2 ? std::atoi(argv[2]) : 5;
    auto scenario = control::parseScenario(control::bundledScenarios().at(control::kDefaultScenario),
                                           control::kDefaultScenario);
    if (!scenario) {
        std::fprintf(stderr, "bench_mpc: %s\n", scenario.error().message().c_str());
        return 3;
    }
    if (argc > 3) {
        const std::string kind = argv[3];
        if (kind != "distributed" && kind != "lumped") {
            std::fprintf(stderr, "bench_mpc: the plant is 'distributed' or 'lumped', not '%s'\n", argv[3]);
            return 2;
        }
        scenario->plant = kind == "lumped" ? plant::PlantKind::Lumped : plant::PlantKind::Distributed;
    }
    std::printf("plant: %s\n", std::string(plant::plantKindName(scenario->plant)).c_str());
    control::ClosedLoopOptions options;
    // "moving-correction": the hybrids' input-driven correction changes over the MPC's horizon as
    // it forecasts (MpcSettings::holdCorrectionOverHorizon off), for the comparison in docs/mpc.md.
    if (argc > 4) {
        if (std::string(argv[4]) != "moving-correction") {
            std::fprintf(stderr, "bench_mpc: the fourth argument is 'moving-correction' or nothing\n");
            return 2;
        }
        options.mpc.holdCorrectionOverHorizon = false;
    }
    // BENCH_MPC_RESIDUAL_ALONG_PREVIOUS_PLAN: the hybrids' learnt residual forecast along the
    // previous plan shifted (MpcSettings::residualAlongHeldHotAir off), the form before 2026-11-28.
    if (std::getenv("BENCH_MPC_RESIDUAL_ALONG_PREVIOUS_PLAN")) {
        options.mpc.residualAlongHeldHotAir = false;
    }
    // BENCH_MPC_MOVE_WEIGHT: the MPC's move weight (MpcSettings::moveWeight), for docs/mpc.md.
    if (const char* weight = std::getenv("BENCH_MPC_MOVE_WEIGHT")) {
        options.mpc.moveWeight = std::atof(weight);
    }
    std::printf("move weight %.3g per K²\n", options.mpc.moveWeight);
    std::printf("input-driven correction over the horizon: %s\n",
                options.mpc.holdCorrectionOverHorizon ? "held at the decision" : "moving");
    std::printf("learnt residual forecast along: %s\n", options.mpc.residualAlongHeldHotAir
                                                            ? "the hot air held at its last value"
                                                            : "the previous plan");
    std::map<std::string, std::vector<double>> iae, viol;
    int pgrlBeatsPbmIae = 0, pgrlFewerViolations = 0, pgrlBeatsPbm = 0, mpcBeatsPi = 0;
    // BENCH_MPC_FIRST_SEED: the scenario seeds start here instead of at the scenario's own (11),
    // so that a setting can be chosen on seeds the reported table does not use.
    unsigned firstSeed = scenario->seed;
    if (const char* first = std::getenv("BENCH_MPC_FIRST_SEED")) {
        firstSeed = static_cast<unsigned>(std::atoi(first));
    }
    for (int i = 0; i < seeds; ++i) {
        control::Scenario s = *scenario;
        s.seed = firstSeed + static_cast<unsigned>(i);
        const auto t0 = std::chrono::steady_clock::now();
        auto r = control::runScenario(s, *model, options);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!r) {
            std::fprintf(stderr, "bench_mpc: %s\n", r.error().message().c_str());
            return 4;
        }
        std::printf("seed %u: %.1f s for %zu controllers x %d steps (plant gain %.4f %%/K)\n", s.seed, wall,
                    r->runs.size(), s.lengthS, r->plantGainPctPerK);
        std::map<std::string, control::ClosedLoopMetrics> m;
        for (const auto& run : r->runs) {
            if (!run.ran) {
                continue;
            }
            const std::string name = control::controllerName(run.kind);
            m[name] = run.metrics;
            iae[name].push_back(run.metrics.iaePctS);
            viol[name].push_back(run.metrics.violationPct);
            if (i == 0 || run.kind != control::ControllerKind::Pi) {
                std::printf(
                    "  %-20s IAE %7.1f  effort %7.1f  viol %5.1f %%  solve median %.2f ms, max %.2f ms, "
                    "model median %.2f ms, fallbacks %d/%d, run %.1f s\n",
                    name.c_str(), run.metrics.iaePctS, run.metrics.effortK2, run.metrics.violationPct,
                    run.metrics.solveMsMedian, run.metrics.solveMsMax, run.metrics.modelMsMedian,
                    run.metrics.fallbacks, run.metrics.decisions, run.elapsedSeconds);
            }
        }
        if (m.count("pgrl_cc") && m.count("pbm")) {
            pgrlBeatsPbmIae += m["pgrl_cc"].iaePctS < m["pbm"].iaePctS;
            pgrlFewerViolations += m["pgrl_cc"].violationPct < m["pbm"].violationPct;
            // Issue #42's Table 2 criterion: lower IAE with no more violations, on the same seed.
            pgrlBeatsPbm +=
                m["pgrl_cc"].iaePctS < m["pbm"].iaePctS && m["pgrl_cc"].violationPct <= m["pbm"].violationPct;
        }
        for (const auto& [name, x] : m) {
            if (name != "pi" && m.count("pi") && x.iaePctS < m["pi"].iaePctS &&
                x.violationPct <= m["pi"].violationPct) {
                ++mpcBeatsPi;
                break;
            }
        }
    }
    std::printf("\nover %d seeds: mean (sd) of IAE [%%*s] and violations [%%]\n", seeds);
    for (const auto& [name, v] : iae) {
        double mean = 0, var = 0, vm = 0;
        for (double x : v) {
            mean += x / v.size();
        }
        for (double x : v) {
            var += (x - mean) * (x - mean) / std::max<std::size_t>(1, v.size() - 1);
        }
        for (double x : viol[name]) {
            vm += x / viol[name].size();
        }
        std::printf("  %-20s IAE %7.1f (%5.1f)   violations %5.1f\n", name.c_str(), mean, std::sqrt(var), vm);
    }
    std::printf(
        "PGRL-CC lower IAE than PBM in %d of %d seeds, fewer violations in %d, both (lower IAE, no more "
        "violations) in %d; an MPC beats PI on IAE with no more violations in %d\n",
        pgrlBeatsPbmIae, seeds, pgrlFewerViolations, pgrlBeatsPbm, mpcBeatsPi);
    return 0;
}
