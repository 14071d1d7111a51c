#pragma once

#include "common/Error.h"
#include "workflow/Session.h"

#include <string>

namespace drytwin::workflow {

/// @brief The latest results a project keeps beside its model file: calibration, evaluation,
/// ablation, discovery (with its extended model) and the what-if run, as typed JSON that reads
/// back into the same structs (issue #26: a reopened project shows its results without re-running
/// them). Simulation and training results are not kept: the simulation is re-run on opening, and
/// the learnt models themselves are in the model file.
///
/// This is a complete dump of the structs, not the contract's result files (CONTRACT.md §3), which
/// are summaries written for people and scripts. Thread-safe.
std::string latestResultsJson(const LatestResults& results);

/// @brief Reads what latestResultsJson() wrote; @p place names the file in errors. Fields this
/// version does not know are ignored and missing ones take their defaults, so an archive of an
/// older or newer version still opens.
Expected<LatestResults> parseLatestResults(const std::string& text, const std::string& place);

} // namespace drytwin::workflow
