#pragma once

#include <string>
#include <utility>
#include <vector>

namespace drytwin {

/// @brief Name and version of every library the engine links, for About boxes and reports.
std::vector<std::pair<std::string, std::string>> engineLibraryVersions();

/// @brief DryTwin's own version.
std::string dryTwinVersion();

} // namespace drytwin
