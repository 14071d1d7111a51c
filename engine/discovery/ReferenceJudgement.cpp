// A cause judged against its normal value on the reference period: the candidates' scores, a
// finding's change beyond the reference's normal spread, and a cause a later one took up
// withdrawn (ReferenceDiscovery.cpp runs the comparison).
#include "discovery/DiscoveryInternal.h"
#include "discovery/DiscoveryNotes.h"

#include "common/Units.h"
#include "monitoring/Monitor.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <chrono>
#include <cmath>
#include <iterator>
#include <set>
#include <string_view>

namespace drytwin::discovery::detail {

namespace {

/// A fitted cause against its value on the reference, with the period-to-period @p spread.
struct FitChange {
    double normalSd = 0; ///< a period's normal scatter about the reference's value
    double z = 0;        ///< the change in units of its combined uncertainty
};
FitChange fitChange(const Finding& f, const ReferenceValue& rv, double spread) {
    const double seHere = (f.ci95High - f.ci95Low) / (2 * 1.96);
    // The reference's fitted value is about as precise as this one (the one-step error of a lag
    // far from 0 understates it): the larger of the two.
    const double seRef = std::max(rv.se, seHere);
    const double normalSd = std::sqrt(seRef * seRef + spread * spread);
    const double sd = std::sqrt(seHere * seHere + normalSd * normalSd);
    return {normalSd, sd > 0 ? (f.value - rv.value) / sd : 0.0};
}

/// A cause of timing (a lag, a transport time): its tangent at 0 says little of a lag of tens of
/// seconds (a 30 s meter lag moves the one-step estimate from 0.8 s on the reference to 1.2 s), so
/// its change cannot be screened by the tangent; its fitted value decides against the reference.
bool isTiming(Param p) {
    return p == Param::tau_meter || p == Param::tau_hot_sensor || p == Param::dtau_conv;
}

} // namespace

void scoreAgainstReference(const Problem& pr, std::vector<Candidate>& cands) {
    if (!pr.reference) {
        return;
    }
    for (auto& c : cands) {
        const auto it = pr.reference->linear.find(c.parameter);
        if (it == pr.reference->linear.end()) {
            continue;
        }
        const ReferenceValue& rv = it->second;
        const double se = std::sqrt(c.linearSe * c.linearSe + rv.se * rv.se + rv.spread * rv.spread);
        if (!(se > 0)) {
            c.score = 0;
            c.pValue = 1;
            continue;
        }
        const double ownP = c.pValue;
        c.score = (c.linearEstimate - rv.value) / se;
        c.pValue = changeP(c.parameter, c.score);
        if (isTiming(c.parameter)) {
            c.pFromOwnScreen =
                ownP < c.pValue; // screened as alone; judged by its fit against the reference's
            c.pValue = std::min(c.pValue, ownP);
        }
    }
    // Bonferroni over the round's candidates, reported beside the raw p (the screen is liberal on
    // purpose; the held-out part and the normal spread decide).
    const double n = static_cast<double>(cands.size());
    for (auto& c : cands) {
        c.pHolm = std::min(1.0, c.pValue * n);
    }
}

Expected<std::string> judgeAgainstReference(const Problem& pr, Finding& f) {
    if (!pr.reference || !pr.reference->fitted) {
        return std::string();
    }
    auto rv = pr.reference->fitted(f.parameter);
    if (!rv) {
        return rv.error();
    }
    const auto& info = properties::info(f.parameter);
    // Once a detector has flagged a change (at its stated false-alarm rate, with the spread's upper
    // bound), naming asks which cause moved: the spread at its point estimate, not its bound.
    const double spread =
        pr.reference->changeDetected && pr.options.pointSpreadOnceDetected ? rv->spreadPoint : rv->spread;
    const auto [normalSd, z] = fitChange(f, *rv, spread);
    f.hasReference = true;
    f.referenceValue = rv->value;
    f.referenceCi95Low = std::max(info.lower, rv->value - 1.96 * normalSd);
    f.referenceCi95High = std::min(info.upper, rv->value + 1.96 * normalSd);
    f.changeZ = z;
    // A cause bounded at 0 (a loss, a lag, fouling) changes by growing; an offset either way.
    // Before any detector has flagged, naming is the only claim of a change: at the rate a
    // detector states (falseAlarmRate per data set, Bonferroni over the round's candidates), so
    // that a healthy pair whose unmeasured drift a falling rate takes up (z 2.1 and 2.7 on two
    // study nulls) names nothing, while a fouling of 0.1 the monitors miss (z 9.4) is still named.
    const bool atDetectorRate = !pr.reference->changeDetected && pr.options.undetectedChangeAtDetectorRate;
    double critical = 1.96;
    if (atDetectorRate) {
        // p (the upper tail, doubled for an offset) times the candidates ≤ the false-alarm rate.
        const double tail = pr.options.falseAlarmRate /
                            static_cast<double>(std::max<std::size_t>(1, pr.reference->candidatesTested)) /
                            (twoSided(f.parameter) ? 2.0 : 1.0);
        critical = boost::math::quantile(boost::math::complement(boost::math::normal(), tail));
    }
    const bool moved = twoSided(f.parameter) ? std::abs(z) > critical : z > critical;
    if (moved) {
        return std::string();
    }
    // A fit that stopped at the model's limit for the parameter understates the change and
    // overstates its uncertainty: say so, or a heavy fouling reads as a normal one.
    std::string atLimit;
    const double span = info.upper - info.lower;
    if (std::isfinite(span) && span > 0) {
        // A cause that grows from 0 (a loss, a lag) at 0 is simply absent: only an offset's lower
        // limit is a limit of the model's form.
        const bool upper = f.value >= info.upper - 1e-6 * span;
        if (upper || (twoSided(f.parameter) && f.value <= info.lower + 1e-6 * span)) {
            atLimit = format("; the fit stopped at the model's %s limit of %.4g%s, so the line may be "
                             "further from its normal than the model's form can say",
                             upper ? "upper" : "lower", upper ? info.upper : info.lower,
                             properties::spacedUnit(f.parameter).c_str());
        }
    }
    // The test weighs this estimate's own uncertainty with the normal spread: say both, so that a
    // value outside the normal range but too uncertain to tell reads as what it is.
    return format(
               "within its normal spread: %.4g%s here (95 %% CI %.4g to %.4g) against %.4g on the "
               "reference period (a period's normal range %.4g to %.4g); the change is %.2g times its "
               "combined uncertainty, needs %s%.3g%s",
               f.value, properties::spacedUnit(f.parameter).c_str(), f.ci95Low, f.ci95High, rv->value,
               f.referenceCi95Low, f.referenceCi95High, z, twoSided(f.parameter) ? "|z| > " : "> ", critical,
               atDetectorRate ? " (no detector has flagged a change: the detectors' false-alarm rate)" : "") +
           atLimit;
}

Status testNamedCauses(const Problem& pr, const std::vector<Finding>& findings, std::size_t tested,
                       double scatterRiseP, ChangeDetection& d) {
    if (!pr.reference || !pr.reference->fitted) {
        return {};
    }
    const auto consider = [&](double p, const std::string& cause) {
        const double adjusted = std::min(1.0, p * static_cast<double>(std::max<std::size_t>(1, tested)));
        if (adjusted < d.causeTest.pValue) {
            d.causeTest.pValue = adjusted;
            d.causeTest.cause = cause;
            d.causeTest.secondLook = true;
            d.causeTest.changed = adjusted <= d.falseAlarmRate / 2;
        }
    };
    // The gauge's scatter is a change of the instrument, seen in its own readings whether or not
    // the scatter explains the model's error: its rise is tested whenever the cause is asked.
    consider(scatterRiseP, std::string(*properties::mechanismOf(Param::phi_X_in_scatter)));
    for (const auto& f : findings) {
        if (!f.hasReference || f.parameter == Param::phi_X_in_scatter) { // the scatter: its own rise
            continue;
        }
        auto rv = pr.reference->fitted(f.parameter);
        if (!rv) {
            return rv.error();
        }
        // As judgeAgainstReference() before any detector has flagged: the spread at its upper
        // bound, so that this look is held to the detector's stated rate whatever flagged before.
        consider(changeP(f.parameter, fitChange(f, *rv, rv->spread).z), f.cause);
    }
    decide(d);
    return {};
}

Status withdrawTakenUp(const Problem& pr, DiscoveryResult& result) {
    // A cause named early and refitted with the causes named after it (restated at the final model)
    // may fall back within its normal spread: it had taken up, while it was alone, what a later
    // cause explains (seed 743 of the study: a re-absorption first named as a transport time of
    // -12.5 s, which at the final model with the re-absorption is 2.5 s, against the reference's 0.5 s).
    // It is no change of the line, and a technician sent to it would find nothing.
    std::vector<Finding> kept;
    for (auto& f : result.findings) {
        // The inlet gauge's scatter is judged by its own rise against the reference's (scatterChange),
        // not by a fitted normal spread: it stays as named.
        if (f.restated && result.findings.size() > 1 && f.parameter != Param::phi_X_in_scatter) {
            Finding atFinal = f;
            auto why = judgeAgainstReference(pr, atFinal);
            if (!why) {
                return why.error();
            }
            // Or its change from the reference is below the cause's own practical floor (a transport
            // time 1.9 s longer than the reference's is below the 3 s worth a maintenance order).
            if (why->empty() && hasOwnFloor(f.parameter) && atFinal.hasReference) {
                const double hours = result.residuals.empty() ? 1.0 : result.residuals.front().meanBatchHours;
                const std::string floor = belowFloor(pr, f.parameter, f.value - atFinal.referenceValue, hours,
                                                     HeldOut{}, HeldOut{});
                if (!floor.empty()) {
                    *why = format(
                        "%.4g%s here against %.4g on the reference period: a change that small (%s)", f.value,
                        properties::spacedUnit(f.parameter).c_str(), atFinal.referenceValue, floor.c_str());
                }
            }
            if (!why->empty()) {
                // The extended model leaves it out too, so that the model and its file agree with the
                // causes named (a file keeps a mechanism only with its finding).
                result.parameters[f.parameter] = result.baseParameters[f.parameter];
                result.notes.push_back(notes::withdrawnAfterLaterCauses(f.cause, *why));
                continue;
            }
        }
        kept.push_back(std::move(f));
    }
    result.findings = std::move(kept); // the caller's verdict follows what is left
    return {};
}

/// Notes for each batch of the new data whose typical value of an input (its median) lies
/// outside what the reference saw (its 0.5-99.5 % range, widened by a quarter of the span): the
/// model's error there is judged beyond the reference's conditions, and the detectors may take
/// the unseen condition for a change (a hot summer day against a winter reference).
std::vector<OutsideReference> outsideReference(const std::vector<data::SiBatch>& reference,
                                               const std::vector<data::SiBatch>& batches) {
    const auto quantile = [](std::vector<double>& v, double q) {
        const auto at = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
        std::nth_element(v.begin(), at, v.end());
        return *at;
    };
    std::vector<OutsideReference> out;
    for (const auto& in : inputColumns()) {
        if (std::string_view(in.name) == "T_hot_sp_C") { // the controller's; the hot air itself is judged
            continue;
        }
        std::vector<double> seen;
        for (const auto& b : reference) {
            for (std::size_t k = 0; k < b.rows(); ++k) {
                if (b.keep[k] && std::isfinite(in.at(b, k))) {
                    seen.push_back(in.at(b, k));
                }
            }
        }
        if (seen.size() < 100) {
            continue;
        }
        const double lo = quantile(seen, 0.005), hi = quantile(seen, 0.995);
        const double margin = 0.25 * (hi - lo);
        for (std::size_t i = 0; i < batches.size(); ++i) {
            const auto& b = batches[i];
            std::vector<double> v;
            for (std::size_t k = 0; k < b.rows(); ++k) {
                if (b.keep[k] && std::isfinite(in.at(b, k))) {
                    v.push_back(in.at(b, k));
                }
            }
            if (v.empty()) {
                continue;
            }
            const double typical = quantile(v, 0.5);
            if (typical < lo - margin || typical > hi + margin) {
                out.push_back({i, &in, typical, lo, hi});
            }
        }
    }
    return out;
}

std::vector<std::string> operatingRangeNotes(const std::vector<data::SiBatch>& reference,
                                             const std::vector<data::SiBatch>& batches, bool levelNotJudged) {
    // One note a batch, its inputs listed (a winter batch is cold and dry: one note, not two).
    std::vector<std::vector<notes::InputOutsideRange>> byBatch(batches.size());
    for (const auto& o : outsideReference(reference, batches)) {
        byBatch[o.batch].push_back(o.asNoteItem());
    }
    std::vector<std::string> notes;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        if (!byBatch[b].empty()) {
            notes.push_back(notes::outsideReference(batches[b].id, byBatch[b], levelNotJudged));
        }
    }
    return notes;
}

} // namespace drytwin::discovery::detail
