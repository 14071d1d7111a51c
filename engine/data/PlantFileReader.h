#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/Batch.h"
#include "data/BatchReader.h"

#include <optional>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief How a time column is written.
enum class TimeFormat {
    Seconds,      ///< seconds since an arbitrary start (the contract's time_s)
    Iso8601,      ///< 2025-06-03T08:00:00(.fff)(Z|±hh:mm), 'T' or a space
    YmdSlash,     ///< 2025/06/03 08:00:00
    DmyDot,       ///< 03.06.2025 08:00:00
    DmySlash,     ///< 03/06/2025 08:00:00
    MdySlash,     ///< 06/03/2025 08:00:00
    ExcelDays,    ///< days since 1899-12-30 (Excel's serial date), fraction = time of day
    EpochSeconds, ///< Unix time
    EpochMillis,
};
/// @brief The mapping file's name of a format ("iso8601", "d.m.Y", …).
std::string timeFormatName(TimeFormat f);
/// @brief The format of a mapping file's name; nullopt for a name that is none.
std::optional<TimeFormat> timeFormatByName(const std::string& name);

/// @brief What a first look at a plant file found (CONTRACT.md §1, historian exports).
struct FileShape {
    int headerLine = 0; ///< 1-based
    char delimiter = ',';
    bool decimalComma = false;
    bool unitsRow = false;
    std::string timeHeader;
    TimeFormat timeFormat = TimeFormat::Seconds;
    /// False for a file in the contract's own form (comma, time_s in seconds, no units row, no
    /// batch column): it is read as one batch exactly as before.
    bool historian = false;
    std::vector<std::string> headers;
    std::vector<std::string> units; ///< the units row's cells, when there is one
};

/// @brief Looks at a plant file's text: delimiter, decimal comma, units row, time column and format.
Expected<FileShape> sniffPlantText(const std::string& text, const std::string& displayName,
                                   const ColumnMapping& mapping);

/// @brief A file read as production runs, and what happened on the way.
struct PlantFileRuns {
    FileShape shape;
    std::vector<Batch> runs;
    std::vector<std::string> notes; ///< duplicates, clock jumps, runs left out, columns not kept; file:line
};

/// @brief Reads a plant file: in the contract's form one batch as readBatchFile; a historian
/// export (timestamps, `;`/tab, decimal commas, a units row, a batch column, one long file) cut
/// into runs at line stops, gaps, clock jumps and batch-id changes, each resampled onto the
/// model's step. Reads the text once; progress and cancel per megabyte. Thread-safe.
Expected<PlantFileRuns> parsePlantText(const std::string& text, const std::string& displayName,
                                       const ReadOptions& options = {}, const Progress& progress = {});
/// @brief parsePlantText of a file on disk.
Expected<PlantFileRuns> readPlantFile(const std::string& path, const ReadOptions& options = {},
                                      const Progress& progress = {});

/// @brief Parses one time-stamp cell in @p format to seconds (epoch seconds for dates; naive
/// local time counts as UTC). False when the cell does not have the format.
bool parseTimeCell(std::string_view cell, TimeFormat format, double& seconds);

} // namespace drytwin::data
