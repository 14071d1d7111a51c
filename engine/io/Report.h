#pragma once

#include "common/Error.h"

#include <string>

namespace drytwin::io {

/// @brief Writes `report.md` into a pipeline folder from the files the pipeline left there
/// (inspect.json, model-calibrated.json, evaluate.json, ablation.json, diagnostics.json):
/// what was run, with which data, and every number in a table. Returns the report's path.
Expected<std::string> writePipelineReport(const std::string& folder);

} // namespace drytwin::io
