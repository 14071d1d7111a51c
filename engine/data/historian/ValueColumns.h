#pragma once

#include "common/Error.h"
#include "data/ColumnMapping.h"
#include "data/Columns.h"
#include "data/historian/FileShape.h"
#include "data/historian/NumberFormat.h"

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data::historian {

/// @brief A unit as people write it ("°F", "[kg/h]", "%RH") in the unit names of ColumnMapping
/// (unitsFor: "degF", "kg/h", "%"); empty when not recognised. Read alike from a units row under
/// the header and from a column mapping's "unit".
std::string normalisedUnit(std::string_view raw, Column column);

/// @brief A value column of a plant file: its contract column (if mapped), unit, and values as
/// read, with what its cells said about the number format and the PI digital states found in it.
struct ValueColumn {
    std::optional<Column> contract;
    std::string header;
    std::string unit; ///< the file's unit for a contract column ("" = the contract's)
    std::size_t field = 0;
    bool numeric = true; ///< false once a cell holds text: not a contract column, not kept in runs
    std::vector<double> values;
    DecimalMarkEvidence marks;
    std::map<std::string, std::size_t> digitalStates; ///< PI states ("Shutdown") and how many cells hold each
    int firstStateLine = 0;
    ColumnMapping conversion; ///< converts from unit to the contract's

    /// @brief "'FEED_WT201.PV' (feed_kg_h)", or "'Status'" for a column no contract column takes.
    std::string label() const;
    /// @brief Reads one cell into values (NaN for a missing cell or a digital state). False, with
    /// @p error naming file:line:column, when a contract column holds text. (A bool rather than a
    /// Status: this runs for every cell of a month at 1 s.)
    bool readCell(std::string_view cell, int line, const std::string& file, Error& error);
};

/// @brief The columns of a plant file as the mapping lays them out.
struct ColumnLayout {
    std::size_t timeIndex = 0;
    std::size_t batchIndex = 0; ///< == number of fields when there is no batch column
    std::vector<ValueColumn> values;
    double timeScale = 1;           ///< 60 when relative time is in minutes
    std::vector<std::string> notes; ///< what the layout decided that a reader must know (file:line:column)
};

/// @brief Lays out the columns of a file of shape @p shape: the time and batch columns, the
/// contract columns (mapped or by their own names) with their units (the mapping's or the units
/// row's), other columns. Fails with file:line:column when the mapping names a header the file
/// lacks, two columns give the same contract column, a unit does not fit, or a required column is
/// missing.
Expected<ColumnLayout> layOutColumns(const FileShape& shape, const ColumnMapping& mapping,
                                     const std::string& file);

/// @brief After the last row: decides each column's decimal mark on the whole file (the mapping's
/// `decimal_mark` first), puts ambiguous cells right (6.497 → 6497 where the point groups
/// thousands), converts to the contract's units, and notes digital states, text columns and
/// guessed number formats in @p notes. Returns the file's decimal mark, or an error naming the
/// cells that contradict each other.
Expected<char> finishColumns(std::vector<ValueColumn>& columns, const ColumnMapping& mapping,
                             const FileShape& shape, const std::string& file,
                             std::vector<std::string>& notes);

} // namespace drytwin::data::historian
