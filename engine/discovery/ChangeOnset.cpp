// Where a change against the reference began: the first batch DryTwin's monitor sees it in, the
// detector whose change point sets the onset, and the later batches that read changed from their
// start (ReferenceDiscovery.cpp judges the causes from there on).
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

/// The first batch from which DryTwin's monitor sees the change: the run that holds its change
/// point's 95 % interval's low end, where every run before it also reads as the reference did
/// (0 when no change, or no onset, was found). The interval alone is not enough: a wall loss
/// present in all four batches had its change point in the second (its first batch shifted a
/// little less), and the causes were judged without the first. So each earlier run's mean of the
/// deciding statistic must lie nearer the reference's (0) than the later runs' mean, and its
/// level must have been judged at all.
std::size_t firstBatchOfChange(const monitoring::Detection& d) {
    if (!d.changed || !d.hasOnset || d.onsetLowWindow < 0 ||
        static_cast<std::size_t>(d.onsetLowWindow) >= d.series.size()) {
        return 0;
    }
    const int first = std::max(0, d.series[static_cast<std::size_t>(d.onsetLowWindow)].runIndex);
    if (first == 0) {
        return 0;
    }
    const bool bySpe = d.statistic == "SPE";
    std::map<int, std::pair<double, int>> sums; // run -> (sum of z, windows)
    for (const auto& pt : d.series) {
        const double z = bySpe ? pt.zSpe : pt.zT2;
        if (std::isfinite(z)) {
            sums[pt.runIndex].first += z;
            ++sums[pt.runIndex].second;
        }
    }
    double laterSum = 0;
    int laterCount = 0;
    for (const auto& [run, sc] : sums) {
        if (run >= first) {
            laterSum += sc.first;
            laterCount += sc.second;
        }
    }
    const double later = laterCount > 0 ? laterSum / laterCount : 0.0;
    for (int run = 0; run < first; ++run) {
        const auto it = sums.find(run);
        if (it == sums.end() || it->second.second == 0) {
            return 0; // a run no window judges: nothing says it ran as the reference did
        }
        const std::string& id =
            d.series[static_cast<std::size_t>(d.runStarts[static_cast<std::size_t>(run)])].run;
        if (std::find(d.levelNotJudged.begin(), d.levelNotJudged.end(), id) != d.levelNotJudged.end()) {
            return 0;
        }
        if (it->second.first / it->second.second > 0.5 * later) {
            return 0;
        }
    }
    return static_cast<std::size_t>(first);
}

/// The detector whose change point the causes' onset is taken from: DryTwin's monitor where it
/// found one, else the PCA monitor's; none where neither did.
const monitoring::Detection* changePointDetector(const ChangeDetection& detection) {
    for (const auto* d : {&detection.drytwin, &detection.pca}) {
        if (d->changed && d->hasOnset) {
            return d;
        }
    }
    return nullptr;
}

/// The batches after the one a change began in that read changed from their start: a fault that
/// began 20 min into B03 and was not repaired is in B04 from its first minute, while t_onset
/// counts from each batch's start. A batch reads so when the deciding statistic's mean over its
/// windows that end before the onset time is above the reference's (0) and at least half its mean
/// after that time: the rule firstBatchOfChange uses for a batch that ran as the reference did,
/// turned round. A change that recurs at the same minute of every batch (a shift's routine, the
/// study's onsets) leaves those first minutes at the reference's level and keeps its onset there.
/// Only where batches that ran as the reference did come before the change (@p firstJudged > 0,
/// judgeFromChangeOn) and the change point lies in a judged batch: then the onset batch's first
/// minutes are healthy by that judgement. With the change in the data's first batch, an onset
/// there cannot be told from a change present from every start that shows only as it grows
/// (fouling, whose change point fell 10-32 min into B01 on seeds 321-322 of the study, the later
/// batches' first minutes raised as well: taken from their start, fouling was fitted from the
/// change point and a second cause named beside it on 2 runs of 66).
/// Indices are the runs' in the judged order (the new data's batches).
std::vector<std::size_t> batchesChangedFromStart(const monitoring::Detection& d, std::size_t firstJudged) {
    std::vector<std::size_t> out;
    if (firstJudged == 0 || !d.changed || !d.hasOnset || d.onsetWindow < 0 ||
        static_cast<std::size_t>(d.onsetWindow) >= d.series.size() || d.onsetS <= 0) {
        return out;
    }
    const int onsetRun = d.series[static_cast<std::size_t>(d.onsetWindow)].runIndex;
    if (onsetRun < static_cast<int>(firstJudged)) {
        return out;
    }
    const bool bySpe = d.statistic == "SPE";
    struct Means {
        double before = 0, after = 0;
        int nBefore = 0, nAfter = 0;
    };
    std::map<int, Means> runs;
    for (const auto& pt : d.series) {
        const double z = bySpe ? pt.zSpe : pt.zT2;
        if (pt.runIndex <= onsetRun || !std::isfinite(z)) {
            continue;
        }
        auto& m = runs[pt.runIndex];
        if (pt.timeS <= d.onsetS) {
            m.before += z;
            ++m.nBefore;
        } else {
            m.after += z;
            ++m.nAfter;
        }
    }
    for (const auto& [run, m] : runs) {
        if (m.nBefore == 0 || m.nAfter == 0) {
            continue; // nothing before the onset time to tell by, or nothing after
        }
        const double before = m.before / m.nBefore, after = m.after / m.nAfter;
        if (before > 0 && before >= 0.5 * after) {
            out.push_back(static_cast<std::size_t>(run));
        }
    }
    return out;
}

} // namespace drytwin::discovery::detail
