#pragma once

#include "control/ClosedLoop.h"

#include "data/DataSetSummary.h"
#include "data/SiBatch.h"
#include "discovery/Discovery.h"
#include "hybrid/Evaluation.h"
#include "hybrid/HybridTraining.h"
#include "hybrid/ResidualDiagnostics.h"
#include "physics/LineSimulator.h"
#include <string>
#include <vector>

namespace drytwin::io {

/// @brief The JSON of CONTRACT.md §3 for `evaluate`.
std::string evaluationJson(const evaluation::EvaluationResult& result);

/// @brief The ablation table (paper Table 3) as JSON.
std::string ablationJson(const hybrid::AblationResult& result);

/// @brief `mpc --json` (CONTRACT.md §3): metrics per controller, plus the scenario, the
/// trajectories of the scored part and the predicted horizons kept for plots.
std::string mpcJson(const control::ClosedLoopResult& result);

/// @brief Residual ACF, PSD and eigenvalues (paper Figs. 4 and 6) as JSON.
std::string residualDiagnosticsJson(const hybrid::ResidualDiagnostics& diagnostics);

/// @brief What `inspect --json` writes: batches, column ranges, cleaning counts.
std::string inspectJson(const data::DataSetSummary& summary);

/// @brief What `simulate --out` writes (CONTRACT.md §2): per row the batch id, the input columns
/// in file units, the predictions in file units and the proxy states in SI units.
std::string simulationCsv(const std::vector<data::SiBatch>& batches,
                          const std::vector<physics::SimulationResult>& simulations);

/// @brief The JSON of CONTRACT.md §3 for `discover`, with the residual analysis beside it.
std::string discoveryJson(const discovery::DiscoveryResult& result, bool hasHybrid, double hybridMaeXBefore,
                          double hybridMaeXAfter, double hybridMaeTBefore, double hybridMaeTAfter,
                          bool keptStartingModel = false);

} // namespace drytwin::io
