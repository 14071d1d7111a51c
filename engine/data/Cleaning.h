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
    /// A frozen transmitter (a hung device, a lost update): a measured column that reads exactly
    /// the same value for at least @ref stuckMinS and for @ref stuckRunFactor times the longest
    /// usual run of identical readings of that column in the data set (its 99th percentile), so
    /// that a column that is often held (a slow, coarsely quantised hall thermometer, a
    /// deadband-compressed historian tag) is not taken for frozen. Its cells are treated as
    /// missing: an input is bridged like a dropout, and the rows are dropped from fits and metrics.
    bool maskStuck = true;
    double stuckMinS = 60;
    double stuckRunFactor = 4;
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
    std::size_t droppedStuck = 0;      ///< a frozen reading (CleaningOptions::maskStuck)
    /// One frozen stretch of one column: rows [begin, end) of batch @p batch read @p value.
    struct StuckSpan {
        std::size_t batch = 0;
        Column column = Column::Time;
        std::size_t begin = 0, end = 0;
        double value = 0;
        double seconds = 0;
    };
    std::vector<StuckSpan> stuck;
    /// Rules that could not be applied because the column is absent (e.g. "X_hdt_pct not measured").
    std::vector<std::string> skippedRules;
};

/// @brief Applies the cleaning rules; a row may fail several rules, each counted.
/// Rows are masked, not removed, so the time series stays continuous for simulation.
CleaningReport clean(const DataSet& data, const CleaningOptions& options = {});

/// @brief One cleaning rule in words with its thresholds ("X_hdt_pct < 11 % wb") and the rows it
/// dropped, in the order `inspect` lists them; the last is the frozen-reading rule.
struct DroppedByRule {
    std::string rule;
    std::size_t rows = 0;
};
std::vector<DroppedByRule> droppedByRule(const CleaningReport& report, const CleaningOptions& options);

} // namespace drytwin::data
