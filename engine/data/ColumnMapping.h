#pragma once

#include "common/Error.h"

#include <map>
#include <string>

namespace drytwin::data {

/// @brief Maps contract column names to the names a plant's files use
/// (e.g. "X_out_pct" -> "Moisture_Outlet"). Unmapped contract columns keep their own name.
struct ColumnMapping {
    std::map<std::string, std::string> contractToFile;

    /// @brief Contract name for a header found in a file ("" when it maps to none).
    std::string contractNameFor(const std::string& fileHeader) const;
    /// @brief Every key must be a contract column and no file name may be used twice.
    Status validate() const;
};

/// @brief Reads a mapping file: a JSON object {"<contract name>": "<file header>", ...}.
Expected<ColumnMapping> readColumnMapping(const std::string& path);

} // namespace drytwin::data
