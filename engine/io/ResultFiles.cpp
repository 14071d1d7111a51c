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

double HybridReferences::bestMoisture(bool keptStartingModel) const {
    return std::fmin(persistenceMoisture, keptStartingModel ? pbmHoldMoistureBefore : pbmHoldMoistureAfter);
}

double HybridReferences::bestTemperature(bool keptStartingModel) const {
    return std::fmin(persistenceTemperature,
                     keptStartingModel ? pbmHoldTemperatureBefore : pbmHoldTemperatureAfter);
}

namespace {

/// One detector's judgement against the reference, with its window series for plots.
json detectionJson(const monitoring::Detection& d, const std::vector<std::string>& columns) {
    const auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    const auto judgement = [&](const monitoring::StatisticJudgement& s) {
        return json{{"changed", s.changed},
                    {"p_value", num(s.pValue)},
                    {"glr", num(s.glr)},
                    {"glr_threshold", num(s.glrThreshold)},
                    {"cusum_threshold", num(s.cusumThreshold)}};
    };
    json j = {{"changed", d.changed},
              {"p_value", num(d.pValue)},
              {"statistic", d.statistic},
              {"false_alarm_rate", num(d.falseAlarmRate)},
              {"columns", columns},
              {"components", d.components},
              {"variance_explained", num(d.varianceExplainedActual)},
              {"t2", judgement(d.t2)},
              {"spe", judgement(d.spe)},
              {"limits",
               {{"t2_theoretical", num(d.limits.t2Theoretical)},
                {"spe_theoretical", num(d.limits.speTheoretical)},
                {"t2_empirical", num(d.limits.t2Empirical)},
                {"spe_empirical", num(d.limits.speEmpirical)},
                {"t2_window", num(d.limits.t2Window)},
                {"spe_window", num(d.limits.speWindow)}}}};
    j["first_alarm"] = d.hasFirstAlarm ? json{{"batch", d.firstAlarmRun}, {"time_s", num(d.firstAlarmTimeS)}}
                                       : json(nullptr);
    // Batches in conditions the reference never saw: only changes within them are judged.
    j["level_not_judged"] = d.levelNotJudged;
    j["onset"] = d.hasOnset ? json{{"batch", d.onsetRun},
                                   {"time_s", num(d.onsetS)},
                                   {"ci95", {num(d.onsetLowS), num(d.onsetHighS)}}}
                            : json(nullptr);
    j["contributions"] = json::array();
    for (const auto& c : d.contributions) {
        // Ranked by the reconstruction-based shares (Alcala & Qin 2009): the plain squared-residual
        // shares smear a fault onto the columns it correlates with.
        j["contributions"].push_back({{"column", c.column},
                                      {"spe_reconstruction_share", num(c.speReconstructionShare)},
                                      {"t2_reconstruction_share", num(c.t2ReconstructionShare)},
                                      {"spe_share", num(c.speShare)},
                                      {"t2_share", num(c.t2Share)}});
    }
    json series = {{"batch", json::array()},
                   {"time_s", json::array()},
                   {"t2", json::array()},
                   {"spe", json::array()},
                   {"alarm", json::array()}};
    for (const auto& w : d.series) {
        series["batch"].push_back(w.run);
        series["time_s"].push_back(num(w.timeS));
        series["t2"].push_back(num(w.t2));
        series["spe"].push_back(num(w.spe));
        series["alarm"].push_back(w.alarm);
    }
    j["series"] = series;
    return j;
}

} // namespace

std::string discoveryJson(const discovery::DiscoveryResult& r, bool hasHybrid, double hybridMaeXBefore,
                          double hybridMaeXAfter, double hybridMaeTBefore, double hybridMaeTAfter,
                          bool keptStartingModel, const HybridReferences& references) {
    const auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json j;
    j["verdict"] = r.verdict;
    j["units"] = {{"moisture", "% wb"}, {"temperature", "°C"}};
    j["findings"] = json::array();
    for (const auto& f : r.findings) {
        const auto& g = f.gain;
        j["findings"].push_back(
            {{"cause", f.cause},
             {"parameter",
              {{"name", std::string(properties::info(f.parameter).symbol)},
               {"value", num(f.value)},
               {"unit", std::string(properties::info(f.parameter).unit)},
               {"ci95", {num(f.ci95Low), num(f.ci95High)}},
               // The fit when it was named, which its evidence, gain and parts
               // describe; "value" is at the final model (every cause jointly).
               {"when_named",
                {{"value", num(f.restated ? f.valueWhenNamed : f.value)},
                 {"ci95",
                  {num(f.restated ? f.ci95LowWhenNamed : f.ci95Low),
                   num(f.restated ? f.ci95HighWhenNamed : f.ci95High)}}}}}},
             {"explained_fraction", num(f.explainedFraction)},
             {"explained_fraction_fast", num(f.explainedFractionFast)},
             // A meter's lag (X_out) or a transport time (X_out and T_out): of those
             // channels' error alone, whole and fast part (null: not judged there).
             {"explained_fraction_on_its_channels",
              f.judgedOnItsChannels ? num(f.explainedFractionOnItsChannels) : json(nullptr)},
             {"explained_fraction_on_its_channels_fast",
              f.judgedOnItsChannels ? num(f.explainedFractionOnItsChannelsFast) : json(nullptr)},
             {"on_its_channels_counted", f.onItsChannelsCounted},
             {"evidence", f.evidence},
             {"gain",
              {{"split", g.split},
               {"mae_moisture_before", num(g.maeMoistureBefore)},
               {"mae_moisture_after", num(g.maeMoistureAfter)},
               {"mae_temperature_before", num(g.maeTemperatureBefore)},
               {"mae_temperature_after", num(g.maeTemperatureAfter)},
               {"r2_moisture_before", num(g.r2MoistureBefore)},
               {"r2_moisture_after", num(g.r2MoistureAfter)},
               {"r2_temperature_before", num(g.r2TemperatureBefore)},
               {"r2_temperature_after", num(g.r2TemperatureAfter)},
               {"ljung_box_p_moisture_before", num(g.ljungBoxPMoistureBefore)},
               {"ljung_box_p_moisture_after", num(g.ljungBoxPMoistureAfter)},
               {"low_frequency_share_before", num(g.lowFrequencyShareBefore)},
               {"low_frequency_share_after", num(g.lowFrequencyShareAfter)},
               {"p_value", num(g.pValue)}}}});
        // Specificity: per-part estimates, transfer, onset, look-alikes (CONTRACT.md §2 discover).
        json& out = j["findings"].back();
        out["output"] = f.output;
        if (!f.group.empty()) { // CONTRACT.md §3: every member, the favoured cause first
            json members = json::array({f.cause});
            for (const auto& l : f.lookAlikes) {
                if (!l.ruledOut) {
                    members.push_back(l.cause);
                }
            }
            out["group"] = members;
            out["group_name"] = f.group;
        }
        out["look_alikes"] = json::array();
        for (const auto& l : f.lookAlikes) {
            out["look_alikes"].push_back({{"cause", l.cause},
                                          {"value", num(l.value)},
                                          {"held_out_loss_ratio", num(l.heldOutLossRatio)},
                                          {"p_value", num(l.pValue)},
                                          {"ruled_out", l.ruledOut},
                                          {"by_channels", l.byChannels},
                                          {"moisture_delay_s", num(l.moistureDelayS)},
                                          {"temperature_delay_s", num(l.temperatureDelayS)},
                                          {"worse_output", l.worseOutput},
                                          {"named_after", l.namedAfter},
                                          {"explained_after", num(l.explainedAfter)}});
        }
        if (!f.tellApart.empty()) {
            out["tell_apart"] = f.tellApart;
        }
        out["per_part"] = json::array();
        for (const auto& e : f.perPart) {
            out["per_part"].push_back({{"part", e.part}, {"value", num(e.value)}, {"se", num(e.se)}});
        }
        out["consistent"] = f.consistent;
        out["transfer"] =
            f.transferChecked ? json{{"warm_half_loss_removed", num(f.transferReduction)}} : json(nullptr);
        if (f.hasOnset) {
            out["onset_s"] = num(f.onsetS);
            out["onset_ci95"] = {num(f.onsetLowS), num(f.onsetHighS)};
            if (!f.actsFromStartOf.empty()) { // a change that went on: from these batches' start
                out["acts_from_start_of"] = f.actsFromStartOf;
            }
        }
        if (f.hasReference) { // CONTRACT.md §3: the finding is a change from the reference's value
            out["parameter"]["reference_value"] = num(f.referenceValue);
            out["parameter"]["reference_ci95"] = {num(f.referenceCi95Low), num(f.referenceCi95High)};
        }
        if (f.responseJudged) { // an addition to CONTRACT.md §3 (docs/reference-period.md)
            static const char* const kOutputs[] = {"X_out", "T_out", "X_hdt", "T_hdt"};
            json scale = json::object();
            for (std::size_t c = 0; c < 4; ++c) {
                if (f.actsOn[c]) {
                    scale[kOutputs[c]] = num(f.responseScale[c]);
                }
            }
            out["response_scale"] = scale;
        }
    }
    if (r.hasReference) {
        j["reference"] = {
            {"path", r.referencePath}, {"batches", r.referenceBatches}, {"rows", r.referenceRows}};
        // The judged data's batches left out of the causes' fits: wholly before the change point.
        j["batches_before_change"] = r.batchesBeforeChange;
        // ... and the batches after the one the change began in, where it acts from their start.
        j["batches_changed_from_start"] = r.batchesChangedFromStart;
        const auto& d = r.detection;
        j["detection"] = {{"changed", d.changed},
                          {"statistic", "run-level GLR of a mean shift in the window means of log T² and log "
                                        "SPE (dynamic PCA, leave-one-out reference null), either detector"},
                          {"false_alarm_rate", num(d.falseAlarmRate)},
                          {"decided_by", d.decidedBy},
                          // Either detector or a cause named beyond its normal spread: whether the
                          // line changed, as the headline says (issue #41's reports, 2026-11-27).
                          {"line_changed", d.lineChanged()},
                          {"named_change", {{"changed", d.namedChange()}, {"causes", d.namedCauses}}},
                          {"detectors",
                           {{"drytwin", detectionJson(d.drytwin, d.drytwinColumns)},
                            {"pca", detectionJson(d.pca, d.pcaColumns)}}}};
        // DryTwin's detector is its monitor of the model's error or its test of the causes'
        // parameters against their normal values, each at half the rate.
        auto& ours = j["detection"]["detectors"]["drytwin"];
        ours["monitor_changed"] = d.drytwin.changed;
        ours["changed"] = d.drytwinChanged;
        ours["cause_test"] = {{"changed", d.causeTest.changed},
                              {"p_value", num(d.causeTest.pValue)},
                              {"cause", d.causeTest.cause},
                              // Which look decided: the one-step screen, a named cause's fitted
                              // value, or the inlet gauge's scatter against the reference's.
                              {"look", d.causeTest.look()}};
        // The first alarm of the deciding detectors (the earlier where both alarm).
        const monitoring::Detection* first = nullptr;
        for (const auto* det : {&d.drytwin, &d.pca}) {
            if (d.changed && det->hasFirstAlarm &&
                (!first || det->firstAlarmWindow < first->firstAlarmWindow)) {
                first = det;
            }
        }
        j["detection"]["first_alarm"] =
            first ? json{{"batch", first->firstAlarmRun}, {"time_s", num(first->firstAlarmTimeS)}}
                  : json(nullptr);
    }
    j["ranking"] = json::array();
    for (const auto& c : r.ranking) {
        json e = {{"cause", c.cause},
                  {"score", num(c.score)},
                  {"p_value", num(c.pValue)},
                  {"p_holm", num(c.pHolm)},
                  {"fitted", c.fitted},
                  {"linear_estimate", num(c.linearEstimate)},
                  {"linear_se", num(c.linearSe)}};
        if (c.screenedFromS >= 0) { // screened from the onset its tangent shows
            e["screened_from_s"] = num(c.screenedFromS);
        }
        if (c.fitted) {
            e["training_loss_before"] = num(c.fitLossBefore);
            e["training_loss_after"] = num(c.fitLossAfter);
        }
        j["ranking"].push_back(e);
    }
    j["rounds"] = json::array();
    for (const auto& rd : r.rounds) {
        json fitted = json::array();
        for (const auto& c : rd.candidates) {
            if (c.fitted) {
                fitted.push_back({{"cause", c.cause}, {"training_loss_after", num(c.fitLossAfter)}});
            }
        }
        j["rounds"].push_back({{"fitted", fitted},
                               {"best", rd.best},
                               {"held_out_p_value", num(rd.heldOutPValue)},
                               {"explained_fraction", num(rd.explainedFraction)},
                               {"explained_fraction_fast", num(rd.explainedFractionFast)},
                               {"named", rd.named},
                               {"reason", rd.reason}});
        json rejected = json::array();
        for (const auto& x : rd.rejected) {
            rejected.push_back({{"cause", x.cause}, {"code", x.code}, {"reason", x.reason}});
        }
        j["rounds"].back()["rejected"] = rejected;
    }
    j["bounds"] = json::array();
    for (const auto& b : r.bounds) {
        j["bounds"].push_back({{"cause", b.cause},
                               {"parameter", std::string(properties::info(b.parameter).symbol)},
                               {"unit", std::string(properties::info(b.parameter).unit)},
                               {"estimate", num(b.estimate)},
                               {"ci95", {num(b.ci95Low), num(b.ci95High)}}});
    }
    j["unexplained"] = json::array();
    for (const auto& s : r.unexplained) {
        json e = {{"signature", s.type}, {"output", s.output}, {"strength", num(s.strength)}};
        if (s.type == "periodic") {
            e["period_s"] = num(s.periodS);
        } else if (s.type == "lagged_input") {
            e["column"] = s.column;
            e["lag_s"] = num(s.lagS);
        } else if (s.type == "batch_shift") {
            e["batches"] = s.batches;
        } else if (s.type == "dynamics") {
            e["lag_s"] = num(s.lagS);
        }
        j["unexplained"].push_back(e);
    }
    if (hasHybrid) {
        j["hybrid"] = {{"model", "pgrl_cc, one step ahead, retrained on each physics model"},
                       {"mae_moisture_before", num(hybridMaeXBefore)},
                       {"mae_moisture_after", num(hybridMaeXAfter)},
                       {"mae_temperature_before", num(hybridMaeTBefore)},
                       {"mae_temperature_after", num(hybridMaeTAfter)},
                       {"model_kept", keptStartingModel ? "starting" : "extended"}};
        if (std::isfinite(references.persistenceMoisture)) {
            const auto& ref = references;
            j["hybrid"]["references"] = {{evaluation::kPersistenceKey,
                                          {{"mae_moisture", num(ref.persistenceMoisture)},
                                           {"mae_temperature", num(ref.persistenceTemperature)}}},
                                         {evaluation::kPbmResidualHoldKey,
                                          {{"mae_moisture_before", num(ref.pbmHoldMoistureBefore)},
                                           {"mae_moisture_after", num(ref.pbmHoldMoistureAfter)},
                                           {"mae_temperature_before", num(ref.pbmHoldTemperatureBefore)},
                                           {"mae_temperature_after", num(ref.pbmHoldTemperatureAfter)}}}};
            // Whether the model offered for forecasting earns its place, per output.
            const double maeX = keptStartingModel ? hybridMaeXBefore : hybridMaeXAfter;
            const double maeT = keptStartingModel ? hybridMaeTBefore : hybridMaeTAfter;
            j["hybrid"]["beats_references"] = {
                {"moisture", maeX < ref.bestMoisture(keptStartingModel)},
                {"temperature", maeT < ref.bestTemperature(keptStartingModel)}};
        }
    }
    const auto residualsJson = [&](const std::vector<discovery::OutputResidual>& rs) {
        json a = json::array();
        for (const auto& o : rs) {
            json e = {{"output", o.output},
                      {"unit", o.unit},
                      {"rows", o.rows},
                      {"bias", num(o.bias)},
                      {"bias_se", num(o.biasSe)},
                      {"trend_per_hour", num(o.trendPerHour)},
                      {"trend_se", num(o.trendSe)},
                      {"ljung_box_p", num(o.ljungBoxP)},
                      {"peak_period_s", num(o.peakPeriodS)},
                      {"peak_power_ratio", num(o.peakPowerRatio)}};
            e["series_every_60_s"] = {
                {"batch", o.seriesBatch}, {"time_s", o.seriesTimeS}, {"value", o.seriesValue}};
            for (const auto& b : o.perBatch) {
                e["per_batch"].push_back({{"batch", b.batch}, {"mean", num(b.mean)}, {"se", num(b.se)}});
            }
            for (const auto& c : o.correlates) {
                e["correlates"].push_back({{"column", c.column},
                                           {"lag_s", c.lagS},
                                           {"ccf", num(c.ccf)},
                                           {"significant", c.significant}});
            }
            for (const auto& g : o.regions) {
                json m = json::array();
                for (double v : g.mean) {
                    m.push_back(num(v));
                }
                e["by_region"].push_back(
                    {{"column", g.column}, {"unit", g.unit}, {"bin_upper", g.binUpper}, {"mean", m}});
            }
            a.push_back(e);
        }
        return a;
    };
    j["residuals_before"] = residualsJson(r.residuals);
    j["residuals_after"] = residualsJson(r.residualsAfter);
    j["notes"] = r.notes;
    j["training_rows"] = r.trainingRows;
    j["held_out_rows"] = r.heldOutRows;
    j["elapsed_s"] = r.ending.elapsedSeconds;
    return j.dump(2) + "\n";
}

} // namespace drytwin::io
