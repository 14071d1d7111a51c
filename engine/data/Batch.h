#pragma once

#include "data/Columns.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief A cell that was empty or NaN in the file: reported, never zero-filled.
struct MissingCell {
    int line = 0;   ///< 1-based line in the file
    int column = 0; ///< 1-based column in the file
    std::string columnName;
};

/// @brief Where a production run cut from a long plant file (a historian export) came from.
struct RunSource {
    std::string file;
    int firstLine = 0; ///< first and last file line of the run's samples
    int lastLine = 0;
    std::string startTimestamp;        ///< the run's first sample as the file's clock says (ISO 8601)
    std::size_t samples = 0;           ///< rows of the file in the run
    std::size_t interpolatedCells = 0; ///< cells of the step's grid filled by interpolation
    std::size_t gapCells = 0;          ///< cells of the grid left missing (no sample near enough)
    std::string
        splitReason; ///< why the run ended: "line stop", "gap", "batch id", "clock jump", "end of file"
};

/// @brief One production batch as read from its file, in file units (CONTRACT.md §1).
///
/// Contract columns (after mapping) are numeric, NaN marking a missing cell; any other
/// column is kept verbatim as text so that writing the batch back loses nothing.
struct Batch {
    std::string id;                         ///< file stem, or the `# batch:` metadata value
    std::string sourcePath;                 ///< where it was read from (empty if built in memory)
    std::vector<std::string> metadataLines; ///< lines before the header that begin with '#', verbatim

    struct NumericColumn {
        Column id;
        std::string fileName; ///< header text in the file (differs from the contract name when mapped)
        std::vector<double> values;
        int fileColumn = 0; ///< 1-based column of the file it was read from, for messages (0: none)
    };
    struct TextColumn {
        std::string fileName;
        std::vector<std::string> cells;
    };
    /// Column order of the file: index into numeric (>= 0) or text (-1 - i).
    std::vector<int> fileOrder;
    std::vector<NumericColumn> numeric;
    std::vector<TextColumn> text;

    std::vector<int> lineOfRow; ///< file line of each data row, for messages
    std::vector<MissingCell> missing;
    /// Set when the batch is a run cut from a long plant file; lineOfRow then gives, for each
    /// row of the step's grid, the file line of the sample at or before it.
    std::optional<RunSource> run;

    std::size_t rows() const { return lineOfRow.size(); }
    /// @brief Values of a contract column, or nullptr when the file does not have it.
    const std::vector<double>* values(Column c) const;
    std::vector<double>* values(Column c);
    bool has(Column c) const { return values(c) != nullptr; }
    /// @brief Adds or replaces a contract column (appended at the end of the file order).
    void setValues(Column c, std::vector<double> v);
    /// @brief Value of the first `# key: value` metadata line, or empty.
    std::string metadata(const std::string& key) const;
};

/// @brief A data set: batches in name order.
struct DataSet {
    std::vector<Batch> batches;
    /// What reading the files noticed (duplicate stamps, clock jumps, runs left out), file:line.
    std::vector<std::string> notes;
    std::size_t totalRows() const;
    std::size_t totalMissing() const;
};

} // namespace drytwin::data
