// discovery.json (CONTRACT.md §3): the findings with their evidence, the detection against a
// reference period with its window series, and the hybrid's gain on the extended model.
#include "io/ResultFiles.h"

#include "common/Units.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace drytwin::io {

using nlohmann::json;

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
