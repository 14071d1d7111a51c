// The discovery study of issues #10 and #23: every mechanism (11) x 3 seeds x 2 strengths, 20 data
// sets without any mechanism (with and without drift, with and without sensor spikes and
// dropouts), and four mechanisms that start mid-batch x 3 seeds. Prints how often the hidden cause
// (or a look-alike group holding it) is named first, how often a cause is named that is not there,
// and how close the onsets are, as Markdown tables.
// Run: build/bench/study_discovery [--quick] [--plant distributed|lumped] [--sensors realistic|ideal|default]
//      [--part mechanisms|nulls|onsets|batch-change (with --reference: each mechanism from the third of four
//      batches, seeds FIRST+200; in "all" too)|mid-batch-change (with --reference: from 8-28 min into the
//      third of four batches and the whole fourth; only when asked)] [--onset-in-every-batch (with
//      --reference: t_onset from every batch's start, no batch taken as changed from its start; before
//      2026-11-28, evening)]
//      [--judge-every-batch (with --reference: no batch left out
//      before the change point, as before 2026-11-28)] [--mechanism NAME (e.g. moisture_meter_lag)]
//      [--verbose]
//      [--null-seeds FIRST (20 seeds from it; default 201)] [--min-explained SHARE (default 0.15)]
//      [--candidates N (fitted per round; default 3)] [--evaluations N (per fit; default 120)]
//      [--oracle (each mechanism run asks about its hidden cause alone)]
//      [--reference (issue #41: each run judged against healthy data of another seed, 4 x 3,000 s,
//      by discoverChange; the detectors' flags in each row, and each seed's healthy run first: a detector
//      that flags it flags the seed's conditions, not the mechanism)] [--reference-batches N (with
//      --reference: the reference period's batches, default 4)] [--no-structure (with --reference: the line's
//      own structure not learnt, the causes' normal values alone)] [--size-rule (with --reference: an output
//      a cause acts on counts against it when its error rises, as alone; the rule before 2026-11-27, instead
//      of the direction of the cause's effect)] [--share-of-whole (with --reference: a cause's share counted
//      of the whole held-out error only, not of its change against the reference once a detector flags one;
//      the rule before 2026-11-27, evening)] [--undetected-at-5-percent (with --reference: a cause named
//      while no detector flags judged beyond its normal spread at z 1.96, not at the detectors' rate; the
//      rule before 2026-11-27, night)] [--seeds FIRST (mechanism runs' three seeds; default 101, onsets
//      FIRST+100)] [--unimproved-alpha A (default 0.05; 1: the rule before)]
//      [--no-constancy (an offset, wall loss or gas coupling not checked for constancy within the batch)]
//      [--look-alike-overall (a look-alike ruled out on the overall held-out loss alone, even where
//      it predicts one output better)]: the rules before 2026-11-26, for a before/after
// (lumped, its built-in sensors: about 8 min on 2 cores; --quick: one seed). The default plant is
// the distributed one with realistic sensors (issue #22), whose nulls include its own structure.
#include "discovery/Discovery.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <tuple>

using namespace drytwin;

namespace {

struct Outcome {
    bool rightFirst = false; ///< the hidden cause first, alone or in its look-alike group
    bool asGroup = false;    ///< ... and named as a group (a look-alike not ruled out)
    int falseNames = 0;
    std::string named;
    double seconds = 0;
    bool hasOnset = false;
    double onsetS = 0;
    double value = 0;                            ///< the first finding's fitted value
    bool drytwinFlags = false, pcaFlags = false; ///< --reference: each detector's run-level decision
    std::string leftOut; ///< --reference: the batches left out as wholly before the change
};

bool verbose = false; ///< --verbose: each turned-down candidate's reason, not only its code
/// --oracle: each mechanism run asks about its hidden cause alone (fitted whenever its score points
/// the way that helps) and reports how the judgement rules see it: the bound on what any choice
/// among the candidates can reach with these rules.
bool oracle = false;
discovery::DiscoveryOptions discoveryOptions; ///< --min-explained changes its share
/// --reference: judged against healthy data of another seed (the same plant and sensors, no
/// mechanism, no onset), as an engineer judges a line against the weeks when it ran well.
bool againstReference = false;
constexpr unsigned kReferenceSeedOffset = 7000;
constexpr unsigned kChangedRunSeedOffset = 500; ///< --part batch-change: the changed batches' run
/// --reference-batches N: the reference period's batches of 3,000 s (default 4, as the data judged).
int referenceBatches = 4;

/// Judges @p data (made with the plant options @p o) alone or against the seed's reference.
Outcome judge(const std::vector<data::SiBatch>& data, const plant::PlantOptions& o,
              const std::string& hidden);

Outcome run(plant::PlantOptions o, const std::string& hidden) {
    o.batches = 4;
    o.samples = 3000;
    auto p = plant::runPlant(o);
    if (!p) {
        Outcome out;
        out.named = "plant failed: " + p.error().message();
        return out;
    }
    return judge(plant::toSiBatches(*p, o.seed), o, hidden);
}

/// A change at a batch change: two healthy batches of the seed, then two batches of another run of
/// the line with the mechanism (B03, B04), judged against the seed's reference.
Outcome runFromThirdBatch(plant::PlantOptions o, const std::string& hidden) {
    o.batches = 2;
    o.samples = 3000;
    plant::PlantOptions healthy = o;
    healthy.effects.clear();
    healthy.effectOnsetS.clear();
    auto before = plant::runPlant(healthy);
    plant::PlantOptions changed = o;
    changed.seed = o.seed + kChangedRunSeedOffset;
    auto after = plant::runPlant(changed);
    if (!before || !after) {
        Outcome out;
        out.named = "plant failed: " + (!before ? before : after).error().message();
        return out;
    }
    std::vector<data::SiBatch> week = plant::toSiBatches(*before, healthy.seed);
    int number = static_cast<int>(week.size());
    for (auto& b : plant::toSiBatches(*after, changed.seed)) {
        char id[16];
        std::snprintf(id, sizeof id, "B%02d", ++number);
        b.id = id;
        week.push_back(std::move(b));
    }
    return judge(week, o, hidden);
}

/// --part mid-batch-change: two healthy batches, the change from @p onsetS into the third, and a
/// fourth changed from its start: a fault that began during a batch and was not repaired.
Outcome runFromMidThirdBatch(plant::PlantOptions o, const std::string& hidden, plant::Mechanism m,
                             double onsetS) {
    o.batches = 2;
    o.samples = 3000;
    plant::PlantOptions healthy = o;
    healthy.effects.clear();
    healthy.effectOnsetS.clear();
    auto before = plant::runPlant(healthy);
    plant::PlantOptions third = o;
    third.batches = 1;
    third.seed = o.seed + kChangedRunSeedOffset;
    third.effectOnsetS[m] = onsetS;
    auto during = plant::runPlant(third);
    plant::PlantOptions fourth = o;
    fourth.batches = 1;
    fourth.seed = o.seed + kChangedRunSeedOffset + 1;
    fourth.effectOnsetS.clear();
    auto after = plant::runPlant(fourth);
    if (!before || !during || !after) {
        Outcome out;
        out.named = "plant failed: " + (!before ? before : !during ? during : after).error().message();
        return out;
    }
    std::vector<data::SiBatch> week = plant::toSiBatches(*before, healthy.seed);
    int number = static_cast<int>(week.size());
    for (const auto* run : {&*during, &*after}) {
        for (auto& b : plant::toSiBatches(*run, run == &*during ? third.seed : fourth.seed)) {
            char id[16];
            std::snprintf(id, sizeof id, "B%02d", ++number);
            b.id = id;
            week.push_back(std::move(b));
        }
    }
    return judge(week, o, hidden);
}

Outcome judge(const std::vector<data::SiBatch>& data, const plant::PlantOptions& o,
              const std::string& hidden) {
    Outcome out;
    const auto t0 = std::chrono::steady_clock::now();
    auto asked = discoveryOptions;
    if (oracle && !hidden.empty()) {
        asked.causes = {hidden};
        asked.screenAlpha = 0.49; // fitted whenever its tangent points the way that helps
        asked.maxCauses = 1;
    }
    Expected<discovery::DiscoveryResult> r = Error{};
    if (againstReference) {
        plant::PlantOptions healthy = o;
        healthy.effects.clear();
        healthy.effectOnsetS.clear();
        // The same line in normal operation: where it drifts (an unmeasured disturbance that
        // comes and goes), the reference drifts too; its sensors fault as often.
        healthy.seed = o.seed + kReferenceSeedOffset;
        healthy.batches = referenceBatches;
        auto ref = plant::runPlant(healthy);
        if (!ref) {
            out.named = "reference plant failed: " + ref.error().message();
            return out;
        }
        r = discovery::discoverChange(plant::toSiBatches(*ref, healthy.seed), data, hybrid::HybridModel{},
                                      asked);
        if (r) {
            out.drytwinFlags = r->detection.drytwinChanged;
            out.pcaFlags = r->detection.pca.changed;
            for (const auto& b : r->batchesBeforeChange) {
                out.leftOut += (out.leftOut.empty() ? "" : " ") + b;
            }
            if (verbose) { // which half of each detector decided, and by how much
                const auto& d = r->detection;
                std::printf(
                    "  detection: DryTwin monitor %s p %.4g (%s); cause test %s p %.4g (%s%s); PCA %s p %.4g "
                    "(%s)\n",
                    d.drytwin.changed ? "CHANGED" : "normal", d.drytwin.pValue, d.drytwin.statistic.c_str(),
                    d.causeTest.changed ? "CHANGED" : "normal", d.causeTest.pValue, d.causeTest.cause.c_str(),
                    d.causeTest.secondLook ? ", second look" : "", d.pca.changed ? "CHANGED" : "normal",
                    d.pca.pValue, d.pca.statistic.c_str());
            }
        }
    } else {
        r = discovery::discover(data, hybrid::HybridModel{}, asked);
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r) {
        out.named = "error: " + r.error().message();
        return out;
    }
    for (const auto& f : r->findings) {
        std::string name = f.cause;
        bool inGroup = f.cause == hidden;
        for (const auto& l : f.lookAlikes) {
            if (!l.ruledOut) {
                name += "|" + l.cause;
                inGroup = inGroup || l.cause == hidden;
            }
        }
        out.named += (out.named.empty() ? "" : "+") + name;
        out.falseNames += !inGroup;
    }
    if (!r->findings.empty()) {
        const auto& f = r->findings.front();
        out.asGroup = !f.group.empty();
        out.rightFirst = f.cause == hidden;
        for (const auto& l : f.lookAlikes) {
            out.rightFirst = out.rightFirst || (!l.ruledOut && l.cause == hidden);
        }
        out.hasOnset = f.hasOnset;
        out.onsetS = f.onsetS;
        out.value = f.value;
    }
    if (verbose && !out.named.empty()) { // the look-alikes' numbers and what was turned down
        char text[256];
        for (const auto& f : r->findings) {
            std::snprintf(text, sizeof text, " [%s %.3g (z %.2f, held-out p %.2g, explains %.0f/%.0f %%)",
                          f.cause.c_str(), f.value, f.changeZ, f.gain.pValue, 100 * f.explainedFraction,
                          100 * f.explainedFractionFast);
            out.named += text;
            if (f.hasOnset) {
                std::snprintf(text, sizeof text, " from %.1f min [%.1f, %.1f]", f.onsetS / 60,
                              f.onsetLowS / 60, f.onsetHighS / 60);
                out.named += text;
            }
            for (const auto& l : f.lookAlikes) {
                std::snprintf(text, sizeof text, "; %s %.3g ratio %.3g p %.2g%s", l.cause.c_str(), l.value,
                              l.heldOutLossRatio, l.pValue, l.ruledOut ? " out" : "");
                out.named += text;
                if (l.byChannels) {
                    std::snprintf(text, sizeof text, " (channels: X %.3g s, T %.3g s)", l.moistureDelayS,
                                  l.temperatureDelayS);
                    out.named += text;
                }
            }
            out.named += "]";
        }
        for (const auto& rd : r->rounds) {
            for (const auto& x : rd.rejected) {
                out.named += " {" + x.cause + ": " + x.code + ": " + x.reason + "}";
            }
        }
    }
    if (out.named.empty()) {
        // Why nothing was named: each candidate that was tried and turned down, with its reason.
        std::string why;
        for (const auto& rd : r->rounds) {
            for (const auto& x : rd.rejected) {
                why += (why.empty() ? "; " : ", ") + x.cause + ": " + x.code +
                       (verbose ? " [" + x.reason + "]" : "");
            }
        }
        out.named = "(" + r->verdict + why + ")";
    }
    if (oracle && !hidden.empty()) { // the hidden cause's own held-out evidence, named or not
        char text[200];
        if (!r->findings.empty()) {
            const auto& f = r->findings.front();
            std::snprintf(text, sizeof text, " <oracle named p %.2g share %.3f fast %.3f>", f.gain.pValue,
                          f.explainedFraction, f.explainedFractionFast);
        } else if (!r->rounds.empty() && !r->rounds.front().rejected.empty()) {
            const auto& rd = r->rounds.front();
            std::snprintf(text, sizeof text, " <oracle %s p %.2g share %.3f fast %.3f>",
                          rd.rejected.front().code.c_str(), rd.heldOutPValue, rd.explainedFraction,
                          rd.explainedFractionFast);
        } else {
            std::snprintf(text, sizeof text, " <oracle not_fitted>");
        }
        out.named += text;
    }
    if (verbose) { // the first round's candidates: fitted or not, the screen and the predicted share
        std::string ranking;
        for (const auto& c : r->ranking) {
            char text[160];
            std::snprintf(text, sizeof text, "%s%s p %.2g pred %.0f %% est %.3g±%.2g%s",
                          ranking.empty() ? "" : ", ", c.cause.c_str(), c.pValue, 100 * c.predictedReduction,
                          c.linearEstimate, c.linearSe, c.fitted ? " fitted" : "");
            ranking += text;
        }
        out.named += " <ranking: " + ranking + ">";
    }
    return out;
}

} // namespace

int main(int argc, char** argv) {
    bool quick = false;
    std::string part = "all";
    std::string only; ///< one mechanism's runs alone (mechanisms and onsets), for a quick look
    // The nulls' seeds: 201-220 by default; other seeds choose a setting on nulls the study's
    // own nulls then judge (never choose it on the runs that report it).
    unsigned firstNullSeed = 201;
    // The mechanism runs' seeds (three from it; the onsets add 100): 101 by default, others to
    // choose a setting on runs the study does not report.
    unsigned firstSeed = 101;
    plant::PlantKind kind = plant::PlantKind::Distributed;
    plant::SensorMode sensors = plant::SensorMode::Default;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const std::string next = i + 1 < argc ? argv[i + 1] : "";
        if (a == "--quick") {
            quick = true;
        } else if (a == "--plant" && (next == "distributed" || next == "lumped")) {
            kind = next == "lumped" ? plant::PlantKind::Lumped : plant::PlantKind::Distributed;
            ++i;
        } else if (a == "--sensors" && (next == "realistic" || next == "ideal" || next == "default")) {
            sensors = next == "realistic" ? plant::SensorMode::Realistic
                      : next == "ideal"   ? plant::SensorMode::Ideal
                                          : plant::SensorMode::Default;
            ++i;
        } else if (a == "--part" && (next == "mechanisms" || next == "nulls" || next == "onsets" ||
                                     next == "batch-change" || next == "mid-batch-change")) {
            part = next;
            ++i;
        } else if (a == "--verbose") {
            verbose = true;
        } else if (a == "--oracle") {
            oracle = true;
        } else if (a == "--reference") {
            againstReference = true;
        } else if (a == "--no-constancy") { // the rules before 2026-11-26, for a before/after
            discoveryOptions.checkConstancyWithinBatch = false;
        } else if (a == "--look-alike-overall") {
            discoveryOptions.lookAlikeWorseOnNoOutput = false;
        } else if (a == "--size-rule") { // against a reference: no output made worse, as before 2026-11-27
            discoveryOptions.referenceJudgesDirection = false;
        } else if (a == "--undetected-at-5-percent") { // against a reference: 1.96 also before a detection
            discoveryOptions.undetectedChangeAtDetectorRate = false;
        } else if (a == "--spread-bound") { // against a reference: naming at the spread's upper bound always
            discoveryOptions.pointSpreadOnceDetected = false;
        } else if (a == "--share-of-whole") { // against a reference: the floor of the whole error only
            discoveryOptions.shareOfChangeOnceDetected = false;
        } else if (a ==
                   "--structure-extrapolates") { // against a reference: the ridge beyond its range, as before
            discoveryOptions.lineStructureWithinReferenceRange = false;
        } else if (a == "--spread-all-parts") { // against a reference: every batch in the normal spread, as
                                                // before 2026-11-29
            discoveryOptions.normalSpreadWithinReferenceConditions = false;
        } else if (a == "--later-cause-by-direction") { // against a reference: a cause after another
                                                        // judged as the first, as before 2026-12-08
            discoveryOptions.laterCauseImprovesEveryOutput = false;
        } else if (a == "--share-over-every-channel") { // a downstream cause's share over every
                                                        // channel only, as before 2026-11-29
            discoveryOptions.shareOnTheChannelsItActsOn = false;
        } else if (a == "--cause-test-screen-only") { // against a reference: no second look at named fits
            discoveryOptions.causeTestAtNamedFits = false;
        } else if (a == "--judge-every-batch") { // against a reference: no batch left out before the change
            discoveryOptions.judgeFromChangeOn = false;
        } else if (a == "--onset-in-every-batch") { // t_onset from every batch's start, as before 2026-11-28
                                                    // (evening)
            discoveryOptions.changeGoesOnIntoLaterBatches = false;
        } else if (a == "--lag-from-start") { // against a reference: no lag fitted from the change point
            discoveryOptions.lagFromChangePoint = false;
        } else if (a == "--no-structure") { // against a reference: the causes' normal values alone
            discoveryOptions.learnLineStructure = false;
        } else if (a == "--reference-batches" && std::atoi(next.c_str()) >= 2) {
            referenceBatches = std::atoi(next.c_str());
            ++i;
        } else if (a == "--mechanism" && !next.empty()) {
            only = next;
            ++i;
        } else if (a == "--null-seeds" && std::atoi(next.c_str()) > 0) {
            firstNullSeed = static_cast<unsigned>(std::atoi(next.c_str()));
            ++i;
        } else if (a == "--seeds" && std::atoi(next.c_str()) > 0) {
            firstSeed = static_cast<unsigned>(std::atoi(next.c_str()));
            ++i;
        } else if (a == "--unimproved-alpha" && std::atof(next.c_str()) > 0 && std::atof(next.c_str()) <= 1) {
            discoveryOptions.unimprovedChannelAlpha = std::atof(next.c_str());
            ++i;
        } else if (a == "--min-explained" && std::atof(next.c_str()) >= 0 && std::atof(next.c_str()) < 1) {
            discoveryOptions.minExplainedFraction = std::atof(next.c_str());
            ++i;
        } else if (a == "--candidates" && std::atoi(next.c_str()) > 0) {
            discoveryOptions.candidatesToFit = std::atoi(next.c_str());
            ++i;
        } else if (a == "--evaluations" && std::atoi(next.c_str()) >= 10) {
            discoveryOptions.maxEvaluationsPerFit = std::atoi(next.c_str());
            ++i;
        } else {
            std::fprintf(
                stderr, "usage: study_discovery [--quick] [--plant distributed|lumped] "
                        "[--sensors realistic|ideal|default] [--part "
                        "mechanisms|nulls|onsets|batch-change|mid-batch-change] "
                        "[--mechanism NAME] [--verbose] [--seeds FIRST] [--null-seeds FIRST] "
                        "[--min-explained SHARE] [--unimproved-alpha A] [--candidates N] "
                        "[--evaluations N] [--oracle] [--reference] [--reference-batches N] [--no-structure] "
                        "[--structure-extrapolates] [--spread-all-parts] [--share-over-every-channel] "
                        "[--later-cause-by-direction] "
                        "[--cause-test-screen-only] "
                        "[--keep-taken-up] "
                        "[--lag-from-start] [--judge-every-batch] [--onset-in-every-batch] [--size-rule] "
                        "[--spread-bound] [--undetected-at-5-percent] [--share-of-whole] "
                        "[--no-constancy] [--look-alike-overall]\n");
            return 2;
        }
    }
    const auto options = [&] {
        plant::PlantOptions o;
        o.plant = kind;
        o.sensors = sensors;
        return o;
    };
    std::printf("Plant: %s, sensors: %s\n", std::string(plant::plantKindName(kind)).c_str(),
                options().realisticSensors()          ? "realistic"
                : sensors == plant::SensorMode::Ideal ? "ideal"
                                                      : "built-in");
    std::printf("A named cause removes at least %.0f %% of the held-out error left (or of its fast part); "
                "nulls from seed %u.\n\n",
                100 * discoveryOptions.minExplainedFraction, firstNullSeed);
    const unsigned seeds[] = {firstSeed, firstSeed + 1, firstSeed + 2};
    const int nSeeds = quick ? 1 : 3;
    // A realistic strength, and half of it. The sensor causes, the outlet meter's offset among
    // them: the plant's typical value and twice it, since half would be within the instrument's
    // stated accuracy, below which a cause is not named (a 0.1 % wb meter offset is within the
    // meter's 0.15 % wb: turning it down as below_floor is the right answer, not a miss; until
    // 2026-11-25 the meter offset ran at 0.2 and 0.1 against this rule).
    const std::tuple<plant::Mechanism, double, double> cases[] = {
        {plant::Mechanism::TubeWallHeatLoss, 0.3, 0.5},
        {plant::Mechanism::GasPhaseCoupling, 0.5, 0.5},
        {plant::Mechanism::HeatTransferFouling, 0.2, 0.5},
        {plant::Mechanism::MoistureMeterLag, 30, 0.5},
        {plant::Mechanism::MoistureMeterOffset, 0.2, 2},
        {plant::Mechanism::TransportDelayError, 15, 0.5},
        {plant::Mechanism::FallingRateDrying, 0.5, 0.5},
        {plant::Mechanism::AmbientReabsorption, 3, 0.5},
        {plant::Mechanism::InletMoistureSensorOffset, 0.5, 2},
        {plant::Mechanism::HotAirSensorLag, 30, 2},
        {plant::Mechanism::InletMoistureSensorNoise, 0.4, 2}};
    int runs = 0, right = 0, asGroup = 0, withFalse = 0;
    int flaggedEither = 0, rightWhenFlagged = 0, pcaFlagged = 0, pcaMissedByDrytwin = 0;
    int pcaFlaggedHealthySeed = 0, pcaMissedOnHealthyFlaggedSeed = 0, drytwinFlaggedHealthySeed = 0;
    const auto flags = [](const Outcome& out) {
        return againstReference ? std::string(out.drytwinFlags ? "D" : "-") + (out.pcaFlags ? "P" : "-")
                                : std::string("");
    };
    if (part == "all" || part == "mechanisms") {
        std::printf("| mechanism | strength | seed | named | right first | detected (D DryTwin, P PCA) | s "
                    "|\n| --- | "
                    "--- | --- | --- | --- | --- | --- |\n");
        // Against a reference: each seed's own healthy run (the same line, weather and sensor faults,
        // no mechanism), judged first. A detector that flags it flags that seed's conditions (a
        // weather the reference never saw), not the mechanism: its flags on that seed's mechanism
        // runs are counted apart.
        bool healthyPcaFlags[3] = {false, false, false}, healthyDrytwinFlags[3] = {false, false, false};
        if (againstReference) {
            for (int s = 0; s < nSeeds; ++s) {
                plant::PlantOptions o = options();
                o.seed = seeds[s];
                const auto out = run(o, "");
                healthyPcaFlags[s] = out.pcaFlags;
                healthyDrytwinFlags[s] = out.drytwinFlags;
                std::printf("| (none: the seed's healthy run) | 0 | %u | %s | - | %s | %.1f |\n", o.seed,
                            out.named.c_str(), flags(out).c_str(), out.seconds);
            }
        }
        for (const auto& [m, strength, other] : cases) {
            if (!only.empty() && only != plant::info(m).name) {
                continue;
            }
            for (double scale : {1.0, other}) {
                for (int s = 0; s < nSeeds; ++s) {
                    plant::PlantOptions o = options();
                    o.seed = seeds[s];
                    o.effects[m] = strength * scale;
                    const std::string hidden(plant::info(m).name);
                    const auto out = run(o, hidden);
                    ++runs;
                    right += out.rightFirst;
                    asGroup += out.rightFirst && out.asGroup;
                    withFalse += out.falseNames > 0;
                    flaggedEither += out.drytwinFlags || out.pcaFlags;
                    rightWhenFlagged += (out.drytwinFlags || out.pcaFlags) && out.rightFirst;
                    pcaFlagged += out.pcaFlags;
                    pcaMissedByDrytwin += out.pcaFlags && !out.drytwinFlags;
                    pcaFlaggedHealthySeed += out.pcaFlags && healthyPcaFlags[s];
                    pcaMissedOnHealthyFlaggedSeed += out.pcaFlags && !out.drytwinFlags && healthyPcaFlags[s];
                    drytwinFlaggedHealthySeed += out.drytwinFlags && healthyDrytwinFlags[s];
                    std::printf("| %s | %g | %u | %s%s | %s | %s | %.1f |\n", hidden.c_str(),
                                strength * scale, o.seed, out.named.c_str(),
                                out.leftOut.empty() ? "" : (" (judged without " + out.leftOut + ")").c_str(),
                                out.rightFirst ? (out.asGroup ? "yes (group)" : "yes") : "no",
                                flags(out).c_str(), out.seconds);
                    std::fflush(stdout);
                }
            }
        }
    }
    int nullRuns = 0, nullFalse = 0, nullAlarms = 0;
    if (part == "all" || part == "nulls") {
        std::printf("\n| null | seed | named | detected | s |\n| --- | --- | --- | --- | --- |\n");
        for (int s = 0; s < (quick ? 4 : 20); ++s) {
            plant::PlantOptions o = options();
            o.seed = firstNullSeed + static_cast<unsigned>(s);
            o.unmeasuredDrift = s % 2 == 1;
            const bool faults = (s / 2) % 2 == 1; // spikes, stuck values and dropouts, or none
            if (!faults) {
                o.sensorFaults = plant::SensorFaultRates{0, 0, 0};
            }
            const auto out = run(o, "");
            ++nullRuns;
            nullFalse += out.falseNames > 0;
            nullAlarms += out.drytwinFlags || out.pcaFlags;
            std::printf("| none%s%s | %u | %s | %s | %.1f |\n", o.unmeasuredDrift ? ", drift" : "",
                        faults ? ", sensor faults" : "", o.seed, out.named.c_str(), flags(out).c_str(),
                        out.seconds);
            std::fflush(stdout);
        }
    }
    int onsetRuns = 0, onsetRight = 0;
    if (part == "all" || part == "onsets") {
        // Onsets between 8 and 28 min into each 50 min batch (inside the training part).
        std::printf(
            "\n| mechanism (onset) | seed | onset true [min] | named | onset found [min] | within 10 min "
            "|\n| --- | --- | --- | --- | --- | --- |\n");
        const std::pair<plant::Mechanism, double> onsetCases[] = {
            {plant::Mechanism::MoistureMeterLag, 60},
            {plant::Mechanism::MoistureMeterOffset, 0.5},
            {plant::Mechanism::HotAirSensorLag, 60},
            {plant::Mechanism::InletMoistureSensorOffset, 1.0}};
        for (const auto& [m, strength] : onsetCases) {
            if (!only.empty() && only != plant::info(m).name) {
                continue;
            }
            for (int s = 0; s < nSeeds; ++s) {
                plant::PlantOptions o = options();
                o.seed = seeds[s] + 100;
                o.effects[m] = strength;
                const double onset = 60.0 * (8 + (o.seed * 7919 % 21));
                o.effectOnsetS[m] = onset;
                const std::string hidden(plant::info(m).name);
                const auto out = run(o, hidden);
                ++onsetRuns;
                // Against a reference the issue asks for ±5 min; alone, ±10 min (issue #23).
                const bool close = out.rightFirst && out.hasOnset &&
                                   std::abs(out.onsetS - onset) <= (againstReference ? 300 : 600);
                onsetRight += close;
                std::printf("| %s | %u | %.0f | %s | %s | %s |\n", hidden.c_str(), o.seed, onset / 60,
                            out.named.c_str(),
                            out.hasOnset ? std::to_string(out.onsetS / 60).substr(0, 5).c_str() : "-",
                            close ? "yes" : "no");
                std::fflush(stdout);
            }
        }
    }
    int changeRuns = 0, changeRight = 0, changeLeftOutRight = 0, changeFlagged = 0;
    if (againstReference && (part == "all" || part == "batch-change")) {
        // The change begins at a batch change: the third of four batches (a failed cleaning, a
        // maintenance). Each mechanism at its realistic strength, three seeds.
        std::printf(
            "\n| mechanism (from the third batch) | strength | seed | named | right first | batches left out "
            "| detected | s |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (const auto& [m, strength, other] : cases) {
            if (!only.empty() && only != plant::info(m).name) {
                continue;
            }
            for (int s = 0; s < nSeeds; ++s) {
                plant::PlantOptions o = options();
                o.seed = seeds[s] + 200;
                o.effects[m] = strength;
                const std::string hidden(plant::info(m).name);
                const auto out = runFromThirdBatch(o, hidden);
                ++changeRuns;
                changeRight += out.rightFirst;
                changeLeftOutRight += out.leftOut == "B01 B02";
                changeFlagged += out.drytwinFlags || out.pcaFlags;
                std::printf("| %s | %g | %u | %s | %s | %s | %s | %.1f |\n", hidden.c_str(), strength, o.seed,
                            out.named.c_str(), out.rightFirst ? (out.asGroup ? "yes (group)" : "yes") : "no",
                            out.leftOut.empty() ? "-" : out.leftOut.c_str(), flags(out).c_str(), out.seconds);
                std::fflush(stdout);
            }
        }
    }
    int midRuns = 0, midRight = 0, midOnsetClose = 0;
    double midValueError = 0;
    if (againstReference && part == "mid-batch-change") {
        // The change begins during the third of four batches and goes on in the fourth from its
        // start (not repaired). Each mechanism at its realistic strength, three seeds; the onset
        // between 8 and 28 min into the third batch.
        std::printf(
            "\n| mechanism (from mid-B03 on) | strength | seed | onset true [min] | named | right first | "
            "onset found [min] | value / true | batches left out | detected | s |\n"
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (const auto& [m, strength, other] : cases) {
            if (!only.empty() && only != plant::info(m).name) {
                continue;
            }
            for (int s = 0; s < nSeeds; ++s) {
                plant::PlantOptions o = options();
                o.seed = seeds[s] + 200;
                o.effects[m] = strength;
                const double onset = 60.0 * (8 + (o.seed * 7919 % 21));
                const std::string hidden(plant::info(m).name);
                const auto out = runFromMidThirdBatch(o, hidden, m, onset);
                ++midRuns;
                midRight += out.rightFirst;
                const bool close = out.rightFirst && out.hasOnset && std::abs(out.onsetS - onset) <= 300;
                midOnsetClose += close;
                const double ratio = out.rightFirst && strength != 0 ? out.value / strength : 0;
                if (out.rightFirst) {
                    midValueError += std::abs(std::log(std::max(ratio, 1e-3)));
                }
                std::printf("| %s | %g | %u | %.0f | %s | %s | %s | %s | %s | %s | %.1f |\n", hidden.c_str(),
                            strength, o.seed, onset / 60, out.named.c_str(),
                            out.rightFirst ? (out.asGroup ? "yes (group)" : "yes") : "no",
                            out.hasOnset ? std::to_string(out.onsetS / 60).substr(0, 5).c_str() : "-",
                            out.rightFirst ? std::to_string(ratio).substr(0, 5).c_str() : "-",
                            out.leftOut.empty() ? "-" : out.leftOut.c_str(), flags(out).c_str(), out.seconds);
                std::fflush(stdout);
            }
        }
    }
    if (runs > 0) {
        std::printf("\nHidden cause named first: %d of %d (%.0f %%), %d of them as a look-alike group. Runs "
                    "naming a cause that is not there: %d of %d.\n",
                    right, runs, 100.0 * right / runs, asGroup, withFalse, runs);
        if (againstReference) {
            std::printf(
                "Flagged by either detector: %d of %d; of those, hidden cause named first: %d. PCA flags "
                "%d, of which DryTwin's detector misses %d.\n",
                flaggedEither, runs, rightWhenFlagged, pcaFlagged, pcaMissedByDrytwin);
            std::printf(
                "On seeds whose own healthy run a detector flags too (its conditions, not the mechanism): "
                "PCA "
                "flags %d (DryTwin misses %d of them), DryTwin %d. So on the other seeds DryTwin misses %d "
                "of the %d runs the PCA flags.\n",
                pcaFlaggedHealthySeed, pcaMissedOnHealthyFlaggedSeed, drytwinFlaggedHealthySeed,
                pcaMissedByDrytwin - pcaMissedOnHealthyFlaggedSeed, pcaFlagged - pcaFlaggedHealthySeed);
        }
    }
    if (nullRuns > 0) {
        std::printf("Nulls naming a cause: %d of %d (%.0f %%).\n", nullFalse, nullRuns,
                    100.0 * nullFalse / nullRuns);
        if (againstReference) {
            std::printf("Nulls with an alarm (either detector): %d of %d.\n", nullAlarms, nullRuns);
        }
    }
    if (changeRuns > 0) {
        std::printf(
            "From the third batch: hidden cause named first %d of %d (%.0f %%); the two healthy batches "
            "left out (and no other) in %d; flagged by either detector %d.\n",
            changeRight, changeRuns, 100.0 * changeRight / changeRuns, changeLeftOutRight, changeFlagged);
    }
    if (midRuns > 0) {
        std::printf(
            "From mid-B03 on: hidden cause named first %d of %d (%.0f %%), with the onset within 5 min "
            "%d; mean |log(value / true)| of the right ones %.3f.\n",
            midRight, midRuns, 100.0 * midRight / midRuns, midOnsetClose,
            midRight > 0 ? midValueError / midRight : 0.0);
    }
    if (onsetRuns > 0) {
        std::printf("Onsets named with the onset within %d min: %d of %d (%.0f %%).\n",
                    againstReference ? 5 : 10, onsetRight, onsetRuns, 100.0 * onsetRight / onsetRuns);
    }
    return 0;
}
