#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/Batch.h"
#include "data/BatchReader.h"
#include "data/historian/FileShape.h"
#include "data/historian/TimeStamps.h"

#include <string>
#include <vector>

namespace drytwin::data {

/// @brief A file read as production runs, and what happened on the way.
struct PlantFileRuns {
    FileShape shape;
    std::vector<Batch> runs;
    /// Encoding conversions, digital states, duplicates, clock steps, runs left out, columns not
    /// kept, guessed number formats; each with file:line.
    std::vector<std::string> notes;
};

/// @brief Reads a plant file: in the contract's form one batch as readBatchFile; a historian
/// export (timestamps, `;`/tab, decimal commas and thousands marks, a units row, a batch column,
/// PI digital states, one long file; UTF-8, UTF-16 or Windows-1252) cut into runs at line stops,
/// gaps, daylight-saving steps and batch-id changes, each resampled onto the model's step. Reads
/// the text once (a second time for the time column only when its dates could be day/month or
/// month/day); progress and cancel per megabyte. Errors name file:line:column, the cause and the
/// setting that fixes it. Thread-safe.
Expected<PlantFileRuns> parsePlantText(const std::string& text, const std::string& displayName,
                                       const ReadOptions& options = {}, const Progress& progress = {});
/// @brief parsePlantText of a file on disk. A line longer than 1 MiB stops the reading there,
/// whatever the file's size.
Expected<PlantFileRuns> readPlantFile(const std::string& path, const ReadOptions& options = {},
                                      const Progress& progress = {});
/// @brief The first @p maxBytes of a plant file (all of it for 0), cut after its last whole line,
/// for a preview or a guess; read with the same line limit as readPlantFile, so that a file
/// without line breaks is refused alike and never read whole.
Expected<std::string> readPlantFileHead(const std::string& path, std::size_t maxBytes);

} // namespace drytwin::data
