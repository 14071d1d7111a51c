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
    int horizonSteps = 30;      ///< multi-step horizon reported beside the one-step error
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
    bool hasStability = false;
    double spectralRadiusBefore = 0, spectralRadiusAfter = 0, alpha = 0, certificateMaxEig = 0;
};

/// @brief Held-out evaluation of every model a model file holds.
struct EvaluationResult {
    std::string split;
    std::size_t testRows = 0;
    int horizonSteps = 1;
    int multiStepHorizon = 0;
    std::vector<ModelMetrics> models;
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

/// @brief Keys of the reference predictors (CONTRACT.md §3).
inline constexpr const char* kPersistenceKey = "persistence";
inline constexpr const char* kPbmResidualHoldKey = "pbm_residual_hold";

/// @brief The reference predictions of a view's rows @p horizon steps ahead: the last measurement
/// held (persistence, ŷ_{k+H} = y_k), or with @p holdPbmError the PBM with its last measured error
/// held (ŷ_{k+H} = ŷ_mech,k+H + e_k). NaN where the batch has no measurement H steps before.
residual::HybridPrediction referencePrediction(const residual::BatchView& view, int horizon,
                                               bool holdPbmError);

/// @brief The PBM's own predictions of a view's rows (% wb, °C).
residual::HybridPrediction pbmPrediction(const residual::BatchView& view);

} // namespace drytwin::evaluation
