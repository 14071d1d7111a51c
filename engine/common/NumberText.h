#pragma once

#include <cstdio>
#include <string>

namespace drytwin {

/// @brief A number for a message or a label, in printf's %g (six significant digits, no trailing
/// zeros: "11", "1e-05", "5800"), the form every message names a bound or a threshold in.
inline std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace drytwin
