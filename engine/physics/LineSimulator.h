#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "physics/BatchedIntegrator.h"
#include "physics/LineInputs.h"
#include "properties/Properties.h"

#include <string>
#include <vector>

namespace drytwin::physics {

/// @brief Which winnower model of the paper to use.
enum class WinnowerForm {
    Transient, ///< Eqs. 18–19 integrated with the section's inputs
    Terminal   ///< Eq. 17 for moisture; Eq. 19 as one explicit energy step for temperature
};

/// @brief Options of a line simulation.
struct SimulationOptions {
    properties::ModelSwitches switches;
    WinnowerForm winnower = WinnowerForm::Transient;
    bool reference = false; ///< per-parcel BDF with dense Newton (slow; checks the fast path)
    /// At 1e-5 the fast path stays within ~2e-6 kg/kg and ~1e-3 K of the reference path
    /// (tests/engine/physics), far below the instruments' noise (0.02 % wb, 0.03 K).
    double relTol = 1e-5;
    /// Cap on solver steps per section; a parcel needing more fails the run with an error.
    long maxStepsPerSection = 50000;
    /// Parameters to compute output sensitivities for: CVODES forward sensitivities for rate
    /// parameters, central differences for residence times (they move integration windows).
    std::vector<properties::Param> sensitivities;
    /// With the moisture_meter_lag extension and a subset of rows, the run covers a grid of this
    /// spacing [s] plus the subset instead of every row up to the last; 0: every row (exact).
    double meterGridS = 5;
    Status validate() const;
};

/// @brief Output sensitivities with respect to one parameter, per simulated row.
struct OutputSensitivity {
    properties::Param param;
    std::vector<double> dXOut; ///< ∂X_out/∂θ [dry basis per unit of θ]
    std::vector<double> dTOut; ///< ∂T_out/∂θ [K per unit of θ]
    std::vector<double> dXHdt;
    std::vector<double> dTHdt;
};

/// @brief Predictions aligned with the rows they were asked for.
/// Outlet values at row k come from the parcel that leaves the line at time_s[k]; the
/// proxies are that parcel's states at the end of each section (the paper's [X_HDT, T_HDT,
/// X_Conv, T_Conv] and the winnower inlet mix); tube-outlet predictions come from the parcel
/// that leaves the tube at time_s[k].
struct SimulationResult {
    std::vector<std::size_t> rows;
    std::vector<double> xOutDb, tOutK;
    std::vector<double> xHdtDb, tHdtK;
    std::vector<double> proxyXHdtDb, proxyTHdtK, proxyXConvDb, proxyTConvK, proxyXMixDb, proxyTMixK;
    std::vector<OutputSensitivity> sensitivities;
    IntegratorStats stats;
    double elapsedSeconds = 0;
};

/// @brief Names of the proxy states in the order of SimulationResult (for files and the GUI).
const std::vector<std::string>& proxyNames();

/// @brief Simulates the paper's three-section line model (Eqs. 1–19) at the given rows of a
/// batch (all rows when @p rows is empty). Thread-safe for distinct arguments.
Expected<SimulationResult> simulateLine(const LineInputs& inputs, const properties::ParameterSet& params,
                                        const SimulationOptions& options = {},
                                        const std::vector<std::size_t>& rows = {});

/// @brief Simulates several batches, spread over @p threads worker threads (0: one per core).
/// Progress is reported per finished batch from the calling thread; returning Stop cancels
/// the batches not yet started (the error is then Cancelled).
Expected<std::vector<SimulationResult>> simulateBatches(const std::vector<LineInputs>& batches,
                                                        const properties::ParameterSet& params,
                                                        const SimulationOptions& options = {},
                                                        unsigned threads = 0, const Progress& progress = {});

/// @brief Total transport delay from tube inlet to line outlet [s].
double totalDelay(const properties::ParameterSet& params);

} // namespace drytwin::physics
