#pragma once

#include <functional>
#include <string>

namespace drytwin {

/// @brief What a progress callback tells the engine to do next.
enum class ProgressAction { Continue, Stop };

/// @brief One progress report of long engine work.
struct ProgressInfo {
    std::string stage;   ///< short machine-stable stage name, e.g. "load", "simulate"
    double fraction = 0; ///< 0..1 within the stage
    std::string detail;  ///< human-readable detail (file name, iteration ...)
};

/// @brief Engine-side progress and cancel hook (ARCHITECTURE.md rule 3).
/// Called from the thread that runs the engine call; return Stop to cancel.
using Progress = std::function<ProgressAction(const ProgressInfo&)>;

/// @brief Calls @p progress if set; true when the work should stop.
inline bool reportProgress(const Progress& progress, const std::string& stage, double fraction,
                           const std::string& detail = {}) {
    return progress && progress(ProgressInfo{stage, fraction, detail}) == ProgressAction::Stop;
}

} // namespace drytwin
