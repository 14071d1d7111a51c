#pragma once

#include "common/Error.h"

#include <string>

namespace drytwin {

/// @brief Writes @p contents to @p path atomically: a temporary file in the same folder is
/// written, flushed and renamed over the target, so a crash or full disk never leaves a
/// half-written file and an existing file survives a failed write.
Status writeFileAtomically(const std::string& path, const std::string& contents);

/// @brief Reads a whole file; the error names the file and the system's reason.
Expected<std::string> readWholeFile(const std::string& path);

} // namespace drytwin
