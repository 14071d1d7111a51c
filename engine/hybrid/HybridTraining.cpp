#include "hybrid/HybridTraining.h"

#include "baselines/LstmNetwork.h"
#include "calibration/Calibration.h"
#include "common/Parallel.h"
#include "hybrid/Evaluation.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>

namespace drytwin::hybrid {

Expected<std::vector<physics::SimulationResult>> simulatePbm(const std::vector<data::SiBatch>& batches,
                                                             const HybridModel& model,
                                                             const properties::ModelSwitches& switches,
                                                             const Progress& progress) {
    std::vector<physics::LineInputs> inputs;
    for (const auto& b : batches) {
        inputs.push_back(physics::toLineInputs(b));
    }
    physics::SimulationOptions so = model.simulationOptions();
    so.switches = switches;
    return physics::simulateBatches(inputs, model.parameters, so, 0, progress);
}

std::vector<residual::BatchView> splitViews(const std::vector<data::SiBatch>& batches,
                                            const std::vector<physics::SimulationResult>& pbm, bool test,
                                            double trainFraction) {
    std::vector<std::size_t> rows;
    for (const auto& b : batches) {
        rows.push_back(b.rows());
    }
    const auto split = data::chronologicalSplit(rows, trainFraction);
    std::vector<residual::BatchView> views;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const auto& range = test ? split.test[b] : split.train[b];
        if (range.size() > 0) {
            views.push_back({&batches[b], &pbm[b], range});
        }
    }
    return views;
}

std::vector<residual::BatchView> regimeViews(const std::vector<data::SiBatch>& batches,
                                             const std::vector<physics::SimulationResult>& pbm, bool test,
                                             double testFraction) {
    std::vector<std::pair<double, std::size_t>> byAmbient;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        double sum = 0;
        std::size_t n = 0;
        for (double t : batches[b].tAmbK) {
            if (std::isfinite(t)) {
                sum += t;
                ++n;
            }
        }
        byAmbient.push_back({n > 0 ? sum / double(n) : 0.0, b});
    }
    std::sort(byAmbient.begin(), byAmbient.end());
    const auto testCount = static_cast<std::size_t>(std::ceil(testFraction * double(batches.size())));
    std::vector<residual::BatchView> views;
    for (std::size_t i = 0; i < byAmbient.size(); ++i) {
        const std::size_t b = byAmbient[i].second;
        const bool isTest = i + testCount >= byAmbient.size();
        if (isTest == test && batches[b].rows() > 0) {
            views.push_back({&batches[b], &pbm[b], {0, batches[b].rows()}});
        }
    }
    return views;
}

Status ModelSelection::validate() const {
    if (!enabled) {
        return {};
    }
    if (lags.empty() || ridge.empty() || horizons.empty()) {
        return invalidOption("model selection", "needs at least one lag count, ridge weight and horizon");
    }
    if (!(validationFraction > 0.05 && validationFraction < 0.6)) {
        return invalidOption("model selection", "validation fraction must lie in (0.05, 0.6)");
    }
    return {};
}

namespace {

/// The training views cut into a fitting part and a validation tail per batch.
std::pair<std::vector<residual::BatchView>, std::vector<residual::BatchView>>
innerSplit(const std::vector<residual::BatchView>& views, double validationFraction) {
    std::pair<std::vector<residual::BatchView>, std::vector<residual::BatchView>> out;
    for (const auto& v : views) {
        const auto n = v.rows.size();
        const auto cut =
            v.rows.begin + static_cast<std::size_t>(std::round((1.0 - validationFraction) * double(n)));
        if (cut > v.rows.begin) {
            out.first.push_back({v.batch, v.pbm, {v.rows.begin, cut}});
        }
        if (cut < v.rows.end) {
            out.second.push_back({v.batch, v.pbm, {cut, v.rows.end}});
        }
    }
    return out;
}

} // namespace

Expected<TrainingResult> trainResidualModels(const std::vector<data::SiBatch>& batches,
                                             const HybridModel& model,
                                             const residual::ResidualOptions& options,
                                             const baselines::LstmOptions& lstmOptions,
                                             const Progress& progress, const ModelSelection& selection) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = selection.validate(); !st) {
        return st.error();
    }
    // The LSTM's module is loaded now, not after PGRL-CC's fits: a program without it says so at
    // once instead of after minutes of work.
    if (auto module = baselines::lstmModule(); !module) {
        return module.error();
    }
    auto pbm = simulatePbm(batches, model, model.switches, progress);
    if (!pbm) {
        return pbm.error();
    }
    const auto views = splitViews(batches, *pbm, false);
    // The LSTM trains on the second core while PGRL-CC is selected and fitted on this one (it
    // uses one libtorch thread, PGRL-CC's fits mostly one core). The caller's progress callback
    // is only ever called from this thread: the LSTM's reports are kept here and relayed while
    // this thread waits for it, and what the caller answers (stop, stop keeping the best) is
    // passed on to it.
    std::atomic<ProgressAction> callerAction{ProgressAction::Continue};
    std::mutex lstmReportMutex;
    std::optional<ProgressInfo> lstmReport;
    const Progress lstmProgress = [&](const ProgressInfo& info) {
        {
            std::lock_guard<std::mutex> lock(lstmReportMutex);
            lstmReport = info;
        }
        return callerAction.load();
    };
    auto lstmTraining = std::async(std::launch::async, [&views, &lstmOptions, &lstmProgress] {
        return baselines::LstmBaseline::train(views, lstmOptions, lstmProgress);
    });
    // Every early return below stops the LSTM first (the future's destructor waits for it).
    struct StopLstmOnReturn {
        std::atomic<ProgressAction>& action;
        ~StopLstmOnReturn() {
            if (action.load() == ProgressAction::Continue) {
                action = ProgressAction::Stop;
            }
        }
    };
    StopLstmOnReturn stopLstmOnReturn{callerAction};
    const auto reportTraining = [&](const Progress& p, const std::string& stage, double fraction,
                                    const std::string& detail) {
        const ProgressAction a = progressAction(p, stage, fraction, detail);
        if (a != ProgressAction::Continue) {
            callerAction = ProgressAction::Stop; // PGRL-CC has no best-so-far to keep
        }
        return a != ProgressAction::Continue;
    };
    residual::ResidualOptions chosen = options;
    std::vector<SelectionCandidate> candidates;
    // The input-driven correction does not depend on the settings the selection tries (lags,
    // ridge, P⊥): its basis is chosen once, by cross-validation on the training rows, and every
    // other fit (the candidates', the external-input baseline's) uses that basis.
    if (reportTraining(progress, "train", 0.0, "input-driven correction")) {
        return cancelledError("train");
    }
    auto fullCorrection = residual::ResidualModel::fitInputDriven(views, options);
    if (!fullCorrection) {
        return fullCorrection.error();
    }
    residual::ResidualOptions concrete = options;
    if (*fullCorrection) {
        concrete.inputDrivenOptions.basis = (*fullCorrection)->options().basis;
    }
    if (selection.enabled) {
        const auto [fit, validation] = innerSplit(views, selection.validationFraction);
        auto fitCorrection = residual::ResidualModel::fitInputDriven(fit, concrete);
        if (!fitCorrection) {
            return fitCorrection.error();
        }
        // The references' MAE per horizon on the validation rows, once.
        std::vector<double> refX(selection.horizons.size(), std::numeric_limits<double>::infinity());
        std::vector<double> refT = refX;
        for (bool hold : {false, true}) {
            const auto scored = evaluation::scoreHorizons(validation, evaluation::referencePredictor(hold),
                                                          selection.horizons, 1);
            for (std::size_t h = 0; h < scored.size(); ++h) {
                refX[h] = std::min(refX[h], scored[h].moisture.mae);
                refT[h] = std::min(refT[h], scored[h].temperature.mae);
            }
        }
        for (bool projection : selection.tryWithoutProjection
                                   ? std::vector<bool>{true, false}
                                   : std::vector<bool>{options.orthogonalProjection}) {
            for (int lags : selection.lags) {
                for (double ridge : selection.ridge) {
                    candidates.push_back({lags, ridge, projection, 0, false});
                }
            }
        }
        double best = std::numeric_limits<double>::infinity();
        std::size_t bestIndex = 0;
        for (std::size_t c = 0; c < candidates.size(); ++c) {
            if (reportTraining(progress, "train", 0.3 * double(c) / double(candidates.size()),
                               "selecting settings " + std::to_string(c + 1) + "/" +
                                   std::to_string(candidates.size()))) {
                return cancelledError("train");
            }
            residual::ResidualOptions o = options;
            // Candidates are compared with each other: s_H and κ_H from the tail of their fitting
            // rows (one extra fit each) instead of blocked cross-validation (three).
            o.correctionFolds = 0;
            o.residualLags = candidates[c].lags;
            o.lambdaA = o.lambdaB = o.lambdaE = candidates[c].ridge;
            o.orthogonalProjection = candidates[c].orthogonalProjection;
            auto m = residual::ResidualModel::trainWith(fit, o, *fitCorrection);
            if (!m) {
                candidates[c].validationSkill = std::numeric_limits<double>::infinity();
                continue; // a candidate that cannot be fitted is not chosen
            }
            const auto scored = evaluation::scoreHorizons(
                validation,
                [&](const residual::BatchView& v, const std::vector<int>& hs) {
                    return m->predictHorizons(v, hs);
                },
                selection.horizons, 1);
            double skill = 0;
            for (std::size_t h = 0; h < scored.size(); ++h) {
                skill += 0.5 * (scored[h].moisture.mae / refX[h] + scored[h].temperature.mae / refT[h]);
            }
            candidates[c].validationSkill = skill / double(scored.size());
            if (candidates[c].validationSkill < best) {
                best = candidates[c].validationSkill;
                bestIndex = c;
            }
        }
        if (!std::isfinite(best)) {
            return Error{ErrorKind::Numerical, "model selection", "no candidate setting could be fitted"};
        }
        candidates[bestIndex].chosen = true;
        chosen.residualLags = candidates[bestIndex].lags;
        chosen.lambdaA = chosen.lambdaB = chosen.lambdaE = candidates[bestIndex].ridge;
        chosen.orthogonalProjection = candidates[bestIndex].orthogonalProjection;
    }
    if (reportTraining(progress, "train", 0.3, "PGRL-CC")) {
        return cancelledError("train");
    }
    auto full = residual::ResidualModel::trainWith(views, chosen, *fullCorrection);
    if (!full) {
        return full.error();
    }
    if (reportTraining(progress, "train", 0.7, "external-input residual")) {
        return cancelledError("train");
    }
    // The external-input baseline gets the same settings and the same basis: the comparison
    // isolates z.
    residual::ResidualOptions ext = chosen;
    ext.inputDrivenOptions.basis = concrete.inputDrivenOptions.basis;
    ext.useProxies = false;
    auto extModel = residual::ResidualModel::train(views, ext);
    if (!extModel) {
        return extModel.error();
    }
    while (lstmTraining.wait_for(std::chrono::milliseconds(200)) != std::future_status::ready) {
        std::optional<ProgressInfo> latest;
        {
            std::lock_guard<std::mutex> lock(lstmReportMutex);
            latest.swap(lstmReport);
        }
        if (latest) {
            const ProgressAction a =
                progressAction(progress, latest->stage, latest->fraction, latest->detail);
            if (a != ProgressAction::Continue) {
                callerAction = a;
            }
        }
    }
    auto lstm = lstmTraining.get();
    if (!lstm) {
        return lstm.error();
    }
    reportTraining(progress, "train", 1.0, "done");
    TrainingResult r{std::move(*full), std::move(*extModel), std::move(*lstm), std::move(candidates), 0, {}};
    r.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.ending = {Termination::Completed, "PGRL-CC, external-input residual and LSTM trained",
                r.elapsedSeconds};
    return r;
}

void storeResidualModels(HybridModel& model, TrainingResult&& trained) {
    model.pgrlCc = std::make_shared<const residual::ResidualModel>(std::move(trained.pgrlCc));
    model.extInput = std::make_shared<const residual::ResidualModel>(std::move(trained.extInput));
    model.lstm = std::make_shared<const baselines::LstmBaseline>(std::move(trained.lstm));
}

Expected<AblationResult> runAblation(const std::vector<data::SiBatch>& batches, const HybridModel& model,
                                     const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    enum class Physics { None, NoClamp, NoLatentCorrection, NoCpMoisture, OtherEnergyBalance };
    enum class Learning {
        None,
        NoProjection,
        LiteralEq27,
        NoWeights,
        NoConstraint,
        EigenvaluePull,
        LevelForm
    };
    struct Variant {
        const char* name;
        std::string description;
        Physics physics;
        Learning learning;
    };
    const bool consistent = model.switches.consistentEnergyBalance;
    // The full row is the PGRL-CC the model holds (its settings chosen in training), or the defaults.
    const residual::ResidualOptions base =
        model.pgrlCc ? model.pgrlCc->options() : residual::ResidualOptions{};
    const bool withProjection = base.orthogonalProjection;
    const std::vector<Variant> variants{
        {"full", "PGRL-CC, all components", Physics::None, Learning::None},
        {"no_aw_clamp", "1. no a_w clamping", Physics::NoClamp, Learning::None},
        {"no_lv_correction", "2. no L_v correction", Physics::NoLatentCorrection, Learning::None},
        {"no_cp_moisture", "3. no C_p(X) dependency", Physics::NoCpMoisture, Learning::None},
        {consistent ? "paper_energy_balance" : "consistent_energy_balance",
         consistent ? "E. energy balance as printed (Eqs. 12, 14, 19 count C_p,w (T - T_ref) twice)"
                    : "E. consistent energy balance (L_v only)",
         Physics::OtherEnergyBalance, Learning::None},
        {withProjection ? "no_orthogonal_projection" : "orthogonal_projection",
         withProjection ? "4. no orthogonal learning (P_perp)"
                        : "4. with orthogonal learning (P_perp, Eq. 27; the trained model has none)",
         Physics::None, Learning::NoProjection},
        {"literal_eq27", "4b. Eq. 27 read literally (base part of e dropped from the prediction)",
         Physics::None, Learning::LiteralEq27},
        {"no_cc_weights", "5. no control-consistent weights", Physics::None, Learning::NoWeights},
        {"no_stability_constraint", "6. no stability constraint (EDMDc-S)", Physics::None,
         Learning::NoConstraint},
        {"eigenvalue_pull", "6b. eigenvalues pulled in after an unconstrained fit instead of Eq. 30",
         Physics::None, Learning::EigenvaluePull},
        {"level_form", "7. the paper's lifted model of e itself (the trivial predictors not nested)",
         Physics::None, Learning::LevelForm},
    };
    AblationResult result;
    const double total = static_cast<double>(variants.size());
    const int multiStepHorizon = result.multiStepHorizon;
    // The base PBM run serves the full model and the learning variants; a physics variant
    // refits h_HDT, k_HDT for its switches first, then runs with them.
    auto baseRun = simulatePbm(batches, model, model.switches);
    if (!baseRun) {
        return baseRun.error();
    }
    const std::vector<physics::SimulationResult> basePbm = std::move(*baseRun);
    // The input-driven correction depends on the PBM run and the rows, not on what the learning
    // rows ablate: it is fitted once per split on the base PBM and shared by those rows, and
    // every row uses the basis the trained model chose (no row chooses it again).
    residual::ResidualOptions concreteBase = base;
    if (model.pgrlCc && model.pgrlCc->inputDriven()) {
        concreteBase.inputDrivenOptions.basis = model.pgrlCc->inputDriven()->options().basis;
    }
    if (reportProgress(progress, "ablation", 0.0, "input-driven correction")) {
        return cancelledError("ablation");
    }
    // The extrapolation split trains on whole batches and judges the warmest: one batch (a shift
    // exported as one run) has nothing to train on, so that column is left empty and says why,
    // rather than the whole table failing.
    const bool regimeSplitPossible =
        !regimeViews(batches, basePbm, false).empty() && !regimeViews(batches, basePbm, true).empty();
    if (!regimeSplitPossible) {
        result.regimeSplit = std::string(kRegimeSplitName) + " not run: it needs two batches or more";
    }
    auto regimeCorrectionFit = std::async(std::launch::async, [&] {
        return regimeSplitPossible
                   ? residual::ResidualModel::fitInputDriven(regimeViews(batches, basePbm, false),
                                                             concreteBase)
                   : Expected<std::shared_ptr<const residual::InputDrivenCorrection>>(nullptr);
    });
    auto chronologicalCorrection =
        residual::ResidualModel::fitInputDriven(splitViews(batches, basePbm, false), concreteBase);
    auto regimeCorrection = regimeCorrectionFit.get();
    if (!chronologicalCorrection) {
        return chronologicalCorrection.error();
    }
    if (!regimeCorrection) {
        return regimeCorrection.error();
    }

    // One row: its physics (refitted where a switch differs), its learning options, both splits.
    const auto runRow = [&](const Variant& v) -> Expected<AblationRow> {
        properties::ModelSwitches sw = model.switches;
        sw.clampWaterActivity = sw.clampWaterActivity && v.physics != Physics::NoClamp;
        sw.latentHeatCorrection = sw.latentHeatCorrection && v.physics != Physics::NoLatentCorrection;
        sw.moistureDependentCp = sw.moistureDependentCp && v.physics != Physics::NoCpMoisture;
        if (v.physics == Physics::OtherEnergyBalance) {
            sw.consistentEnergyBalance = !sw.consistentEnergyBalance;
        }
        AblationRow row;
        row.variant = v.name;
        row.description = v.description;
        HybridModel variantModel = model;
        variantModel.switches = sw;
        std::vector<physics::SimulationResult> variantPbm;
        if (v.physics != Physics::None) {
            calibration::CalibrationOptions co;
            co.globalSearch = false;
            co.intervals = false;
            co.maxEvaluations = 200;
            co.simulation = model.simulationOptions();
            co.simulation.switches = sw;
            auto cal = calibration::calibrate(batches, model.parameters, co);
            if (!cal) {
                return cal.error();
            }
            variantModel.parameters = cal->parameters;
            row.recalibrated = true;
            auto sims = simulatePbm(batches, variantModel, sw);
            if (!sims) {
                return sims.error();
            }
            variantPbm = std::move(*sims);
        }
        row.hHdt = variantModel.parameters[properties::Param::h_HDT];
        row.kHdt = variantModel.parameters[properties::Param::k_HDT];
        const auto& pbm = v.physics == Physics::None ? basePbm : variantPbm;
        residual::ResidualOptions o = concreteBase;
        if (v.learning == Learning::NoProjection) {
            o.orthogonalProjection = !base.orthogonalProjection;
            o.projectResidual = true;
        }
        if (v.learning == Learning::LiteralEq27) {
            // Eq. 27's ẽ = P⊥e is a statement about the paper's lifted model of e.
            o.orthogonalProjection = o.projectResidual = true;
            o.restoreBasePart = false;
            o.nestReferences = false;
        }
        if (v.learning == Learning::LevelForm) {
            o.nestReferences = false;
        }
        // The variants are compared with each other: s_H and κ_H from the last part of the
        // training rows (one extra fit) instead of blocked cross-validation (three).
        o.correctionFolds = 0;
        o.controlConsistentWeights = base.controlConsistentWeights && v.learning != Learning::NoWeights;
        o.stabilityConstraint = base.stabilityConstraint && v.learning != Learning::NoConstraint;
        if (v.learning == Learning::EigenvaluePull) {
            o.stabilityMethod = residual::StabilityMethod::EigenvaluePull;
        }
        // A physics row fits its own correction (its PBM differs); the others share the base's.
        const auto fitOn = [&](const std::vector<residual::BatchView>& views,
                               const std::shared_ptr<const residual::InputDrivenCorrection>& shared) {
            return v.physics != Physics::None ? residual::ResidualModel::train(views, o)
                                              : residual::ResidualModel::trainWith(views, o, shared);
        };
        // Chronological split: one step and multi-step.
        auto m = fitOn(splitViews(batches, pbm, false), *chronologicalCorrection);
        if (!m) {
            return m.error();
        }
        const auto test = splitViews(batches, pbm, true);
        const auto scored = evaluation::scoreHorizons(
            test,
            [&](const residual::BatchView& view, const std::vector<int>& hs) {
                return m->predictHorizons(view, hs);
            },
            {1, multiStepHorizon}, 20);
        row.maeMoisture = scored[0].moisture.mae;
        row.r2Moisture = scored[0].moisture.r2;
        row.maeTemperature = scored[0].temperature.mae;
        row.r2Temperature = scored[0].temperature.r2;
        row.ljungBoxPMoisture = scored[0].moisture.ljungBoxP;
        row.maeMoistureMultiStep = scored[1].moisture.mae;
        // Extrapolation split: trained on the cooler seasons, tested on the warmest.
        if (!regimeSplitPossible) {
            row.regimeMaeMoisture = row.regimeR2Moisture = row.regimeMaeTemperature =
                std::numeric_limits<double>::quiet_NaN();
            return row;
        }
        auto mr = fitOn(regimeViews(batches, pbm, false), *regimeCorrection);
        if (!mr) {
            return mr.error();
        }
        const auto regime = evaluation::scorePredictions(
            regimeViews(batches, pbm, true),
            [&](const residual::BatchView& view) { return mr->predictOneStep(view); }, 20);
        row.regimeMaeMoisture = regime.moisture.mae;
        row.regimeR2Moisture = regime.moisture.r2;
        row.regimeMaeTemperature = regime.temperature.mae;
        return row;
    };

    // The rows are independent: two run at a time (the caller's thread and one more; two
    // rows' fits already hold 1.3 GB), each taking the next row not yet taken.
    std::vector<std::optional<Expected<AblationRow>>> rows(variants.size());
    std::atomic<std::size_t> rowsDone{0};
    std::atomic<bool> stopRequested{false};
    const auto askCaller = [&](const std::string& detail) {
        if (!stopRequested &&
            reportProgress(progress, "ablation", static_cast<double>(rowsDone) / total, detail)) {
            stopRequested = true;
        }
    };
    parallelForFromCaller(
        variants.size(), 2,
        [&](std::size_t i, bool onCallerThread) {
            if (onCallerThread) {
                askCaller(variants[i].name);
            }
            if (stopRequested) {
                return;
            }
            rows[i] = runRow(variants[i]);
            ++rowsDone;
            if (!*rows[i]) {
                stopRequested = true; // the first failure ends the table
            }
        },
        [&] { askCaller("the last rows"); });
    for (auto& r : rows) {
        if (r && !*r) {
            return r->error();
        }
    }
    if (std::any_of(rows.begin(), rows.end(), [](const auto& r) { return !r; })) {
        return cancelledError("ablation");
    }
    for (auto& r : rows) {
        result.rows.push_back(std::move(**r));
    }
    reportProgress(progress, "ablation", 1.0, "done");
    result.ending = {Termination::Completed,
                     std::to_string(variants.size()) + " variants trained and scored on two splits",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
    return result;
}

} // namespace drytwin::hybrid
