#pragma once

#include "common/Error.h"

#include "data/Columns.h"

#include <map>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief Maps contract column names to the names a plant's files use
/// (e.g. "X_out_pct" -> "Moisture_Outlet"). Unmapped contract columns keep their own name.
struct ColumnMapping {
    std::map<std::string, std::string> contractToFile;
    /// The unit a plant's file uses for a contract column, when it is not the contract's
    /// (e.g. "T_hot_C" -> "degF"); values are converted to the contract's unit when read.
    std::map<std::string, std::string> contractToUnit;

    /// @brief Contract name for a header found in a file ("" when it maps to none).
    std::string contractNameFor(const std::string& fileHeader) const;
    /// @brief Every key must be a contract column, no file name may be used twice, and every
    /// unit must be one this column's quantity converts from (unitsFor).
    Status validate() const;
    /// @brief A file value of contract column @p column in the contract's unit.
    double toContractUnit(Column column, double value) const;
};

/// @brief The units a contract column's values may come in, the contract's own first
/// (temperatures: degC, degF, K; moisture: % wb, % db, fraction wb; feed: kg/h, kg/s, kg/min, t/h;
/// humidity: %, fraction; time: s, min; air speed: m/s).
std::vector<std::string> unitsFor(Column column);

/// @brief Reads a mapping file: a JSON object {"<contract name>": "<file header>", ...}; a value
/// may also be {"header": "<file header>", "unit": "<unit>"} for a column in another unit.
Expected<ColumnMapping> readColumnMapping(const std::string& path);

} // namespace drytwin::data
