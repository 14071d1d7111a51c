#pragma once

#include "common/Error.h"

#include "data/Columns.h"

#include <map>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief How one long plant file is cut into production runs and put on the model's time step.
struct RunSplitOptions {
    double stepS = 1.0;                 ///< the model's step: runs are resampled onto it
    double lineStopFeedKgPerHour = 500; ///< feed below this: the line stands
    double minStopS = 60;               ///< a dip of the feed shorter than this is not a stop
    double maxInterpolatedGapS = 10;    ///< a gap in time up to this is interpolated; longer splits
    double minRunS = 300;               ///< shorter runs are left out (and reported)
    Status validate() const;
};

/// @brief Maps contract column names to the names a plant's files use
/// (e.g. "X_out_pct" -> "Moisture_Outlet"). Unmapped contract columns keep their own name.
struct ColumnMapping {
    std::map<std::string, std::string> contractToFile;
    /// The unit a plant's file uses for a contract column, when it is not the contract's
    /// (e.g. "T_hot_C" -> "degF"); values are converted to the contract's unit when read.
    std::map<std::string, std::string> contractToUnit;
    /// How the time column is written (CONTRACT.md §1 `"time_s": {"header": …, "format": …}`):
    /// empty = detected; "seconds", "iso8601", "Y/m/d", "d.m.Y", "d/m/Y", "m/d/Y",
    /// "excel_days", "epoch_s", "epoch_ms".
    std::string timeFormat;
    /// A column that names the production run (`"batch_id": {"header": "Batch"}`); empty: none.
    std::string batchIdHeader;
    RunSplitOptions runs; ///< the mapping file's optional "runs" object
    /// The files' decimal mark (`"decimal_mark": ","` or `"."`); 0: decided from each file's
    /// cells (the other mark then groups thousands: 6.497,5 or 6,497.5).
    char decimalMark = 0;
    /// The mapping file this was read from, for messages ("" when built in code).
    std::string sourceName;

    /// @brief Contract name for a header found in a file ("" when it maps to none).
    std::string contractNameFor(const std::string& fileHeader) const;
    /// @brief Every key must be a contract column, no file name may be used twice, and every
    /// unit must be one this column's quantity converts from (unitsFor).
    Status validate() const;
    /// @brief A file value of contract column @p column in the contract's unit.
    double toContractUnit(Column column, double value) const;
    /// @brief Fails when the mapping names a header that @p headers (a file's header row, at line
    /// @p headerLine of @p file) lack, whatever the column: a misspelt tag of an optional column
    /// would otherwise leave the column absent and its default used without a word. The message
    /// names every such header, its contract column, the closest header the file has, and the mapping.
    Status checkHeadersPresent(const std::vector<std::string>& headers, const std::string& file,
                               int headerLine) const;
};

/// @brief The header of @p headers closest to @p name (case and punctuation aside, then by edit
/// distance); "" when none is near.
std::string closestHeader(const std::string& name, const std::vector<std::string>& headers);

/// @brief The units a contract column's values may come in, the contract's own first
/// (temperatures: degC, degF, K; moisture: % wb, % db, fraction wb; feed: kg/h, kg/s, kg/min, t/h;
/// humidity: %, fraction; time: s, min; air speed: m/s).
std::vector<std::string> unitsFor(Column column);

/// @brief Reads a mapping file: a JSON object {"<contract name>": "<file header>", ...}; a value
/// may also be {"header": "<file header>", "unit": "<unit>"} for a column in another unit. Text
/// that is not JSON is reported as file:line:column with what the parser expected there.
Expected<ColumnMapping> readColumnMapping(const std::string& path);
/// @brief readColumnMapping of JSON text; @p name is used in messages.
Expected<ColumnMapping> readColumnMappingText(const std::string& text, const std::string& name);

} // namespace drytwin::data
