#pragma once

#include "io/Evaluation.h"
#include "io/ModelFile.h"

#include <string>

namespace drytwin::evaluation {

/// @brief Residual diagnostics as data for plots and reports: ACF and Welch PSD of every
/// model's held-out moisture residual (paper Fig. 4) and, for PGRL-CC, the eigenvalues of A
/// before and after the stability constraint with their contraction rates (Fig. 6). JSON.
std::string residualDiagnosticsJson(const EvaluationResult& evaluation, const io::ModelFile& model);

} // namespace drytwin::evaluation
