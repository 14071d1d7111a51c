#include "hybrid/Evaluation.h"

#include "common/Units.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/Metrics.h"
#include "hybrid/HybridTraining.h"
#include "physics/LineSimulator.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace drytwin::evaluation {

OutputMetrics outputMetrics(const std::vector<double>& observed, const std::vector<double>& predicted,
                            int lbLags) {
    OutputMetrics m;
    m.mae = diagnostics::meanAbsoluteError(observed, predicted);
    m.r2 = diagnostics::rSquared(observed, predicted);
    std::vector<double> r(observed.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        r[i] = observed[i] - predicted[i];
    }
    m.ljungBoxP = diagnostics::ljungBox(r, lbLags).pValue;
    return m;
}

Status EvaluationOptions::validate() const {
    if (horizonSteps < 1) {
        return invalidOption("horizon", "must be at least 1 step");
    }
    if (!(trainFraction > 0 && trainFraction < 1)) {
        return invalidOption("train fraction", "must lie strictly between 0 and 1");
    }
    if (ljungBoxLags < 1) {
        return invalidOption("Ljung-Box lags", "must be at least 1");
    }
    return {};
}

residual::HybridPrediction referencePrediction(const residual::BatchView& v, int horizon, bool holdPbmError) {
    residual::HybridPrediction p;
    const auto& b = *v.batch;
    const auto& m = *v.pbm;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
        if (k < static_cast<std::size_t>(horizon)) {
            p.xOutPct.push_back(nan);
            p.tOutC.push_back(nan);
            continue;
        }
        const std::size_t j = k - static_cast<std::size_t>(horizon); // the last measurement seen
        double x = units::dryToWetPct(b.xOutDb[j]);
        double t = units::kelvinToCelsius(b.tOutK[j]);
        if (holdPbmError) {
            x = units::dryToWetPct(m.xOutDb[k]) + (x - units::dryToWetPct(m.xOutDb[j]));
            t = units::kelvinToCelsius(m.tOutK[k]) + (t - units::kelvinToCelsius(m.tOutK[j]));
        }
        p.xOutPct.push_back(x); // NaN where the measurement was missing
        p.tOutC.push_back(t);
    }
    return p;
}

residual::HybridPrediction pbmPrediction(const residual::BatchView& v) {
    residual::HybridPrediction p;
    for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
        p.xOutPct.push_back(units::dryToWetPct(v.pbm->xOutDb[k]));
        p.tOutC.push_back(v.pbm->tOutK[k] - units::kKelvinOffset);
    }
    return p;
}

ScoredPredictions scorePredictions(const std::vector<residual::BatchView>& views, const Predictor& predict,
                                   int lbLags) {
    std::vector<double> ox, px, ot, pt;
    for (const auto& v : views) {
        const auto p = predict(v);
        for (std::size_t i = 0; i < v.rows.size(); ++i) {
            const std::size_t k = v.rows.begin + i;
            if (v.batch->keep[k] && std::isfinite(p.xOutPct[i]) && std::isfinite(p.tOutC[i])) {
                ox.push_back(units::dryToWetPct(v.batch->xOutDb[k]));
                px.push_back(p.xOutPct[i]);
                ot.push_back(v.batch->tOutK[k] - units::kKelvinOffset);
                pt.push_back(p.tOutC[i]);
            }
        }
    }
    ScoredPredictions s;
    s.moisture = outputMetrics(ox, px, lbLags);
    s.temperature = outputMetrics(ot, pt, lbLags);
    for (std::size_t i = 0; i < ox.size(); ++i) {
        s.moistureResidual.push_back(ox[i] - px[i]);
        s.temperatureResidual.push_back(ot[i] - pt[i]);
    }
    return s;
}

Expected<EvaluationResult> evaluate(const std::vector<data::SiBatch>& batches,
                                    const hybrid::HybridModel& model, const EvaluationOptions& options,
                                    const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto sims = hybrid::simulatePbm(batches, model, model.switches, progress);
    if (!sims) {
        return sims.error();
    }
    const auto test = hybrid::splitViews(batches, *sims, true, options.trainFraction);
    EvaluationResult out;
    {
        std::vector<std::size_t> rowsPerBatch;
        for (const auto& b : batches) {
            rowsPerBatch.push_back(b.rows());
        }
        out.split = data::chronologicalSplit(rowsPerBatch, options.trainFraction).name;
    }
    out.multiStepHorizon = options.horizonSteps;
    const int lags = options.ljungBoxLags;
    // The PBM runs open loop on the inputs: its one-step and multi-step predictions coincide.
    ModelMetrics pbm;
    pbm.name = "pbm";
    const auto pbmScore = scorePredictions(test, pbmPrediction, lags);
    pbm.moisture = pbm.moistureMultiStep = pbmScore.moisture;
    pbm.temperature = pbm.temperatureMultiStep = pbmScore.temperature;
    pbm.moistureResidual = pbmScore.moistureResidual;
    pbm.temperatureResidual = pbmScore.temperatureResidual;
    out.testRows = pbm.moistureResidual.size();
    if (out.testRows < 30) {
        return Error{ErrorKind::BadInput, "held-out data",
                     "only " + std::to_string(out.testRows) + " held-out rows pass the cleaning rules"};
    }
    out.models.push_back(std::move(pbm));

    // One-step and H-step scores of a model.
    auto score = [&](const char* name, const Predictor& oneStep, const Predictor& ahead) {
        ModelMetrics m;
        m.name = name;
        const auto one = scorePredictions(test, oneStep, lags);
        const auto multi = scorePredictions(test, ahead, lags);
        m.moisture = one.moisture;
        m.temperature = one.temperature;
        m.moistureResidual = one.moistureResidual;
        m.temperatureResidual = one.temperatureResidual;
        m.moistureMultiStep = multi.moisture;
        m.temperatureMultiStep = multi.temperature;
        return m;
    };
    // The two predictors every forecast must beat (CONTRACT.md §3), one step and H steps ahead.
    for (const char* name : {kPersistenceKey, kPbmResidualHoldKey}) {
        const bool hold = std::string(name) == kPbmResidualHoldKey;
        out.models.push_back(score(
            name, [&](const residual::BatchView& v) { return referencePrediction(v, 1, hold); },
            [&](const residual::BatchView& v) {
                return referencePrediction(v, options.horizonSteps, hold);
            }));
    }

    const int h = options.horizonSteps;
    if (const auto& lstm = model.lstm) {
        out.models.push_back(score(
            hybrid::kLstmKey, [&](const residual::BatchView& v) { return lstm->predictAhead(v, 1); },
            [&](const residual::BatchView& v) { return lstm->predictAhead(v, h); }));
    }
    const std::pair<const char*, const residual::ResidualModel*> residualModels[] = {
        {hybrid::kExtInputKey, model.extInput.get()}, {hybrid::kPgrlCcKey, model.pgrlCc.get()}};
    for (const auto& [key, rm] : residualModels) {
        if (!rm) {
            continue;
        }
        ModelMetrics m = score(
            key, [&](const residual::BatchView& v) { return rm->predictOneStep(v); },
            [&](const residual::BatchView& v) { return rm->predictAhead(v, h); });
        const auto& c = rm->stability();
        m.hasStability = true;
        m.spectralRadiusBefore = c.spectralRadiusBefore;
        m.spectralRadiusAfter = c.spectralRadiusAfter;
        m.alpha = c.alpha;
        m.certificateMaxEig = c.certificateMaxEig;
        out.models.push_back(std::move(m));
    }
    // Skill: MAE over the better of the two reference predictors at the same horizon (< 1 beats both).
    const auto reference = [&](auto metric) {
        double best = std::numeric_limits<double>::infinity();
        for (const auto& m : out.models) {
            if (m.name == kPersistenceKey || m.name == kPbmResidualHoldKey) {
                best = std::min(best, metric(m));
            }
        }
        return best;
    };
    const double refX = reference([](const ModelMetrics& m) { return m.moisture.mae; });
    const double refT = reference([](const ModelMetrics& m) { return m.temperature.mae; });
    const double refXH = reference([](const ModelMetrics& m) { return m.moistureMultiStep.mae; });
    const double refTH = reference([](const ModelMetrics& m) { return m.temperatureMultiStep.mae; });
    for (auto& m : out.models) {
        m.skillMoisture = m.moisture.mae / refX;
        m.skillTemperature = m.temperature.mae / refT;
        m.skillMoistureMultiStep = m.moistureMultiStep.mae / refXH;
        m.skillTemperatureMultiStep = m.temperatureMultiStep.mae / refTH;
    }
    out.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.ending = {Termination::Completed,
                  std::to_string(out.models.size()) + " model(s) scored on " + std::to_string(out.testRows) +
                      " held-out rows",
                  out.elapsedSeconds};
    return out;
}

} // namespace drytwin::evaluation
