#include "io/Evaluation.h"

#include "diagnostics/LjungBox.h"
#include "diagnostics/Metrics.h"
#include "io/HybridTraining.h"
#include "physics/LineSimulator.h"

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

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

residual::HybridPrediction pbmPrediction(const residual::BatchView& v) {
    residual::HybridPrediction p;
    for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
        p.xOutPct.push_back(data::dryToWetPct(v.pbm->xOutDb[k]));
        p.tOutC.push_back(v.pbm->tOutK[k] - data::kKelvinOffset);
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
                ox.push_back(data::dryToWetPct(v.batch->xOutDb[k]));
                px.push_back(p.xOutPct[i]);
                ot.push_back(v.batch->tOutK[k] - data::kKelvinOffset);
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

Expected<EvaluationResult> evaluate(const std::vector<data::SiBatch>& batches, const io::ModelFile& model,
                                    const EvaluationOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (options.horizonSteps < 1) {
        return Error{ErrorKind::Usage, "horizon", "must be at least 1 step"};
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

    // One-step and H-step scores of a learnt model.
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
    const int h = options.horizonSteps;
    bool present = false;
    auto lstm = hybrid::loadLstm(model, present);
    if (present && !lstm) {
        return lstm.error();
    }
    if (present) {
        out.models.push_back(score(
            hybrid::kLstmKey, [&](const residual::BatchView& v) { return lstm->predictAhead(v, 1); },
            [&](const residual::BatchView& v) { return lstm->predictAhead(v, h); }));
    }
    for (const char* key : {hybrid::kExtInputKey, hybrid::kPgrlCcKey}) {
        auto rm = hybrid::loadResidualModel(model, key, present);
        if (!present) {
            continue;
        }
        if (!rm) {
            return rm.error();
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
    out.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

std::string toJson(const EvaluationResult& r) {
    using nlohmann::json;
    auto metrics = [](const OutputMetrics& m) {
        auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
        return json{{"mae", num(m.mae)}, {"r2", num(m.r2)}, {"ljung_box_p", num(m.ljungBoxP)}};
    };
    json j;
    j["split"] = r.split;
    j["horizon_steps"] = r.horizonSteps;
    j["test_rows"] = r.testRows;
    j["units"] = {{"moisture", "% wb"}, {"temperature", "°C"}};
    json multi;
    multi["horizon_steps"] = r.multiStepHorizon;
    for (const auto& m : r.models) {
        j["models"][m.name] = {{"moisture", metrics(m.moisture)}, {"temperature", metrics(m.temperature)}};
        if (m.hasStability) {
            j["models"][m.name]["stability"] = {{"spectral_radius_before", m.spectralRadiusBefore},
                                                {"spectral_radius_after", m.spectralRadiusAfter},
                                                {"alpha", m.alpha},
                                                {"certificate_max_eig", m.certificateMaxEig}};
        }
        multi["models"][m.name] = {{"moisture", metrics(m.moistureMultiStep)},
                                   {"temperature", metrics(m.temperatureMultiStep)}};
    }
    j["multi_step"] = multi;
    return j.dump(2) + "\n";
}

} // namespace drytwin::evaluation
