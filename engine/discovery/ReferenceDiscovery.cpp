// What changed since the line ran well: the model commissioned on a reference period, each
// cause's normal value there, and the new data judged by how far a cause moved from it.
//
// Why a reference: on a line that is not the model (a distributed tube, a gas phase) the model's
// own structural error is as large as a mechanism, and a fitted cause compensates it on one
// channel while worsening another (issue #23: the hidden cause alone named in 27 of 66 runs).
// That structure is present in every period; a change is not. So the commissioned parameters
// stay fixed on the new data, a cause's one-step estimate is compared with the one it has on the
// reference (its "normal value", with the spread between the reference's parts), and a fitted
// cause is named only when its value lies beyond that normal spread.
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

namespace drytwin::discovery {

using namespace detail;

namespace detail {

namespace {

/// The normal value of column @p col of @p st (at the commissioned model, nothing else free):
/// the pooled one-step estimate, its HAC error, and the spread between the parts beyond what
/// their own errors explain (a period's value varies with its operating point and weather).
/// @p leftOutOfSpread: reference batches whose values do not enter the spread (their conditions
/// lie outside the other batches': see discoverAgainstReference), as long as three parts remain.
ReferenceValue normalValue(const Problem& pr, const Stack& st, int col, double tolerance,
                           const std::set<std::string>& leftOutOfSpread) {
    ReferenceValue rv;
    const auto sc = scoreTest(st, {}, col);
    rv.value = sc.estimate;
    rv.se = sc.se;
    const auto parts = consistencyAt(pr, st, {}, col, 0.0, tolerance);
    rv.parts = parts.parts;
    std::vector<PartEstimate> spreadParts;
    for (const auto& e : parts.parts) {
        if (leftOutOfSpread.count(e.part) == 0) {
            spreadParts.push_back(e);
        }
    }
    if (spreadParts.size() < 3) {
        spreadParts = parts.parts;
    }
    if (spreadParts.size() >= 2) {
        double mean = 0, ownVariance = 0;
        for (const auto& e : spreadParts) {
            mean += e.value;
            ownVariance += e.se * e.se;
        }
        const double n = static_cast<double>(spreadParts.size());
        mean /= n;
        ownVariance /= n;
        double between = 0;
        for (const auto& e : spreadParts) {
            between += (e.value - mean) * (e.value - mean);
        }
        between /= n - 1;
        // From 3-4 parts the between-part variance has 2-3 degrees of freedom and falls short of
        // the truth half the time, and a new period then sits beyond the normal spread by chance.
        // Its upper 75 % confidence bound, (K − 1) s² / χ²_{0.25, K−1}, as the monitor's null
        // takes its run effects (monitoring/ChangePoint.cpp): one rule for both halves of the detector.
        rv.spreadPoint = std::sqrt(std::max(0.0, between - ownVariance));
        const boost::math::chi_squared chi(n - 1);
        between *= (n - 1) / boost::math::quantile(chi, 0.25);
        rv.spread = std::sqrt(std::max(0.0, between - ownVariance));
    }
    return rv;
}

} // namespace

} // namespace detail

namespace {

/// The weighted training loss (calibration's definition: Σ_channel w · mean squared error) of
/// the stack's residuals.
double stackLoss(const Stack& st) {
    std::array<double, 4> sum{};
    std::array<std::size_t, 4> n{};
    for (Eigen::Index i = 0; i < st.r.size(); ++i) {
        const auto c = static_cast<std::size_t>(st.channel[static_cast<std::size_t>(i)]);
        sum[c] += st.r(i) * st.r(i);
        ++n[c];
    }
    double loss = 0;
    for (std::size_t c = 0; c < 4; ++c) {
        loss += n[c] ? sum[c] / static_cast<double>(n[c]) : 0.0;
    }
    return loss;
}

/// A gauge that scatters more than the reference's (whose share of the inlet moisture's fast
/// variation the commissioning took as gauge scatter) is a change of the instrument: its share
/// refitted on the new data, named when that predicts the held-out part clearly better. The
/// model then carries the new share, refitted with any later cause.
constexpr double kScatterRise = 1.25; ///< the measured fast scatter must rise by a quarter first
/// The instrument's own practical floor: a gauge whose fast scatter has at least doubled against
/// the reference has changed, whatever share of the model's error that explains. Where the
/// commissioning already took nearly all of the inlet's fast variation as scatter (the distributed
/// plant: 99 %), the model barely uses the fast reading, and even a fivefold scatter explains 1-2 %
/// of the held-out error: the 15 % floor for a cause's effect on the model would hide a gauge that
/// the plant's own feed-forward still reads (10 of 12 runs unnamed in the reference study).
constexpr double kScatterPracticalRise = 2.0;

Status scatterChange(const Problem& pr, const Problem& referencePr, const CauseFit& refit, ModelSoFar& model,
                     DiscoveryResult& result) {
    const Param phi = Param::phi_X_in_scatter;
    const double before = inletFastScatterPct(referencePr);
    const double now = inletFastScatterPct(pr);
    if (!(now > kScatterRise * before)) {
        return {};
    }
    auto fit = refit(model.parameters, {phi}, false, nullptr);
    if (!fit) {
        return fit.error().kind == ErrorKind::Cancelled ? Status(fit.error()) : Status();
    }
    if (!(fit->parameters[phi] > model.parameters[phi])) {
        return {};
    }
    auto after = heldOut(pr, fit->parameters);
    if (!after) {
        return after.error();
    }
    const auto [explained, explainedFast] = explainedShares(model.held, *after, pr.options);
    Finding f;
    f.gain = gainOf(model.held, *after);
    const bool gaugeFloor = now >= kScatterPracticalRise * before;
    if (!(f.gain.pValue < pr.options.gainAlpha) ||
        (std::max(explained, explainedFast) < pr.options.minExplainedFraction && !gaugeFloor)) {
        return {};
    }
    f.cause = std::string(*properties::mechanismOf(phi));
    f.parameter = phi;
    f.value = fit->parameters[phi];
    double se = 0;
    if (auto at = stackAt(pr, fit->parameters, {phi}); at) {
        se = scoreTest(*at, {}, 0).se;
    }
    f.ci95Low = std::max(0.0, f.value - 1.96 * se);
    f.ci95High = std::min(1.0, f.value + 1.96 * se);
    f.explainedFraction = explained;
    f.explainedFractionFast = explainedFast;
    f.fastPartCounted = explained < pr.options.minExplainedFraction;
    f.hasReference = true;
    f.referenceValue = model.parameters[phi];
    f.referenceCi95Low = f.referenceCi95High = f.referenceValue;
    describeOutput(f, model.residuals);
    f.evidence =
        findingEvidence(f, pr.options) +
        format(" The inlet gauge's fast scatter is %.2g %% wb here against %.2g %% wb on the reference (%.1f "
               "times).",
               now, before, now / before);
    Round record;
    record.best = f.cause;
    record.named = true;
    record.heldOutPValue = f.gain.pValue;
    record.explainedFraction = explained;
    record.explainedFractionFast = explainedFast;
    result.rounds.push_back(record);
    result.findings.push_back(f);
    auto sims = physics::simulateBatches(pr.inputs, fit->parameters, pr.simulation);
    if (!sims) {
        return sims.error();
    }
    model.sims = std::move(*sims);
    model.residuals = analyse(pr, model.sims);
    model.parameters = fit->parameters;
    model.loss = fit->after.loss;
    model.held = std::move(*after);
    model.nuisance.push_back(phi);
    return {};
}

} // namespace

Expected<DiscoveryResult> discoverChange(const std::vector<data::SiBatch>& reference,
                                         const std::vector<data::SiBatch>& batches,
                                         const hybrid::HybridModel& model, const DiscoveryOptions& options,
                                         const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (reference.empty() || batches.empty()) {
        return Error{ErrorKind::BadInput,
                     "discover",
                     reference.empty() ? "the reference period holds no batches" : "no batches to judge",
                     ErrorCode::NotEnoughData,
                     {reference.empty() ? "reference batches" : "batches", "0"}};
    }
    double fraction = 0;
    const auto stop = [&](double f, const std::string& detail) {
        fraction = f;
        return reportProgress(progress, "discover", f, detail);
    };
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };

    // Commissioning: h_HDT, k_HDT and the inlet gauge's normal scatter share fitted on every kept
    // row of the reference; extensions the model already holds refitted with them.
    auto refPrepared = prepare(reference, model, options, true);
    if (!refPrepared) {
        Error e = refPrepared.error();
        e.reason = "the reference period: " + e.reason;
        return e;
    }
    const Problem& refPr = refPrepared->pr;
    const CauseFit refFit = makeCauseFit(reference, refPr, progress, fraction);
    std::vector<Param> commissioned{Param::h_HDT, Param::k_HDT, Param::phi_X_in_scatter};
    for (Param m : properties::mechanismParams()) {
        if (model.parameters[m] != 0 && m != Param::phi_X_in_scatter) {
            commissioned.push_back(m);
        }
    }
    if (stop(0.02, "commissioning the model on the reference period")) {
        return cancelledError("discover");
    }
    auto base = refFit(model.parameters, commissioned, !model.calibration.has_value(), nullptr);
    if (!base) {
        return base.error();
    }
    const ParameterSet commissionedParameters = base->parameters;

    const auto asked = [&](Param m) {
        const auto name = properties::mechanismOf(m);
        return options.causes.empty() || (name && std::find(options.causes.begin(), options.causes.end(),
                                                            *name) != options.causes.end());
    };
    // Every cause is a candidate, those the model already holds too (issue #72): commissioned on
    // the reference, a mechanism the model carries (a fouling taken in by Extend) has a normal value
    // there like any other cause, and its change on the new data is judged the same way. Left out,
    // a model extended by a cause could no longer name that cause when it grew.
    std::vector<Param> remaining;
    for (Param m : properties::mechanismParams()) {
        if (m != Param::phi_X_in_scatter && asked(m)) { // the gauge's scatter: its own rise (scatterChange)
            remaining.push_back(m);
        }
    }

    // The line's own structure: what the commissioned model always gets wrong, learnt on the
    // reference and taken off every period's measurements (LineStructure.cpp).
    if (stop(0.05, "the line's own structure on the reference period")) {
        return cancelledError("discover");
    }
    auto refSims = physics::simulateBatches(refPr.inputs, commissionedParameters, refPr.simulation);
    if (!refSims) {
        return refSims.error();
    }
    auto newSims = physics::simulateBatches(
        [&] {
            std::vector<physics::LineInputs> in;
            for (const auto& b : batches) {
                in.push_back(physics::toLineInputs(b));
            }
            return in;
        }(),
        commissionedParameters, model.simulationOptions());
    if (!newSims) {
        return newSims.error();
    }
    std::vector<data::SiBatch> refForModel = reference;
    std::vector<data::SiBatch> newForModel = batches;
    LineStructure structure;
    std::vector<std::string> spreadNotes;
    if (options.learnLineStructure) {
        structure = learnLineStructure(reference, *refSims, options.lineStructureWithinReferenceRange);
        // A reference batch whose conditions the other batches never saw (a winter batch among
        // summer ones) was corrected by a map fitted on those others (each part's is), so its
        // causes' values carry the map's extrapolation, not the line's normal variation; new data
        // inside the reference's conditions are corrected by the map fitted on all of it. Such a
        // batch is left out of the causes' normal spread (its value stays in the pooled one).
        if (options.normalSpreadWithinReferenceConditions && reference.size() >= 3) {
            for (std::size_t p = 0; p < reference.size(); ++p) {
                std::vector<data::SiBatch> others;
                for (std::size_t q = 0; q < reference.size(); ++q) {
                    if (q != p) {
                        others.push_back(reference[q]);
                    }
                }
                std::vector<notes::InputOutsideRange> beyond;
                for (const auto& o : outsideReference(others, {reference[p]})) {
                    beyond.push_back(o.asNoteItem());
                }
                if (!beyond.empty()) {
                    structure.extrapolatedBatches.insert(reference[p].id);
                    spreadNotes.push_back(notes::referenceBatchBeyondOthers(reference[p].id, beyond));
                }
            }
            // Fewer than three batches would be left: the spread is taken over every batch
            // (normalValue), and no note says otherwise.
            if (reference.size() - structure.extrapolatedBatches.size() < 3) {
                structure.extrapolatedBatches.clear();
                spreadNotes.clear();
            }
        }
        refForModel = structure.referenceCorrected;
        for (std::size_t b = 0; b < batches.size(); ++b) {
            newForModel[b] = structure.apply(batches[b], (*newSims)[b]);
        }
    }

    // Each cause's normal value: its one-step estimate at the commissioned model on the
    // reference (its structure taken off), pooled and part by part.
    if (stop(0.06, "each cause's normal value on the reference period")) {
        return cancelledError("discover");
    }
    auto normalPrepared = prepare(refForModel, model, options, true);
    if (!normalPrepared) {
        return normalPrepared.error();
    }
    const Problem& normalPr = normalPrepared->pr;
    const CauseFit normalFit = makeCauseFit(refForModel, normalPr, progress, fraction);
    Reference ref;
    {
        auto refStack = stackAt(normalPr, commissionedParameters, remaining);
        if (!refStack) {
            return refStack.error();
        }
        for (std::size_t i = 0; i < remaining.size(); ++i) {
            ref.linear[remaining[i]] =
                normalValue(normalPr, *refStack, static_cast<int>(i), options.consistencyTolerance,
                            structure.extrapolatedBatches);
        }
        // The reference's own error level, every kept row (the commissioning leaves no held-out
        // part): what a period has without a change.
        ref.normalHeldLoss = stackLoss(*refStack);
    }
    // A cause fitted on the reference alone, once, when a finding asks for its normal value; a
    // failed fit keeps the one-step estimate (no better evidence), a cancel stops discovery.
    std::map<Param, ReferenceValue> fittedOnReference;
    ref.fitted = [&](Param m) -> Expected<ReferenceValue> {
        if (auto it = fittedOnReference.find(m); it != fittedOnReference.end()) {
            return it->second;
        }
        ReferenceValue rv = ref.linear[m];
        const auto& info = properties::info(m);
        ParameterSet start = commissionedParameters;
        start[m] = std::clamp(start[m] + rv.value, info.lower, info.upper);
        auto fit = normalFit(start, {m}, false, nullptr);
        if (!fit && fit.error().kind == ErrorKind::Cancelled) {
            return fit.error();
        }
        if (fit) {
            rv.value = fit->parameters[m];
        }
        fittedOnReference[m] = rv;
        return rv;
    };

    // Detection first: does the new data differ from the reference at all, and from when?
    if (stop(0.08, "detection against the reference period")) {
        return cancelledError("discover");
    }
    auto detection = detectChange(reference, refForModel, *refSims, batches, newForModel, *newSims, options);
    if (!detection) {
        return detection.error();
    }

    // The causes are judged from the change on: the batches wholly before the change point's
    // interval ran as the reference did (judgeFromChangeOn). Too little left after it to split
    // into a training and a held-out part: every batch, as before.
    std::size_t firstJudged = options.judgeFromChangeOn ? firstBatchOfChange(detection->drytwin) : 0;
    std::vector<data::SiBatch> judged;
    const auto prepareFrom = [&](std::size_t first) {
        judged.assign(newForModel.begin() + static_cast<std::ptrdiff_t>(first), newForModel.end());
        return prepare(judged, model, options);
    };
    auto prepared = prepareFrom(firstJudged);
    if (!prepared && firstJudged > 0 && prepared.error().kind != ErrorKind::Cancelled) {
        firstJudged = 0;
        prepared = prepareFrom(0);
    }
    if (!prepared) {
        return prepared.error();
    }
    // A change that began during a batch and went on acts from the start of the batches after it.
    // (batchesChangedFromStart returns only runs after a judged one.)
    std::vector<std::string> changedFromStart;
    const monitoring::Detection* changeDetector = changePointDetector(*detection);
    if (options.changeGoesOnIntoLaterBatches && changeDetector) {
        for (const std::size_t run : batchesChangedFromStart(*changeDetector, firstJudged)) {
            if (run - firstJudged < prepared->pr.inputs.size()) {
                prepared->pr.inputs[run - firstJudged].mechanismsFromStart = true;
                changedFromStart.push_back(batches[run].id);
            }
        }
    }
    prepared->pr.reference = &ref;
    const Problem& pr = prepared->pr;
    const CauseFit refit = makeCauseFit(judged, pr, progress, fraction);

    DiscoveryResult result;
    result.hasReference = true;
    result.referenceBatches = reference.size();
    result.referenceRows = refPrepared->keptTrain;
    result.baseParameters = commissionedParameters;
    result.notes = dataNotes(batches);
    // A reference is the line running well. One whose own error drifts within its batches (a
    // fouling that grows from every cleaning, a meter that fogs) makes that drift the normal, and a
    // line that runs well afterwards reads as "no change": say so (a newcomer's review swapped the
    // periods and got "no change" beside a reference drifting 1.7 % wb a batch).
    for (const auto& o : analyse(refPr, *refSims)) {
        const bool moisture = o.unit == "% wb";
        const double drift = std::abs(o.trendPerHour) * o.meanBatchHours;
        if ((o.output == "X_out" || o.output == "T_out") && o.trendSe > 0 &&
            std::abs(o.trendPerHour) > 3 * o.trendSe && drift > (moisture ? 0.5 : 3.0)) {
            result.notes.push_back(notes::referenceDrifts(o.output, o.trendPerHour * o.meanBatchHours, o.unit,
                                                          o.trendPerHour, o.trendSe));
        }
    }
    result.notes.push_back(notes::commissionedOnReference(reference.size(), refPrepared->keptTrain,
                                                          commissionedParameters[Param::h_HDT],
                                                          commissionedParameters[Param::k_HDT]));
    if (options.learnLineStructure) {
        result.notes.push_back(notes::lineStructureLearnt(structure.lambda));
    }
    result.notes.insert(result.notes.end(), spreadNotes.begin(), spreadNotes.end());
    // Fewer than three batches: a period's normal spread comes from thirds of a recording, which
    // share its day and weather; what varies between weeks is not in it.
    if (reference.size() < 3) {
        result.notes.push_back(notes::shortReference(reference.size()));
    }
    for (auto& note :
         detail::operatingRangeNotes(reference, batches, options.judgeOnlyChangesBeyondReferenceConditions)) {
        result.notes.push_back(std::move(note));
    }
    if (!options.causes.empty()) {
        result.notes.push_back(notes::onlyCausesAsked(options.causes));
    }
    if (firstJudged > 0) {
        for (std::size_t b = 0; b < firstJudged; ++b) {
            result.batchesBeforeChange.push_back(batches[b].id);
        }
        result.notes.push_back(
            notes::judgedFromChangeOn(result.batchesBeforeChange, batches[firstJudged].id));
    }
    if (!changedFromStart.empty()) {
        result.notes.push_back(notes::changeGoesOnFromStart(changedFromStart));
        result.batchesChangedFromStart = std::move(changedFromStart);
    }
    result.trainingRows = prepared->keptTrain;
    result.heldOutRows = prepared->keptTest;

    std::vector<physics::SimulationResult> sims(
        std::make_move_iterator(newSims->begin() + static_cast<std::ptrdiff_t>(firstJudged)),
        std::make_move_iterator(newSims->end()));
    result.residuals = analyse(pr, sims);
    auto held = heldOut(pr, commissionedParameters);
    if (!held) {
        return held.error();
    }
    auto lossStack = stackAt(pr, commissionedParameters, {});
    if (!lossStack) {
        return lossStack.error();
    }

    result.detection = std::move(*detection);
    ref.changeDetected = result.detection.changed;
    if (const auto* d = changePointDetector(result.detection)) {
        ref.changePoint = Onset{true, d->onsetS, d->onsetLowS, d->onsetHighS, 0};
    }
    ref.strictScreenAlpha = options.screenAlpha;
    if (result.detection.changed && options.screenAlphaOnceDetected > 0) {
        auto& screen = prepared->pr.options.screenAlpha;
        screen = std::max(screen, options.screenAlphaOnceDetected);
    }

    ModelSoFar extended{commissionedParameters, stackLoss(*lossStack), {},
                        std::move(remaining),   std::move(sims),       result.residuals,
                        std::move(*held)};
    if (asked(Param::phi_X_in_scatter)) {
        if (auto st = scatterChange(pr, normalPr, refit, extended, result); !st) {
            return st.error();
        }
    }
    if (auto st = selectCauses(*prepared, refit, stop, extended, result); !st) {
        return st.error();
    }
    testCauses(result.ranking, result.detection);
    if (stop(0.95, "what is left")) {
        return cancelledError("discover");
    }
    conclude(pr, extended.parameters, extended.nuisance, extended.sims, std::move(extended.residuals),
             result);
    if (options.withdrawCausesTakenUpLater) {
        if (auto st = withdrawTakenUp(pr, result); !st) {
            return st.error();
        }
    }
    // Every finding against a reference is a change (its parameter beyond its normal spread).
    for (const auto& f : result.findings) {
        result.detection.namedCauses.push_back(f.cause);
    }
    if (options.causeTestAtNamedFits) {
        const bool scatterAsked = asked(Param::phi_X_in_scatter);
        const double scatterRiseP = scatterAsked ? inletScatterRiseP(pr, normalPr) : 1.0;
        if (auto st = testNamedCauses(pr, result.findings, result.ranking.size() + (scatterAsked ? 1 : 0),
                                      scatterRiseP, result.detection);
            !st) {
            return st.error();
        }
    }
    // The line's own structure is on the reference too: only a change the detectors see and no
    // cause explains is "unexplained structure" here.
    if (result.findings.empty()) {
        result.verdict = result.detection.changed ? "unexplained_structure" : "no_structural_cause";
    }
    reportProgress(progress, "discover", 1.0, "done");
    result.ending = {Termination::Completed,
                     std::string(result.detection.changed ? "changed against the reference; "
                                 : result.detection.namedChange()
                                     ? "a cause changed against the reference "
                                       "(the detectors did not flag the data set); "
                                     : "no change against the reference; ") +
                         std::to_string(result.findings.size()) + " cause(s) named",
                     elapsed()};
    return result;
}

} // namespace drytwin::discovery
