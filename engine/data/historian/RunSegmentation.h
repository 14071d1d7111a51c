#pragma once

#include "data/Batch.h"
#include "data/ColumnMapping.h"
#include "data/historian/FileShape.h"
#include "data/historian/ValueColumns.h"

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::data::historian {

/// @brief One row of a plant file as the run segmentation needs it.
struct RowStamp {
    double t = 0;   ///< seconds (epoch seconds for dates)
    int line = 0;   ///< file line
    int batch = -1; ///< index into the batch ids; -1 without a batch column
};

/// @brief A run of rows [begin, end) and why it ended.
struct RowSpan {
    std::size_t begin = 0, end = 0;
    std::string reason; ///< "line stop", "clock jump", "batch id", "gap", "end of file"
};

/// @brief Cuts the rows into runs: at line stops (the feed below its threshold for at least the
/// minimum stop; the stop's rows belong to no run), clock jumps (rows listed in @p clockJumpBefore,
/// ascending), batch-id changes and gaps in time longer than the interpolation limit.
std::vector<RowSpan> cutIntoRuns(const std::vector<RowStamp>& rows, const std::vector<double>* feed,
                                 const std::vector<std::size_t>& clockJumpBefore,
                                 const RunSplitOptions& runs);

/// @brief Puts each run onto the step's grid (linear interpolation between samples, counted;
/// missing cells kept missing) and names it (the batch id, or the file's stem with _R01, _R02 …);
/// runs shorter than the minimum are left out with a note. Frees each column's values once used.
void resampleRuns(const std::vector<RowSpan>& spans, const std::vector<RowStamp>& rows,
                  std::vector<ValueColumn>& columns, const std::vector<std::string>& batchIds,
                  const std::vector<std::string>& metadata, const FileShape& shape, const std::string& file,
                  const RunSplitOptions& runs, std::vector<Batch>& out, std::vector<std::string>& notes);

} // namespace drytwin::data::historian
