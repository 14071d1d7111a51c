// Question 3, its second half: is a cause that predicts better also specific? Per-part
// estimates, transfer between operating regions, the line's own dynamics against a meter's lag,
// and practical floors in physical units (onsets and lags: Dynamics.cpp).
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Units.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace drytwin::discovery::detail {

namespace {

/// The part of each stack entry: its batch when there are three or more batches, else a third
/// of its batch's training span (a single recording still shows whether a cause holds throughout).
std::vector<int> partOfEntries(const Stack& st, int batches, std::vector<std::string>& names,
                               const std::vector<data::SiBatch>& data) {
    std::vector<int> part(st.batch.size());
    std::vector<double> span(static_cast<std::size_t>(batches), 0.0);
    for (std::size_t i = 0; i < st.batch.size(); ++i) {
        auto& s = span[static_cast<std::size_t>(st.batch[i])];
        s = std::max(s, st.timeS[i]);
    }
    int used = 0;
    for (double s : span) {
        used += s > 0;
    }
    const bool thirds = used < 3;
    names.clear();
    std::map<int, int> index;
    for (std::size_t i = 0; i < st.batch.size(); ++i) {
        const int b = st.batch[i];
        int key = b;
        if (thirds) {
            const double s = span[static_cast<std::size_t>(b)];
            const int third = s > 0 ? std::min(2, static_cast<int>(3 * st.timeS[i] / s)) : 0;
            key = 3 * b + third;
        }
        auto [it, fresh] = index.emplace(key, static_cast<int>(names.size()));
        if (fresh) {
            const std::string& id = data[static_cast<std::size_t>(b)].id;
            names.push_back(thirds ? id + ", part " + std::to_string(key % 3 + 1) + "/3" : id);
        }
        part[i] = it->second;
    }
    return part;
}

/// HAC variance of Σ u over the entries of one part (per-row sums, the part's rows in order).
double partVariance(const Stack& st, const Eigen::VectorXd& u, const std::vector<int>& part, int which) {
    std::vector<std::vector<double>> series(1);
    int lastRow = -1, lastBatch = -1;
    for (std::size_t i = 0; i < part.size(); ++i) {
        if (part[i] != which) {
            continue;
        }
        if (st.row[i] != lastRow || st.batch[i] != lastBatch) {
            series.back().push_back(0.0);
            lastRow = st.row[i];
            lastBatch = st.batch[i];
        }
        series.back().back() += u(static_cast<Eigen::Index>(i));
    }
    return hacVarianceOfSum(series, false);
}

/// The cause's estimate on the entries of part @p which alone (one Gauss-Newton step from the
/// pooled fit @p pooled, its score column @p sc and score contributions @p u), with its HAC
/// standard error; none where the part holds no information about it.
std::optional<PartEstimate> estimateOnPart(const Stack& st, const Eigen::VectorXd& sc,
                                           const Eigen::VectorXd& u, const std::vector<int>& part, int which,
                                           double pooled) {
    double info = 0, score = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        if (part[i] == which) {
            info += sc(static_cast<Eigen::Index>(i)) * sc(static_cast<Eigen::Index>(i));
            score += u(static_cast<Eigen::Index>(i));
        }
    }
    if (!(info > 0)) {
        return std::nullopt;
    }
    PartEstimate e;
    e.value = pooled + score / info;
    e.se = std::sqrt(std::max(0.0, partVariance(st, u, part, which))) / info;
    return e;
}

} // namespace

Consistency consistencyAt(const Problem& pr, const Stack& atFit, const std::vector<int>& nuisance, int cand,
                          double pooled, double tolerance) {
    Consistency out;
    const Eigen::VectorXd sc = projectedColumn(atFit, nuisance, cand);
    std::vector<std::string> names;
    const auto part = partOfEntries(atFit, static_cast<int>(pr.batches->size()), names, *pr.batches);
    const Eigen::VectorXd u = sc.cwiseProduct(atFit.r);
    int strays = 0, informed = 0;
    for (int p = 0; p < static_cast<int>(names.size()); ++p) {
        auto estimate = estimateOnPart(atFit, sc, u, part, p, pooled);
        if (!estimate) {
            continue;
        }
        PartEstimate& e = *estimate;
        e.part = names[static_cast<std::size_t>(p)];
        out.parts.push_back(e);
        ++informed;
        const bool opposite = e.value * pooled < 0 && std::abs(e.value) > 1.96 * e.se;
        const bool far = std::abs(e.value - pooled) > 1.96 * e.se + tolerance * std::abs(pooled);
        strays += opposite || far;
        out.opposite = out.opposite || opposite;
    }
    // One part in four may stray (a batch with a trouble of its own); a significantly opposite
    // sign anywhere is not the same cause.
    out.consistent = !out.opposite && strays <= informed / 4;
    out.strays = strays;
    return out;
}

bool constantWithinBatch(Param p) {
    // The gauges' offsets, the wall's loss and the gas phase's coupling: properties of an
    // instrument or of the tube that a batch does not change. Not fouling (its parameter is a
    // growth rate, and deposits need not grow linearly), nor the causes that act through the
    // product's state (falling-rate drying, re-absorption), whose one-step estimates differ
    // between the wet start and the drier end of a batch on any model, nor the lags and delays,
    // whose tangent says little about their size.
    return p == Param::X_in_offset || p == Param::X_meter_offset || p == Param::theta_wall ||
           p == Param::theta_gas;
}

Constancy constancyWithinBatch(const Stack& atFit, const std::vector<int>& nuisance, int cand, double pooled,
                               double onsetS) {
    Constancy out;
    std::map<int, double> span; // per batch: the last training entry's time
    for (std::size_t i = 0; i < atFit.batch.size(); ++i) {
        auto& s = span[atFit.batch[i]];
        s = std::max(s, atFit.timeS[i]);
    }
    const double from = std::max(0.0, onsetS);
    std::vector<int> half(atFit.batch.size(), -1); // -1: before the onset, where the cause is 0
    for (std::size_t i = 0; i < half.size(); ++i) {
        const double end = span[atFit.batch[i]];
        // A batch the change goes on into acts from its start (Stack::batchFromStart).
        const double batchFrom = atFit.timeS[i] - atFit.sinceOnsetS(i, from);
        if (atFit.timeS[i] >= batchFrom && end > batchFrom) {
            half[i] = atFit.timeS[i] < 0.5 * (batchFrom + end) ? 0 : 1;
        }
    }
    const Eigen::VectorXd sc = projectedColumn(atFit, nuisance, cand);
    const Eigen::VectorXd u = sc.cwiseProduct(atFit.r);
    auto early = estimateOnPart(atFit, sc, u, half, 0, pooled);
    auto late = estimateOnPart(atFit, sc, u, half, 1, pooled);
    if (!early || !late) {
        return out;
    }
    out.early = *early;
    out.late = *late;
    out.early.part = "first half";
    out.late.part = "second half";
    out.checked = true;
    const double difference = std::abs(out.late.value - out.early.value);
    // Significant and large, both: a long record makes any difference the model's structure
    // leaves significant, and a short one's noise can make a half stray by half the value.
    out.constant =
        !(difference > 3 * std::hypot(out.early.se, out.late.se) && difference > 0.5 * std::abs(pooled));
    return out;
}

Transfer transferBetweenRegions(const Problem& pr, const Stack& atStart, const Stack& atFit,
                                const std::vector<int>& nuisance, int fitCol, double pooled) {
    Transfer out;
    if (atStart.r.size() != atFit.r.size()) {
        return out; // a channel went missing between the two models: entries do not pair up
    }
    std::vector<std::string> names;
    const auto part = partOfEntries(atFit, static_cast<int>(pr.batches->size()), names, *pr.batches);
    const auto parts = static_cast<int>(names.size());
    // Two parts at least in each half: a single part against another is the consistency check's
    // business, and the thirds of one recording split by T_hot are rarely two operating regions.
    if (parts < 4) {
        return out;
    }
    // The operating region of each part: its mean hot-air temperature.
    std::vector<double> hot(static_cast<std::size_t>(parts), 0.0),
        count(static_cast<std::size_t>(parts), 0.0);
    for (std::size_t i = 0; i < part.size(); ++i) {
        const auto& b = (*pr.batches)[static_cast<std::size_t>(atFit.batch[i])];
        const std::size_t k =
            pr.subset[static_cast<std::size_t>(atFit.batch[i])][static_cast<std::size_t>(atFit.row[i])];
        hot[static_cast<std::size_t>(part[i])] += b.tHotK[k];
        count[static_cast<std::size_t>(part[i])] += 1;
    }
    for (int p = 0; p < parts; ++p) {
        hot[static_cast<std::size_t>(p)] /= std::max(1.0, count[static_cast<std::size_t>(p)]);
    }
    std::vector<double> sorted = hot;
    std::sort(sorted.begin(), sorted.end());
    const double median = 0.5 * (sorted[static_cast<std::size_t>((parts - 1) / 2)] +
                                 sorted[static_cast<std::size_t>(parts / 2)]);
    // Regions must differ by a couple of kelvins, else "cooler" and "warmer" are one region.
    if (sorted.back() - sorted.front() < 2.0) {
        return out;
    }
    // Fitted on the cooler half: one Gauss-Newton step from the pooled fit with its data alone.
    const Eigen::VectorXd sc = projectedColumn(atFit, nuisance, fitCol);
    double infoCool = 0, scoreCool = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        if (hot[static_cast<std::size_t>(part[i])] <= median) {
            infoCool += sc(ii) * sc(ii);
            scoreCool += sc(ii) * atFit.r(ii);
        }
    }
    if (!(infoCool > 0)) {
        return out;
    }
    const double cool = pooled + scoreCool / infoCool;
    // On the warmer half: its loss without the cause (the model before it) against its loss with
    // the cooler half's value (linearised about the pooled fit).
    double lossWithout = 0, lossCool = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        if (hot[static_cast<std::size_t>(part[i])] > median) {
            lossWithout += atStart.r(ii) * atStart.r(ii);
            const double e = atFit.r(ii) - sc(ii) * (cool - pooled);
            lossCool += e * e;
        }
    }
    if (!(lossWithout > 0)) {
        return out;
    }
    out.checked = true;
    out.reduction = 1.0 - lossCool / lossWithout;
    return out;
}

/// Compensation: the measured channel whose held-out error the cause raises, or -1.
int worsenedChannel(const HeldOut& before, const HeldOut& after, const DiscoveryOptions& options,
                    const std::array<bool, 4>& actsOn) {
    const auto changes = channelChanges(before, after);
    for (int c = 0; c < 4; ++c) {
        if (!actsOn[static_cast<std::size_t>(c)]) {
            continue;
        }
        const auto& ch = changes[static_cast<std::size_t>(c)];
        // The rise must be significant, a share of the error, and more than an instrument
        // would notice (the practical floors' effect sizes, in the channel's units).
        const double w = std::max(1e-12, channelWeight(options.weights, c));
        const double rise = std::sqrt(ch.mseAfter / w) - std::sqrt(ch.mseBefore / w);
        const double floor =
            c == kXOut || c == kXHdt ? options.floors.moistureEffectPct : options.floors.temperatureEffectK;
        if (ch.measured && ch.mseAfter > ch.mseBefore * (1 + options.maxChannelWorsening) &&
            ch.pWorse < 0.05 && rise > floor) {
            return c;
        }
    }
    return -1;
}

namespace {

/// How far the line's response to a cause may differ in size from the model's on an output and
/// still count as the cause's: a factor of 4 either way (the distributed plant's fouling moves the
/// temperatures 0.3-0.6 times as much as the model's, its moisture 1.0 times).
constexpr double kMinResponseScale = 0.25;
constexpr double kResponseZ = 1.96; ///< beyond a bound significantly (two-sided 5 %) to count against it

} // namespace

ResponseMismatch responseMismatch(const HeldOut& before, const HeldOut& after,
                                  const std::array<bool, 4>& actsOn) {
    ResponseMismatch out;
    for (int c = 0; c < 4; ++c) {
        const auto cu = static_cast<std::size_t>(c);
        // The change the cause makes on this channel, d = e_before - e_after, and the error before
        // it, e: the best scale of the effect is g = <e, d> / <d, d>. Evidence against the cause is
        // g significantly below 1/4 (the line moved the wrong way, not at all, or far less than
        // the model form says) or above 4: the score Σ (e - g0 d)·d at the bound g0, with a HAC
        // variance per batch (the rows are autocorrelated). Where the channel's noise hides the
        // effect, the channel cannot judge the cause and does not count against it.
        double ed = 0, dd = 0;
        std::vector<std::vector<double>> atLow, atHigh;
        for (std::size_t b = 0; b < before.channels.size() && b < after.channels.size(); ++b) {
            const auto& eb = before.channels[b][cu].weightedError;
            const auto& ea = after.channels[b][cu].weightedError;
            atLow.emplace_back();
            atHigh.emplace_back();
            for (std::size_t i = 0; i < eb.size() && i < ea.size(); ++i) {
                const double d = eb[i] - ea[i];
                ed += eb[i] * d;
                dd += d * d;
                atLow.back().push_back((eb[i] - kMinResponseScale * d) * d);
                atHigh.back().push_back((eb[i] - d / kMinResponseScale) * d);
            }
        }
        if (!(dd > 0)) {
            continue;
        }
        out.scale[cu] = ed / dd;
        const double varLow = hacVarianceOfSum(atLow, false);
        const double varHigh = hacVarianceOfSum(atHigh, false);
        const double zLow = varLow > 0 ? (ed - kMinResponseScale * dd) / std::sqrt(varLow) : 0.0;
        const double zHigh = varHigh > 0 ? (ed - dd / kMinResponseScale) / std::sqrt(varHigh) : 0.0;
        out.z[cu] = out.scale[cu] < 1 ? zLow : zHigh;
        if (out.channel < 0 && actsOn[cu] && (zLow < -kResponseZ || zHigh > kResponseZ)) {
            out.channel = c;
        }
    }
    return out;
}

Expected<Specificity> judgeSpecificity(const SpecificityInput& in) {
    Specificity out;
    // The cause's own effect: the fit against the same fit with the cause set to 0.
    ParameterSet off = in.fitParameters;
    off[in.parameter] = 0;
    auto withoutIt = heldOut(in.pr, off);
    if (!withoutIt) {
        return withoutIt.error();
    }
    // The channels the cause acts on: its own effect (the fit against the same fit with it at 0)
    // moves them by more than an instrument would notice. A cause is judged on those alone: an
    // outlet-meter offset does not act on the temperature, whatever the refit of h_HDT and k_HDT
    // does to it.
    const auto& floors = in.pr.options.floors;
    std::array<bool, 4> actsOn{};
    std::array<double, 4> effectMs{}; // the cause's own effect, weighted mean square per channel
    for (int c = 0; c < 4; ++c) {
        double sum = 0;
        std::size_t n = 0;
        for (std::size_t b = 0; b < in.after.channels.size() && b < withoutIt->channels.size(); ++b) {
            const auto& with = in.after.channels[b][static_cast<std::size_t>(c)].weightedError;
            const auto& without = withoutIt->channels[b][static_cast<std::size_t>(c)].weightedError;
            for (std::size_t i = 0; i < with.size() && i < without.size(); ++i) {
                sum += (with[i] - without[i]) * (with[i] - without[i]);
                ++n;
            }
        }
        const double w = std::max(1e-12, channelWeight(in.pr.options.weights, c));
        effectMs[static_cast<std::size_t>(c)] = n ? sum / static_cast<double>(n) : 0.0;
        const double rms = std::sqrt(effectMs[static_cast<std::size_t>(c)] / w);
        actsOn[static_cast<std::size_t>(c)] =
            rms > (c == kXOut || c == kXHdt ? floors.moistureEffectPct : floors.temperatureEffectK);
    }
    const auto changes = channelChanges(in.before, in.after);
    // Every channel it acts on must improve: a conveyor delay shifts moisture and temperature
    // alike, and one that helps the temperature while the moisture gets worse is some other
    // timing error of the line. "Does not improve" is evidence only where the data could have
    // shown the improvement: were the cause right on that channel, its own effect d would have
    // removed itself from the error, lowering the mean square by about mean(d²). A channel whose
    // error did not fall is held against the cause when that shortfall is significant (one-sided,
    // HAC standard error of the change); where the channel's noise hides an effect of that size,
    // the channel cannot judge it (a 30 s hot-air sensor lag moves the outlet temperature by
    // 0.2 K rms under 0.6-0.7 K of the line's own error). Its raising the error
    // significantly is compensation either way (worsenedChannel).
    int notImproved = -1;
    double shortfallP = 1;
    int worse = -1;
    ResponseMismatch mismatch;
    if (in.pr.reference && in.pr.options.referenceJudgesDirection) {
        // Against a reference the line's own structure is already taken off: what is left on a
        // channel is the change. The lumped model may state a change's size wrongly on an output
        // (its fouling moves the temperatures 2-3 times as much as a line with a gas phase does,
        // while it explains the moisture exactly), so a channel counts against the cause when
        // the cause's effect does not point the way the change did, not when its size is off.
        mismatch = responseMismatch(in.before, in.after, actsOn);
        worse = mismatch.channel;
        out.responseJudged = true;
        out.responseScale = mismatch.scale;
    } else {
        for (int c = 0; c < 4 && notImproved < 0; ++c) {
            const auto& ch = changes[static_cast<std::size_t>(c)];
            if (!actsOn[static_cast<std::size_t>(c)] || !ch.measured || ch.mseAfter < ch.mseBefore) {
                continue;
            }
            const double p = unimprovedChannelP(ch, effectMs[static_cast<std::size_t>(c)]);
            if (p < in.pr.options.unimprovedChannelAlpha) {
                notImproved = c;
                shortfallP = p;
            }
        }
        worse = worsenedChannel(in.before, in.after, in.pr.options, actsOn);
    }
    // A cause after another against a reference: every output it acts on must be better for it.
    int notBetterLater = -1;
    double notBetterP = 1;
    if (in.pr.reference && in.afterOtherCauses && in.pr.options.laterCauseImprovesEveryOutput && worse < 0) {
        for (int c = 0; c < 4 && notBetterLater < 0; ++c) {
            const auto& ch = changes[static_cast<std::size_t>(c)];
            if (!actsOn[static_cast<std::size_t>(c)] || !ch.measured) {
                continue;
            }
            const double pBetter = 1 - ch.pWorse;
            if (!(pBetter < in.pr.options.laterCauseAlpha)) {
                notBetterLater = c;
                notBetterP = pBetter;
            }
        }
    }
    if (notBetterLater >= 0) {
        const auto& ch = changes[static_cast<std::size_t>(notBetterLater)];
        const double w = std::max(1e-12, channelWeight(in.pr.options.weights, notBetterLater));
        out.code = "not_on_every_output";
        out.why =
            format("after the causes named before it, it acts on %s but does not lower its held-out "
                   "error clearly (rms %.3g to %.3g %s, p = %.2g, needs < %.2g): what is left there is "
                   "not this cause's",
                   kChannelName[notBetterLater], std::sqrt(ch.mseBefore / w), std::sqrt(ch.mseAfter / w),
                   kChannelUnit[notBetterLater], notBetterP, in.pr.options.laterCauseAlpha);
    } else if (worse >= 0 || notImproved >= 0) {
        const int c = worse >= 0 ? worse : notImproved;
        const auto& ch = changes[static_cast<std::size_t>(c)];
        const double w = std::max(1e-12, channelWeight(in.pr.options.weights, c));
        out.code = "compensation";
        const double rmsBefore = std::sqrt(ch.mseBefore / w);
        const double rmsAfter = std::sqrt(ch.mseAfter / w);
        out.why =
            mismatch.channel >= 0
                ? format("its effect on %s does not match how that output changed against the reference: "
                         "the best scale of its effect there is %.2g, z = %.2g against the bound of %.2g "
                         "to %.2g (|z| > %.2g counts): not this cause",
                         kChannelName[c], mismatch.scale[static_cast<std::size_t>(c)],
                         mismatch.z[static_cast<std::size_t>(c)], kMinResponseScale, 1 / kMinResponseScale,
                         kResponseZ)
            : worse >= 0
                ? format("it lowers the error overall but raises the held-out rms error of %s from "
                         "%.3g to %.3g %s: compensation, not a cause",
                         kChannelName[c], rmsBefore, rmsAfter, kChannelUnit[c])
                : format("it acts on %s but does not improve it (held-out rms error %.3g to %.3g "
                         "%s, where its own effect of %.3g %s rms should have lowered it; p = "
                         "%.2g): not this cause",
                         kChannelName[c], rmsBefore, rmsAfter, kChannelUnit[c],
                         std::sqrt(effectMs[static_cast<std::size_t>(c)] / w), kChannelUnit[c], shortfallP);
    } else if (auto floor =
                   belowFloor(in.pr, in.parameter, in.value, in.meanBatchHours, *withoutIt, in.after);
               !floor.empty()) {
        out.code = "below_floor";
        out.why = floor + ": not worth a maintenance order";
    }
    out.actsOn = actsOn;
    out.consistency =
        consistencyAt(in.pr, in.atFit, in.nuisance, in.atCol, in.value, in.pr.options.consistencyTolerance);
    out.transfer = transferBetweenRegions(in.pr, in.atStart, in.atFit, in.nuisance, in.atCol, in.value);
    if (out.code.empty() && !out.consistency.consistent) {
        out.code = "inconsistent";
        out.why = inconsistencyReason(out.consistency, in.parameter, in.value);
    }
    if (in.pr.options.checkConstancyWithinBatch && constantWithinBatch(in.parameter)) {
        out.constancy =
            constancyWithinBatch(in.atFit, in.nuisance, in.atCol, in.value, in.fitParameters[Param::t_onset]);
        if (out.code.empty() && out.constancy.checked && !out.constancy.constant) {
            const std::string unit(properties::info(in.parameter).unit);
            out.code = "not_constant";
            out.why = format("%s does not change within a batch, but its estimate is %.3g±%.2g %s over "
                             "the first half of the batches and %.3g±%.2g %s over the second: the error "
                             "changes within the batch, as fouling or a drifting reading does",
                             in.parameter == Param::X_in_offset || in.parameter == Param::X_meter_offset
                                 ? "an offset"
                                 : "a property of the tube",
                             out.constancy.early.value, 1.96 * out.constancy.early.se, unit.c_str(),
                             out.constancy.late.value, 1.96 * out.constancy.late.se, unit.c_str());
        }
    }
    if (out.code.empty() && out.transfer.checked && out.transfer.reduction < 0) {
        out.code = "inconsistent";
        out.why = "fitted on the cooler half of the data it makes the warmer half worse";
    }
    if (out.code.empty() && in.parameter == Param::tau_meter) {
        // A meter lags its own reading: the outlet moisture's error must follow its rate of
        // change over tens of seconds (not merely be smoothed: a lag also filters the input
        // scatter the simulation carries), and the outlet temperature's must not, or the
        // slowness is the line's.
        // Judged at the fitted lag and from its onset: a long lag smooths what −d/dt sees.
        const double onsetS = in.fitParameters[Param::t_onset];
        const ChannelLag lagX = lagOnChannel(in.pr, in.currentSims, kXOut, in.value, onsetS);
        const ChannelLag lagT = lagOnChannel(in.pr, in.currentSims, kTOut, in.value, onsetS);
        if (!(lagX.ok && lagX.z > 3 && lagX.tauS >= 0.25 * in.value)) {
            out.code = "line_dynamics";
            out.why = format("over 30 s the outlet-moisture error does not follow its rate of change (tau = "
                             "%.3g s, z = %.2g, against the fitted %.3g s): the lag smooths the simulation's "
                             "input scatter, it is not a meter's",
                             lagX.tauS, lagX.z, in.value);
        } else if (lagT.ok && lagT.z > 3 && lagT.tauS >= 0.5 * lagX.tauS) {
            out.code = "line_dynamics";
            out.why =
                format("the outlet temperature lags the model too (tau = %.3g s against %.3g s for the "
                       "moisture): the line responds more slowly than the model, the meter is not to blame",
                       lagT.tauS, lagX.tauS);
        }
    }
    return out;
}

Expected<std::optional<Finding>> inletScatterFinding(const Problem& pr, const ParameterSet& current,
                                                     const std::vector<Param>& nuisance, const HeldOut& held,
                                                     const std::vector<OutputResidual>& residuals,
                                                     const DiscoveryOptions& options) {
    const Param phi = Param::phi_X_in_scatter;
    const auto col = std::find(nuisance.begin(), nuisance.end(), phi);
    if (col == nuisance.end()) {
        return std::optional<Finding>{};
    }
    ParameterSet raw = current;
    raw[phi] = 0;
    auto rawHeld = heldOut(pr, raw);
    if (!rawHeld) {
        return rawHeld.error();
    }
    const auto [explained, explainedFast] = explainedShares(*rawHeld, held, options);
    const Gain gain = gainOf(*rawHeld, held);
    if (!belowFloor(pr, phi, current[phi], 0, *rawHeld, held).empty() || !(gain.pValue < options.gainAlpha) ||
        std::max(explained, explainedFast) < options.minExplainedFraction) {
        return std::optional<Finding>{};
    }
    Finding f;
    f.cause = std::string(*properties::mechanismOf(phi));
    f.parameter = phi;
    f.value = current[phi];
    double se = 0;
    if (auto at = stackAt(pr, current, nuisance); at) {
        const int c = static_cast<int>(col - nuisance.begin());
        se = scoreTest(*at, columnsBut(static_cast<int>(nuisance.size()), c), c).se;
    }
    f.ci95Low = std::max(0.0, f.value - 1.96 * se);
    f.ci95High = std::min(1.0, f.value + 1.96 * se);
    f.explainedFraction = explained;
    f.explainedFractionFast = explainedFast;
    f.fastPartCounted = explained < options.minExplainedFraction;
    f.gain = gain;
    f.output = "X_out";
    for (const auto& o : residuals) {
        if (o.output == f.output) {
            f.biasBefore = o.bias;
            f.trendPerHourBefore = o.trendPerHour;
        }
    }
    f.evidence = findingEvidence(f, options);
    return std::optional<Finding>{f};
}

std::string outputPredictedWorse(const HeldOut& other, const HeldOut& named, double alpha,
                                 const std::array<bool, 4>& namedActsOn) {
    // A look-alike that wins on one output and loses on another is a different balance of the
    // same signature (the model's own structure decides which output it favours), not a worse
    // explanation: the named cause must not be significantly worse on any measured output it
    // acts on.
    const auto changes = channelChanges(other, named);
    for (int c = 0; c < 4; ++c) {
        const auto& ch = changes[static_cast<std::size_t>(c)];
        if (namedActsOn[static_cast<std::size_t>(c)] && ch.measured && ch.mseAfter > ch.mseBefore &&
            ch.pWorse < alpha) {
            return kChannelName[c];
        }
    }
    return "";
}

Expected<LookAlike> compareLookAlike(const Problem& pr, Param other, const ParameterSet& fitted,
                                     const std::array<bool, 4>& namedActsOn, const HeldOut& namedHeld,
                                     const DiscoveryOptions& options) {
    auto otherHeld = heldOut(pr, fitted);
    if (!otherHeld) {
        return otherHeld.error();
    }
    LookAlike l;
    l.cause = std::string(*properties::mechanismOf(other));
    l.parameter = other;
    l.value = fitted[other];
    const double mine = meanOf(namedHeld.loss);
    l.heldOutLossRatio = mine > 0 ? meanOf(otherHeld->loss) / mine : 1.0;
    l.pValue = heldOutPValue(*otherHeld, namedHeld);
    l.worseOutput = outputPredictedWorse(*otherHeld, namedHeld, options.gainAlpha, namedActsOn);
    l.ruledOut = l.pValue < options.gainAlpha && (l.worseOutput.empty() || !options.lookAlikeWorseOnNoOutput);
    return l;
}

} // namespace drytwin::discovery::detail
