#include "data/Cleaning.h"

#include "common/NumberText.h"

#include <algorithm>
#include <cmath>

namespace drytwin::data {

Status CleaningOptions::validate() const {
    if (!(minXhdtPct >= 0 && minXhdtPct < 100)) {
        return Error{ErrorKind::BadInput, "minXhdtPct", "must lie in [0, 100) % wet basis"};
    }
    if (!(minThdtC > -50 && minThdtC < 300)) {
        return Error{ErrorKind::BadInput, "minThdtC", "must lie in (-50, 300) °C"};
    }
    if (!(minFeedKgPerHour >= 0 && std::isfinite(minFeedKgPerHour))) {
        return Error{ErrorKind::BadInput, "minFeedKgPerHour", "must be a finite value ≥ 0 kg/h"};
    }
    if (!(stuckMinS > 0 && std::isfinite(stuckMinS)) ||
        !(stuckRunFactor >= 1 && std::isfinite(stuckRunFactor))) {
        return Error{ErrorKind::BadInput, "stuckMinS / stuckRunFactor",
                     "a frozen reading needs a positive least duration [s] and a run factor ≥ 1"};
    }
    return {};
}

namespace {

/// Runs of exactly identical finite readings of one column, as [begin, end) rows.
std::vector<std::pair<std::size_t, std::size_t>> identicalRuns(const std::vector<double>& v) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    std::size_t begin = 0;
    for (std::size_t r = 1; r <= v.size(); ++r) {
        if (r == v.size() || !(v[r] == v[begin])) { // NaN ends a run (and starts none)
            if (std::isfinite(v[begin])) {
                runs.emplace_back(begin, r);
            }
            begin = r;
        }
    }
    return runs;
}

/// Frozen stretches of every measured column (not the setpoint, which is written, not measured):
/// runs of identical readings far longer than the column's own usual ones.
std::vector<CleaningReport::StuckSpan> frozenReadings(const DataSet& data, const CleaningOptions& o) {
    std::vector<CleaningReport::StuckSpan> spans;
    for (const auto& cs : columnSpecs()) {
        if (cs.role == ColumnRole::Index || cs.id == Column::THotSp) {
            continue;
        }
        // Each batch's runs, found once: their lengths say what is usual, the long ones are flagged.
        std::vector<std::vector<std::pair<std::size_t, std::size_t>>> runs(data.batches.size());
        std::vector<std::size_t> lengths;
        for (std::size_t bi = 0; bi < data.batches.size(); ++bi) {
            if (const auto* v = data.batches[bi].values(cs.id)) {
                runs[bi] = identicalRuns(*v);
                for (const auto& [from, to] : runs[bi]) {
                    lengths.push_back(to - from);
                }
            }
        }
        if (lengths.size() < 20) {
            // Too few changes to say what is usual for this column. An outlet or tube-outlet
            // transmitter of a running line is never that still: one that holds its value for ten
            // minutes or more (a whole file of 12.0, a fresh user's test, calibrated with exit 0)
            // is dead or filled in. Ambient and input columns may legitimately hold a coarse value.
            if (cs.role != ColumnRole::Output) {
                continue;
            }
            for (std::size_t bi = 0; bi < data.batches.size(); ++bi) {
                const auto* v = data.batches[bi].values(cs.id);
                const auto* t = data.batches[bi].values(Column::Time);
                for (const auto& [from, to] : runs[bi]) {
                    const double seconds = t && std::isfinite((*t)[to - 1]) && std::isfinite((*t)[from])
                                               ? (*t)[to - 1] - (*t)[from]
                                               : static_cast<double>(to - from) - 1;
                    if (seconds >= std::max(600.0, o.stuckMinS)) {
                        spans.push_back({bi, cs.id, from, to, (*v)[from], seconds});
                    }
                }
            }
            continue;
        }
        const auto at = lengths.begin() + static_cast<std::ptrdiff_t>(0.99 * double(lengths.size() - 1));
        std::nth_element(lengths.begin(), at, lengths.end());
        const double usualRows = static_cast<double>(*at);
        for (std::size_t bi = 0; bi < data.batches.size(); ++bi) {
            const auto* v = data.batches[bi].values(cs.id);
            const auto* t = data.batches[bi].values(Column::Time);
            for (const auto& [from, to] : runs[bi]) {
                const double rows = static_cast<double>(to - from);
                const double seconds = t && std::isfinite((*t)[to - 1]) && std::isfinite((*t)[from])
                                           ? (*t)[to - 1] - (*t)[from]
                                           : rows - 1;
                if (rows >= o.stuckRunFactor * usualRows && seconds >= o.stuckMinS) {
                    spans.push_back({bi, cs.id, from, to, (*v)[from], seconds});
                }
            }
        }
    }
    return spans;
}

} // namespace

CleaningReport clean(const DataSet& data, const CleaningOptions& options) {
    CleaningReport report;
    if (options.maskStuck) {
        report.stuck = frozenReadings(data, options);
    }
    bool anyXhdt = false;
    bool anyThdt = false;
    for (const auto& b : data.batches) {
        const std::size_t n = b.rows();
        std::vector<std::uint8_t> keep(n, 1);
        std::vector<std::uint8_t> frozen(n, 0);
        for (const auto& span : report.stuck) {
            if (span.batch == report.keep.size()) {
                std::fill(frozen.begin() + static_cast<std::ptrdiff_t>(span.begin),
                          frozen.begin() + static_cast<std::ptrdiff_t>(span.end), 1);
            }
        }
        const auto* xhdt = b.values(Column::XHdt);
        const auto* thdt = b.values(Column::THdt);
        const auto* feed = b.values(Column::Feed);
        anyXhdt = anyXhdt || xhdt;
        anyThdt = anyThdt || thdt;
        for (std::size_t r = 0; r < n; ++r) {
            // A missing value fails no threshold rule: it is counted under "missing".
            if (xhdt && (*xhdt)[r] < options.minXhdtPct) {
                keep[r] = 0;
                ++report.droppedXhdt;
            }
            if (thdt && (*thdt)[r] < options.minThdtC) {
                keep[r] = 0;
                ++report.droppedThdt;
            }
            if (feed && (*feed)[r] < options.minFeedKgPerHour) {
                keep[r] = 0;
                ++report.droppedFeed;
            }
            if (options.dropMissing) {
                bool missing = false;
                for (const auto& col : b.numeric) {
                    const bool needed = spec(col.id).required;
                    missing = missing || (needed && std::isnan(col.values[r]));
                }
                if (missing) {
                    keep[r] = 0;
                    ++report.droppedMissing;
                }
            }
            bool impossible = false;
            for (const auto& col : b.numeric) {
                impossible = impossible || impossibleValue(col.id, col.values[r]);
            }
            if (impossible) {
                keep[r] = 0;
                ++report.droppedImpossible;
            }
            if (frozen[r]) {
                keep[r] = 0;
                ++report.droppedStuck;
            }
            report.kept += keep[r];
        }
        report.rows += n;
        report.keep.push_back(std::move(keep));
    }
    if (!anyXhdt) {
        report.skippedRules.push_back("X_hdt_pct ≥ " + std::to_string(options.minXhdtPct) +
                                      " %: not measured");
    }
    if (!anyThdt) {
        report.skippedRules.push_back("T_hdt_C ≥ " + std::to_string(options.minThdtC) + " °C: not measured");
    }
    return report;
}

std::vector<DroppedByRule> droppedByRule(const CleaningReport& r, const CleaningOptions& o) {
    return {{"X_hdt_pct < " + shortNumber(o.minXhdtPct) + " % wb", r.droppedXhdt},
            {"T_hdt_C < " + shortNumber(o.minThdtC) + " °C", r.droppedThdt},
            {"feed_kg_h < " + shortNumber(o.minFeedKgPerHour) + " kg/h", r.droppedFeed},
            {"missing input or output", r.droppedMissing},
            {"physically impossible value", r.droppedImpossible},
            {"frozen reading (the same value for " + shortNumber(o.stuckMinS) +
                 " s or more, far longer than the column usually holds it)",
             r.droppedStuck}};
}

} // namespace drytwin::data
