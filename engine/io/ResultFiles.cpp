#include "io/ResultFiles.h"

#include "common/Units.h"
#include "data/BatchWriter.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace drytwin::io {

using nlohmann::json;

namespace {

json spectrumJson(const hybrid::EigenSpectrum& s) {
    json j;
    for (const auto& l : s.eigenvalues) {
        j["re"].push_back(l.real());
        j["im"].push_back(l.imag());
    }
    for (double r : s.contractionRatePerStep) {
        j["contraction_rate_per_step"].push_back(std::isfinite(r) ? json(r) : json(nullptr));
    }
    j["spectral_radius"] = s.spectralRadius;
    return j;
}

} // namespace

std::string evaluationJson(const evaluation::EvaluationResult& r) {
    auto metrics = [](const evaluation::OutputMetrics& m) {
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
        j["models"][m.name] = {
            {"moisture", metrics(m.moisture)},
            {"temperature", metrics(m.temperature)},
            {"skill", {{"moisture", m.skillMoisture}, {"temperature", m.skillTemperature}}}};
        if (m.hasStability) {
            j["models"][m.name]["stability"] = {{"spectral_radius_before", m.spectralRadiusBefore},
                                                {"spectral_radius_after", m.spectralRadiusAfter},
                                                {"alpha", m.alpha},
                                                {"certificate_max_eig", m.certificateMaxEig},
                                                {"cholesky_passes", m.choleskyPasses},
                                                {"p_condition_number", m.pConditionNumber}};
            const auto& c = m.stabilityComparison;
            j["models"][m.name]["stability"]["training_loss"] = {{"unconstrained", c.lossUnconstrained},
                                                                 {"eigenvalue_pull", c.lossEigenvaluePull},
                                                                 {"eq30_constrained", c.lossConstrained}};
            j["models"][m.name]["stability"]["spectral_radius"] = {
                {"unconstrained", c.radiusUnconstrained},
                {"eigenvalue_pull", c.radiusEigenvaluePull},
                {"eq30_constrained", c.radiusConstrained}};
        }
        multi["models"][m.name] = {
            {"moisture", metrics(m.moistureMultiStep)},
            {"temperature", metrics(m.temperatureMultiStep)},
            {"skill",
             {{"moisture", m.skillMoistureMultiStep}, {"temperature", m.skillTemperatureMultiStep}}}};
    }
    j["multi_step"] = multi;
    // The horizon curve (CONTRACT.md §3): MAE and skill at each horizon for every model.
    json horizons;
    horizons["steps"] = r.horizons;
    for (const auto& m : r.models) {
        json h;
        for (std::size_t i = 0; i < m.moistureByHorizon.size(); ++i) {
            h["moisture_mae"].push_back(m.moistureByHorizon[i].mae);
            h["temperature_mae"].push_back(m.temperatureByHorizon[i].mae);
            h["moisture_skill"].push_back(m.skillMoistureByHorizon[i]);
            h["temperature_skill"].push_back(m.skillTemperatureByHorizon[i]);
        }
        horizons["models"][m.name] = h;
    }
    j["horizons"] = horizons;
    for (const auto& m : r.freeRun) {
        j["free_run"][m.name] = {
            {"moisture", metrics(m.moisture)},
            {"temperature", metrics(m.temperature)},
            {"skill", {{"moisture", m.skillMoisture}, {"temperature", m.skillTemperature}}}};
    }
    return j.dump(2) + "\n";
}

std::string ablationJson(const hybrid::AblationResult& result) {
    json j;
    j["split"] = "chronological_70_30";
    j["horizon_steps"] = 1;
    j["multi_step_horizon"] = result.multiStepHorizon;
    j["regime_split"] = result.regimeSplit;
    j["units"] = {{"moisture", "% wb"}, {"temperature", "°C"}};
    for (const auto& r : result.rows) {
        j["variants"].push_back({{"variant", r.variant},
                                 {"description", r.description},
                                 {"mae_moisture", r.maeMoisture},
                                 {"r2_moisture", r.r2Moisture},
                                 {"mae_temperature", r.maeTemperature},
                                 {"r2_temperature", r.r2Temperature},
                                 {"ljung_box_p_moisture", r.ljungBoxPMoisture},
                                 {"mae_moisture_multi_step", r.maeMoistureMultiStep},
                                 {"regime",
                                  {{"mae_moisture", r.regimeMaeMoisture},
                                   {"r2_moisture", r.regimeR2Moisture},
                                   {"mae_temperature", r.regimeMaeTemperature}}},
                                 {"recalibrated", r.recalibrated},
                                 {"h_HDT", r.hHdt},
                                 {"k_HDT", r.kHdt}});
    }
    return j.dump(2) + "\n";
}

std::string mpcJson(const control::ClosedLoopResult& result) {
    json j;
    const auto& sc = result.scenario;
    j["steps"] = sc.lengthS;
    j["scenario"] = {{"name", sc.name},
                     {"description", sc.description},
                     {"seed", sc.seed},
                     {"warmup_s", sc.warmupS},
                     {"length_s", sc.lengthS},
                     {"control_interval_s", sc.controlIntervalS},
                     {"band_pct", sc.bandPct},
                     // Which line it ran against: a file without "plant" runs on the lumped one.
                     {"plant", std::string(plant::plantKindName(sc.plant))},
                     {"sensors", std::string(sc.instrumentsName())}};
    j["units"] = {{"iae", "% wb * s"},
                  {"effort", "K^2"},
                  {"violation_pct", "% of steps"},
                  {"solve_ms", "ms"},
                  {"gain", "% wb/K"},
                  {"x_out", "% wb"},
                  {"t_hot", "°C"},
                  {"time", "s from the start of the scored part"}};
    j["termination"] = terminationName(result.ending.termination);
    j["plant_gain_pct_per_k"] = result.plantGainPctPerK;
    // CONTRACT.md §3: the steady gain of X_out to T_hot [% wb per K], the plant's from its
    // open-loop step test, each model's as its MPC saw it (the median over its decisions).
    j["gains"] = {{"plant", result.plantGainPctPerK}};
    for (const auto& r : result.runs) {
        if (r.ran && r.kind != control::ControllerKind::Pi && r.metrics.decisions > 0) {
            j["gains"][control::controllerName(r.kind)] = r.metrics.gainPctPerKMedian;
        }
    }
    j["controllers"] = json::object();
    for (const auto& r : result.runs) {
        const std::string name = control::controllerName(r.kind);
        if (!r.ran) {
            j["skipped"][name] = r.skippedReason;
            continue;
        }
        const auto& m = r.metrics;
        // The PI loop decides nothing by a model: its solve times and believed gain are null, not
        // 0 (a script read the PI loop's gain as 0 % wb/K).
        const bool byModel = r.kind != control::ControllerKind::Pi;
        const auto modelValue = [byModel](double v) { return byModel ? json(v) : json(nullptr); };
        j["controllers"][name] = {{"iae", m.iaePctS},
                                  {"effort", m.effortK2},
                                  {"violation_pct", m.violationPct},
                                  {"solve_ms_median", modelValue(m.solveMsMedian)},
                                  {"solve_ms_max", modelValue(m.solveMsMax)},
                                  {"model_ms_median", modelValue(m.modelMsMedian)},
                                  {"gain_pct_per_k_median", modelValue(m.gainPctPerKMedian)},
                                  {"decisions", m.decisions},
                                  {"fallbacks", m.fallbacks},
                                  {"last_fallback_reason", m.lastFallbackReason},
                                  {"elapsed_s", r.elapsedSeconds}};
        if (r.forecastCheck) {
            j["controllers"][name]["forecast_check"] = {{"horizons_s", r.forecastCheck->horizonsS},
                                                        {"mae_pct", r.forecastCheck->maePct},
                                                        {"origins", r.forecastCheck->origins}};
        }
        json t;
        t["time_s"] = r.timeS;
        t["x_out_measured"] = r.xOutMeasuredPct;
        t["x_out_true"] = r.xOutTruePct;
        t["setpoint"] = r.setpointPct;
        t["t_hot_setpoint"] = r.hotAirSetpointC;
        t["t_hot"] = r.hotAirC;
        for (const auto& p : r.predictions) {
            t["predictions"].push_back({{"at_s", p.atS}, {"x_out", p.xOutPct}});
        }
        j["trajectories"][name] = t;
    }
    return j.dump(1) + "\n";
}

std::string residualDiagnosticsJson(const hybrid::ResidualDiagnostics& d) {
    json j;
    j["units"] = {{"moisture_residual", "% wb"}, {"psd", "(% wb)^2/Hz"}, {"frequency", "Hz"}};
    for (const auto& m : d.models) {
        json e;
        e["acf_lags_0_to_40"] = m.acf;
        if (m.hasPsd) {
            e["psd"] = {{"frequency_hz", m.psdFrequencyHz}, {"density", m.psdDensity}};
            e["low_frequency_share_below_0_01_hz"] = m.lowFrequencyShareBelow0p01Hz;
        }
        j["models"][m.name] = e;
    }
    if (d.hasPgrlCcEigenvalues) {
        j["pgrl_cc_eigenvalues"] = {{"before", spectrumJson(d.pgrlCcBefore)},
                                    {"after", spectrumJson(d.pgrlCcAfter)}};
    }
    return j.dump(1) + "\n";
}

std::string inspectJson(const data::DataSetSummary& s) {
    json j;
    j["rows"] = s.rows;
    j["missing"] = s.missing;
    for (const auto& b : s.batches) {
        j["batches"].push_back({{"id", b.id},
                                {"rows", b.rows},
                                {"start_s", b.startS},
                                {"end_s", b.endS},
                                {"missing", b.missing},
                                {"dropped_by_cleaning", b.droppedByCleaning},
                                {"file", b.path}});
        if (b.run) {
            j["batches"].back()["run"] = {{"start", b.run->startTimestamp},
                                          {"first_line", b.run->firstLine},
                                          {"last_line", b.run->lastLine},
                                          {"samples", b.run->samples},
                                          {"interpolated_cells", b.run->interpolatedCells},
                                          {"gap_cells", b.run->gapCells},
                                          {"ended_by", b.run->splitReason}};
        }
    }
    j["notes"] = s.notes;
    for (const auto& col : s.columns) {
        if (col.present) {
            j["columns"][col.name] = {{"unit", col.unit},
                                      {"min", col.min},
                                      {"max", col.max},
                                      {"mean", col.mean},
                                      {"missing", col.missing}};
        }
    }
    const auto& c = s.cleaning;
    j["cleaning"] = {{"kept", c.kept},
                     {"dropped_x_hdt", c.droppedXhdt},
                     {"dropped_t_hdt", c.droppedThdt},
                     {"dropped_feed", c.droppedFeed},
                     {"dropped_missing", c.droppedMissing},
                     {"dropped_impossible", c.droppedImpossible},
                     {"dropped_stuck", c.droppedStuck},
                     {"frozen_readings", json::array()}};
    for (const auto& f : c.stuck) {
        j["cleaning"]["frozen_readings"].push_back(
            {{"batch", f.batch < s.batches.size() ? s.batches[f.batch].id : std::to_string(f.batch)},
             {"column", std::string(data::spec(f.column).name)},
             {"first_row", f.begin + 1},
             {"rows", f.end - f.begin},
             {"seconds", f.seconds},
             {"value", f.value}});
    }
    // Where the missing cells are (the first few per column; `missing` counts them all).
    j["missing_cells"] = json::array();
    for (const auto& m : s.missingCells) {
        j["missing_cells"].push_back({{"file", m.file},
                                      {"line", m.line},
                                      {"file_column", m.fileColumn},
                                      {"column", m.column},
                                      {"contract_column", m.contractColumn}});
    }
    j["impossible_values"] = {{"total", s.impossibleTotal}, {"listed", json::array()}};
    for (const auto& w : s.impossible) {
        j["impossible_values"]["listed"].push_back({{"file", w.file},
                                                    {"line", w.line},
                                                    {"file_column", w.fileColumn},
                                                    {"column", w.column},
                                                    {"contract_column", w.contractColumn},
                                                    {"value", w.value},
                                                    {"rule", w.rule}});
    }
    return j.dump(2) + "\n";
}

std::string simulationCsv(const std::vector<data::SiBatch>& batches,
                          const std::vector<physics::SimulationResult>& simulations) {
    using namespace units;
    std::string out =
        "batch,time_s,T_hot_sp_C,T_hot_C,air_speed_m_s,feed_kg_h,X_in_pct,T_in_C,T_amb_C,RH_amb_pct,"
        "pred_X_out_pct,pred_T_out_C,pred_X_hdt_pct,pred_T_hdt_C";
    for (const auto& n : physics::proxyNames()) {
        out += ",proxy_" + n;
    }
    // The measured outputs last (CONTRACT.md §2 fixes the columns before them), so that the file
    // compares prediction and measurement without the batch files beside it; empty where not measured.
    out += ",X_out_pct,T_out_C,X_hdt_pct,T_hdt_C\n";
    // Ten significant digits: the inputs come back from SI units, and the shortest round-trip form
    // wrote 25.4 °C as 25.399999999999977; ten digits are far beyond any transmitter's.
    const auto number = [](double x) {
        if (std::isnan(x)) {
            return std::string();
        }
        char text[32];
        std::snprintf(text, sizeof text, "%.10g", x);
        return std::string(text);
    };
    for (std::size_t b = 0; b < batches.size() && b < simulations.size(); ++b) {
        const auto& s = batches[b];
        const auto& r = simulations[b];
        for (std::size_t k = 0; k < s.rows(); ++k) {
            const double v[] = {s.timeS[k],
                                kelvinToCelsius(s.tHotSpK[k]),
                                kelvinToCelsius(s.tHotK[k]),
                                s.airSpeedMPerS[k],
                                kgPerSToKgPerHour(s.feedKgPerS[k]),
                                dryToWetPct(s.xInDb[k]),
                                kelvinToCelsius(s.tInK[k]),
                                kelvinToCelsius(s.tAmbK[k]),
                                fractionToPercent(s.rhAmb[k]),
                                dryToWetPct(r.xOutDb[k]),
                                kelvinToCelsius(r.tOutK[k]),
                                dryToWetPct(r.xHdtDb[k]),
                                kelvinToCelsius(r.tHdtK[k]),
                                r.proxyXHdtDb[k],
                                r.proxyTHdtK[k],
                                r.proxyXConvDb[k],
                                r.proxyTConvK[k],
                                r.proxyXMixDb[k],
                                r.proxyTMixK[k],
                                dryToWetPct(s.xOutDb[k]),
                                kelvinToCelsius(s.tOutK[k]),
                                dryToWetPct(s.xHdtDb[k]),
                                kelvinToCelsius(s.tHdtK[k])};
            out += s.id;
            for (double x : v) {
                out += ",";
                out += number(x);
            }
            out += "\n";
        }
    }
    return out;
}

} // namespace drytwin::io
