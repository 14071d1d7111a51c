#include "io/Evaluation.h"

#include "diagnostics/LjungBox.h"
#include "diagnostics/Metrics.h"
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
    std::vector<std::size_t> rowsPerBatch;
    std::vector<physics::LineInputs> inputs;
    for (const auto& b : batches) {
        rowsPerBatch.push_back(b.rows());
        inputs.push_back(data::toLineInputs(b));
    }
    const auto split = data::chronologicalSplit(rowsPerBatch, options.trainFraction);
    physics::SimulationOptions so;
    so.switches = model.switches;
    so.winnower = model.winnower;
    auto sims = physics::simulateBatches(inputs, model.parameters, so, 0, progress);
    if (!sims) {
        return sims.error();
    }
    EvaluationResult out;
    out.split = split.name;
    out.multiStepHorizon = options.horizonSteps;
    std::vector<double> obsX, predX, obsT, predT;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const auto& s = batches[b];
        const auto& r = (*sims)[b];
        for (std::size_t k = split.test[b].begin; k < split.test[b].end; ++k) {
            if (!s.keep[k]) {
                continue;
            }
            obsX.push_back(data::dryToWetPct(s.xOutDb[k]));
            predX.push_back(data::dryToWetPct(r.xOutDb[k]));
            obsT.push_back(s.tOutK[k] - data::kKelvinOffset);
            predT.push_back(r.tOutK[k] - data::kKelvinOffset);
        }
    }
    out.testRows = obsX.size();
    if (out.testRows < 30) {
        return Error{ErrorKind::BadInput, "held-out data",
                     "only " + std::to_string(out.testRows) + " held-out rows pass the cleaning rules"};
    }
    // The PBM runs open loop on the inputs: its one-step and multi-step predictions coincide.
    ModelMetrics pbm;
    pbm.name = "pbm";
    pbm.moisture = outputMetrics(obsX, predX, options.ljungBoxLags);
    pbm.temperature = outputMetrics(obsT, predT, options.ljungBoxLags);
    pbm.moistureMultiStep = pbm.moisture;
    pbm.temperatureMultiStep = pbm.temperature;
    for (std::size_t i = 0; i < obsX.size(); ++i) {
        pbm.moistureResidual.push_back(obsX[i] - predX[i]);
        pbm.temperatureResidual.push_back(obsT[i] - predT[i]);
    }
    out.models.push_back(std::move(pbm));
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
        multi["models"][m.name] = {{"moisture", metrics(m.moistureMultiStep)},
                                   {"temperature", metrics(m.temperatureMultiStep)}};
    }
    j["multi_step"] = multi;
    return j.dump(2) + "\n";
}

} // namespace drytwin::evaluation
