#pragma once

// What the files of the workflow Session (workflow/Session.cpp and workflow/session/) share and
// nobody else needs: the elapsed time an Ending carries, and the precondition of every action on
// the loaded data. Not part of the engine's public API.

#include "workflow/Session.h"

#include <chrono>
#include <string>

namespace drytwin::workflow {

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class Options> Status Session::ready(const Options& options, const std::string& action) const {
    if (auto st = options.validate(); !st) {
        return st;
    }
    if (auto st = requireData(action); !st) {
        return st;
    }
    return requireUsableRows(action);
}

} // namespace drytwin::workflow
