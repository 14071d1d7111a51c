#pragma once

#include "control/ClosedLoop.h"

#include "data/DataSetSummary.h"
#include "data/SiBatch.h"
#include "discovery/Discovery.h"
#include "hybrid/Evaluation.h"
#include "hybrid/HybridTraining.h"
#include "hybrid/ResidualDiagnostics.h"
#include "physics/LineSimulator.h"
#include <limits>
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

/// @brief The two forecasts every learnt one must beat (CONTRACT.md §3), one step ahead on the
/// rows PGRL-CC is scored on after discovery: the last measurement held, and the PBM with its
/// last measured error held, on the starting and on the extended physics model. NaN: not scored.
struct HybridReferences {
    double persistenceMoisture = std::numeric_limits<double>::quiet_NaN();    ///< % wb
    double persistenceTemperature = std::numeric_limits<double>::quiet_NaN(); ///< °C
    double pbmHoldMoistureBefore = std::numeric_limits<double>::quiet_NaN(),  ///< % wb
        pbmHoldMoistureAfter = std::numeric_limits<double>::quiet_NaN();
    double pbmHoldTemperatureBefore = std::numeric_limits<double>::quiet_NaN(), ///< °C
        pbmHoldTemperatureAfter = std::numeric_limits<double>::quiet_NaN();
    /// The better of the two references on the model offered for forecasting (the extended one,
    /// or the starting one where it was kept).
    double bestMoisture(bool keptStartingModel) const;
    double bestTemperature(bool keptStartingModel) const;
};

/// @brief The JSON of CONTRACT.md §3 for `discover`, with the residual analysis beside it.
std::string discoveryJson(const discovery::DiscoveryResult& result, bool hasHybrid, double hybridMaeXBefore,
                          double hybridMaeXAfter, double hybridMaeTBefore, double hybridMaeTAfter,
                          bool keptStartingModel = false, const HybridReferences& references = {});

} // namespace drytwin::io
