#include "hybrid/Evaluation.h"

#include "common/Units.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/Metrics.h"
#include "hybrid/HybridTraining.h"
#include "physics/LineSimulator.h"

#include <algorithm>
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
    if (horizonSteps < 1 || horizonSteps > 3600) {
        return invalidOption("horizon", "must lie in [1, 3600] steps");
    }
    if (!(trainFraction > 0 && trainFraction < 1)) {
        return invalidOption("train fraction", "must lie strictly between 0 and 1");
    }
    for (int h : horizons) {
        if (h < 1 || h > 3600) {
            return invalidOption("horizons", "each must lie in [1, 3600] steps");
        }
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

HorizonPredictor referencePredictor(bool holdPbmError) {
    return [holdPbmError](const residual::BatchView& v, const std::vector<int>& horizons) {
        std::vector<residual::HybridPrediction> p;
        for (int h : horizons) {
            p.push_back(referencePrediction(v, h, holdPbmError));
        }
        return p;
    };
}

residual::HybridPrediction pbmPrediction(const residual::BatchView& v) {
    residual::HybridPrediction p;
    for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
        p.xOutPct.push_back(units::dryToWetPct(v.pbm->xOutDb[k]));
        p.tOutC.push_back(v.pbm->tOutK[k] - units::kKelvinOffset);
    }
    return p;
}

namespace {

/// Pools observed and predicted values of the kept rows of every view, then scores them.
struct Pool {
    std::vector<double> ox, px, ot, pt;
    void add(const residual::BatchView& v, const residual::HybridPrediction& p) {
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
    ScoredPredictions score(int lbLags) const {
        ScoredPredictions s;
        s.moisture = outputMetrics(ox, px, lbLags);
        s.temperature = outputMetrics(ot, pt, lbLags);
        for (std::size_t i = 0; i < ox.size(); ++i) {
            s.moistureResidual.push_back(ox[i] - px[i]);
            s.temperatureResidual.push_back(ot[i] - pt[i]);
        }
        return s;
    }
};

} // namespace

ScoredPredictions scorePredictions(const std::vector<residual::BatchView>& views, const Predictor& predict,
                                   int lbLags) {
    Pool pool;
    for (const auto& v : views) {
        pool.add(v, predict(v));
    }
    return pool.score(lbLags);
}

std::vector<ScoredPredictions> scoreHorizons(const std::vector<residual::BatchView>& views,
                                             const HorizonPredictor& predict,
                                             const std::vector<int>& horizons, int lbLags) {
    std::vector<Pool> pools(horizons.size());
    for (const auto& v : views) {
        const auto p = predict(v, horizons);
        for (std::size_t h = 0; h < horizons.size(); ++h) {
            pools[h].add(v, p.at(h));
        }
    }
    std::vector<ScoredPredictions> out;
    for (const auto& pool : pools) {
        out.push_back(pool.score(lbLags));
    }
    return out;
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
    const data::ChronologicalSplit split = [&] {
        std::vector<std::size_t> rowsPerBatch;
        for (const auto& b : batches) {
            rowsPerBatch.push_back(b.rows());
        }
        return data::chronologicalSplit(rowsPerBatch, options.trainFraction);
    }();
    out.split = split.name;
    out.multiStepHorizon = options.horizonSteps;
    out.horizons = options.horizons;
    out.horizons.push_back(1);
    out.horizons.push_back(options.horizonSteps);
    std::sort(out.horizons.begin(), out.horizons.end());
    out.horizons.erase(std::unique(out.horizons.begin(), out.horizons.end()), out.horizons.end());
    const auto& horizons = out.horizons;
    const auto slotOf = [&](int h) {
        return static_cast<std::size_t>(std::find(horizons.begin(), horizons.end(), h) - horizons.begin());
    };
    const std::size_t oneStep = slotOf(1);
    const std::size_t multiStep = slotOf(options.horizonSteps);
    const int lags = options.ljungBoxLags;

    // A model's scores at every horizon; the one-step and headline multi-step ones copied out.
    auto score = [&](const char* name, const HorizonPredictor& predict) {
        ModelMetrics m;
        m.name = name;
        const auto scored = scoreHorizons(test, predict, horizons, lags);
        for (const auto& s : scored) {
            m.moistureByHorizon.push_back(s.moisture);
            m.temperatureByHorizon.push_back(s.temperature);
        }
        m.moisture = scored[oneStep].moisture;
        m.temperature = scored[oneStep].temperature;
        m.moistureResidual = scored[oneStep].moistureResidual;
        m.temperatureResidual = scored[oneStep].temperatureResidual;
        m.moistureMultiStep = scored[multiStep].moisture;
        m.temperatureMultiStep = scored[multiStep].temperature;
        return m;
    };
    const auto cancelled = [&](double fraction) { return reportProgress(progress, "evaluate", fraction); };

    // The PBM runs open loop on the inputs: the same prediction at every horizon.
    out.models.push_back(score("pbm", [](const residual::BatchView& v, const std::vector<int>& hs) {
        return std::vector<residual::HybridPrediction>(hs.size(), pbmPrediction(v));
    }));
    out.testRows = out.models.front().moistureResidual.size();
    if (out.testRows < 30) {
        return Error{ErrorKind::BadInput, "held-out data",
                     "only " + std::to_string(out.testRows) + " held-out rows pass the cleaning rules"};
    }
    // The headline horizon: one no held-out batch is long enough to reach scores nothing (a fresh user's
    // --horizon 100000 printed NaN for five models and a "perfect" 0.000 skill for the PBM, exit 0).
    {
        std::size_t longest = 0;
        for (const auto& r : split.test) {
            longest = std::max(longest, r.size());
        }
        if (static_cast<std::size_t>(options.horizonSteps) >= longest) {
            return invalidOption("horizon", "a horizon of " + std::to_string(options.horizonSteps) +
                                                " steps is as long as the held-out part's longest batch (" +
                                                std::to_string(longest) +
                                                " rows) or longer: nothing to score");
        }
    }
    // The two predictors every forecast must beat (CONTRACT.md §3).
    for (const char* name : {kPersistenceKey, kPbmResidualHoldKey}) {
        const bool hold = std::string(name) == kPbmResidualHoldKey;
        out.models.push_back(score(name, referencePredictor(hold)));
    }
    if (cancelled(0.3)) {
        return cancelledError("evaluate");
    }
    if (const auto& lstm = model.lstm) {
        out.models.push_back(
            score(hybrid::kLstmKey, [&](const residual::BatchView& v, const std::vector<int>& hs) {
                return lstm->predictHorizons(v, hs);
            }));
    }
    if (cancelled(0.6)) {
        return cancelledError("evaluate");
    }
    {
        ModelMetrics pbmFree = out.models.front();
        pbmFree.moistureByHorizon.clear();
        pbmFree.temperatureByHorizon.clear();
        out.freeRun.push_back(std::move(pbmFree));
    }
    const std::pair<const char*, const residual::ResidualModel*> residualModels[] = {
        {hybrid::kExtInputKey, model.extInput.get()}, {hybrid::kPgrlCcKey, model.pgrlCc.get()}};
    for (const auto& [key, rm] : residualModels) {
        if (!rm) {
            continue;
        }
        ModelMetrics m = score(key, [rm = rm](const residual::BatchView& v, const std::vector<int>& hs) {
            return rm->predictHorizons(v, hs);
        });
        const auto& c = rm->stability();
        m.hasStability = true;
        m.spectralRadiusBefore = c.spectralRadiusBefore;
        m.spectralRadiusAfter = c.spectralRadiusAfter;
        m.alpha = c.alpha;
        m.certificateMaxEig = c.certificateMaxEig;
        m.choleskyPasses = c.choleskyPasses;
        m.pConditionNumber = c.pConditionNumber;
        m.stabilityComparison = rm->stabilityComparison();
        out.models.push_back(std::move(m));

        ModelMetrics free;
        free.name = key;
        const auto s = scorePredictions(
            test, [rm = rm](const residual::BatchView& v) { return rm->predictFreeRun(v); }, lags);
        free.moisture = free.moistureMultiStep = s.moisture;
        free.temperature = free.temperatureMultiStep = s.temperature;
        free.moistureResidual = s.moistureResidual;
        free.temperatureResidual = s.temperatureResidual;
        out.freeRun.push_back(std::move(free));
    }
    // Skill: MAE over the better of the two reference predictors at the same horizon (< 1 beats both).
    std::vector<double> refX(horizons.size(), std::numeric_limits<double>::infinity()), refT = refX;
    for (const auto& m : out.models) {
        if (m.name == kPersistenceKey || m.name == kPbmResidualHoldKey) {
            for (std::size_t h = 0; h < horizons.size(); ++h) {
                refX[h] = std::min(refX[h], m.moistureByHorizon[h].mae);
                refT[h] = std::min(refT[h], m.temperatureByHorizon[h].mae);
            }
        }
    }
    for (auto& m : out.models) {
        for (std::size_t h = 0; h < horizons.size(); ++h) {
            m.skillMoistureByHorizon.push_back(m.moistureByHorizon[h].mae / refX[h]);
            m.skillTemperatureByHorizon.push_back(m.temperatureByHorizon[h].mae / refT[h]);
        }
        m.skillMoisture = m.skillMoistureByHorizon[oneStep];
        m.skillTemperature = m.skillTemperatureByHorizon[oneStep];
        m.skillMoistureMultiStep = m.skillMoistureByHorizon[multiStep];
        m.skillTemperatureMultiStep = m.skillTemperatureByHorizon[multiStep];
    }
    // A free run is compared with the best reference at the longest horizon: it never sees an
    // output, so it is at least that far ahead.
    for (auto& m : out.freeRun) {
        m.skillMoisture = m.skillMoistureMultiStep = m.moisture.mae / refX.back();
        m.skillTemperature = m.skillTemperatureMultiStep = m.temperature.mae / refT.back();
    }
    out.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.ending = {Termination::Completed,
                  std::to_string(out.models.size()) + " model(s) scored on " + std::to_string(out.testRows) +
                      " held-out rows at " + std::to_string(horizons.size()) + " horizons",
                  out.elapsedSeconds};
    return out;
}

} // namespace drytwin::evaluation
