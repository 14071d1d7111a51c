#include "commands/CommandHelpers.h"
#include "HeadlessCommands.h"

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
#include <limits>
#include <string>

namespace drytwin::app::detail {

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
bool open(const CommandOptions& o, workflow::Session& session, int& exitCode, bool withData,
          bool printNotes) {
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
    // What the files did not say (a gap, an empty column, a parameter the model file lacks): on
    // stderr, so that a JSON answer on stdout stays clean; `inspect` lists every data note.
    std::vector<std::string> notes = r->modelNotes;
    if (printNotes) {
        notes.insert(notes.end(), r->summary.notes.begin(), r->summary.notes.end());
    }
    constexpr std::size_t kShown = 8;
    for (std::size_t i = 0; i < notes.size() && i < kShown; ++i) {
        std::fprintf(stderr, "drytwin: note: %s\n", notes[i].c_str());
    }
    if (notes.size() > kShown) {
        std::fprintf(stderr, "drytwin: note: %zu more (drytwin inspect lists the data's)\n",
                     notes.size() - kShown);
    }
    return true;
}

std::string fmt(double v, int precision) {
    if (std::isnan(v)) {
        return "-";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", precision, v);
    return buf;
}

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
                fail(Error{ErrorKind::Usage, "--bound " + b, "no parameter '" + b.substr(0, eq) + "'"});
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
                    fail(Error{ErrorKind::Usage, "--free " + name, "no such parameter; known:" + known});
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
    // Every parameter against its bounds, or a fit that leaves the outlet error at several % wb:
    // the model cannot follow these data, which a wrong unit or two swapped columns cause far more
    // often than the physics (a fresh user's test: X_out and T_out swapped calibrated with exit 0
    // and every parameter AT BOUND). Said on stderr, where a script's log keeps it.
    const bool allAtBound = !r.estimates.empty() && std::all_of(r.estimates.begin(), r.estimates.end(),
                                                                [](const auto& e) { return e.atBound; });
    if (allAtBound || r.after.maeXOutPct > 2.0) {
        std::fprintf(
            stderr,
            "drytwin: warning: the calibrated model does not follow these data (%s; outlet moisture MAE "
            "%.3g %% wb): check the columns' units and names (`drytwin inspect`) before using it\n",
            allAtBound ? "every free parameter at a bound" : "the fit leaves a large error",
            r.after.maeXOutPct);
    }
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

void printLstmValidation(const baselines::LstmBaseline& lstm) {
    // Whether the LSTM beats the trivial references on its validation part; when it does not (or
    // was not checked), that is flagged where nobody can miss it.
    const auto& v = lstm.validation();
    std::printf("%-20s %s%s\n", "lstm", v.validated && v.beatsReferences ? "" : "WARNING: ",
                v.message.empty() ? "no validation record in the model file (trained before issue #42)"
                                  : v.message.c_str());
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
    for (const auto* m : {t.pgrlCc.get(), t.extInput.get()}) {
        const auto* c = m->inputDriven();
        if (!c) {
            continue;
        }
        // Issue #42: the free-run layer under the lifted model, judged on batches it was not fitted on.
        const auto& v = c->validation();
        std::printf("%-20s input-driven correction (free run), cross-validated over %d folds: MAE X %.4f -> "
                    "%.4f %% wb, "
                    "T %.3f -> %.3f °C%s%s\n",
                    m == t.pgrlCc.get() ? "pgrl_cc" : "ext_input_residual", v.folds, v.maeMoisturePbm,
                    v.maeMoistureCorrected, v.maeTemperaturePbm, v.maeTemperatureCorrected,
                    v.note.empty() ? "" : "; ", v.note.c_str());
        if (!v.basisChoice.empty()) {
            std::printf("%-20s   basis: %s\n", "", v.basisChoice.c_str());
        }
    }
    for (const auto* m : {t.pgrlCc.get(), t.extInput.get()}) {
        if (!m->options().nestReferences || m->correctionWeightHorizons().empty()) {
            continue;
        }
        // The velocity form: the reference blend s_H and the learnt correction's weight κ_H.
        std::printf("%-20s forecast = e_k - s_H (PBM change) + k_H (learnt); one-step s %.2f; X_out s_H/k_H:",
                    m == t.pgrlCc.get() ? "pgrl_cc" : "ext_input_residual", m->referenceChangeWeight());
        for (int h : m->correctionWeightHorizons()) {
            std::printf(" %d: %.2f/%.2f", h, m->referenceChangeAt(h)(0), m->correctionWeight(h)(0));
        }
        std::printf("\n");
    }
    {
        const auto& lstm = *t.lstm;
        const auto& losses = lstm.lossHistory();
        const auto kept = static_cast<std::size_t>(std::max(1, lstm.validation().bestEpoch));
        std::printf("%-20s trained in %.1f s, %s; training loss %.4g (Huber, standardised step change)\n",
                    "lstm", lstm.trainingSeconds(), lstm.ending().message.c_str(),
                    kept <= losses.size() ? losses[kept - 1] : std::nan(""));
        printLstmValidation(lstm);
    }
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

} // namespace drytwin::app::detail
