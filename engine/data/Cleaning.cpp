#include "data/Cleaning.h"

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
    return {};
}

CleaningReport clean(const DataSet& data, const CleaningOptions& options) {
    CleaningReport report;
    bool anyXhdt = false;
    bool anyThdt = false;
    for (const auto& b : data.batches) {
        const std::size_t n = b.rows();
        std::vector<std::uint8_t> keep(n, 1);
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

} // namespace drytwin::data
