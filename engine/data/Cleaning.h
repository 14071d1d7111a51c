#pragma once

#include "common/Error.h"
#include "data/Batch.h"

#include <cstdint>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief Data-quality rules of the paper §IV.A; every threshold configurable.
struct CleaningOptions {
    double minXhdtPct = 11.0;         ///< tube-outlet moisture ≥ 11 % wb
    double minThdtC = 50.0;           ///< tube-outlet temperature ≥ 50 °C
    double minFeedKgPerHour = 5800.0; ///< feed ≥ 5800 kg/h
    bool dropMissing = true;          ///< drop rows with a missing input or final output
    Status validate() const;
};

/// @brief Which rows of each batch pass, and why the others do not.
struct CleaningReport {
    std::vector<std::vector<std::uint8_t>> keep; ///< per batch, per row: 1 keep, 0 drop
    std::size_t rows = 0;
    std::size_t kept = 0;
    std::size_t droppedXhdt = 0;
    std::size_t droppedThdt = 0;
    std::size_t droppedFeed = 0;
    std::size_t droppedMissing = 0;
    std::size_t droppedImpossible = 0; ///< a value outside its column's possible range (possibleRange)
    /// Rules that could not be applied because the column is absent (e.g. "X_hdt_pct not measured").
    std::vector<std::string> skippedRules;
};

/// @brief Applies the cleaning rules; a row may fail several rules, each counted.
/// Rows are masked, not removed, so the time series stays continuous for simulation.
CleaningReport clean(const DataSet& data, const CleaningOptions& options = {});

} // namespace drytwin::data
