#pragma once

#include <string>
#include <vector>

namespace drytwin {

/// @brief "a, b, c": the items of a message's list (columns, files, batches) joined by ", ".
inline std::string commaList(const std::vector<std::string>& items) {
    std::string list;
    for (const auto& item : items) {
        list += (list.empty() ? "" : ", ") + item;
    }
    return list;
}

} // namespace drytwin
