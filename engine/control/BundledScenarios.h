#pragma once

#include <map>
#include <string>

namespace drytwin::control {

/// @brief The scenarios of resources/scenarios/, by file name without ".json", as their JSON text.
const std::map<std::string, std::string>& bundledScenarios();

/// @brief The scenario `drytwin mpc` runs when none is given: the paper-like 1,000-step one.
inline constexpr const char* kDefaultScenario = "paper_like_1000";

} // namespace drytwin::control
