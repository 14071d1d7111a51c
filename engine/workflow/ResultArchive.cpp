#include "workflow/ResultArchive.h"

#include "io/ModelFile.h"

#include <complex>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

// The structs are dumped field by field with nlohmann's macros (one line per struct, the library's
// own reader and writer) rather than by a hand-written walker: a field added to a struct and to its
// line here round-trips, a field missing from an older archive takes its default (_WITH_DEFAULT).
// Enums are written as their integer values: the archive is read only by this program.

namespace nlohmann {

/// std::optional as {"has": bool, "value": …}: a null is reserved for NaN (see parseLatestResults).
template <class T> struct adl_serializer<std::optional<T>> {
    static void to_json(json& j, const std::optional<T>& o) {
        j = json{{"has", o.has_value()}};
        if (o) {
            j["value"] = *o;
        }
    }
    static void from_json(const json& j, std::optional<T>& o) {
        if (j.is_object() && j.value("has", false) && j.contains("value")) {
            o = j.at("value").get<T>();
        } else {
            o.reset();
        }
    }
};

template <> struct adl_serializer<std::complex<double>> {
    static void to_json(json& j, const std::complex<double>& c) { j = json::array({c.real(), c.imag()}); }
    static void from_json(const json& j, std::complex<double>& c) {
        c = {j.at(0).get<double>(), j.at(1).get<double>()};
    }
};

} // namespace nlohmann

namespace drytwin {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Ending, termination, message, elapsedSeconds)

namespace properties {
void to_json(nlohmann::json& j, const ParameterSet& p) {
    j = nlohmann::json::array();
    for (std::size_t i = 0; i < kParamCount; ++i) {
        j.push_back(p.data()[i]);
    }
}
void from_json(const nlohmann::json& j, ParameterSet& p) {
    // An archive of a version with fewer parameters keeps this version's defaults for the rest.
    for (std::size_t i = 0; i < kParamCount && i < j.size(); ++i) {
        p.data()[i] = j.at(i).get<double>();
    }
}
} // namespace properties

namespace calibration {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(IterationRecord, evaluation, phase, values, loss, bestLoss,
                                                failed)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Estimate, param, value, standardError, standardErrorFisher,
                                                ci95Low, ci95High, atBound)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Fit, loss, maeXOutPct, maeTOutC)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(CalibrationResult, parameters, estimates, before, after,
                                                history, evaluations, failedEvaluations, rowsUsed, algorithm,
                                                intervalMethod, elapsedSeconds, ending)
} // namespace calibration

namespace residual {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(StabilityComparison, lossUnconstrained, lossEigenvaluePull,
                                                lossConstrained, radiusUnconstrained, radiusEigenvaluePull,
                                                radiusConstrained, admmIterations, outerIterations)
} // namespace residual

namespace evaluation {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(OutputMetrics, mae, r2, ljungBoxP)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ModelMetrics, name, moisture, temperature, moistureMultiStep,
                                                temperatureMultiStep, moistureResidual, temperatureResidual,
                                                skillMoisture, skillTemperature, skillMoistureMultiStep,
                                                skillTemperatureMultiStep, moistureByHorizon,
                                                temperatureByHorizon, skillMoistureByHorizon,
                                                skillTemperatureByHorizon, hasStability, spectralRadiusBefore,
                                                spectralRadiusAfter, alpha, certificateMaxEig, choleskyPasses,
                                                pConditionNumber, stabilityComparison)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(EvaluationResult, split, testRows, horizonSteps,
                                                multiStepHorizon, models, horizons, freeRun, elapsedSeconds,
                                                ending)
} // namespace evaluation

namespace hybrid {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ModelResidualDiagnostics, name, acf, hasPsd, psdFrequencyHz,
                                                psdDensity, lowFrequencyShareBelow0p01Hz)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(EigenSpectrum, eigenvalues, contractionRatePerStep,
                                                spectralRadius)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ResidualDiagnostics, models, hasPgrlCcEigenvalues,
                                                pgrlCcBefore, pgrlCcAfter)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(AblationRow, variant, description, maeMoisture, r2Moisture,
                                                maeTemperature, r2Temperature, ljungBoxPMoisture,
                                                maeMoistureMultiStep, regimeMaeMoisture, regimeR2Moisture,
                                                regimeMaeTemperature, recalibrated, hHdt, kHdt)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(AblationResult, rows, multiStepHorizon, regimeSplit, ending)
} // namespace hybrid

namespace monitoring {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Contribution, column, speShare, t2Share,
                                                speReconstructionShare, t2ReconstructionShare)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(MonitorLimits, t2Theoretical, speTheoretical, t2Empirical,
                                                speEmpirical, t2Window, speWindow)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(WindowPoint, run, runIndex, timeS, t2, spe, t2Limit, speLimit,
                                                zT2, zSpe, cusumT2, cusumSpe, alarm)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(StatisticJudgement, changed, pValue, glr, glrThreshold,
                                                cusumThreshold, firstAlarmWindow, onsetWindow, onsetLowWindow,
                                                onsetHighWindow)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Detection, changed, pValue, statistic, falseAlarmRate,
                                                hasFirstAlarm, firstAlarmRun, firstAlarmTimeS,
                                                firstAlarmWindow, hasOnset, onsetRun, onsetS, onsetLowS,
                                                onsetHighS, onsetWindow, onsetLowWindow, onsetHighWindow,
                                                contributions, series, runStarts, levelNotJudged, t2, spe,
                                                limits, components, varianceExplainedActual, ending)
} // namespace monitoring

namespace discovery {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(OutputResidual::BatchBias, batch, mean, se)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(OutputResidual::Correlate, column, lagS, ccf, significant)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(OutputResidual::RegionBias, column, unit, binUpper, mean)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(OutputResidual, output, unit, rows, bias, biasSe, perBatch,
                                                withinBatchSd, meanBatchHours, trendPerHour, trendSe,
                                                ljungBoxP, correlates, regions, peakPeriodS, peakPowerRatio,
                                                seriesBatch, seriesTimeS, seriesValue)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Candidate, cause, parameter, score, pValue, pHolm,
                                                predictedReduction, linearEstimate, linearSe, fitted,
                                                fitLossBefore, fitLossAfter, pFromOwnScreen)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Gain, split, maeMoistureBefore, maeMoistureAfter,
                                                maeTemperatureBefore, maeTemperatureAfter, r2MoistureBefore,
                                                r2MoistureAfter, r2TemperatureBefore, r2TemperatureAfter,
                                                pValue, ljungBoxPMoistureBefore, ljungBoxPMoistureAfter,
                                                lowFrequencyShareBefore, lowFrequencyShareAfter, hasHybrid,
                                                hybridMaeMoistureBefore, hybridMaeMoistureAfter,
                                                hybridMaeTemperatureBefore, hybridMaeTemperatureAfter)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PartEstimate, part, value, se)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(LookAlike, cause, parameter, value, heldOutLossRatio, pValue,
                                                ruledOut, byChannels, moistureDelayS, temperatureDelayS,
                                                worseOutput, namedAfter, explainedAfter)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(
    Finding, cause, parameter, value, ci95Low, ci95High, explainedFraction, explainedFractionFast,
    fastPartCounted, judgedOnItsChannels, explainedFractionOnItsChannels, explainedFractionOnItsChannelsFast,
    onItsChannelsCounted, output, biasBefore, trendPerHourBefore, evidence, gain, perPart, consistent,
    transferChecked, transferReduction, hasOnset, onsetS, onsetLowS, onsetHighS, actsFromStartOf, group,
    lookAlikes, tellApart, restated, valueWhenNamed, ci95LowWhenNamed, ci95HighWhenNamed, hasReference,
    referenceValue, referenceCi95Low, referenceCi95High, responseJudged, responseScale)
// A result judged against a reference comes back with its detection and reference values, so that
// a reopened project shows the headline, the monitor chart and each finding's change as they were.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ChangeDetection::CauseTest, changed, pValue, cause,
                                                secondLook)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ChangeDetection, changed, falseAlarmRate, decidedBy,
                                                drytwinChanged, causeTest, namedCauses, drytwin, pca,
                                                drytwinColumns, pcaColumns)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Signature, type, output, periodS, column, lagS, batches,
                                                strength)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Round::Rejection, cause, code, reason)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Round, candidates, best, heldOutPValue, explainedFraction,
                                                explainedFractionFast, named, reason, rejected)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Bound, cause, parameter, estimate, ci95Low, ci95High)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(DiscoveryResult, verdict, residuals, residualsAfter, ranking,
                                                rounds, findings, unexplained, bounds, baseParameters,
                                                parameters, trainingRows, heldOutRows, notes, hasReference,
                                                referencePath, referenceBatches, referenceRows,
                                                batchesBeforeChange, batchesChangedFromStart, detection,
                                                ending)
} // namespace discovery

namespace control {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(InputChange, input, atS, durationS, to)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SetpointStep, atS, toPct)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(HiddenMechanism, mechanism, strength, atS)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Scenario, name, description, seed, lengthS, warmupS,
                                                controlIntervalS, setpointPct, bandPct, feedKgH, xInPct, tInC,
                                                tAmbC, rhPct, airSpeedMPerS, fluctuation, noiseScale, plant,
                                                sensors, unmeasuredDrift, setpointSteps, inputChanges,
                                                mechanisms)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ClosedLoopMetrics, iaePctS, effortK2, violationPct,
                                                solveMsMedian, solveMsMax, modelMsMedian, gainPctPerKMedian,
                                                decisions, fallbacks, lastFallbackReason)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ForecastCheck, horizonsS, maePct, origins)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PredictionSnapshot, atS, xOutPct)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ControllerRun, kind, ran, skippedReason, metrics, timeS,
                                                xOutMeasuredPct, xOutTruePct, setpointPct, hotAirSetpointC,
                                                hotAirC, predictions, forecastCheck, elapsedSeconds)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ClosedLoopResult, scenario, plantGainPctPerK, runs, ending)
} // namespace control

namespace workflow {

using nlohmann::json;

namespace {

constexpr const char* kFormat = "drytwin-results";
constexpr int kFormatVersion = 1;

/// nlohmann writes NaN and ±inf as null (JSON has neither); read back, every null is a NaN
/// (optionals never write null). An infinite value comes back as NaN: only the contraction rate of
/// an eigenvalue exactly 0 is infinite, and the panels show both as "–".
void nullsToNaN(json& j) {
    if (j.is_null()) {
        j = std::numeric_limits<double>::quiet_NaN();
    } else if (j.is_structured()) {
        for (auto& child : j) {
            nullsToNaN(child);
        }
    }
}

} // namespace

std::string latestResultsJson(const LatestResults& r) {
    json j;
    j["format"] = kFormat;
    j["format_version"] = kFormatVersion;
    if (r.calibrate) {
        j["calibrate"] = {{"calibration", r.calibrate->calibration},
                          {"start_parameters", r.calibrate->startParameters},
                          {"dropped_residual_models", r.calibrate->droppedResidualModels},
                          {"ending", r.calibrate->ending}};
    }
    if (r.evaluate) {
        j["evaluate"] = {{"evaluation", r.evaluate->evaluation},
                         {"diagnostics", r.evaluate->diagnostics},
                         {"ending", r.evaluate->ending}};
    }
    if (r.ablation) {
        j["ablation"] = *r.ablation;
    }
    if (r.discover) {
        const auto& d = *r.discover;
        j["discover"] = {
            {"discovery", d.discovery},
            // The model file's own format, so the extended model's learnt parts come back too.
            {"extended_model", json::parse(io::formatModelFile(d.extendedModel))},
            {"has_hybrid", d.hasHybrid},
            {"hybrid_mae_moisture", {d.hybridMaeMoistureBefore, d.hybridMaeMoistureAfter}},
            {"hybrid_mae_temperature", {d.hybridMaeTemperatureBefore, d.hybridMaeTemperatureAfter}},
            {"kept_starting_model", d.keptStartingModel},
            {"hybrid_references",
             {{"persistence", {d.references.persistenceMoisture, d.references.persistenceTemperature}},
              {"pbm_hold_moisture", {d.references.pbmHoldMoistureBefore, d.references.pbmHoldMoistureAfter}},
              {"pbm_hold_temperature",
               {d.references.pbmHoldTemperatureBefore, d.references.pbmHoldTemperatureAfter}}}},
            {"ending", d.ending}};
    }
    if (r.mpc) {
        j["mpc"] = {{"closed_loop", r.mpc->closedLoop}, {"ending", r.mpc->ending}};
    }
    return j.dump(1);
}

Expected<LatestResults> parseLatestResults(const std::string& text, const std::string& place) {
    const auto bad = [&](const std::string& why) {
        return Error{ErrorKind::BadInput, place, why, ErrorCode::Unspecified, {}};
    };
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return bad("not valid JSON at byte " + std::to_string(e.byte) +
                   " (the file is damaged or cut short)");
    } catch (const json::exception& e) {
        // A number no double holds (1e400) is the parser's out_of_range, not a parse_error: it
        // ended the program (a trainer's session file closed the whole window).
        return bad("not valid JSON (" + std::string(e.what()) + "; the file is damaged)");
    }
    if (!j.is_object()) {
        return bad("not a DryTwin results file (not a JSON object)");
    }
    if (j.value("format", std::string()) != kFormat) {
        return bad("not a DryTwin results file");
    }
    LatestResults r;
    std::string section;
    try {
        if (j.contains("calibrate")) {
            section = "calibrate";
            json& c = j["calibrate"];
            nullsToNaN(c);
            CalibrateResult out;
            c.at("calibration").get_to(out.calibration);
            c.at("start_parameters").get_to(out.startParameters);
            out.droppedResidualModels = c.value("dropped_residual_models", false);
            c.at("ending").get_to(out.ending);
            r.calibrate = std::move(out);
        }
        if (j.contains("evaluate")) {
            section = "evaluate";
            json& e = j["evaluate"];
            nullsToNaN(e);
            EvaluateResult out;
            e.at("evaluation").get_to(out.evaluation);
            e.at("diagnostics").get_to(out.diagnostics);
            e.at("ending").get_to(out.ending);
            r.evaluate = std::move(out);
        }
        if (j.contains("ablation")) {
            section = "ablation";
            nullsToNaN(j["ablation"]);
            r.ablation = j["ablation"].get<hybrid::AblationResult>();
        }
        if (j.contains("discover")) {
            section = "discover";
            json& d = j["discover"];
            auto model =
                io::parseModelFile(d.at("extended_model").dump(), place + " (discover: extended model)");
            if (!model) {
                return model.error();
            }
            d.erase("extended_model"); // the model file's own reader took it as it is
            nullsToNaN(d);
            DiscoverResult out;
            d.at("discovery").get_to(out.discovery);
            out.extendedModel = std::move(*model);
            out.hasHybrid = d.value("has_hybrid", false);
            // Two numbers under one key (before and after, or moisture and temperature); a key
            // missing (an older archive) leaves them as they are (NaN for the references).
            const auto pair = [](const json& from, const char* key, double& first, double& second) {
                if (from.contains(key) && from[key].is_array() && from[key].size() == 2) {
                    first = from[key][0].get<double>();
                    second = from[key][1].get<double>();
                }
            };
            pair(d, "hybrid_mae_moisture", out.hybridMaeMoistureBefore, out.hybridMaeMoistureAfter);
            pair(d, "hybrid_mae_temperature", out.hybridMaeTemperatureBefore, out.hybridMaeTemperatureAfter);
            out.keptStartingModel = d.value("kept_starting_model", false);
            if (d.contains("hybrid_references") && d["hybrid_references"].is_object()) {
                const json& refs = d["hybrid_references"];
                auto& ref = out.references;
                pair(refs, "persistence", ref.persistenceMoisture, ref.persistenceTemperature);
                pair(refs, "pbm_hold_moisture", ref.pbmHoldMoistureBefore, ref.pbmHoldMoistureAfter);
                pair(refs, "pbm_hold_temperature", ref.pbmHoldTemperatureBefore, ref.pbmHoldTemperatureAfter);
            }
            d.at("ending").get_to(out.ending);
            r.discover = std::move(out);
        }
        if (j.contains("mpc")) {
            section = "mpc";
            json& m = j["mpc"];
            nullsToNaN(m);
            MpcResult out;
            m.at("closed_loop").get_to(out.closedLoop);
            m.at("ending").get_to(out.ending);
            r.mpc = std::move(out);
        }
    } catch (const json::exception& e) {
        return bad("section \"" + section + "\" cannot be read (" + e.what() + ")");
    }
    return r;
}

} // namespace workflow

} // namespace drytwin
