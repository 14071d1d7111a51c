#include "HeadlessCommands.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"

#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include "common/AtomicFile.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace drytwin::app {

namespace {

int fail(const Error& e) {
    // Several rejected files: each one, then the summary; one: its own error says it all.
    if (e.causes.size() > 1) {
        for (const auto& cause : e.causes) {
            std::fprintf(stderr, "drytwin: error: %s\n", cause.message().c_str());
        }
    }
    std::fprintf(stderr, "drytwin: error: %s\n", e.message().c_str());
    return exitCodeFor(e.kind);
}

/// Opens --data (with --mapping and the cleaning rules) and --model in @p session.
bool open(const CommandOptions& o, workflow::Session& session, int& exitCode, bool withData = true) {
    workflow::OpenOptions oo;
    oo.dataPath = withData ? o.dataPath : std::string();
    oo.mappingPath = o.mappingPath;
    oo.modelPath = o.modelPath;
    oo.cleaning = o.cleaning;
    if (oo.dataPath.empty() && oo.modelPath.empty()) {
        return true;
    }
    auto r = session.open(oo, o.progress);
    if (!r) {
        exitCode = fail(r.error());
        return false;
    }
    return true;
}

std::string fmt(double v, int precision = 3) {
    if (std::isnan(v)) {
        return "-";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", precision, v);
    return buf;
}

} // namespace

int runInspect(const CommandOptions& o) {
    if (auto st = o.cleaning.validate(); !st) {
        return fail(Error{ErrorKind::Usage, "--" + st.error().place, st.error().reason});
    }
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto summary = session.inspect();
    if (!summary) {
        return fail(summary.error());
    }
    const auto& s = *summary;
    std::printf("Data set %s: %zu batch(es), %zu rows, %zu missing cell(s)\n\n", o.dataPath.c_str(),
                s.batches.size(), s.rows, s.missing);
    std::printf("%-14s %7s %10s %10s %8s %8s %8s %8s  %s\n", "batch", "rows", "start [s]", "end [s]",
                "step [s]", "gap [s]", "missing", "dropped", "file");
    for (const auto& b : s.batches) {
        std::printf("%-14s %7zu %10s %10s %8s %8s %8zu %8zu  %s\n", b.id.c_str(), b.rows,
                    fmt(b.startS, 1).c_str(), fmt(b.endS, 1).c_str(), fmt(b.medianStepS, 2).c_str(),
                    fmt(b.largestGapS, 2).c_str(), b.missing, b.droppedByCleaning, b.path.c_str());
    }
    std::printf("\n%-15s %-7s %12s %12s %12s %8s\n", "column", "unit", "min", "max", "mean", "missing");
    for (const auto& c : s.columns) {
        if (!c.present) {
            std::printf("%-15s %-7s %12s\n", c.name.c_str(), c.unit.c_str(), "(absent)");
            continue;
        }
        std::printf("%-15s %-7s %12s %12s %12s %8zu\n", c.name.c_str(), c.unit.c_str(), fmt(c.min).c_str(),
                    fmt(c.max).c_str(), fmt(c.mean).c_str(), c.missing);
    }
    if (!s.extraColumns.empty()) {
        std::printf("\nextra columns kept as text:");
        for (const auto& e : s.extraColumns) {
            std::printf(" %s", e.c_str());
        }
        std::printf("\n");
    }
    if (s.impossibleTotal > 0) {
        std::printf(
            "\nWARNING: %zu physically impossible value(s); no model should see them (fix the file or "
            "the column mapping/units):\n",
            s.impossibleTotal);
        for (const auto& w : s.impossible) {
            std::printf("  %s:%d: %s = %g %s\n", w.file.c_str(), w.line, w.column.c_str(), w.value,
                        w.rule.c_str());
        }
        if (s.impossible.size() < s.impossibleTotal) {
            std::printf("  … and %zu more (the first %zu per column are listed)\n",
                        s.impossibleTotal - s.impossible.size(), data::DataSetSummary::kMaxListedImpossible);
        }
    }
    const auto& c = s.cleaning;
    std::printf(
        "\nCleaning rules (paper §IV.A) keep %zu of %zu rows (%.1f %%). Dropped by rule (a row can fail "
        "several):\n",
        c.kept, c.rows, c.rows ? 100.0 * static_cast<double>(c.kept) / static_cast<double>(c.rows) : 0.0);
    std::printf("  X_hdt_pct < %g %% wb: %zu\n  T_hdt_C < %g °C: %zu\n  feed_kg_h < %g kg/h: %zu\n"
                "  missing input or output: %zu\n  physically impossible value: %zu\n",
                o.cleaning.minXhdtPct, c.droppedXhdt, o.cleaning.minThdtC, c.droppedThdt,
                o.cleaning.minFeedKgPerHour, c.droppedFeed, c.droppedMissing, c.droppedImpossible);
    for (const auto& r : c.skippedRules) {
        std::printf("  rule not applied: %s\n", r.c_str());
    }
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::inspectJson(s)); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runGenerate(const CommandOptions& o) {
    workflow::GenerateOptions go;
    const plant::PlantKind kind =
        o.plantKind == "lumped" ? plant::PlantKind::Lumped : plant::PlantKind::Distributed;
    go.plant = o.demo ? plant::PlantOptions::demo(o.seed, kind) : plant::PlantOptions{};
    go.plant.plant = kind;
    // Unless told otherwise, each plant reads through its own default instruments: realistic
    // transmitters on the distributed line, the lumped plant's built-in noise on the lumped one
    // (which keeps its files byte-identical to earlier versions).
    if (o.sensorModeGiven) {
        if (o.sensorMode == "builtin" && kind != plant::PlantKind::Lumped) {
            return fail(Error{ErrorKind::Usage, "--sensors builtin", "only the lumped plant has built-in sensors"});
        }
        go.plant.sensors = o.sensorMode == "ideal"       ? plant::SensorMode::Ideal
                           : o.sensorMode == "realistic" ? plant::SensorMode::Realistic
                                                         : plant::SensorMode::Default;
    }
    go.plant.sensorFaults = o.sensorFaults;
    go.plant.seed = o.seed;
    go.plant.batches = o.batches;
    go.plant.samples = o.samples;
    go.outFolder = o.outPath;
    go.truthPath = o.truthPath;
    go.plant.unmeasuredDrift = go.plant.unmeasuredDrift || o.drift;
    if (!o.periodic.empty()) {
        if (std::sscanf(o.periodic.c_str(), "%lf:%lf", &go.plant.hiddenPeriodS, &go.plant.hiddenAmplitudeK) !=
            2) {
            return fail(Error{ErrorKind::Usage, "--periodic " + o.periodic, "expected PERIOD_S:AMPLITUDE_K"});
        }
    }
    for (const auto& e : o.effects) {
        const auto eq = e.find('=');
        const std::string name = e.substr(0, eq);
        const auto m = plant::mechanismByName(name);
        if (!m) {
            std::string known;
            for (const auto& i : plant::mechanisms()) {
                known += " " + std::string(i.name);
            }
            return fail(Error{ErrorKind::Usage, "--effect " + name, "unknown mechanism; known:" + known});
        }
        double strength = plant::info(*m).defaultStrength;
        if (eq != std::string::npos) {
            try {
                std::size_t used = 0;
                strength = std::stod(e.substr(eq + 1), &used);
                if (used != e.size() - eq - 1) {
                    throw std::invalid_argument("trailing text");
                }
            } catch (const std::exception&) {
                return fail(Error{ErrorKind::Usage, "--effect " + e, "strength is not a number"});
            }
        }
        go.plant.effects[*m] = strength;
    }
    auto result = workflow::Session().generate(go, o.progress);
    if (!result) {
        return fail(result.error());
    }
    std::printf("wrote %zu batch(es) of %d samples of the %s plant (%s sensors) to %s in %.2f s\n",
                result->files.size(), result->samplesPerBatch, std::string(plant::plantKindName(kind)).c_str(),
                go.plant.realisticSensors()                   ? "realistic"
                : go.plant.sensors == plant::SensorMode::Ideal ? "ideal"
                                                              : "built-in",
                o.outPath.c_str(), result->ending.elapsedSeconds);
    return 0;
}

int runSimulate(const CommandOptions& o) {
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.simulate({}, o.progress);
    if (!result) {
        return fail(result.error());
    }
    std::printf("%-10s %8s %14s %14s\n", "batch", "rows", "MAE X_out [%]", "MAE T_out [°C]");
    for (const auto& f : result->fits) {
        std::printf("%-10s %8zu %14.4f %14.4f\n", f.id.c_str(), f.rows, f.maeXOutPct, f.maeTOutC);
    }
    if (auto st = writeFileAtomically(o.outPath, io::simulationCsv(session.siBatches(), result->simulations));
        !st) {
        return fail(st.error());
    }
    return 0;
}

namespace {

/// "--bound NAME=LO:HI" into the options; false with a message on a malformed one.
bool parseBounds(const std::vector<std::string>& specs, calibration::CalibrationOptions& co, int& exitCode) {
    for (const auto& b : specs) {
        const auto eq = b.find('=');
        const auto colon = b.find(':', eq == std::string::npos ? 0 : eq);
        const auto p = properties::paramBySymbol(b.substr(0, eq));
        double lo = 0;
        double hi = 0;
        try {
            if (eq == std::string::npos || colon == std::string::npos) {
                throw std::invalid_argument("form");
            }
            lo = std::stod(b.substr(eq + 1, colon - eq - 1));
            hi = std::stod(b.substr(colon + 1));
        } catch (const std::exception&) {
            exitCode = fail(Error{ErrorKind::Usage, "--bound " + b, "expected NAME=LOWER:UPPER"});
            return false;
        }
        if (!p) {
            exitCode =
                fail(Error{ErrorKind::BadInput, "--bound " + b, "no parameter '" + b.substr(0, eq) + "'"});
            return false;
        }
        co.bounds[*p] = {lo, hi};
    }
    return true;
}

/// The calibration options of the command line; false with a message on a malformed one.
bool calibrateOptions(const CommandOptions& o, workflow::CalibrateOptions& options, int& exitCode) {
    auto& co = options.calibration;
    co.seed = o.seed;
    co.maxEvaluations = o.maxEvaluations;
    if (!o.freeParameters.empty()) {
        co.freeParameters.clear();
        for (const auto& name : o.freeParameters) {
            const auto p = properties::paramBySymbol(name);
            if (!p) {
                std::string known;
                for (const auto& i : properties::parameterTable()) {
                    known += " " + std::string(i.symbol);
                }
                exitCode =
                    fail(Error{ErrorKind::BadInput, "--free " + name, "no such parameter; known:" + known});
                return false;
            }
            co.freeParameters.push_back(*p);
        }
    }
    if (!parseBounds(o.bounds, co, exitCode)) {
        return false;
    }
    if (std::sscanf(o.subset.c_str(), "%zu:%zu", &options.subsetStride, &options.subsetCount) != 2 ||
        options.subsetStride == 0) {
        exitCode =
            fail(Error{ErrorKind::Usage, "--subset " + o.subset, "expected STRIDE:COUNT with STRIDE ≥ 1"});
        return false;
    }
    if (auto st = options.validate(); !st) {
        exitCode = fail(st.error());
        return false;
    }
    return true;
}

void printCalibration(const workflow::CalibrateResult& result) {
    const auto& r = result.calibration;
    std::printf("Calibrated %zu parameter(s) on %zu rows (%s), %d evaluations (%d failed), %.2f s\n",
                r.estimates.size(), r.rowsUsed, r.algorithm.c_str(), r.evaluations, r.failedEvaluations,
                r.elapsedSeconds);
    std::printf("%-12s %12s %12s %26s %-12s %s\n", "parameter", "start", "estimate", "95 % interval", "unit",
                "");
    for (const auto& e : r.estimates) {
        const auto& info = properties::info(e.param);
        char ci[64];
        std::snprintf(ci, sizeof ci, "[%.5g, %.5g]", e.ci95Low, e.ci95High);
        std::printf("%-12s %12.5g %12.5g %26s %-12s %s\n", std::string(info.symbol).c_str(),
                    result.startParameters[e.param], e.value, ci, std::string(info.unit).c_str(),
                    e.atBound ? "AT BOUND: the fit wants to leave the range" : "");
    }
    std::printf(
        "loss %.5g -> %.5g; MAE X_out %.4f -> %.4f %% wb; MAE T_out %.3f -> %.3f °C (calibration rows)\n",
        r.before.loss, r.after.loss, r.before.maeXOutPct, r.after.maeXOutPct, r.before.maeTOutC,
        r.after.maeTOutC);
    if (!r.intervalMethod.empty()) {
        std::printf("intervals: %s; the Fisher intervals (independent rows assumed) would be",
                    r.intervalMethod.c_str());
        for (const auto& e : r.estimates) {
            std::printf(" %s %.2gx", std::string(properties::info(e.param).symbol).c_str(),
                        e.standardErrorFisher / e.standardError);
        }
        std::printf(" as wide\n");
    }
    std::printf("ended: %s (%s)\n", terminationName(result.ending.termination),
                result.ending.message.c_str());
}

void printEvaluation(const evaluation::EvaluationResult& ev) {
    std::printf("held-out part: %s, %zu rows\n", ev.split.c_str(), ev.testRows);
    std::printf("%-20s %10s %8s %10s %10s %8s %10s %7s | %d-step: %9s %10s %7s\n", "model", "MAE X [%]",
                "R2 X", "LB p X", "MAE T [C]", "R2 T", "LB p T", "skill X", ev.multiStepHorizon, "MAE X [%]",
                "MAE T [C]", "skill X");
    for (const auto& m : ev.models) {
        std::printf("%-20s %10.4f %8.4f %10.3g %10.4f %8.4f %10.3g %7.3f |          %9.4f %10.4f %7.3f\n",
                    m.name.c_str(), m.moisture.mae, m.moisture.r2, m.moisture.ljungBoxP, m.temperature.mae,
                    m.temperature.r2, m.temperature.ljungBoxP, m.skillMoisture, m.moistureMultiStep.mae,
                    m.temperatureMultiStep.mae, m.skillMoistureMultiStep);
    }
    std::printf(
        "skill: MAE over the better of persistence and pbm_residual_hold at the same horizon (< 1 beats "
        "both)\n");
    std::printf("\nskill X (moisture) by horizon [steps = s]\n%-20s", "model");
    for (int h : ev.horizons) {
        std::printf(" %6d", h);
    }
    std::printf("\n");
    for (const auto& m : ev.models) {
        std::printf("%-20s", m.name.c_str());
        for (double s : m.skillMoistureByHorizon) {
            std::printf(" %6.3f", s);
        }
        std::printf("\n");
    }
    std::printf("\nfree run (never sees a measured output; skill against the references at %d steps)\n",
                ev.horizons.empty() ? 0 : ev.horizons.back());
    for (const auto& m : ev.freeRun) {
        std::printf("%-20s MAE X %.4f %% wb, R2 X %.4f, MAE T %.4f °C, skill X %.3f\n", m.name.c_str(),
                    m.moisture.mae, m.moisture.r2, m.temperature.mae, m.skillMoisture);
    }
}

void printTraining(const workflow::TrainResult& t) {
    for (const auto* m : {t.pgrlCc.get(), t.extInput.get()}) {
        const auto& c = m->stability();
        std::printf("%-20s state %3d, %zu snapshots, %.2f s; spectral radius %.4f -> %.4f, alpha %.4f, "
                    "certificate max eig %.3g (%s)\n",
                    m == t.pgrlCc.get() ? "pgrl_cc" : "ext_input_residual", m->stateSize(),
                    m->trainingSnapshots(), m->trainingSeconds(), c.spectralRadiusBefore,
                    c.spectralRadiusAfter, c.alpha, c.certificateMaxEig,
                    c.certified ? "certified" : "NOT certified");
    }
    std::printf("%-20s trained in %.1f s, final training loss %.4g (standardised)\n", "lstm",
                t.lstm->trainingSeconds(),
                t.lstm->lossHistory().empty() ? std::nan("") : t.lstm->lossHistory().back());
    const auto& cmp = t.pgrlCc->stabilityComparison();
    std::printf(
        "Eq. 30 training loss (per unit weight): unconstrained %.6g (radius %.5f), eigenvalues pulled "
        "%.6g (%.5f), constrained %.6g (%.5f; %d ADMM iterations); certificate by Cholesky %s, "
        "cond(P) %.3g\n",
        cmp.lossUnconstrained, cmp.radiusUnconstrained, cmp.lossEigenvaluePull, cmp.radiusEigenvaluePull,
        cmp.lossConstrained, cmp.radiusConstrained, cmp.admmIterations,
        t.pgrlCc->stability().choleskyPasses ? "passes" : "FAILS", t.pgrlCc->stability().pConditionNumber);
    if (!t.selection.empty()) {
        std::printf("settings chosen by multi-step validation inside the training part (mean skill over "
                    "horizons and outputs; < 1 beats the references):\n");
        for (const auto& c : t.selection) {
            std::printf("  lags %2d, ridge %.0e, P_perp %-3s  skill %.4f%s\n", c.lags, c.ridge,
                        c.orthogonalProjection ? "on" : "off", c.validationSkill,
                        c.chosen ? "  <- chosen" : "");
        }
    }
}

void printAblation(const hybrid::AblationResult& a) {
    std::printf(
        "Ablation (paper Table 3 and more): chronological held-out 30 %% (one step, %d steps) and the "
        "extrapolation split %s (one step)\n",
        a.multiStepHorizon, a.regimeSplit.c_str());
    std::printf("%-26s %10s %8s %10s %8s %10s %10s | %10s %8s %10s | %s\n", "variant", "MAE X [%]", "R2 X",
                "MAE T [C]", "R2 T", "LB p X", "MAE X H", "MAE X [%]", "R2 X", "MAE T [C]", "h_HDT, k_HDT");
    for (const auto& r : a.rows) {
        std::printf("%-26s %10.4f %8.4f %10.4f %8.4f %10.3g %10.4f | %10.4f %8.4f %10.4f | %.4g, %.4g%s\n",
                    r.variant.c_str(), r.maeMoisture, r.r2Moisture, r.maeTemperature, r.r2Temperature,
                    r.ljungBoxPMoisture, r.maeMoistureMultiStep, r.regimeMaeMoisture, r.regimeR2Moisture,
                    r.regimeMaeTemperature, r.hHdt, r.kHdt, r.recalibrated ? " (refitted)" : "");
    }
}

/// The training options of the command line; false with a message on a malformed one.
bool trainOptions(const CommandOptions& o, workflow::TrainOptions& options, int& exitCode) {
    auto& ro = options.residual;
    if (o.residualLags > 0) {
        ro.residualLags = o.residualLags;
        options.selection.lags = {o.residualLags}; // a given value is not second-guessed
    }
    options.selection.enabled = !o.noSelect;
    ro.degree = o.degree;
    ro.baseFeatures = o.baseFeatures;
    if (o.ridge >= 0) {
        ro.lambdaA = ro.lambdaB = ro.lambdaE = o.ridge;
        options.selection.ridge = {o.ridge};
    }
    options.lstm.seed = o.seed;
    options.lstm.epochs = o.lstmEpochs;
    if (auto st = options.validate(); !st) {
        exitCode = fail(Error{ErrorKind::Usage, st.error().place, st.error().reason});
        return false;
    }
    return true;
}

} // namespace

int runCalibrate(const CommandOptions& o) {
    workflow::CalibrateOptions options;
    workflow::Session session;
    int rc = 0;
    if (!calibrateOptions(o, options, rc) || !open(o, session, rc)) {
        return rc;
    }
    auto result = session.calibrate(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printCalibration(*result);
    if (auto st = session.saveModel(o.outPath); !st) {
        return fail(st.error());
    }
    return 0;
}

int runEvaluate(const CommandOptions& o) {
    workflow::EvaluateOptions options;
    options.evaluation.horizonSteps = o.horizonSteps;
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.evaluate(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printEvaluation(result->evaluation);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::evaluationJson(result->evaluation)); !st) {
            return fail(st.error());
        }
    }
    if (!o.diagnosticsPath.empty()) {
        if (auto st =
                writeFileAtomically(o.diagnosticsPath, io::residualDiagnosticsJson(result->diagnostics));
            !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runTrain(const CommandOptions& o) {
    workflow::TrainOptions options;
    workflow::Session session;
    int rc = 0;
    if (!trainOptions(o, options, rc) || !open(o, session, rc)) {
        return rc;
    }
    if (!session.model().calibration) {
        std::fprintf(stderr,
                     "drytwin train: note: %s holds no calibration; the residual model is learnt on top of "
                     "the default physics parameters\n",
                     o.modelPath.c_str());
    }
    auto result = session.train(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printTraining(*result);
    if (auto st = session.saveModel(o.outPath); !st) {
        return fail(st.error());
    }
    return 0;
}

int runAblation(const CommandOptions& o) {
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.ablation(o.progress);
    if (!result) {
        return fail(result.error());
    }
    printAblation(*result);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::ablationJson(*result)); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runDiscover(const CommandOptions& o) {
    workflow::DiscoverOptions options;
    options.discovery.maxCauses = o.maxCauses;
    options.discovery.minExplainedFraction = o.minExplained;
    options.discovery.fastBandWindowS = o.fastWindowS;
    workflow::Session session;
    int rc = 0;
    if (auto st = options.validate(); !st) {
        return fail(st.error());
    }
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.discover(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& d = result->discovery;
    std::printf(
        "What the simulation gets wrong (after refitting h_HDT, k_HDT on the training part; residual = "
        "measured - simulated):\n");
    std::printf("%-6s %-5s %10s %10s %12s %10s %12s  %s\n", "output", "unit", "bias", "± se", "trend [/h]",
                "± se", "line [s]", "strongest correlate (differences)");
    for (const auto& r : d.residuals) {
        const auto c = r.correlates.empty() ? std::string("-")
                                            : r.correlates[0].column + " at " + fmt(r.correlates[0].lagS, 0) +
                                                  " s, ccf " + fmt(r.correlates[0].ccf, 2);
        std::printf("%-6s %-5s %10.4f %10.4f %12.4f %10.4f %12s  %s\n", r.output.c_str(), r.unit.c_str(),
                    r.bias, r.biasSe, r.trendPerHour, r.trendSe,
                    r.peakPowerRatio > 1
                        ? (fmt(r.peakPeriodS, 0) + " (x" + fmt(r.peakPowerRatio, 1) + ")").c_str()
                        : "-",
                    c.c_str());
    }
    for (const auto& note : d.notes) {
        std::printf("note: %s\n", note.c_str());
    }
    std::printf("\nCandidate causes (score test on the training part, HAC variance, Holm-corrected):\n");
    std::printf("%-24s %8s %10s %10s %12s %14s\n", "cause", "z", "p", "p (Holm)", "fitted", "train loss");
    for (const auto& c : d.ranking) {
        std::printf("%-24s %8.2f %10.3g %10.3g %12s %14s\n", c.cause.c_str(), c.score, c.pValue, c.pHolm,
                    c.fitted ? "yes" : "no",
                    c.fitted ? (fmt(c.fitLossBefore, 4) + " -> " + fmt(c.fitLossAfter, 4)).c_str() : "-");
    }
    for (std::size_t i = 0; i < d.rounds.size(); ++i) {
        const auto& rd = d.rounds[i];
        std::printf("round %zu: %s%s%s\n", i + 1, rd.best.empty() ? "" : (rd.best + ": ").c_str(),
                    rd.named ? "named" : "stop, ", rd.reason.c_str());
    }
    std::printf("\nVerdict: %s\n", d.verdict.c_str());
    for (const auto& f : d.findings) {
        std::printf("\n* %s\n  %s\n", f.cause.c_str(), f.evidence.c_str());
    }
    if (!d.bounds.empty()) {
        std::printf("\nNot named; what the data allow (one step from 0 at the final model, 95 %%):\n");
        for (const auto& b : d.bounds) {
            const auto& info = properties::info(b.parameter);
            std::printf("  %-24s %-15s %10.4g  [%.3g, %.3g] %s\n", b.cause.c_str(),
                        std::string(info.symbol).c_str(), b.estimate, b.ci95Low, b.ci95High,
                        std::string(info.unit).c_str());
        }
    }
    for (const auto& s : d.unexplained) {
        std::printf("\nUnexplained (%s): %s", s.output.c_str(), s.type.c_str());
        if (s.type == "periodic") {
            std::printf(", period %.0f s, power x%.1f over its background", s.periodS, s.strength);
        } else if (s.type == "lagged_input") {
            std::printf(", %s at %.0f s (ccf %.2f)", s.column.c_str(), s.lagS, s.strength);
        } else if (s.type == "batch_shift") {
            std::printf(", batches");
            for (const auto& b : s.batches) {
                std::printf(" %s", b.c_str());
            }
        } else {
            std::printf(", %+.3g per hour", s.strength);
        }
        std::printf("\n");
    }
    if (result->hasHybrid) {
        std::printf("\nPGRL-CC retrained on top, held-out one-step MAE: X_out %.4f -> %.4f %% wb, T_out %.4f "
                    "-> %.4f °C\n",
                    result->hybridMaeMoistureBefore, result->hybridMaeMoistureAfter,
                    result->hybridMaeTemperatureBefore, result->hybridMaeTemperatureAfter);
    }
    std::printf("\n%.1f s\n", result->ending.elapsedSeconds);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::discoveryJson(d, result->hasHybrid,
                                                                        result->hybridMaeMoistureBefore,
                                                                        result->hybridMaeMoistureAfter,
                                                                        result->hybridMaeTemperatureBefore,
                                                                        result->hybridMaeTemperatureAfter));
            !st) {
            return fail(st.error());
        }
    }
    if (!o.outPath.empty()) {
        if (auto st = io::writeModelFile(result->extendedModel, o.outPath); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runMpc(const CommandOptions& o) {
    workflow::MpcOptions options;
    // A bare name picks a bundled scenario; anything else is a file.
    if (!o.scenarioPath.empty()) {
        if (control::bundledScenarios().count(o.scenarioPath)) {
            options.bundledScenario = o.scenarioPath;
        } else {
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
            options.closedLoop.controllers.push_back(*k);
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
    const auto& r = result->closedLoop;
    std::printf(
        "Scenario %s: %d scored steps of 1 s after %d s of PI warm-up, MPC every %d s, band ±%.2f %% wb\n",
        r.scenario.name.c_str(), r.scenario.lengthS, r.scenario.warmupS, r.scenario.controlIntervalS,
        r.scenario.bandPct);
    std::printf("\n%-20s %12s %12s %10s %11s %11s %11s %9s %12s\n", "controller", "IAE [%*s]", "effort [K^2]",
                "viol. [%]", "solve med", "solve max", "model med", "fallback", "gain [%/K]");
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
    }
    std::printf(
        "\nIAE and violations on the product's true outlet moisture; solve = Ipopt per decision, model = "
        "forecasts and linearisation; gain = the model's steady dX_out/dT_hot (the plant's: %.4f %%/K).\n",
        r.plantGainPctPerK);
    std::printf(
        "\nWhy the ranking: each model forecasting the PI run as its MPC would (disturbances held, same "
        "update), MAE of X_out [%% wb]\n%-20s",
        "model");
    bool header = false;
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
            std::printf(" %11.4f", m);
        }
        std::printf("\n");
    }
    std::printf("\n%.1f s\n", result->ending.elapsedSeconds);
    if (result->ending.termination == Termination::StoppedKeptBest) {
        std::printf("%s\n", result->ending.message.c_str());
    }
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::mpcJson(r)); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runTraining(const CommandOptions& o) {
    workflow::TrainingOptions options;
    options.scriptPath = o.scriptPath;
    options.outFolder = o.outPath;
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc, false)) {
        return rc;
    }
    auto result = session.training(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& r = *result;
    std::printf("Training session %s: replayed %zu event(s) to %.0f s\n", o.scriptPath.c_str(), r.events,
                r.endS);
    for (const auto& f : r.score.faults) {
        const auto& mi = plant::info(f.fault.mechanism);
        std::printf("  fault %-24s %g %s from %.0f s: %s, %.1f %% of the time out of the band meanwhile, "
                    "%.0f points\n",
                    std::string(mi.name).c_str(), f.fault.strength, std::string(mi.unit).c_str(),
                    f.fault.onsetS,
                    f.found ? ("found after " + fmt(f.timeToFindS, 0) + " s").c_str() : "not found",
                    f.offSpecPctWhileOpen, f.points);
    }
    std::printf("Score: %s\n", r.score.summary.c_str());
    std::printf("Wrote %s and %s\n", r.files.sessionFile.c_str(), r.files.recordingFiles.front().c_str());
    return 0;
}

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
            std::printf("%-20s IAE %8.1f %%*s, effort %8.1f K^2, violations %5.1f %%\n",
                        control::controllerName(run.kind), run.metrics.iaePctS, run.metrics.effortK2,
                        run.metrics.violationPct);
        }
    }
    std::printf(
        "\nreport %s, with inspect.json, model-calibrated.json, model.json, evaluate.json, ablation.json, "
        "diagnostics.json, discover.json, model-extended.json and mpc.json beside it\n",
        r.reportPath.c_str());
    if (o.renderReport) {
        const auto t0 = std::chrono::steady_clock::now();
        std::string error;
        const auto files = o.renderReport(r, session, o.outPath, error);
        if (!error.empty()) {
            return fail(Error{ErrorKind::BadInput, o.outPath, "the HTML/PDF report: " + error});
        }
        for (const auto& f : files) {
            std::printf("report %s", f.c_str());
            std::printf("\n");
        }
        std::printf("HTML and PDF report with figures: %.1f s\n",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return 0;
}

} // namespace drytwin::app
