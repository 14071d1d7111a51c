#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/Batch.h"
#include "data/ColumnMapping.h"

#include <string>
#include <vector>

namespace drytwin::data {

/// @brief Options for reading batch files.
struct ReadOptions {
    ColumnMapping mapping;
    Status validate() const { return mapping.validate(); }
};

/// @brief Reads and validates one batch file (CONTRACT.md §1).
/// Errors name "file:line:column" and the reason. Thread-safe.
Expected<Batch> readBatchFile(const std::string& path, const ReadOptions& options = {});

/// @brief Rejects text that is empty, UTF-16, not valid UTF-8 or holds NUL bytes (file:line:column).
Status checkBatchTextEncoding(const std::string& text, const std::string& displayName);

/// @brief Parses batch text already in memory; @p displayName is used in messages and as id.
Expected<Batch> parseBatchText(const std::string& text, const std::string& displayName,
                               const ReadOptions& options = {});

/// @brief Result of loading a data set.
struct LoadResult {
    DataSet dataSet;
    std::vector<Error> errors; ///< one per rejected file; loading stops at none of them
    /// What a plant file's reading noticed and did (duplicate stamps, clock jumps, runs left out,
    /// text columns not kept), each with file:line.
    std::vector<std::string> notes;
    double elapsedSeconds = 0;
    bool cancelled = false;
    bool ok() const { return errors.empty() && !cancelled; }
};

/// @brief Loads a file or every `*.csv` of a folder (sorted by name). Every file is read and
/// every rejection reported, so a user fixes all of them in one go. A historian export is cut
/// into production runs (PlantFileReader.h), each a batch.
LoadResult loadDataSet(const std::string& path, const ReadOptions& options = {},
                       const Progress& progress = {});

} // namespace drytwin::data
