// What each step on the session's model does and what it changes: simulate() (the fit per
// batch), calibrate() (the model takes the new parameters and drops the learnt residual models
// trained on the old ones), train() (the residual models on top of the physics), evaluate()
// (held-out metrics and residual diagnostics) and ablation(). Each keeps its latest result.

#include "workflow/Session.h"

#include "common/Units.h"
#include "diagnostics/Metrics.h"
#include "hybrid/Evaluation.h"
#include "workflow/session/SessionInternal.h"

#include <limits>

namespace drytwin::workflow {

Expected<SimulateResult> Session::simulate(const SimulateOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = ready(options, "simulate"); !st) {
        return st.error();
    }
    std::optional<hybrid::HybridModel> withParameters;
    if (options.parameters) {
        withParameters = m_model; // its structure (extensions, switches) with the other parameters
        withParameters->parameters = *options.parameters;
    }
    auto sims =
        hybrid::simulatePbm(m_si, withParameters ? *withParameters : m_model, m_model.switches, progress);
    if (!sims) {
        return sims.error();
    }
    SimulateResult result;
    for (std::size_t b = 0; b < m_si.size(); ++b) {
        const auto& s = m_si[b];
        const auto& r = (*sims)[b];
        std::vector<double> obsX, predX, obsT, predT;
        for (std::size_t k = 0; k < s.rows(); ++k) {
            if (s.keep[k]) {
                obsX.push_back(units::dryToWetPct(s.xOutDb[k]));
                predX.push_back(units::dryToWetPct(r.xOutDb[k]));
                obsT.push_back(s.tOutK[k]);
                predT.push_back(r.tOutK[k]);
            }
        }
        result.fits.push_back({s.id, s.rows(), diagnostics::meanAbsoluteError(obsX, predX),
                               diagnostics::meanAbsoluteError(obsT, predT), obsX.size()});
    }
    result.simulations = std::move(*sims);
    result.ending = {Termination::Completed, std::to_string(m_si.size()) + " batch(es) simulated",
                     secondsSince(t0)};
    if (!options.parameters) {
        m_latest.simulate = result;
    }
    return result;
}

namespace {
double keptRowsWeightedMean(const std::vector<BatchFit>& fits, double BatchFit::*mae) {
    double sum = 0;
    std::size_t rows = 0;
    for (const auto& f : fits) {
        if (f.keptRows > 0) {
            sum += f.*mae * static_cast<double>(f.keptRows);
            rows += f.keptRows;
        }
    }
    return rows > 0 ? sum / static_cast<double>(rows) : std::numeric_limits<double>::quiet_NaN();
}
} // namespace

double SimulateResult::maeXOutPctAllKeptRows() const {
    return keptRowsWeightedMean(fits, &BatchFit::maeXOutPct);
}

double SimulateResult::maeTOutCAllKeptRows() const {
    return keptRowsWeightedMean(fits, &BatchFit::maeTOutC);
}

std::size_t SimulateResult::keptRows() const {
    std::size_t rows = 0;
    for (const auto& f : fits) {
        rows += f.keptRows;
    }
    return rows;
}

Expected<CalibrateResult> Session::calibrate(const CalibrateOptions& options, const Progress& progress) {
    if (auto st = ready(options, "calibrate"); !st) {
        return st.error();
    }
    calibration::CalibrationOptions co = options.calibration;
    co.simulation = m_model.simulationOptions();
    co.rows = data::calibrationSubset(m_si, options.subsetStride,
                                      options.subsetCount == 0 ? std::numeric_limits<std::size_t>::max()
                                                               : options.subsetCount);
    auto r = calibration::calibrate(m_si, m_model.parameters, co, progress);
    if (!r) {
        return r.error();
    }
    CalibrateResult result;
    result.startParameters = m_model.parameters;
    hybrid::CalibrationRecord rec;
    for (const auto& e : r->estimates) {
        rec.estimates.push_back({std::string(properties::info(e.param).symbol), e.value, e.ci95Low,
                                 e.ci95High, e.atBound, e.standardErrorFisher});
    }
    rec.intervalMethod = r->intervalMethod;
    rec.lossBefore = r->before.loss;
    rec.lossAfter = r->after.loss;
    rec.evaluations = r->evaluations;
    rec.seed = co.seed;
    rec.algorithm = r->algorithm;
    m_model.parameters = r->parameters;
    m_model.calibration = rec;
    result.droppedResidualModels = m_model.hasResidualModels();
    m_model.pgrlCc.reset();
    m_model.extInput.reset();
    m_model.lstm.reset();
    result.ending = r->ending;
    if (result.droppedResidualModels) {
        result.ending.message += "; the learnt residual models were dropped (trained on the old parameters)";
    }
    result.calibration = std::move(*r);
    m_latest.calibrate = result;
    return result;
}

Expected<TrainResult> Session::train(const TrainOptions& options, const Progress& progress) {
    if (auto st = ready(options, "train"); !st) {
        return st.error();
    }
    auto trained = hybrid::trainResidualModels(m_si, m_model, options.residual, options.lstm, progress,
                                               options.selection);
    if (!trained) {
        return trained.error();
    }
    TrainResult result;
    result.selection = trained->selection;
    result.onDefaultParameters = !m_model.calibration.has_value();
    result.ending = trained->ending;
    hybrid::storeResidualModels(m_model, std::move(*trained));
    result.pgrlCc = m_model.pgrlCc;
    result.extInput = m_model.extInput;
    result.lstm = m_model.lstm;
    if (result.onDefaultParameters) {
        result.ending.message += "; on the default physics parameters (the model holds no calibration)";
    }
    m_latest.train = result;
    return result;
}

Expected<EvaluateResult> Session::evaluate(const EvaluateOptions& options, const Progress& progress) {
    if (auto st = ready(options, "evaluate"); !st) {
        return st.error();
    }
    auto ev = evaluation::evaluate(m_si, m_model, options.evaluation, progress);
    if (!ev) {
        return ev.error();
    }
    EvaluateResult result;
    result.diagnostics = hybrid::residualDiagnostics(*ev, m_model);
    result.ending = ev->ending;
    result.evaluation = std::move(*ev);
    m_latest.evaluate = result;
    return result;
}

Expected<hybrid::AblationResult> Session::ablation(const Progress& progress) {
    if (auto st = requireData("ablation"); !st) {
        return st.error();
    }
    auto rows = hybrid::runAblation(m_si, m_model, progress);
    if (!rows) {
        return rows.error();
    }
    m_latest.ablation = *rows;
    return rows;
}

} // namespace drytwin::workflow
