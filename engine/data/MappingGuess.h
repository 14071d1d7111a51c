#pragma once

#include "common/Error.h"
#include "data/ColumnMapping.h"
#include "data/PlantFileReader.h"

#include <map>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief A first guess at how a plant file's columns map onto the contract's.
struct MappingGuess {
    FileShape shape;
    ColumnMapping mapping;
    /// Why each contract column got its header: "name and range", "range 140–200", …
    std::map<std::string, std::string> reasons;
    /// Headers no contract column took.
    std::vector<std::string> unused;
};

/// @brief Guesses the mapping of a plant file from its headers (words and ISA tag letters such as
/// TT, MT, WT) and the ranges its first rows' values live in (a column in 140–200 is probably the
/// hot-air temperature, one in 10–16 the outlet moisture). Reads at most the first 2,000 rows of
/// @p text. The guess is a proposal for a person to check, never applied silently.
Expected<MappingGuess> guessMapping(const std::string& text, const std::string& displayName);

/// @brief The mapping file's JSON for @p mapping (CONTRACT.md §1), as readColumnMapping reads it.
std::string mappingJson(const ColumnMapping& mapping);

} // namespace drytwin::data
