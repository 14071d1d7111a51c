#pragma once

#include <mutex>

namespace drytwin::diagnostics {

/// @brief The one lock around FFTW's planner, which is not thread-safe (executing a plan is):
/// every plan made or destroyed in the engine takes it.
std::mutex& fftwPlanMutex();

} // namespace drytwin::diagnostics
