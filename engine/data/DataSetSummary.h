#pragma once

#include "data/Batch.h"
#include "data/Cleaning.h"

#include <string>
#include <vector>

namespace drytwin::data {

/// @brief Range of one column over a data set, in file units.
struct ColumnSummary {
    std::string name;
    std::string unit;
    bool present = false; ///< in at least one batch
    double min = 0;
    double max = 0;
    double mean = 0;
    std::size_t missing = 0;
};

/// @brief One batch at a glance.
struct BatchSummary {
    std::string id;
    std::string path;
    std::size_t rows = 0;
    double startS = 0;
    double endS = 0;
    double medianStepS = 0;
    double largestGapS = 0;
    std::size_t missing = 0;
    std::size_t droppedByCleaning = 0;
    std::optional<RunSource> run; ///< where a run cut from a long plant file came from
};

/// @brief A value no drying line can produce (RH outside 0–100 %, negative feed, a moisture
/// outside 0–100 %, a temperature outside the line's range), found before any model sees it.
struct ImpossibleValue {
    std::string file;           ///< path of the batch file (or its id when read from memory)
    int line = 0;               ///< 1-based line in the file
    int fileColumn = 0;         ///< 1-based column in the file (0: not known, e.g. a batch made in code)
    std::string column;         ///< the file's header
    std::string contractColumn; ///< the contract column it is read as ("X_out_pct")
    double value = 0;
    std::string rule; ///< e.g. "must lie in [0, 100] %"
};

/// @brief A missing cell (empty, NaN, #N/A, a historian's bad-quality state) where it is in its file.
struct MissingCellPlace {
    std::string file;           ///< path of the batch file (or its id when read from memory)
    int line = 0;               ///< 1-based line in the file (0: not known)
    int fileColumn = 0;         ///< 1-based column in the file (0: not known)
    std::string column;         ///< the file's header
    std::string contractColumn; ///< the contract column it is read as
};

/// @brief What a user needs to trust a data set (drytwin inspect, the GUI's data panel).
struct DataSetSummary {
    std::vector<BatchSummary> batches;
    std::vector<ColumnSummary> columns; ///< contract columns, then nothing else
    std::vector<std::string> extraColumns;
    std::size_t rows = 0;
    std::size_t missing = 0;
    CleaningReport cleaning;
    /// The first kMaxListedImpossible impossible values per column, in file order …
    std::vector<ImpossibleValue> impossible;
    std::size_t impossibleTotal = 0; ///< … and how many there are in all
    /// The first kMaxListedMissing missing cells per column, in file order (the count per column
    /// is in `columns`, per batch in `batches`): CONTRACT.md §1 reports them with file and line.
    std::vector<MissingCellPlace> missingCells;
    /// Distinct places (file, line, column) of all missing cells: fewer than the cells where a
    /// historian run's 1 s grid fills several rows from one sample.
    std::size_t missingPlaces = 0;
    std::vector<std::string> notes; ///< what reading the files noticed (DataSet::notes)
    /// The notes (also in `notes`) on a required column without a single value: why no row can be
    /// used, kept apart so that an error can say so without matching the notes' wording.
    std::vector<std::string> emptyRequiredColumns;
    static constexpr std::size_t kMaxListedImpossible = 20;
    static constexpr std::size_t kMaxListedMissing = 5;
};

/// @brief Summarises a loaded data set and what the cleaning rules would drop.
DataSetSummary summarize(const DataSet& data, const CleaningOptions& cleaning = {});

} // namespace drytwin::data
