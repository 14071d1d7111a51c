#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/SiBatch.h"
#include "hybrid/HybridModel.h"
#include "residual/ResidualModel.h"

#include <functional>

#include <string>
#include <vector>

namespace drytwin::evaluation {

/// @brief Options of a held-out evaluation.
struct EvaluationOptions {
    int horizonSteps = 30; ///< multi-step horizon reported beside the one-step error
    /// Horizons of the horizon curve [steps]; 1 and horizonSteps are always added. The line's
    /// transport delay is about 70 s, so the curve runs well past it.
    std::vector<int> horizons{1, 2, 5, 10, 20, 30, 45, 60, 90, 120, 150, 180};
    double trainFraction = 0.7; ///< chronological split (paper §IV.A)
    int ljungBoxLags = 20;
    Status validate() const;
};

/// @brief Accuracy of one output: MAE and R² in % wb or °C, Ljung-Box p of the residual.
struct OutputMetrics {
    double mae = 0;
    double r2 = 0;
    double ljungBoxP = 0;
};

/// @brief One model's held-out metrics.
struct ModelMetrics {
    std::string name; ///< contract key: pbm, ext_input_residual, lstm, pgrl_cc
    OutputMetrics moisture;
    OutputMetrics temperature;
    OutputMetrics moistureMultiStep;
    OutputMetrics temperatureMultiStep;
    std::vector<double> moistureResidual;    ///< held-out rows, % wb, for plots (ACF, PSD)
    std::vector<double> temperatureResidual; ///< held-out rows, °C
    /// MAE over the better of persistence and pbm_residual_hold at the same horizon (< 1 beats both).
    double skillMoisture = 0, skillTemperature = 0, skillMoistureMultiStep = 0, skillTemperatureMultiStep = 0;
    /// The horizon curve: metrics and skill at each of EvaluationResult::horizons.
    std::vector<OutputMetrics> moistureByHorizon, temperatureByHorizon;
    std::vector<double> skillMoistureByHorizon, skillTemperatureByHorizon;
    bool hasStability = false;
    double spectralRadiusBefore = 0, spectralRadiusAfter = 0, alpha = 0, certificateMaxEig = 0;
    bool choleskyPasses = false; ///< α²P − AᵀPA ≻ 0 by Cholesky, checked apart from the solver
    double pConditionNumber = 0;
    residual::StabilityComparison stabilityComparison; ///< training loss: unconstrained / pulled / Eq. 30
};

/// @brief Held-out evaluation of every model a model file holds.
struct EvaluationResult {
    std::string split;
    std::size_t testRows = 0;
    int horizonSteps = 1;
    int multiStepHorizon = 0;
    std::vector<ModelMetrics> models;
    std::vector<int> horizons; ///< of the horizon curve, ascending, with 1 and multiStepHorizon
    /// Predictions that never see a measured output (pbm, ext_input_residual, pgrl_cc): the
    /// residual model rolled from each batch's start on inputs and proxies alone. Only
    /// moisture/temperature metrics are filled; the LSTM has no such mode (it needs outputs).
    std::vector<ModelMetrics> freeRun;
    double elapsedSeconds = 0;
    Ending ending;
};

/// @brief Metrics on the chronological held-out part (rows the cleaning keeps).
Expected<EvaluationResult> evaluate(const std::vector<data::SiBatch>& batches,
                                    const hybrid::HybridModel& model, const EvaluationOptions& options = {},
                                    const Progress& progress = {});

/// @brief Output metrics of observed/predicted series (moisture in % wb or temperature in °C).
OutputMetrics outputMetrics(const std::vector<double>& observed, const std::vector<double>& predicted,
                            int lbLags);

/// @brief Makes a model's predictions for the rows of a view.
using Predictor = std::function<residual::HybridPrediction(const residual::BatchView&)>;

/// @brief Metrics and residuals of predictions over the rows of the views that the cleaning
/// keeps and the model could predict.
struct ScoredPredictions {
    OutputMetrics moisture;
    OutputMetrics temperature;
    std::vector<double> moistureResidual;    ///< % wb
    std::vector<double> temperatureResidual; ///< °C
};
ScoredPredictions scorePredictions(const std::vector<residual::BatchView>& views, const Predictor& predict,
                                   int lbLags);

/// @brief Makes a model's predictions for the rows of a view at several horizons, one per entry.
using HorizonPredictor = std::function<std::vector<residual::HybridPrediction>(const residual::BatchView&,
                                                                               const std::vector<int>&)>;

/// @brief scorePredictions at each horizon, predicting each view once for all horizons.
std::vector<ScoredPredictions> scoreHorizons(const std::vector<residual::BatchView>& views,
                                             const HorizonPredictor& predict,
                                             const std::vector<int>& horizons, int lbLags);

/// @brief Keys of the reference predictors (CONTRACT.md §3).
inline constexpr const char* kPersistenceKey = "persistence";
inline constexpr const char* kPbmResidualHoldKey = "pbm_residual_hold";

/// @brief The reference predictions of a view's rows @p horizon steps ahead: the last measurement
/// held (persistence, ŷ_{k+H} = y_k), or with @p holdPbmError the PBM with its last measured error
/// held (ŷ_{k+H} = ŷ_mech,k+H + e_k). NaN where the batch has no measurement H steps before.
residual::HybridPrediction referencePrediction(const residual::BatchView& view, int horizon,
                                               bool holdPbmError);

/// @brief A reference predictor as a HorizonPredictor: referencePrediction at each horizon.
HorizonPredictor referencePredictor(bool holdPbmError);

/// @brief The PBM's own predictions of a view's rows (% wb, °C).
residual::HybridPrediction pbmPrediction(const residual::BatchView& view);

} // namespace drytwin::evaluation
