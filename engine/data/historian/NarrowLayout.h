#pragma once

#include "common/Error.h"

#include <optional>
#include <string>
#include <vector>

namespace drytwin::data::historian {

/// @brief A tag/value ("narrow") export pivoted to one column per tag.
struct NarrowPivot {
    std::string wideText;           ///< the same data, one row per time stamp, one column per tag
    std::vector<std::string> notes; ///< what the pivot did (tags, stamps, cells left empty)
    std::size_t tags = 0, stamps = 0;
};

/// @brief Reads a tag/value export, one row per tag and time stamp as PI, Wonderware and WinCC
/// write it (`Timestamp,Tag,Value[,Quality…]`, any order, any of the reader's delimiters), into
/// the wide layout the rest of the reader knows: rows ordered by time, one column per tag named
/// by the tag (which the column mapping then maps), a cell left empty where a tag has no sample
/// at that stamp holds its last sample for at most @p maxHoldS (a historian's deadband), else stays
/// empty. nullopt when the header is not such a layout; an error naming the line when it is one
/// but a row cannot be read.
Expected<std::optional<NarrowPivot>> pivotNarrowExport(const std::string& text, const std::string& file,
                                                       double maxHoldS);

} // namespace drytwin::data::historian
