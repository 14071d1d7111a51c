#pragma once

#include "baselines/LstmBaseline.h"
#include "common/Error.h"
#include "data/SiBatch.h"
#include "physics/LineSimulator.h"
#include "residual/ResidualModel.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::control {

/// @brief What an MPC knows at a decision at row @p now of a closed-loop record: the measured
/// inputs of rows < now and the measured outputs of rows ≤ now (the inputs of row now are
/// recorded when the decision is applied, as on a plant whose controller and logger share a scan).
struct DecisionPoint {
    const data::SiBatch* record = nullptr;
    std::size_t now = 0;
};

/// @brief A prediction model as an MPC uses it: the outlet moisture over a horizon for
/// candidate hot-air trajectories, from the line's current state. The line's state is the
/// history of every parcel still in it, so "from this state" means from the record.
class OutletForecaster {
public:
    virtual ~OutletForecaster() = default;
    /// @brief X_out [% wb] of rows now … now+horizon for each plan. A plan is the hot-air
    /// temperature [K] of rows now … now+horizon; the measured disturbances are held at their
    /// last recorded values. Entry 0 is the model's estimate of row now made without the
    /// measurement of row now (the output-disturbance update compares it with that measurement).
    virtual Expected<std::vector<std::vector<double>>>
    forecast(const DecisionPoint& at, const std::vector<std::vector<double>>& hotAirPlansK, int horizon) = 0;
    /// @brief Rows of history the model needs before it can forecast.
    virtual std::size_t historyNeeded() const = 0;
};

/// @brief The calibrated PBM alone (Eqs. 1–19).
std::unique_ptr<OutletForecaster> pbmForecaster(properties::ParameterSet params,
                                                physics::SimulationOptions options);
/// @brief PBM + a residual model (PGRL-CC or the external-input baseline), Eq. 21. With
/// @p controlThroughPhysics the residual is forecast along the first plan only and every plan
/// gets it added to its own PBM run (MpcSettings::controlThroughPhysics). With
/// @p holdCorrection the input-driven correction is held at its value at the decision
/// (MpcSettings::holdCorrectionOverHorizon). With @p residualAlongHeldHotAir (and
/// @p controlThroughPhysics) the residual is forecast along a plan holding the hot air at its last
/// measured value (MpcSettings::residualAlongHeldHotAir).
std::unique_ptr<OutletForecaster>
residualForecaster(properties::ParameterSet params, physics::SimulationOptions options,
                   std::shared_ptr<const residual::ResidualModel> model, bool controlThroughPhysics = true,
                   bool holdCorrection = true, bool residualAlongHeldHotAir = true);
/// @brief Holds the correction of @p corrected over @p pbm (outlet moisture in % wb, temperature
/// in K) at its value at row @p origin for every later row: after a decision the corrected run
/// changes as the physics does (MpcSettings::holdCorrectionOverHorizon). Rows up to @p origin,
/// and a run without a finite correction at @p origin, are left as they are.
void holdCorrectionAfter(std::size_t origin, const physics::SimulationResult& pbm,
                         physics::SimulationResult& corrected);
/// @brief The black-box LSTM, carried along the record row by row.
std::unique_ptr<OutletForecaster> lstmForecaster(std::shared_ptr<const baselines::LstmBaseline> model);

/// @brief The record's rows [from, now+horizon] with the inputs a plan gives after row now−1
/// (disturbances held, hot air from the plan) and no outputs after row now.
data::SiBatch planWindow(const DecisionPoint& at, std::size_t from, const std::vector<double>& hotAirPlanK,
                         int horizon);

} // namespace drytwin::control
