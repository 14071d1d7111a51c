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
    // Observed and predicted series over the kept held-out rows; predictions NaN-free rows only.
    struct Series {
        std::vector<double> ox, px, ot, pt;
        void add(double oX, double pX, double oT, double pT) {
            if (std::isfinite(pX) && std::isfinite(pT)) {
                ox.push_back(oX);
                px.push_back(pX);
                ot.push_back(oT);
                pt.push_back(pT);
            }
        }
    };
    auto metricsOf = [&](const Series& s, ModelMetrics& m, bool multi) {
        (multi ? m.moistureMultiStep : m.moisture) = outputMetrics(s.ox, s.px, options.ljungBoxLags);
        (multi ? m.temperatureMultiStep : m.temperature) = outputMetrics(s.ot, s.pt, options.ljungBoxLags);
        if (!multi) {
            for (std::size_t i = 0; i < s.ox.size(); ++i) {
                m.moistureResidual.push_back(s.ox[i] - s.px[i]);
                m.temperatureResidual.push_back(s.ot[i] - s.pt[i]);
            }
        }
    };
    Series pbmSeries;
    for (const auto& v : test) {
        for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
            if (v.batch->keep[k]) {
                pbmSeries.add(data::dryToWetPct(v.batch->xOutDb[k]), data::dryToWetPct(v.pbm->xOutDb[k]),
                              v.batch->tOutK[k] - data::kKelvinOffset, v.pbm->tOutK[k] - data::kKelvinOffset);
            }
        }
    }
    out.testRows = pbmSeries.ox.size();
    if (out.testRows < 30) {
        return Error{ErrorKind::BadInput, "held-out data",
                     "only " + std::to_string(out.testRows) + " held-out rows pass the cleaning rules"};
    }
    // The PBM runs open loop on the inputs: its one-step and multi-step predictions coincide.
    ModelMetrics pbm;
    pbm.name = "pbm";
    metricsOf(pbmSeries, pbm, false);
    metricsOf(pbmSeries, pbm, true);
    out.models.push_back(std::move(pbm));

    {
        bool present = false;
        auto lstm = hybrid::loadLstm(model, present);
        if (present && !lstm) {
            return lstm.error();
        }
        if (present) {
            ModelMetrics m;
            m.name = hybrid::kLstmKey;
            for (int pass = 0; pass < 2; ++pass) {
                Series s;
                for (const auto& v : test) {
                    const auto p = lstm->predictAhead(v, pass == 0 ? 1 : options.horizonSteps);
                    for (std::size_t i = 0; i < v.rows.size(); ++i) {
                        const std::size_t k = v.rows.begin + i;
                        if (v.batch->keep[k]) {
                            s.add(data::dryToWetPct(v.batch->xOutDb[k]), p.xOutPct[i],
                                  v.batch->tOutK[k] - data::kKelvinOffset, p.tOutC[i]);
                        }
                    }
                }
                metricsOf(s, m, pass == 1);
            }
            out.models.push_back(std::move(m));
        }
    }
    for (const char* key : {hybrid::kExtInputKey, hybrid::kPgrlCcKey}) {
        bool present = false;
        auto rm = hybrid::loadResidualModel(model, key, present);
        if (!present) {
            continue;
        }
        if (!rm) {
            return rm.error();
        }
        ModelMetrics m;
        m.name = key;
        for (int pass = 0; pass < 2; ++pass) {
            Series s;
            for (const auto& v : test) {
                const auto p = pass == 0 ? rm->predictOneStep(v) : rm->predictAhead(v, options.horizonSteps);
                for (std::size_t i = 0; i < v.rows.size(); ++i) {
                    const std::size_t k = v.rows.begin + i;
                    if (v.batch->keep[k]) {
                        s.add(data::dryToWetPct(v.batch->xOutDb[k]), p.xOutPct[i],
                              v.batch->tOutK[k] - data::kKelvinOffset, p.tOutC[i]);
                    }
                }
            }
            metricsOf(s, m, pass == 1);
        }
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
