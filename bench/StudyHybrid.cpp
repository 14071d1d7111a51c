// The hybrid study of issue #42: does the learnt layer hold on data sets it was not tuned on, and
// is the hybrid a better simulator than the physics alone?
//   --part unseen: ten data sets (both plants, the demo mix and plain nulls, 3 x 2,000 to
//     10 x 6,300 samples, realistic sensors with spikes, stuck values and dropouts), each
//     generated, calibrated, trained and evaluated as `drytwin pipeline` does; the skill of every
//     learnt model (MAE over the better trivial predictor) at each horizon of the held-out part.
//   --part free-run: the distributed plant without mechanism or drift, three pairs of seeds: the
//     model is calibrated and trained on one data set (6 x 4,000 s) and judged as a simulator
//     (free run: never a measured output) on every row of another (3 x 4,000 s), beside the PBM and
//     a ridge regression on lagged inputs and proxies (lags 0-300 s) fitted on the same rows.
// Run: build/bench/study_hybrid [--part unseen|free-run] [--quick (the first 3 sets / 1 pair)]
//      [--seed-base N (unseen: seeds N+1 … N+10, default 900)] [--work DIR (default
//      /tmp/drytwin-study-hybrid)]
// Writes Markdown tables to stdout, progress to stderr. Free-run variants for studies, by environment:
// STUDY_HYBRID_VARIANTS (other bases and grids), STUDY_HYBRID_ORACLE (the ridge fitted on the judged
// rows), STUDY_HYBRID_EXTENDED=gas,wall[,fall] (the physics given the line's structure first).
#include "common/Units.h"
#include "hybrid/Evaluation.h"
#include "hybrid/HybridTraining.h"
#include "plant/PlantExport.h"
#include "residual/InputDrivenCorrection.h"
#include "workflow/Session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace drytwin;

namespace {

std::string workDir = "/tmp/drytwin-study-hybrid";
/// --design-pair A:B: the free run on seeds kept for designing the method (700:701), never the
/// judged ones.
std::pair<unsigned, unsigned> designPair{0, 0};
/// --seed-base N: the unseen part's ten data sets on seeds N+1 … N+10 instead of 901 … 910 (the
/// same sizes, plants and mixes), for a judgement on seeds a change was not prompted by.
unsigned seedBase = 900;

struct DataSetSpec {
    std::string name;
    unsigned seed = 1;
    int batches = 5;
    int samples = 4000;
    plant::PlantKind plant = plant::PlantKind::Distributed;
    bool demoMix = true;     ///< the bundled demo's mechanisms and drift; false: no mechanism, no drift
    bool drift = false;      ///< with demoMix false: the unmeasured drift alone
    double faultScale = 1.0; ///< multiplies the transmitters' spike, stuck and dropout rates
};

plant::PlantOptions plantOptions(const DataSetSpec& s) {
    plant::PlantOptions o = s.demoMix ? plant::PlantOptions::demo(s.seed, s.plant) : plant::PlantOptions{};
    o.plant = s.plant;
    o.sensors = plant::SensorMode::Realistic;
    o.seed = s.seed;
    o.batches = s.batches;
    o.samples = s.samples;
    if (!s.demoMix) {
        o.effects.clear();
        o.unmeasuredDrift = s.drift;
    }
    o.sensorFaults.spikesPerHour *= s.faultScale;
    o.sensorFaults.stuckPerHour *= s.faultScale;
    o.sensorFaults.dropoutsPerHour *= s.faultScale;
    return o;
}

void fail(const std::string& what, const Error& e) {
    std::fprintf(stderr, "study_hybrid: %s: %s\n", what.c_str(), e.message().c_str());
    std::exit(1);
}

/// A session holding the data set (generated once into the work folder) and its calibration.
workflow::Session calibratedSession(const DataSetSpec& s, bool train) {
    workflow::Session session;
    const std::string folder = workDir + "/" + s.name;
    workflow::GenerateOptions g;
    g.plant = plantOptions(s);
    g.outFolder = folder;
    if (auto r = session.generate(g); !r) {
        fail(s.name + " generate", r.error());
    }
    workflow::OpenOptions open;
    open.dataPath = folder;
    if (auto r = session.open(open); !r) {
        fail(s.name + " open", r.error());
    }
    if (auto r = session.calibrate(); !r) {
        fail(s.name + " calibrate", r.error());
    }
    if (train) {
        if (auto r = session.train(); !r) {
            fail(s.name + " train", r.error());
        }
    }
    return session;
}

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int partUnseen(bool quick) {
    using K = plant::PlantKind;
    // Seeds 901-910 were never looked at while the method was designed (issue #42); the realised
    // reference blend and held-error decay (2026-11-27) were prompted by them, and are judged on
    // --seed-base 960 (961-970).
    std::vector<DataSetSpec> sets{
        {"d901-demo-3x2000", 901, 3, 2000, K::Distributed, true},
        {"d902-demo-5x4000", 902, 5, 4000, K::Distributed, true},
        {"d903-null-4x3000", 903, 4, 3000, K::Distributed, false},
        {"d904-drift-3x2000", 904, 3, 2000, K::Distributed, false, true},
        {"d905-null-6x4000", 905, 6, 4000, K::Distributed, false},
        {"d906-demo-10x6300", 906, 10, 6300, K::Distributed, true},
        {"d907-faults-6x4000", 907, 6, 4000, K::Distributed, true, false, 5.0},
        {"l908-demo-5x4000", 908, 5, 4000, K::Lumped, true},
        {"l909-null-4x3000", 909, 4, 3000, K::Lumped, false},
        {"l910-demo-10x6300", 910, 10, 6300, K::Lumped, true},
    };
    for (auto& s : sets) {
        const unsigned seed = s.seed - 900 + seedBase;
        s.name = s.name.substr(0, 1) + std::to_string(seed) + s.name.substr(4);
        s.seed = seed;
    }
    if (quick) {
        sets.resize(3);
    }
    std::printf("| data set | PGRL-CC skill X, H = 1 | worst over H = 1-180 (at H) | mean | input-only H = 1 "
                "| LSTM H = 1 "
                "| free run MAE X: PBM / PGRL-CC [%% wb] | T: PBM / PGRL-CC [°C] | s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    int failures = 0;
    std::vector<std::string> lstmRows; // the LSTM baseline's own table, printed after this one
    for (const auto& s : sets) {
        const auto t0 = std::chrono::steady_clock::now();
        std::fprintf(stderr, "study_hybrid: %s ...\n", s.name.c_str());
        auto session = calibratedSession(s, true);
        auto ev = session.evaluate();
        if (!ev) {
            fail(s.name + " evaluate", ev.error());
        }
        const auto& r = ev->evaluation;
        auto model = [&](const std::string& key) -> const evaluation::ModelMetrics* {
            for (const auto& m : r.models) {
                if (m.name == key) {
                    return &m;
                }
            }
            return nullptr;
        };
        auto freeRun = [&](const std::string& key) -> const evaluation::ModelMetrics* {
            for (const auto& m : r.freeRun) {
                if (m.name == key) {
                    return &m;
                }
            }
            return nullptr;
        };
        const auto* pgrl = model(hybrid::kPgrlCcKey);
        const auto* ext = model(hybrid::kExtInputKey);
        const auto* lstm = model(hybrid::kLstmKey);
        const auto* pbmFree = freeRun(hybrid::kPbmKey);
        const auto* pgrlFree = freeRun(hybrid::kPgrlCcKey);
        if (!pgrl || !ext || !lstm || !pbmFree || !pgrlFree) {
            fail(s.name, Error{ErrorKind::Numerical, "evaluate", "a model is missing from the evaluation"});
        }
        double worst = 0, mean = 0;
        int worstH = 0;
        for (std::size_t i = 0; i < r.horizons.size(); ++i) {
            const double k = pgrl->skillMoistureByHorizon[i];
            mean += k / double(r.horizons.size());
            if (k > worst) {
                worst = k;
                worstH = r.horizons[i];
            }
        }
        failures += worst > 1.0 || ext->skillMoisture > 1.2 || lstm->skillMoisture > 1.2;
        std::printf("| %s | %.3f | %.3f (%d) | %.3f | %.3f | %.3f | %.4f / %.4f | %.3f / %.3f | %.0f |\n",
                    s.name.c_str(), pgrl->skillMoisture, worst, worstH, mean, ext->skillMoisture,
                    lstm->skillMoisture, pbmFree->moisture.mae, pgrlFree->moisture.mae,
                    pbmFree->temperature.mae, pgrlFree->temperature.mae, seconds(t0));
        std::fflush(stdout);
        if (const auto& trained = session.model().lstm) {
            const auto& v = trained->validation();
            char row[512];
            std::snprintf(row, sizeof row, "| %s | %.3f | %.3f | %.3f / %.3f (%s) | %d of %zu | %.1f |\n",
                          s.name.c_str(), lstm->skillMoisture, lstm->skillTemperature, v.skillMoisture,
                          v.skillTemperature,
                          v.validated ? (v.beatsReferences ? "beats" : "does not beat") : "not validated",
                          v.bestEpoch, trained->epochs().size(), trained->trainingSeconds());
            lstmRows.push_back(row);
        }
    }
    std::printf("\n%d of %zu data sets miss a goal (PGRL-CC skill X > 1.0 at some horizon, or the input-only "
                "correction's or the LSTM's one-step skill > 1.2)\n",
                failures, sets.size());
    std::printf("\nLSTM baseline: one-step skill on the held-out part; on its own validation part (the "
                "training part's last batches or rows), with the verdict; the epoch kept of those run; "
                "training time\n\n");
    std::printf(
        "| data set | LSTM skill X, H = 1 | LSTM skill T, H = 1 | validation skill X / T | epoch kept "
        "| training s |\n|---|---|---|---|---|---|\n");
    for (const auto& row : lstmRows) {
        std::printf("%s", row.c_str());
    }
    return 0;
}

/// --part never-worse (issue #75): is the hybrid never worse than its physics? On each data set,
/// generated, calibrated, trained and evaluated as `drytwin pipeline` does: PGRL-CC's skill at
/// every horizon to 180 s (X_out and T_out), and the free-run MAE of PGRL-CC and of the input-only
/// correction over the PBM's (X_out and T_out). Goals: skill ≤ 1.0 everywhere, free run ≤ 1.02.
/// The judged sets are 30 seeds from --seed-base + 1: six sizes (3 × 2,000 … 10 × 6,300) × five
/// mixes (distributed demo, null, drift; lumped demo, null); --design runs the issue's own
/// seeds 78-84 instead (the data sets that showed the defect; design data).
bool designSets = false;
int lstmEpochsForStudy = 30;
/// --only: a comma-separated list of data set names (or their seeds) to run, for a quick look.
std::string onlySets;
/// --guards: which of the input-driven correction's guards of issue #75 are on (for comparison).
std::string guards = "support,agreement,range,within,every-fold,later,take-back,bic"; // the defaults

std::vector<DataSetSpec> neverWorseSets() {
    using K = plant::PlantKind;
    if (designSets) {
        return {{"d78-demo-5x4000", 78, 5, 4000, K::Distributed, true},
                {"d79-demo-5x4000", 79, 5, 4000, K::Distributed, true},
                {"d81-demo-3x2000", 81, 3, 2000, K::Distributed, true},
                {"d82-null-8x5000", 82, 8, 5000, K::Distributed, false},
                {"d83-demo-5x4000", 83, 5, 4000, K::Distributed, true},
                {"d84-null-4x3000", 84, 4, 3000, K::Distributed, false}};
    }
    const std::pair<int, int> sizes[] = {{3, 2000}, {4, 3000}, {5, 4000}, {6, 4000}, {8, 5000}, {10, 6300}};
    struct Mix {
        const char* tag;
        K plant;
        bool demo, drift;
    };
    const Mix mixes[] = {{
                             "d",
                             K::Distributed,
                             true,
                             false,
                         },
                         {"d", K::Distributed, false, false},
                         {"d", K::Distributed, false, true},
                         {"l", K::Lumped, true, false},
                         {"l", K::Lumped, false, false}};
    std::vector<DataSetSpec> sets;
    for (int m = 0; m < 5; ++m) {
        for (int z = 0; z < 6; ++z) {
            DataSetSpec s;
            s.seed = seedBase + 1 + static_cast<unsigned>(m * 6 + z);
            s.batches = sizes[z].first;
            s.samples = sizes[z].second;
            s.plant = mixes[m].plant;
            s.demoMix = mixes[m].demo;
            s.drift = mixes[m].drift;
            s.name = std::string(mixes[m].tag) + std::to_string(s.seed) + "-" +
                     (s.demoMix ? "demo" : (s.drift ? "drift" : "null")) + "-" + std::to_string(s.batches) +
                     "x" + std::to_string(s.samples);
            sets.push_back(s);
        }
    }
    return sets;
}

int partNeverWorse(bool quick) {
    auto sets = neverWorseSets();
    if (quick) {
        sets.resize(std::min<std::size_t>(sets.size(), 3));
    }
    if (!onlySets.empty()) {
        std::vector<DataSetSpec> kept;
        for (const auto& s : sets) {
            if (("," + onlySets + ",").find("," + std::to_string(s.seed) + ",") != std::string::npos ||
                ("," + onlySets + ",").find("," + s.name + ",") != std::string::npos) {
                kept.push_back(s);
            }
        }
        sets = kept;
    }
    std::printf("| data set | PGRL-CC worst skill X (H) | worst skill T (H) | free run X: PGRL-CC / PBM | T: "
                "PGRL-CC / PBM | input-only X / PBM | input-only T / PBM | PBM free run X [%% wb] / T [°C] | "
                "goals | s |\n|---|---|---|---|---|---|---|---|---|---|\n");
    int missed = 0;
    for (const auto& s : sets) {
        const auto t0 = std::chrono::steady_clock::now();
        std::fprintf(stderr, "study_hybrid: %s ...\n", s.name.c_str());
        workflow::Session session = calibratedSession(s, false);
        workflow::TrainOptions train;
        train.lstm.epochs = lstmEpochsForStudy;
        train.residual.inputDrivenOptions.supportGuard = guards.find("support") != std::string::npos;
        train.residual.inputDrivenOptions.agreementAcrossFolds =
            guards.find("agreement") != std::string::npos;
        train.residual.inputDrivenOptions.rangeGuard = guards.find("range") != std::string::npos;
        train.residual.inputDrivenOptions.withinBatch = guards.find("within") != std::string::npos;
        train.residual.inputDrivenOptions.everyFoldNoWorse = guards.find("every-fold") != std::string::npos;
        train.residual.inputDrivenOptions.laterInTime = guards.find("later") != std::string::npos;
        train.residual.realisedPriorPerHorizon = guards.find("prior-h") != std::string::npos;
        train.residual.realisedCorrectionChange = guards.find("take-back") != std::string::npos;
        train.residual.parsimoniousWeights = guards.find("bic") != std::string::npos;
        train.residual.trainedHeldErrorDecay = guards.find("decay") != std::string::npos;
        if (auto r = session.train(train); !r) {
            fail(s.name + " train", r.error());
        }
        // Kept beside the data for `--part why` and `drytwin evaluate`.
        if (auto st = session.saveModel(workDir + "/" + s.name + ".model.json"); !st) {
            fail(s.name + " save", st.error());
        }
        auto ev = session.evaluate();
        if (!ev) {
            fail(s.name + " evaluate", ev.error());
        }
        const auto& r = ev->evaluation;
        const auto find = [](const std::vector<evaluation::ModelMetrics>& list,
                             const char* key) -> const evaluation::ModelMetrics* {
            for (const auto& m : list) {
                if (m.name == key) {
                    return &m;
                }
            }
            return nullptr;
        };
        const auto* pgrl = find(r.models, hybrid::kPgrlCcKey);
        const auto* pbmFree = find(r.freeRun, hybrid::kPbmKey);
        const auto* pgrlFree = find(r.freeRun, hybrid::kPgrlCcKey);
        const auto* extFree = find(r.freeRun, hybrid::kExtInputKey);
        if (!pgrl || !pbmFree || !pgrlFree || !extFree) {
            fail(s.name, Error{ErrorKind::Numerical, "evaluate", "a model is missing from the evaluation"});
        }
        double worstX = 0, worstT = 0;
        int atX = 0, atT = 0;
        for (std::size_t i = 0; i < r.horizons.size(); ++i) {
            if (r.horizons[i] > 180) {
                continue;
            }
            if (pgrl->skillMoistureByHorizon[i] > worstX) {
                worstX = pgrl->skillMoistureByHorizon[i];
                atX = r.horizons[i];
            }
            if (pgrl->skillTemperatureByHorizon[i] > worstT) {
                worstT = pgrl->skillTemperatureByHorizon[i];
                atT = r.horizons[i];
            }
        }
        const double fx = pgrlFree->moisture.mae / pbmFree->moisture.mae;
        const double ft = pgrlFree->temperature.mae / pbmFree->temperature.mae;
        const double ex = extFree->moisture.mae / pbmFree->moisture.mae;
        const double et = extFree->temperature.mae / pbmFree->temperature.mae;
        std::string goals;
        const auto miss = [&](bool failed, const char* what) {
            if (failed) {
                goals += goals.empty() ? what : std::string(", ") + what;
            }
        };
        miss(worstX > 1.0, "skill X");
        miss(fx > 1.02, "free X");
        miss(ft > 1.02, "free T");
        miss(ex > 1.02, "input-only X");
        miss(et > 1.02, "input-only T");
        missed += !goals.empty();
        std::printf("| %s | %.3f (%d) | %.3f (%d) | %.3f | %.3f | %.3f | %.3f | %.4f / %.3f | %s | %.0f |\n",
                    s.name.c_str(), worstX, atX, worstT, atT, fx, ft, ex, et, pbmFree->moisture.mae,
                    pbmFree->temperature.mae, goals.empty() ? "met" : goals.c_str(), seconds(t0));
        std::fflush(stdout);
    }
    std::printf("\n%d of %zu data sets miss a goal (PGRL-CC moisture skill > 1.0 at a horizon to 180 s, or a "
                "free-run MAE above 1.02 times the PBM's)\n",
                missed, sets.size());
    return 0;
}

/// Free-run MAE (% wb, °C) of predictions against every kept row of the views.
std::pair<double, double> freeRunMae(const std::vector<residual::BatchView>& views,
                                     const evaluation::Predictor& predict) {
    const auto scored = evaluation::scorePredictions(views, predict, 1);
    return {scored.moisture.mae, scored.temperature.mae};
}

int partFreeRun(bool quick) {
    std::vector<std::pair<unsigned, unsigned>> pairs{{931, 932}, {933, 934}, {935, 936}};
    if (quick) {
        pairs.resize(1);
    }
    if (designPair.first != 0) {
        pairs = {designPair};
    }
    std::printf(
        "Free-run MAE against the measured outlet (X %% wb, T °C); in brackets against its true value. "
        "Floor: the transmitters' own error (measured minus true), below which no simulator judged on "
        "measured data can go.\n\n");
    std::printf("| trained on / judged on | floor X | PBM X | ridge X | PGRL-CC X | PGRL-CC vs PBM X | floor "
                "T | PBM T | "
                "ridge T | PGRL-CC T | PGRL-CC vs PBM T |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& [trainSeed, judgeSeed] : pairs) {
        const DataSetSpec a{"free-train-" + std::to_string(trainSeed),
                            trainSeed,
                            6,
                            4000,
                            plant::PlantKind::Distributed,
                            false};
        const DataSetSpec b{"free-judge-" + std::to_string(judgeSeed),
                            judgeSeed,
                            3,
                            4000,
                            plant::PlantKind::Distributed,
                            false};
        std::fprintf(stderr, "study_hybrid: free run %u -> %u ...\n", trainSeed, judgeSeed);
        auto trained = calibratedSession(a, true);
        const auto& model = trained.model();
        // The ridge reference: fitted on the rows the hybrid was trained on (the chronological 70 %).
        auto pbmA = hybrid::simulatePbm(trained.siBatches(), model, model.switches);
        if (!pbmA) {
            fail(a.name + " PBM", pbmA.error());
        }
        residual::InputDrivenOptions ridgeOptions;
        ridgeOptions.basis = residual::InputBasis::LaggedInputs;
        auto ridge = residual::InputDrivenCorrection::train(
            hybrid::splitViews(trained.siBatches(), *pbmA, false), ridgeOptions);
        if (!ridge) {
            fail(a.name + " ridge", ridge.error());
        }
        auto bank = residual::InputDrivenCorrection::train(
            hybrid::splitViews(trained.siBatches(), *pbmA, false), residual::InputDrivenOptions{});
        if (!bank) {
            fail(a.name + " input-driven correction", bank.error());
        }
        std::fprintf(stderr, "study_hybrid: %s: %s\n", a.name.c_str(),
                     bank->validation().basisChoice.c_str());
        std::vector<std::pair<std::string, residual::InputDrivenCorrection>> variants;
        if (std::getenv("STUDY_HYBRID_VARIANTS")) {
            auto add = [&](const std::string& name, residual::InputDrivenOptions o) {
                auto c = residual::InputDrivenCorrection::train(
                    hybrid::splitViews(trained.siBatches(), *pbmA, false), o);
                if (c) {
                    variants.emplace_back(name, std::move(*c));
                }
            };
            const std::vector<double> wideGrid{1e-3, 1e-2, 1e-1, 1.0, 3.0, 10.0, 30.0, 100.0};
            residual::InputDrivenOptions o;
            o.basis = residual::InputBasis::LaggedInputs;
            o.ridgeGrid = wideGrid;
            add("lags, wide grid", o);
            o.basis = residual::InputBasis::FilterBankAndLags;
            add("bank+lags, wide grid", o);
        }
        // The judged data straight from the plant, with the outlet's true values beside the
        // transmitters' readings: the instruments' floor says how close any simulator can come.
        auto judgedPlant = plant::runPlant(plantOptions(b));
        if (!judgedPlant) {
            fail(b.name, judgedPlant.error());
        }
        const auto batches = plant::toSiBatches(*judgedPlant, b.seed);
        auto truth = batches;
        for (std::size_t i = 0; i < truth.size(); ++i) {
            truth[i].xOutDb = judgedPlant->batches[i].xOutTrueDb;
            truth[i].tOutK = judgedPlant->batches[i].tOutTrueK;
        }
        auto pbmB = hybrid::simulatePbm(batches, model, model.switches);
        if (!pbmB) {
            fail(b.name + " PBM", pbmB.error());
        }
        std::vector<residual::BatchView> views, truthViews;
        for (std::size_t i = 0; i < batches.size(); ++i) {
            views.push_back({&batches[i], &(*pbmB)[i], {0, batches[i].rows()}});
            truthViews.push_back({&truth[i], &(*pbmB)[i], {0, batches[i].rows()}});
        }
        const auto floor = freeRunMae(views, [&](const residual::BatchView& v) {
            auto p = residual::HybridPrediction::unknown(v.rows.size());
            const auto& t = truth[static_cast<std::size_t>(&v - views.data())];
            for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
                p.xOutPct[k - v.rows.begin] = units::dryToWetPct(t.xOutDb[k]);
                p.tOutC[k - v.rows.begin] = units::kelvinToCelsius(t.tOutK[k]);
            }
            return p;
        });
        const auto pbm = freeRunMae(views, evaluation::pbmPrediction);
        auto corrected = [&](const residual::InputDrivenCorrection& c) {
            return [&c](const residual::BatchView& v) {
                auto p = evaluation::pbmPrediction(v);
                std::vector<double> cx, ct;
                c.correct(*v.batch, *v.pbm, cx, ct);
                for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
                    p.xOutPct[k - v.rows.begin] += cx[k];
                    p.tOutC[k - v.rows.begin] += ct[k];
                }
                return p;
            };
        };
        // STUDY_HYBRID_ORACLE: the lags' ridge fitted on the judged rows themselves (in-sample, a
        // smaller penalty): roughly the most a linear input-driven correction could reach on them,
        // which says whether a free-run goal is within reach of any such model.
        if (std::getenv("STUDY_HYBRID_ORACLE")) {
            residual::InputDrivenOptions o;
            o.basis = residual::InputBasis::LaggedInputs;
            o.ridgeGrid = {1e-5, 1e-4, 1e-3, 1e-2, 1e-1};
            auto oracle = residual::InputDrivenCorrection::train(views, o);
            if (oracle) {
                const auto m = freeRunMae(views, corrected(*oracle));
                const auto mt = freeRunMae(truthViews, corrected(*oracle));
                std::fprintf(stderr,
                             "  oracle (lags fitted on the judged rows): X %.4f (%.4f) T %.3f (%.3f)\n",
                             m.first, mt.first, m.second, mt.second);
            }
        }
        // STUDY_HYBRID_EXTENDED: the physics given the line's structure first. A healthy distributed
        // line has what the lumped model lacks (a gas phase, a wall): its extensions are calibrated
        // with h_HDT and k_HDT on the training seed (every 10th row of all of it), and the lags'
        // ridge learns what is left of that model's free-run error.
        if (const char* extended = std::getenv("STUDY_HYBRID_EXTENDED")) {
            using properties::Param;
            workflow::Session ext = calibratedSession(a, false);
            workflow::CalibrateOptions co;
            co.subsetCount = 0;
            const std::string which = extended;
            if (which.find("gas") != std::string::npos) {
                co.calibration.freeParameters.push_back(Param::theta_gas);
            }
            if (which.find("wall") != std::string::npos) {
                co.calibration.freeParameters.push_back(Param::theta_wall);
            }
            if (which.find("fall") != std::string::npos) {
                co.calibration.freeParameters.push_back(Param::theta_fall);
            }
            if (auto r = ext.calibrate(co); !r) {
                fail(a.name + " extended calibration", r.error());
            }
            const auto& em = ext.model();
            std::fprintf(stderr,
                         "  extended physics (%s): h_HDT %.4g k_HDT %.4g theta_gas %.3g theta_wall %.3g "
                         "theta_fall %.3g\n",
                         extended, em.parameters[Param::h_HDT], em.parameters[Param::k_HDT],
                         em.parameters[Param::theta_gas], em.parameters[Param::theta_wall],
                         em.parameters[Param::theta_fall]);
            auto extA = hybrid::simulatePbm(ext.siBatches(), em, em.switches);
            auto extB = hybrid::simulatePbm(batches, em, em.switches);
            if (!extA || !extB) {
                fail(a.name + " extended PBM", extA ? extB.error() : extA.error());
            }
            auto extRidge = residual::InputDrivenCorrection::train(
                hybrid::splitViews(ext.siBatches(), *extA, false), ridgeOptions);
            if (!extRidge) {
                fail(a.name + " extended ridge", extRidge.error());
            }
            std::vector<residual::BatchView> extViews;
            for (std::size_t i = 0; i < batches.size(); ++i) {
                extViews.push_back({&batches[i], &(*extB)[i], {0, batches[i].rows()}});
            }
            const auto extPbm = freeRunMae(extViews, evaluation::pbmPrediction);
            const auto extCorrected = freeRunMae(extViews, corrected(*extRidge));
            std::fprintf(stderr,
                         "  extended PBM: X %.4f T %.3f; extended PBM + lags' ridge: X %.4f T %.3f "
                         "(plain PBM X %.4f T %.3f)\n",
                         extPbm.first, extPbm.second, extCorrected.first, extCorrected.second, pbm.first,
                         pbm.second);
        }
        const auto ridgeMae = freeRunMae(views, corrected(*ridge));
        const auto bankMae = freeRunMae(views, corrected(*bank));
        if (!variants.empty()) { // what an input-driven model could reach at most: fitted on the judged rows
            if (const char* dump = std::getenv("STUDY_HYBRID_DUMP")) { // rows of the judged set, for a look
                FILE* f = std::fopen(dump, "w");
                std::fprintf(f, "batch,t,x_meas,x_pbm,x_corr,t_meas,t_pbm,t_corr,t_hot,feed,x_in\n");
                for (const auto& v : views) {
                    std::vector<double> cx, ct;
                    variants.front().second.correct(*v.batch, *v.pbm, cx, ct);
                    for (std::size_t k = 0; k < v.rows.end; ++k) {
                        const double xp = units::dryToWetPct(v.pbm->xOutDb[k]);
                        std::fprintf(f, "%s,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g\n", v.batch->id.c_str(),
                                     v.batch->timeS[k], units::dryToWetPct(v.batch->xOutDb[k]), xp,
                                     xp + cx[k], v.batch->tOutK[k] - 273.15, v.pbm->tOutK[k] - 273.15,
                                     v.pbm->tOutK[k] - 273.15 + ct[k], v.batch->tHotK[k] - 273.15,
                                     v.batch->feedKgPerS[k] * 3600, units::dryToWetPct(v.batch->xInDb[k]));
                    }
                }
                std::fclose(f);
            }
            for (const auto& v : views) { // per-batch mean error of the first variant
                std::vector<double> cx, ct;
                variants.front().second.correct(*v.batch, *v.pbm, cx, ct);
                double sx = 0, st = 0, ax = 0, n = 0;
                std::vector<double> ex;
                for (std::size_t k = 0; k < v.rows.end; ++k) {
                    const double e =
                        units::dryToWetPct(v.batch->xOutDb[k]) - units::dryToWetPct(v.pbm->xOutDb[k]) - cx[k];
                    const double t = v.batch->tOutK[k] - v.pbm->tOutK[k] - ct[k];
                    if (std::isfinite(e) && std::isfinite(t)) {
                        sx += e;
                        st += t;
                        ax += std::abs(e);
                        n += 1;
                        ex.push_back(e);
                    }
                }
                double mx = sx / n, dev = 0;
                for (double e : ex)
                    dev += std::abs(e - mx);
                std::fprintf(
                    stderr, "  batch %s: mean error X %+.4f T %+.3f, MAE X %.4f, MAE X about its mean %.4f\n",
                    v.batch->id.c_str(), mx, st / n, ax / n, dev / n);
            }
        }
        for (const auto& [name, c] : variants) {
            const auto m = freeRunMae(views, corrected(c));
            std::fprintf(stderr, "  variant %-20s X %.4f T %.3f (CV ridge %g)\n", name.c_str(), m.first,
                         m.second, c.validation().ridge);
        }
        std::fprintf(stderr, "  input-driven correction alone: X %.4f T %.3f (CV ridge %g; %s)\n",
                     bankMae.first, bankMae.second, bank->validation().ridge,
                     bank->validation().note.c_str());
        const auto pgrl =
            freeRunMae(views, [&](const residual::BatchView& v) { return model.pgrlCc->predictFreeRun(v); });
        const auto pbmTrue = freeRunMae(truthViews, evaluation::pbmPrediction);
        const auto ridgeTrue = freeRunMae(truthViews, corrected(*ridge));
        const auto pgrlTrue = freeRunMae(
            truthViews, [&](const residual::BatchView& v) { return model.pgrlCc->predictFreeRun(v); });
        std::printf("| %u / %u | %.4f | %.4f (%.4f) | %.4f (%.4f) | %.4f (%.4f) | %+.0f %% (%+.0f %%) | %.3f "
                    "| %.3f (%.3f) | "
                    "%.3f (%.3f) | %.3f (%.3f) | %+.0f %% (%+.0f %%) |\n",
                    trainSeed, judgeSeed, floor.first, pbm.first, pbmTrue.first, ridgeMae.first,
                    ridgeTrue.first, pgrl.first, pgrlTrue.first, 100 * (pgrl.first / pbm.first - 1),
                    100 * (pgrlTrue.first / pbmTrue.first - 1), floor.second, pbm.second, pbmTrue.second,
                    ridgeMae.second, ridgeTrue.second, pgrl.second, pgrlTrue.second,
                    100 * (pgrl.second / pbm.second - 1), 100 * (pgrlTrue.second / pbmTrue.second - 1));
        std::fflush(stdout);
    }
    return 0;
}

/// --part diagnose: where on the held-out rows a model's one-step error exceeds persistence's.
int partDiagnose(const std::string& dataPath, const std::string& modelPath) {
    workflow::Session session;
    workflow::OpenOptions open;
    open.dataPath = dataPath;
    open.modelPath = modelPath;
    if (auto r = session.open(open); !r) {
        fail("open", r.error());
    }
    const auto& model = session.model();
    const auto& batches = session.siBatches();
    auto pbm = hybrid::simulatePbm(batches, model, model.switches);
    if (!pbm) {
        fail("PBM", pbm.error());
    }
    const auto test = hybrid::splitViews(batches, *pbm, true);
    for (const auto* rm : {model.pgrlCc.get(), model.extInput.get()}) {
        std::vector<double> excess; // |model error| - |persistence error|, moisture
        double sumModel = 0, sumRef = 0;
        for (const auto& v : test) {
            const auto p = rm->predictOneStep(v);
            const auto ref = evaluation::referencePrediction(v, 1, false);
            for (std::size_t i = 0; i < v.rows.size(); ++i) {
                const std::size_t k = v.rows.begin + i;
                const double y = units::dryToWetPct(v.batch->xOutDb[k]);
                if (!v.batch->keep[k] || !std::isfinite(y) || !std::isfinite(p.xOutPct[i]) ||
                    !std::isfinite(ref.xOutPct[i])) {
                    continue;
                }
                const double a = std::abs(y - p.xOutPct[i]), b = std::abs(y - ref.xOutPct[i]);
                sumModel += a;
                sumRef += b;
                excess.push_back(a - b);
                if (std::getenv("STUDY_HYBRID_BLOCKS") && rm == model.pgrlCc.get()) {
                    static double blockSum = 0;
                    static int blockRows = 0;
                    blockSum += a - b;
                    if (++blockRows == 300) {
                        std::printf("  %s rows to %zu: excess %+.2f\n", v.batch->id.c_str(), k, blockSum);
                        blockSum = 0;
                        blockRows = 0;
                    }
                }
            }
        }
        std::sort(excess.begin(), excess.end(), std::greater<>());
        double top1 = 0, top10 = 0, total = 0;
        for (std::size_t i = 0; i < excess.size(); ++i) {
            total += excess[i];
            top1 += i < excess.size() / 100 ? excess[i] : 0;
            top10 += i < excess.size() / 10 ? excess[i] : 0;
        }
        std::printf("%s: one-step MAE X %.4f, persistence %.4f (%zu rows); excess summed %.2f, of it the "
                    "worst 1 %% of "
                    "rows %.2f, worst 10 %% %.2f\n",
                    rm == model.pgrlCc.get() ? "pgrl_cc" : "ext_input", sumModel / double(excess.size()),
                    sumRef / double(excess.size()), excess.size(), total, top1, top10);
    }
    return 0;
}

/// --part why: where a model's free run goes wrong, by batch and by tenth of each batch: the mean
/// and absolute error of the PBM and of the PBM plus each input-driven correction (X % wb, T °C),
/// training rows and held-out rows apart.
int partWhy(const std::string& dataPath, const std::string& modelPath) {
    workflow::Session session;
    workflow::OpenOptions open;
    open.dataPath = dataPath;
    open.modelPath = modelPath;
    if (auto r = session.open(open); !r) {
        fail("open", r.error());
    }
    const auto& model = session.model();
    const auto& batches = session.siBatches();
    auto pbm = hybrid::simulatePbm(batches, model, model.switches);
    if (!pbm) {
        fail("PBM", pbm.error());
    }
    struct Column {
        const char* name;
        const residual::ResidualModel* model;
    };
    const std::vector<Column> columns{
        {"pbm", nullptr}, {"pgrl_cc", model.pgrlCc.get()}, {"ext_input", model.extInput.get()}};
    std::vector<std::size_t> rowsPerBatch;
    for (const auto& b : batches) {
        rowsPerBatch.push_back(b.rows());
    }
    const auto split = data::chronologicalSplit(rowsPerBatch);
    const int parts = std::getenv("STUDY_HYBRID_PARTS") ? std::atoi(std::getenv("STUDY_HYBRID_PARTS")) : 10;
    std::printf("| batch | part of %d | split | T_hot mean [°C] | T_amb | feed [kg/h] |", parts);
    for (const auto& c : columns) {
        std::printf(" %s mean X / MAE X / MAE T |", c.name);
    }
    std::printf(" pgrl_cc support |\n");
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const auto& batch = batches[b];
        const std::size_t n = batch.rows();
        const std::size_t cut = split.train[b].end;
        residual::BatchView whole{&batch, &(*pbm)[b], {0, n}};
        std::vector<residual::HybridPrediction> predictions;
        for (const auto& c : columns) {
            predictions.push_back(c.model ? c.model->predictFreeRun(whole)
                                          : evaluation::pbmPrediction(whole));
        }
        std::vector<double> cx, ct, support;
        if (model.pgrlCc && model.pgrlCc->inputDriven()) {
            model.pgrlCc->inputDriven()->correct(batch, (*pbm)[b], cx, ct, &support);
        }
        for (int tenth = 0; tenth < parts; ++tenth) {
            const std::size_t from = n * tenth / parts, to = n * (tenth + 1) / parts;
            double hot = 0, amb = 0, feed = 0, supported = 0;
            int count = 0;
            std::vector<double> meanX(columns.size()), maeX(columns.size()), maeT(columns.size());
            for (std::size_t k = from; k < to; ++k) {
                const double y = units::dryToWetPct(batch.xOutDb[k]);
                const double t = units::kelvinToCelsius(batch.tOutK[k]);
                if (!batch.keep[k] || !std::isfinite(y) || !std::isfinite(t)) {
                    continue;
                }
                hot += units::kelvinToCelsius(batch.tHotK[k]);
                amb += units::kelvinToCelsius(batch.tAmbK[k]);
                feed += batch.feedKgPerS[k] * 3600;
                supported += support.empty() ? 1.0 : support[k];
                for (std::size_t c = 0; c < columns.size(); ++c) {
                    meanX[c] += y - predictions[c].xOutPct[k];
                    maeX[c] += std::abs(y - predictions[c].xOutPct[k]);
                    maeT[c] += std::abs(t - predictions[c].tOutC[k]);
                }
                ++count;
            }
            if (count == 0) {
                continue;
            }
            std::printf("| %s | %d | %s | %.1f | %.1f | %.0f |", batch.id.c_str(), tenth + 1,
                        to <= cut ? "train" : (from >= cut ? "held-out" : "both"), hot / count, amb / count,
                        feed / count);
            for (std::size_t c = 0; c < columns.size(); ++c) {
                std::printf(" %+.3f / %.3f / %.2f |", meanX[c] / count, maeX[c] / count, maeT[c] / count);
            }
            std::printf(" %.2f |\n", supported / count);
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    std::string part = "unseen", dataPath, modelPath;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--part") && i + 1 < argc) {
            part = argv[++i];
        } else if (!std::strcmp(argv[i], "--data") && i + 1 < argc) {
            dataPath = argv[++i];
        } else if (!std::strcmp(argv[i], "--model") && i + 1 < argc) {
            modelPath = argv[++i];
        } else if (!std::strcmp(argv[i], "--guards") && i + 1 < argc) {
            guards = argv[++i];
        } else if (!std::strcmp(argv[i], "--design")) {
            designSets = true;
        } else if (!std::strcmp(argv[i], "--lstm-epochs") && i + 1 < argc) {
            lstmEpochsForStudy = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--quick")) {
            quick = true;
        } else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) {
            onlySets = argv[++i];
        } else if (!std::strcmp(argv[i], "--design-pair") && i + 1 < argc) {
            std::sscanf(argv[++i], "%u:%u", &designPair.first, &designPair.second);
        } else if (!std::strcmp(argv[i], "--seed-base") && i + 1 < argc) {
            seedBase = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
        } else if (!std::strcmp(argv[i], "--work") && i + 1 < argc) {
            workDir = argv[++i];
        } else {
            std::fprintf(stderr, "usage: study_hybrid [--part unseen|free-run|never-worse|why|diagnose] "
                                 "[--quick] [--only SEEDS] [--seed-base N] [--guards LIST] [--work DIR]\n");
            return 2;
        }
    }
    if (part == "free-run") {
        return partFreeRun(quick);
    }
    if (part == "diagnose") {
        return partDiagnose(dataPath, modelPath);
    }
    if (part == "never-worse") {
        return partNeverWorse(quick);
    }
    if (part == "why") {
        return partWhy(dataPath, modelPath);
    }
    if (part == "unseen") {
        return partUnseen(quick);
    }
    std::fprintf(stderr, "study_hybrid: unknown part '%s'\n", part.c_str());
    return 2;
}
