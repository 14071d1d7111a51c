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

/// @brief A model's steady gain against the plant's, where it is off enough to explain a poor
/// controller: the ratio model / plant when it is below 0.5, above 2 or of the other sign, else
/// nothing (also when either gain is not known). An MPC whose model underrates the hot air's effect
/// on the moisture over-acts, one that overrates it acts too little, one of the other sign
/// steers the wrong way: what a process engineer reads first when a learnt controller loses.
std::optional<double> mismatchedGainRatio(double modelGainPctPerK, double plantGainPctPerK);
/// @brief What a controller whose model's gain is @p ratio times the plant's does, in English
/// (the CLI and the report; the What-if tab words it itself, translated): "it underrates the hot
/// air's effect, so it over-acts (the setpoint swings towards its limits)".
std::string gainMismatchEffect(double ratio);

/// @brief The hot-air setpoint the line starts at: the PI loop's steady value for the
/// scenario's inlet moisture [K].
double initialSetpointK(const Scenario& scenario);

/// @brief The virtual plant's line of a scenario with the state of the loop around it: the
/// record a controller sees (outputs up to now, inputs before now), the plant's PI loop and the
/// setpoint applied last. Advances one second at a time under the PI loop or an MPC; the what-if
/// runs and the training sessions share it. The warm-up of the scenario always runs under PI.
class ControlledLine {
public:
    /// @brief The line at the start of the scenario's warm-up, its disturbances drawn from the
    /// scenario's seed and its instrument noise from @p random (which must outlive the line).
    ControlledLine(const Scenario& scenario, const plant::PlantOptions& plantOptions,
                   plant::PlantRandom& random);
    /// @brief A full copy (a snapshot) drawing its noise from @p random, copied alongside.
    ControlledLine clone(plant::PlantRandom& random) const;

    /// @brief What one second gave.
    struct Second {
        plant::PlantSample sample;           ///< what the instruments showed
        double setpointK = 0;                ///< the hot-air setpoint applied
        double hotAirK = 0;                  ///< the true hot air during the second
        std::optional<MpcDecision> decision; ///< when an MPC decided at this second
    };
    /// @brief Measures, lets the PI loop (no @p mpc, or during the warm-up) or the MPC (at each
    /// control interval, held in between) choose the setpoint for @p targetPct, applies it. While
    /// an MPC is in charge the PI loop tracks it, so that handing back to PI is bumpless.
    Second step(MpcController* mpc, double targetPct);
    /// @brief Seconds run so far, warm-up included.
    std::size_t sample() const { return m_line->sample(); }
    bool warmingUp() const { return sample() < m_warmupS; }
    const data::SiBatch& record() const { return m_record; }
    plant::PlantLine& line() { return *m_line; }
    const plant::PlantLine& line() const { return *m_line; }

private:
    ControlledLine() = default;
    std::unique_ptr<plant::PlantLine> m_line;
    plant::PlantPiController m_pi;
    data::SiBatch m_record;
    double m_lastSetpointK = 0;
    std::size_t m_warmupS = 0;
    double m_bandPct = 0;
    int m_controlIntervalS = 1;
    double m_warmupTargetPct = 0;
};

/// @brief The prediction model an MPC of @p kind uses, or nullptr with @p missing saying why
/// (the model holds no such part; PI has none).
std::unique_ptr<OutletForecaster> forecasterFor(ControllerKind kind, const hybrid::HybridModel& model,
                                                std::string& missing, bool controlThroughPhysics = true,
                                                bool holdCorrection = true,
                                                bool residualAlongHeldHotAir = true);

} // namespace drytwin::control
