#pragma once

#include "common/Progress.h"

#include <atomic>

namespace drytwin::app {

/// @brief Set by SIGINT; the CLI progress callback then asks the engine to stop (exit 130).
extern std::atomic<bool> g_interrupted;

/// @brief Installs the SIGINT handler that sets g_interrupted.
void installInterruptHandler();

/// @brief Progress on stderr: a rewriting line on a terminal, one line per 10 % otherwise.
Progress makeCliProgress(bool quiet);

} // namespace drytwin::app
