#pragma once

#include <functional>
#include <string>

namespace drytwin {

/// @brief What a progress callback tells the engine to do next (Ceres' IterationCallback).
/// Stop: abandon the work (a Cancelled error). StopKeepBest: end iterative work now and return
/// the best result found so far, marked Termination::StoppedKeptBest; work that is not
/// iterative treats it as Stop.
enum class ProgressAction { Continue, Stop, StopKeepBest };

/// @brief One progress report of long engine work.
struct ProgressInfo {
    std::string stage;   ///< short machine-stable stage name, e.g. "load", "simulate"
    double fraction = 0; ///< 0..1 within the stage
    std::string detail;  ///< human-readable detail (file name, iteration ...)
};

/// @brief Engine-side progress and cancel hook (ARCHITECTURE.md rule 3).
/// Called from the thread that runs the engine call; return Stop to cancel.
using Progress = std::function<ProgressAction(const ProgressInfo&)>;

/// @brief Calls @p progress if set and returns what it asked for (Continue when unset).
inline ProgressAction progressAction(const Progress& progress, const std::string& stage, double fraction,
                                     const std::string& detail = {}) {
    return progress ? progress(ProgressInfo{stage, fraction, detail}) : ProgressAction::Continue;
}

/// @brief Calls @p progress if set; true when the work should stop (either way of stopping).
inline bool reportProgress(const Progress& progress, const std::string& stage, double fraction,
                           const std::string& detail = {}) {
    return progressAction(progress, stage, fraction, detail) != ProgressAction::Continue;
}

/// @brief How a piece of work ended (Ceres' Solver::Summary::termination_type).
enum class Termination {
    Completed,       ///< done; nothing iterative to converge
    Converged,       ///< an iterative method met its convergence test
    BudgetExhausted, ///< an iterative method used its evaluation or iteration budget
    StoppedKeptBest  ///< the user stopped it; the result is the best found so far
};

/// @brief Machine-stable name of a termination ("completed", "stopped_kept_best" ...).
inline const char* terminationName(Termination t) {
    switch (t) {
    case Termination::Completed:
        return "completed";
    case Termination::Converged:
        return "converged";
    case Termination::BudgetExhausted:
        return "budget_exhausted";
    case Termination::StoppedKeptBest:
        return "stopped_kept_best";
    }
    return "completed";
}

/// @brief How a result came about: its termination, a message saying why, the elapsed time.
/// Failures are not endings: they come back as an Error.
struct Ending {
    Termination termination = Termination::Completed;
    std::string message;
    double elapsedSeconds = 0;
};

} // namespace drytwin
