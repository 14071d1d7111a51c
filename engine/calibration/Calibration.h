#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/SiBatch.h"
#include "physics/LineSimulator.h"
#include "properties/Parameters.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace drytwin::calibration {

/// @brief Weights of the calibration loss: Σ_o w_o · mean((y_o − ŷ_o)²), moisture in % wb and
/// temperature in °C. Tube-outlet terms count only where the batch measures them.
struct LossWeights {
    double xOut = 1.0;  ///< per (% wb)²
    double tOut = 0.01; ///< per K²: 1 K weighs like 0.1 % wb
    double xHdt = 1.0;
    double tHdt = 0.01;
};

/// @brief Options of a calibration (paper §IV.B, with a global then a local search).
struct CalibrationOptions {
    std::vector<properties::Param> freeParameters{properties::Param::h_HDT, properties::Param::k_HDT};
    /// Narrower bounds than the parameter table's, by parameter.
    std::map<properties::Param, std::pair<double, double>> bounds;
    LossWeights weights;
    /// Rows to fit; empty: the paper's subset (every 10th kept row, the first 300).
    std::vector<data::RowRef> rows;
    unsigned seed = 1;
    int maxEvaluations = 2000; ///< cap on loss evaluations, both phases together
    int globalEvaluations = 0; ///< 0: 60 per free parameter
    bool globalSearch = true;  ///< false: BOBYQA from the start point only (a refit near a known fit)
    bool intervals = true;     ///< false: skip the sensitivity run behind the Fisher intervals (NaN)
    double localRelTol = 1e-6; ///< BOBYQA's relative tolerance on the parameters
    physics::SimulationOptions simulation;
    Status validate() const;
};

/// @brief One loss evaluation.
struct IterationRecord {
    int evaluation = 0;
    std::string phase; ///< "global" or "local"
    std::vector<double> values;
    double loss = 0;
    double bestLoss = 0;
    bool failed = false; ///< the simulation failed; the loss was set to a penalty
};

/// @brief An estimated parameter.
struct Estimate {
    properties::Param param;
    double value = 0;
    double standardError = 0;       ///< sandwich (HAC) standard error; the interval below uses it
    double standardErrorFisher = 0; ///< F⁻¹ alone (independent rows assumed), for comparison
    double ci95Low = 0;
    double ci95High = 0;
    bool atBound = false; ///< within 0.1 % of the search range of a bound: the fit wants to go further
};

/// @brief Fit quality on the calibration rows.
struct Fit {
    double loss = 0;
    double maeXOutPct = 0;
    double maeTOutC = 0;
};

/// @brief Result of a calibration.
struct CalibrationResult {
    properties::ParameterSet parameters;
    std::vector<Estimate> estimates;
    Fit before;
    Fit after;
    std::vector<IterationRecord> history;
    int evaluations = 0;
    int failedEvaluations = 0;
    std::size_t rowsUsed = 0;
    std::string algorithm;
    std::string intervalMethod; ///< how the intervals were made (empty: none could be)
    double elapsedSeconds = 0;
    Ending ending; ///< converged, budget used, or stopped by the user with the best so far
};

/// @brief Calibrates the free parameters of the line model to measured batches: NLopt CRS2-LM
/// (a controlled-random-search global method, in the spirit of the paper's genetic algorithm)
/// then BOBYQA, in bound-normalised (log where the range spans a decade or more) coordinates.
/// A simulation failure in one evaluation costs that point a penalty; the search goes on.
/// Progress returning Stop gives a Cancelled error; StopKeepBest ends the search and returns
/// the best parameters found so far (with their fit and intervals).
Expected<CalibrationResult> calibrate(const std::vector<data::SiBatch>& batches,
                                      const properties::ParameterSet& start,
                                      const CalibrationOptions& options, const Progress& progress = {});

} // namespace drytwin::calibration
