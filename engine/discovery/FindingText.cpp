// Question 4's wording: the findings' sentences, in the engine's English (the GUI words them
// in its own language from the numbers).
#include "common/TextList.h"
#include "discovery/DiscoveryInternal.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

namespace drytwin::discovery::detail {

std::string format(const char* fmt, ...) {
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return buf;
}

/// What a colleague should look for on the residual plots for each cause.
const char* lookFor(Param p) {
    switch (p) {
    case Param::theta_wall:
        return "the outlet-temperature error grows with the hot-air excess over ambient "
               "(bias by T_amb and T_hot)";
    case Param::theta_gas:
        return "the errors grow with feed rate and inlet moisture (bias by feed rate and by inlet moisture)";
    case Param::theta_foul:
        return "the error drifts over each batch, or over the recording from the fouling's onset, and "
               "starts afresh with each new batch";
    case Param::tau_meter:
        return "the outlet-moisture error follows the rate of change of the simulated outlet moisture, "
               "and the tube-outlet error does not";
    case Param::X_meter_offset:
        return "a steady outlet-moisture bias that the tube-outlet moisture does not share";
    case Param::dtau_conv:
        return "the outlet error correlates with tube-outlet changes at a shifted lag";
    case Param::theta_fall:
        return "the tube-outlet and outlet moisture are wetter than simulated, "
               "most where the tube dries furthest";
    case Param::theta_reabs:
        return "the outlet-moisture error grows with ambient humidity while the tube-outlet error does not";
    case Param::X_in_offset:
        return "a steady bias of the tube-outlet and outlet moisture alike, larger where the tube dries less";
    case Param::tau_hot_sensor:
        return "after each hot-air setpoint step the outlet temperature and moisture move before the "
               "simulation, which follows the slow reading";
    case Param::phi_X_in_scatter:
        return "the inlet-moisture reading scatters from second to second while the outlet does not follow "
               "it, and the simulated outlet does";
    default:
        return "";
    }
}

const LookAlikeGroup* lookAlikeGroupOf(Param p) {
    static const std::vector<LookAlikeGroup> groups{
        {"outlet_response_time",
         {Param::tau_meter, Param::dtau_conv},
         "a step of the hot-air setpoint logged at 1 s: a transport-time error delays the outlet "
         "temperature's response as much as the moisture's, a meter lag delays the moisture reading alone; "
         "or grab samples timed against the meter"},
        {"moisture_offset",
         {Param::X_meter_offset, Param::X_in_offset},
         "oven-dry laboratory samples at the outlet against the meter and at the inlet against the gauge; "
         "or a tube-outlet moisture channel (X_hdt), which an inlet-gauge offset moves and an outlet-meter "
         "offset does not"},
        {"gas_temperature",
         {Param::theta_wall, Param::theta_gas},
         "a gas-temperature reading at the tube's outlet end at two feed rates: wall loss does not change "
         "with the feed, gas-phase cooling grows with it"},
    };
    for (const auto& g : groups) {
        if (std::find(g.members.begin(), g.members.end(), p) != g.members.end()) {
            return &g;
        }
    }
    return nullptr;
}

void describeOutput(Finding& f, const std::vector<OutputResidual>& before) {
    const auto& gain = f.gain;
    const bool moistureHelped = gain.maeMoistureBefore > 0 &&
                                (gain.maeMoistureBefore - gain.maeMoistureAfter) / gain.maeMoistureBefore >=
                                    (gain.maeTemperatureBefore - gain.maeTemperatureAfter) /
                                        std::max(1e-12, gain.maeTemperatureBefore);
    f.output = moistureHelped ? "X_out" : "T_out";
    for (const auto& o : before) {
        if (o.output == f.output) {
            f.biasBefore = o.bias;
            f.trendPerHourBefore = o.trendPerHour;
        }
    }
}

std::string findingEvidence(const Finding& f, const DiscoveryOptions& options) {
    const auto& info = properties::info(f.parameter);
    const auto& gain = f.gain;
    const bool moisture = f.output == "X_out";
    // The fast part is quoted when it is what made the cause count.
    const std::string share =
        f.onItsChannelsCounted
            ? format("it removes %.0f %% of the held-out squared error, and of %s %.0f %% (%.0f %% of its "
                     "fast part)",
                     100 * f.explainedFraction,
                     f.parameter == properties::Param::tau_meter
                         ? "the outlet moisture's, the only measured output it acts on,"
                         : "the outlet moisture's and temperature's, the only measured outputs it acts on,",
                     100 * f.explainedFractionOnItsChannels, 100 * f.explainedFractionOnItsChannelsFast)
        : !f.fastPartCounted
            ? format("it removes %.0f %% of the held-out squared error", 100 * f.explainedFraction)
            : format("it removes %.0f %% of the held-out squared error and %.0f %% of its fast part (the "
                     "error about its %.0f-minute average, where slow drift does not hide it)",
                     100 * f.explainedFraction, 100 * f.explainedFractionFast, options.fastBandWindowS / 60);
    std::string text = format(
        "%s error before: bias %+.3g %s, within-batch trend %+.3g %s/h. With %s (%s = %.4g%s, 95 %% CI "
        "[%.3g, %.3g]) and %s, the held-out MAE of X_out goes from %.3f to %.3f %% "
        "wb and of T_out from %.2f to %.2f °C (Diebold-Mariano p = %.2g); %s. Check on the plots: %s.",
        moisture ? "Outlet-moisture" : "Outlet-temperature", f.biasBefore, moisture ? "% wb" : "°C",
        f.trendPerHourBefore, moisture ? "% wb" : "°C", f.cause.c_str(), std::string(info.symbol).c_str(),
        f.value, properties::spacedUnit(f.parameter).c_str(), f.ci95Low, f.ci95High,
        f.hasReference ? "h_HDT, k_HDT as commissioned on the reference period" : "h_HDT, k_HDT refitted",
        gain.maeMoistureBefore, gain.maeMoistureAfter, gain.maeTemperatureBefore, gain.maeTemperatureAfter,
        gain.pValue, share.c_str(), lookFor(f.parameter));
    if (f.hasReference) {
        text += format(" On the reference period it was %.4g%s (a period's normal range %.3g to %.3g): it "
                       "changed.",
                       f.referenceValue, properties::spacedUnit(f.parameter).c_str(), f.referenceCi95Low,
                       f.referenceCi95High);
    }
    for (int c : outputsMovedOtherThanModelled(f)) {
        const double scale = f.responseScale[static_cast<std::size_t>(c)];
        text +=
            scale < 0
                ? format(" %s moved against this cause's effect (%.2g times what its model form says), by "
                         "less than that output's noise can tell from none: it counts neither for the "
                         "cause nor against it.",
                         kChannelName[c], scale)
                : format(" %s moved %.2g times as much as this cause's model form says: the direction "
                         "agrees, the size is the model's to answer.",
                         kChannelName[c], scale);
    }
    if (!f.perPart.empty()) {
        // Each part's one-step estimate held within the parameter's range: a part that hardly
        // informs it can step far outside (a meter lag of -1,130 ± 650 s in one batch), which is
        // its uncertainty, not a value the line can have.
        const auto& info = properties::info(f.parameter);
        double lo = std::clamp(f.perPart.front().value, info.lower, info.upper), hi = lo;
        bool held = false;
        for (const auto& e : f.perPart) {
            const double v = std::clamp(e.value, info.lower, info.upper);
            held = held || v != e.value;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        text += format(" Fitted part by part (%zu parts) it lies between %.3g and %.3g%s%s.",
                       f.perPart.size(), lo, hi, properties::spacedUnit(f.parameter).c_str(),
                       held ? " (a part whose estimate left the parameter's range held at its bound)" : "");
    }
    if (f.transferChecked) {
        text +=
            format(" Fitted on the cooler half of the data it removes %.0f %% of the warmer half's error.",
                   100 * f.transferReduction);
    }
    if (f.hasOnset) {
        text += format(" It starts %.0f min into the batch (95 %% interval %.0f-%.0f min).", f.onsetS / 60,
                       f.onsetLowS / 60, f.onsetHighS / 60);
        if (!f.actsFromStartOf.empty()) {
            text += " It goes on from the start of " + commaList(f.actsFromStartOf) + ".";
        }
    }
    for (const auto& l : f.lookAlikes) {
        if (l.namedAfter) {
            text += format(" %s was named on top of it (a further %.0f %% of the held-out error): alone "
                           "it predicts worse (%.2g times the held-out error), but the change needs both "
                           "forms, so the data cannot say which of them it is.",
                           l.cause.c_str(), 100 * l.explainedAfter, l.heldOutLossRatio);
            continue;
        }
        if (l.byChannels) {
            // The outlet channels' timing told (or showed that it cannot tell).
            text +=
                l.ruledOut
                    ? format(" Not %s: the moisture answers %.3g s later than the model and the outlet "
                             "temperature %.3g s (each fitted alone, p = %.2g); a transport time delays "
                             "both alike.",
                             l.cause.c_str(), l.moistureDelayS, l.temperatureDelayS, l.pValue)
                    : format(" %s fits too: the moisture answers %.3g s later than the model and the outlet "
                             "temperature %.3g s (each fitted alone, p = %.2g); the channels' timing cannot "
                             "tell them apart (the temperature has dynamics of its own, or the difference is "
                             "within the noise).",
                             l.cause.c_str(), l.moistureDelayS, l.temperatureDelayS, l.pValue);
            continue;
        }
        text +=
            l.ruledOut
                ? format(" Not %s: fitted in its place it leaves %.3g times the held-out error (p = %.2g).",
                         l.cause.c_str(), l.heldOutLossRatio, l.pValue)
                : format(" %s fits these data about as well (held-out error %.3g times, p = %.2g): the "
                         "data cannot tell them apart.",
                         l.cause.c_str(), l.heldOutLossRatio, l.pValue);
    }
    if (!f.group.empty()) {
        text += " To tell them apart: " + f.tellApart + ".";
    }
    return text;
}

std::string inconsistencyReason(const Consistency& c, Param p, double pooled) {
    // The numbers a process engineer needs to judge it: the pooled value and each part's, with
    // its 95 % interval, in the parameter's unit.
    const std::string unit(properties::info(p).unit);
    std::string text = c.opposite
                           ? format("its estimate has the opposite sign in part of the data (pooled %.3g %s)",
                                    pooled, unit.c_str())
                           : format("its estimate strays from the pooled value (%.3g %s) in %d of %zu parts",
                                    pooled, unit.c_str(), c.strays, c.parts.size());
    if (!c.parts.empty()) {
        text += "; per part: " + describeParts(c.parts) + " " + unit;
    }
    return text;
}

} // namespace drytwin::discovery::detail

namespace drytwin::discovery {

std::vector<int> outputsMovedOtherThanModelled(const Finding& f) {
    // Where the line's response differs in size from the model form's: the size is the model's (a
    // lumped tube's) to answer. Its direction agreed, or the output moved the other way by less than
    // its noise can tell (a significant one would have turned the cause down: responseMismatch).
    std::vector<int> outputs;
    for (int c = 0; f.responseJudged && c < 4; ++c) {
        const double scale = f.responseScale[static_cast<std::size_t>(c)];
        if (f.actsOn[static_cast<std::size_t>(c)] && (scale < 2.0 / 3 || scale > 1.5)) {
            outputs.push_back(c);
        }
    }
    return outputs;
}

std::string describeParts(const std::vector<PartEstimate>& parts) {
    std::string text;
    for (const auto& e : parts) {
        text +=
            detail::format("%s%s %.3g±%.2g", text.empty() ? "" : "; ", e.part.c_str(), e.value, 1.96 * e.se);
    }
    return text;
}

} // namespace drytwin::discovery
