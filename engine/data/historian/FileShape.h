#pragma once

#include "common/Error.h"
#include "data/ColumnMapping.h"
#include "data/historian/TimeStamps.h"

#include <string>
#include <vector>

namespace drytwin::data {

/// @brief What a first look at a plant file found (CONTRACT.md §1, historian exports).
struct FileShape {
    int headerLine = 0; ///< 1-based
    char delimiter = ',';
    /// Decimal commas: from the first rows when sniffed; after reading, the whole file's verdict.
    bool decimalComma = false;
    bool unitsRow = false;
    std::string timeHeader;
    TimeFormat timeFormat = TimeFormat::Seconds;
    /// Excel cells holding a time of day alone: the stamps count seconds from an undated midnight
    /// (set when the rows are read).
    bool timesOfDayOnly = false;
    /// False for a file in the contract's own form (comma, time_s in seconds, no units row, no
    /// batch column): it is read as one batch exactly as before.
    bool historian = false;
    std::vector<std::string> headers;
    std::vector<std::string> units; ///< the units row's cells, when there is one
};

/// @brief Looks at a plant file's text (UTF-8; historian::decodeText converts others): delimiter,
/// decimal comma, units row, time column and format. Slash dates that read as day/month and as
/// month/day alike in the first rows are decided on the whole column. Thread-safe.
Expected<FileShape> sniffPlantText(const std::string& text, const std::string& displayName,
                                   const ColumnMapping& mapping);

} // namespace drytwin::data
