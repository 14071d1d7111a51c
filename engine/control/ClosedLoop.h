#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "control/Mpc.h"
#include "control/Scenario.h"
#include "hybrid/HybridModel.h"
#include "plant/PlantLine.h"
#include "plant/VirtualPlant.h"

#include <optional>

#include <string>
#include <vector>

namespace drytwin::control {

/// @brief The controllers a scenario can compare: an MPC on each prediction model, and the
/// plant's own PI loop. Names are the model keys of CONTRACT.md §3.
enum class ControllerKind { Pbm, ExtInputResidual, Lstm, PgrlCc, Pi };
const char* controllerName(ControllerKind k);
std::optional<ControllerKind> controllerByName(const std::string& name);

/// @brief Closed-loop metrics over the scored part (paper Table 2).
struct ClosedLoopMetrics {
    double iaePctS = 0;  ///< Σ |X_out − setpoint| · 1 s over the product's true outlet moisture [%·s]
    double effortK2 = 0; ///< Σ Δu² of the hot-air setpoint, one term per sample [K²]
    double violationPct = 0;  ///< share of samples with the true X_out outside setpoint ± band [%]
    double solveMsMedian = 0; ///< Ipopt time per decision [ms]
    double solveMsMax = 0;
    double modelMsMedian = 0;     ///< forecasts and linearisation per decision [ms]
    double gainPctPerKMedian = 0; ///< the model's steady gain dX_out/dT_hot,sp per decision [% wb/K]
    int decisions = 0;
    int fallbacks = 0;
    std::string lastFallbackReason;
};

/// @brief The computed metrics of a trajectory: X_out true [% wb], setpoint [% wb] and the
/// applied hot-air setpoint [K] per sample (1 s), the band half-width, and the setpoint applied
/// before the first sample (for the first Δu).
ClosedLoopMetrics trajectoryMetrics(const std::vector<double>& xOutPct,
                                    const std::vector<double>& setpointPct,
                                    const std::vector<double>& hotAirSetpointK, double bandPct,
                                    double setpointBeforeK);

/// @brief How well a prediction model forecasts this scenario, as its MPC uses it (disturbances
/// held, the same output-disturbance update), measured on the PI run's record with the hot air
/// that was actually applied: the model error behind a controller's ranking.
struct ForecastCheck {
    std::vector<int> horizonsS = {30, 90, 150};
    std::vector<double> maePct; ///< MAE of the measured X_out per horizon [% wb]
    int origins = 0;
};

/// @brief The horizon a controller predicted at one decision.
struct PredictionSnapshot {
    double atS = 0;              ///< time of the decision in the scored part
    std::vector<double> xOutPct; ///< rows at … at+horizon
};

/// @brief One controller's run.
struct ControllerRun {
    ControllerKind kind = ControllerKind::Pi;
    bool ran = false; ///< false when the model holds no such prediction model
    std::string skippedReason;
    ClosedLoopMetrics metrics;
    // Trajectories of the scored part, one entry per second.
    std::vector<double> timeS, xOutMeasuredPct, xOutTruePct, setpointPct, hotAirSetpointC, hotAirC;
    std::vector<PredictionSnapshot> predictions;
    std::optional<ForecastCheck> forecastCheck; ///< MPC rows, when the PI loop ran too
    double elapsedSeconds = 0;
};

struct ClosedLoopOptions {
    MpcSettings mpc;
    std::vector<ControllerKind> controllers = {ControllerKind::Pbm, ControllerKind::ExtInputResidual,
                                               ControllerKind::Lstm, ControllerKind::PgrlCc,
                                               ControllerKind::Pi};
    /// Times in the scored part [s] whose predicted horizons are kept for plots (empty: one
    /// minute after each setpoint step and at the start).
    std::vector<double> predictionTimesS;
    Status validate() const { return mpc.validate(); }
};

struct ClosedLoopResult {
    Scenario scenario;
    /// The plant's true steady gain of X_out to the hot-air setpoint at the scenario's start
    /// [% wb per K], from two noise-free runs 2 K apart: what each model's gain is compared with.
    double plantGainPctPerK = 0;
    std::vector<ControllerRun> runs;
    Ending ending;
};

/// @brief Runs the scenario once per controller against the virtual plant, each run seeing the
/// same disturbances and instrument noise. The plant carries the scenario's mechanisms in its
/// own forms and true parameters (plant::PlantOptions::defaultTruth), never the controller's
/// model. Cancel (Stop) ends after the current sample with the runs done so far and the
/// current one's scored steps (Ending says so).
Expected<ClosedLoopResult> runScenario(const Scenario& scenario, const hybrid::HybridModel& model,
                                       const ClosedLoopOptions& options, const Progress& progress = {});

/// @brief The plant options and disturbances a scenario implies (for the GUI and tests).
plant::PlantOptions scenarioPlantOptions(const Scenario& scenario);

/// @brief The true disturbances of a scenario run, warm-up included: levels from the scenario
/// with small random fluctuations of the plant's own kinds, drawn from @p rng (seeded with the
/// scenario's seed, the same for every controller).
plant::PlantDisturbances scenarioDisturbances(const Scenario& scenario, std::mt19937_64& rng);

/// @brief The hot-air setpoint the line starts at: the PI loop's steady value for the
/// scenario's inlet moisture [K].
double initialSetpointK(const Scenario& scenario);

/// @brief Adds what the instruments showed at a sample to a controller's record (SI, dry basis).
void appendMeasuredOutputs(data::SiBatch& record, const plant::PlantSample& sample);
/// @brief Adds sample @p k's measured inputs, as the plant recorded them once applied.
void appendAppliedInputs(data::SiBatch& record, const plant::PlantBatch& plantRecord, std::size_t k);

/// @brief The prediction model an MPC of @p kind uses, or nullptr with @p missing saying why
/// (the model holds no such part; PI has none).
std::unique_ptr<OutletForecaster> forecasterFor(ControllerKind kind, const hybrid::HybridModel& model,
                                                std::string& missing);

} // namespace drytwin::control
