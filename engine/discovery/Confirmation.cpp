// Question 3, its confirmatory half: a candidate that fits the training part is named only when
// it predicts clearly better on the held-out part and is specific; and where a meter lag and a
// transport-time error compete, the outlet channels tell them apart; its look-alikes; and the end
// of selection (the findings restated at the extended model, bounds, what is left).
#include "common/TextList.h"
#include "discovery/DiscoveryInternal.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace drytwin::discovery::detail {

std::optional<std::array<bool, 4>> outletChannelsActedOn(Param p) {
    switch (p) {
    case Param::tau_meter:
        return std::array<bool, 4>{true, false, false, false};
    case Param::dtau_conv:
        return std::array<bool, 4>{true, true, false, false};
    default:
        return std::nullopt;
    }
}

std::string outletChannelsName(const std::array<bool, 4>& channels) {
    return channels[kTOut] ? "the outlet channels'" : "the outlet moisture's";
}

Expected<Confirmation> confirmCandidate(const ConfirmationInput& in) {
    const auto& options = in.pr.options;
    Confirmation out;
    auto afterHeld = heldOut(in.pr, in.fitParameters);
    if (!afterHeld) {
        return afterHeld.error();
    }
    const Gain gain = gainOf(in.currentHeld, *afterHeld);
    const auto [explained, explainedFast] = explainedShares(in.currentHeld, *afterHeld, options);
    out.pValue = gain.pValue;
    out.explained = explained;
    out.explainedFast = explainedFast;
    const double ofChange = shareOfChange(in.pr, in.currentHeld, *afterHeld);
    // A cause downstream of the tube's outlet moves the outlet channels alone (the meter's lag
    // X_out, the transport time X_out and T_out); there its share is not diluted by the error of
    // channels it cannot touch (DiscoveryOptions::shareOnTheChannelsItActsOn).
    const auto itsChannels = outletChannelsActedOn(in.cand.parameter);
    const bool judgedOnItsChannels = options.shareOnTheChannelsItActsOn && itsChannels.has_value();
    double onChannels = 0, onChannelsFast = 0;
    if (judgedOnItsChannels) {
        std::tie(onChannels, onChannelsFast) =
            explainedSharesOnChannels(in.currentHeld, *afterHeld, *itsChannels, options);
    }
    if (!(gain.pValue < in.level && std::max({explained, explainedFast, ofChange, onChannels,
                                              onChannelsFast}) >= options.minExplainedFraction)) {
        // It fits the training part but does not predict clearly better: not a cause.
        out.code = "no_held_out_gain";
        if (gain.pValue >= in.level) {
            out.why = format("held-out gain not significant (p = %.2g, needs < %.2g)", gain.pValue, in.level);
        } else {
            std::vector<std::string> shares{format("%.0f %% of the held-out error left", 100 * explained),
                                            format("%.0f %% of its fast part", 100 * explainedFast)};
            if (ofChange > 0) {
                shares.push_back(format("%.0f %% of its change against the reference", 100 * ofChange));
            }
            if (judgedOnItsChannels) {
                shares.push_back(format("%.0f %% of %s error alone", 100 * onChannels,
                                        outletChannelsName(*itsChannels).c_str()));
                shares.push_back(format("%.0f %% of that error's fast part", 100 * onChannelsFast));
            }
            const std::string last = shares.back();
            shares.pop_back();
            out.why = "removes only " + commaList(shares) + " and " + last +
                      format(" (needs %.0f %% of %s)", 100 * options.minExplainedFraction,
                             shares.size() == 1 ? "either" : "one");
        }
        out.held = std::move(*afterHeld);
        return out;
    }
    // Specificity: it predicts better; is it this cause?
    std::vector<Param> sensAt = in.nuisance;
    sensAt.push_back(in.cand.parameter);
    auto at = stackAt(in.pr, in.fitParameters, sensAt);
    if (!at) {
        return at.error();
    }
    const int atCol = static_cast<int>(in.nuisance.size());
    const double value = in.fitParameters[in.cand.parameter];
    auto judged = judgeSpecificity({in.pr, in.cand.parameter, value, in.meanBatchHours, in.currentHeld,
                                    *afterHeld, in.fitParameters, *at, in.roundStack, in.nuisanceCols, atCol,
                                    in.currentSims, in.afterOtherCauses});
    if (!judged) {
        return judged.error();
    }
    if (!judged->code.empty()) {
        out.code = judged->code;
        out.why = judged->why;
        out.held = std::move(*afterHeld);
        return out;
    }
    // Named. Its interval: the sandwich (HAC) standard error at the fit.
    double se = in.cand.linearSe;
    if (const auto sc = scoreTest(*at, in.nuisanceCols, atCol); sc.se > 0) {
        se = sc.se;
    }
    Finding f;
    f.cause = in.cand.cause;
    f.parameter = in.cand.parameter;
    f.value = value;
    f.ci95Low = value - 1.96 * se;
    f.ci95High = value + 1.96 * se;
    f.explainedFraction = explained;
    f.explainedFractionFast = explainedFast;
    f.fastPartCounted = explained < options.minExplainedFraction;
    if (judgedOnItsChannels) {
        f.judgedOnItsChannels = true;
        f.explainedFractionOnItsChannels = onChannels;
        f.explainedFractionOnItsChannelsFast = onChannelsFast;
        f.onItsChannelsCounted =
            std::max({explained, explainedFast, ofChange}) < options.minExplainedFraction;
    }
    f.gain = gain;
    f.perPart = judged->consistency.parts;
    f.actsOn = judged->actsOn;
    f.responseJudged = judged->responseJudged;
    f.responseScale = judged->responseScale;
    f.consistent = judged->consistency.consistent;
    f.transferChecked = judged->transfer.checked;
    f.transferReduction = judged->transfer.reduction;
    f.hasOnset = in.onset.found;
    f.onsetS = in.onset.s;
    f.onsetLowS = in.onset.lowS;
    f.onsetHighS = in.onset.highS;
    if (f.hasOnset) {
        for (std::size_t b = 0; b < in.pr.inputs.size(); ++b) {
            if (in.pr.inputs[b].mechanismsFromStart) {
                f.actsFromStartOf.push_back((*in.pr.batches)[b].id);
            }
        }
    }
    out.finding = std::move(f);
    out.held = std::move(*afterHeld);
    return out;
}

ChannelTiming channelTiming(const Problem& pr, double currentDelayS, double moistureDelayS,
                            double temperatureDelayS, const HeldOut& atMoistureDelay,
                            const HeldOut& atTemperatureDelay) {
    ChannelTiming out;
    out.moistureDelayS = moistureDelayS;
    out.temperatureDelayS = temperatureDelayS;
    // Apart by more than a transport time's own floor, and the later channel predicted better on
    // the held-out part at its own delay than at the other's.
    const double apart = std::max(2 * pr.samplingStepS, pr.options.floors.transportTimeS);
    if (moistureDelayS - temperatureDelayS >= apart) {
        out.pValue = channelChanges(atMoistureDelay, atTemperatureDelay)[kXOut].pWorse;
        out.pattern = out.pValue < pr.options.gainAlpha ? ChannelTiming::Pattern::MoistureLater
                                                        : ChannelTiming::Pattern::Undecided;
    } else if (temperatureDelayS - moistureDelayS >= apart) {
        out.pValue = channelChanges(atTemperatureDelay, atMoistureDelay)[kTOut].pWorse;
        out.pattern = out.pValue < pr.options.gainAlpha ? ChannelTiming::Pattern::TemperatureLater
                                                        : ChannelTiming::Pattern::Undecided;
    }
    // Does the moisture ask for a delay at all? Both causes delay it (a meter lag nothing else);
    // the distributed line's outlet temperature answers 15-20 s later than the model with nothing
    // hidden, and that alone is neither cause. The size of the moisture's own delay decides, not
    // a held-out test, which turned down a real 15 s meter lag (seed 102: 13 s asked) while the
    // nulls ask for 1-5 s (docs/discovery-study.md).
    out.moistureFloorS = std::max(apart, pr.options.floors.moistureResponseS);
    const bool moistureAsks = moistureDelayS - currentDelayS >= out.moistureFloorS;
    if (!moistureAsks && temperatureDelayS - moistureDelayS >= apart) {
        out.pattern = ChannelTiming::Pattern::TemperatureOnly;
        out.moistureWorseAtTemperatureDelayP =
            channelChanges(atMoistureDelay, atTemperatureDelay)[kXOut].pWorse;
    }
    return out;
}

bool transportSparedByMoisture(const Problem& pr, const ChannelTiming& timing) {
    // Against a reference the line's own thermal answer is part of the structure learnt there
    // (the reference's channels then ask for 0-1 s): a later temperature is a change, and it is the
    // line's dynamics only where the moisture contradicts the temperature's delay (held-out worse
    // there). A transport time 30 s longer on a one-hour training recording under the PI loop
    // delayed the temperature 18 s and the moisture 3 s, whose error was no worse at 18 s (p 0.64-
    // 0.74); on seed 322 of the study the temperature answered 10-12 s later and the moisture's
    // error was clearly worse there (p < 0.001). A meter lag is never spared: it delays the
    // moisture alone, which here asks for no delay (a 73 s lag was named where the moisture asked
    // for -5 s, lumped seed 102).
    return pr.reference && timing.pattern == ChannelTiming::Pattern::TemperatureOnly &&
           timing.moistureWorseAtTemperatureDelayP >= pr.options.gainAlpha;
}

std::string lineDynamicsReason(const ChannelTiming& timing) {
    return format("the outlet temperature answers %.3g s later than the model, the moisture only %.3g s "
                  "(within a meter's normal response of %.3g s): the line's thermal dynamics (product heat "
                  "capacity, pyrometer), neither a transport time (it delays both) nor a meter lag (the "
                  "moisture alone)",
                  timing.temperatureDelayS, timing.moistureDelayS, timing.moistureFloorS);
}

std::string moistureLaterReason(const ChannelTiming& timing) {
    return format("the moisture answers %.3g s later than the model and the outlet temperature %.3g s "
                  "(p = %.2g): a transport time delays both alike",
                  timing.moistureDelayS, timing.temperatureDelayS, timing.pValue);
}

Expected<ChannelTiming> timeOutletChannels(const Problem& pr, const ParameterSet& current, double startDelayS,
                                           const DelayFit& fitDelay) {
    double delay[2] = {0, 0};
    std::optional<HeldOut> held[2];
    for (int c = 0; c < 2; ++c) {
        calibration::LossWeights alone{0, 0, 0, 0}; // the one channel at its usual weight
        if (c == 0) {
            alone.xOut = pr.options.weights.xOut;
        } else {
            alone.tOut = pr.options.weights.tOut;
        }
        ParameterSet start = current;
        start[Param::dtau_conv] = startDelayS;
        auto one = fitDelay(start, alone);
        if (!one) {
            return one.error();
        }
        delay[c] = one->parameters[Param::dtau_conv];
        auto h = heldOut(pr, one->parameters);
        if (!h) {
            return h.error();
        }
        held[c] = std::move(*h);
    }
    return channelTiming(pr, current[Param::dtau_conv], delay[0], delay[1], *held[0], *held[1]);
}

Status addLookAlikes(const Problem& pr, Finding& f, const std::vector<Param>& remaining,
                     const PlaceFit& fitInPlace, const HeldOut& namedHeld,
                     const std::optional<ChannelTiming>& timing) {
    const LookAlikeGroup* group = lookAlikeGroupOf(f.parameter);
    if (!group) {
        return {};
    }
    for (Param other : group->members) {
        if (other == f.parameter || std::find(remaining.begin(), remaining.end(), other) == remaining.end()) {
            continue; // itself, or already part of the model
        }
        auto fitted = fitInPlace(other);
        if (!fitted) {
            return fitted.error();
        }
        if (!*fitted) {
            continue; // its fit failed: no evidence either way
        }
        auto l = compareLookAlike(pr, other, **fitted, f.actsOn, namedHeld, pr.options);
        if (!l) {
            return l.error();
        }
        if (timing) {
            l->byChannels = true;
            l->moistureDelayS = timing->moistureDelayS;
            l->temperatureDelayS = timing->temperatureDelayS;
            l->pValue = timing->pValue;
            // The moisture later: not a transport time. Otherwise either: a group.
            l->ruledOut = timing->pattern == ChannelTiming::Pattern::MoistureLater;
        }
        if (!l->ruledOut) {
            f.group = group->name;
            f.tellApart = group->tellApart;
        }
        f.lookAlikes.push_back(*l);
    }
    return {};
}

namespace {

/// Every finding at the extended model's value, its interval from the score of the final fit
/// (the others held as nuisance); later rounds refit the causes named before.
void restateAtExtendedModel(const Problem& pr, const ParameterSet& extended,
                            const std::vector<Param>& nuisance, std::vector<Finding>& findings) {
    auto at = stackAt(pr, extended, nuisance);
    if (!at) {
        return; // the intervals of the rounds stand
    }
    for (auto& f : findings) {
        const auto col =
            static_cast<int>(std::find(nuisance.begin(), nuisance.end(), f.parameter) - nuisance.begin());
        const auto sc = scoreTest(*at, columnsBut(static_cast<int>(nuisance.size()), col), col);
        if (!f.restated) {
            f.restated = true;
            f.valueWhenNamed = f.value;
            f.ci95LowWhenNamed = f.ci95Low;
            f.ci95HighWhenNamed = f.ci95High;
        }
        f.value = extended[f.parameter];
        for (auto& l : f.lookAlikes) {
            if (l.namedAfter) { // folded into this finding: its joint value
                l.value = extended[l.parameter];
            }
        }
        const double se = sc.se > 0 ? sc.se : 0.5 * (f.ci95High - f.ci95Low) / 1.96;
        f.ci95Low = f.value - 1.96 * se;
        f.ci95High = f.value + 1.96 * se;
    }
}

/// What the data allow for each cause tested in the last round and not named.
std::vector<Bound> boundsOf(const std::vector<Candidate>& tested) {
    std::vector<Bound> out;
    for (const auto& c : tested) {
        const auto& info = properties::info(c.parameter);
        Bound b;
        b.cause = c.cause;
        b.parameter = c.parameter;
        // Held within the parameter's range like its interval: an estimate of -0.48 beside an
        // interval [0, 0] (a re-absorption rate below 0, which no line has) read as a contradiction;
        // at the bound it says the data point away from the cause.
        b.estimate = std::clamp(c.linearEstimate, info.lower, info.upper);
        b.ci95Low = std::clamp(c.linearEstimate - 1.96 * c.linearSe, info.lower, info.upper);
        b.ci95High = std::clamp(c.linearEstimate + 1.96 * c.linearSe, info.lower, info.upper);
        out.push_back(b);
    }
    return out;
}

} // namespace

void conclude(const Problem& pr, const ParameterSet& extended, const std::vector<Param>& nuisance,
              const std::vector<physics::SimulationResult>& sims, std::vector<OutputResidual> residuals,
              DiscoveryResult& result) {
    // Later rounds refit the causes named before: report every cause at the extended model's
    // value, with its interval from the score of the final fit (the others held as nuisance).
    if (nuisance.size() > 1) {
        restateAtExtendedModel(pr, extended, nuisance, result.findings);
    }
    // Bounds for what was tested last and not named: that round's score tests ran at the final
    // model. (When selection ended on a named cause, no round tested the rest at that model.)
    if (!result.rounds.empty() && !result.rounds.back().named) {
        result.bounds = boundsOf(result.rounds.back().candidates);
    }
    // The residual of the extended model was analysed when its last cause was added (or is the
    // starting model's, when none was): no further simulation.
    result.residualsAfter = std::move(residuals);
    result.unexplained = signatures(result.residualsAfter);
    for (int c : {kXOut, kTOut}) { // the line's own dynamics, where no cause took them
        if (const auto lag = dynamicsSignature(pr, sims, c); lag) {
            result.unexplained.push_back(*lag);
        }
    }
    result.parameters = extended;
    result.verdict = !result.findings.empty()      ? "cause_found"
                     : !result.unexplained.empty() ? "unexplained_structure"
                                                   : "no_structural_cause";
}

} // namespace drytwin::discovery::detail
