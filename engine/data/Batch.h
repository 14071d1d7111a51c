#pragma once

#include "data/Columns.h"

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief A cell that was empty or NaN in the file: reported, never zero-filled.
struct MissingCell {
    int line = 0;   ///< 1-based line in the file
    int column = 0; ///< 1-based column in the file
    std::string columnName;
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
    std::size_t totalRows() const;
    std::size_t totalMissing() const;
};

} // namespace drytwin::data
