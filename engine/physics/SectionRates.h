#pragma once

#include "properties/Properties.h"

namespace drytwin::physics {

using properties::ModelSwitches;
using properties::ParameterSet;

// Every section is written per kilogram of dry matter (M_dry = 1 kg): Eqs. 7–19 are linear in
// M_dry, so a parcel of any size follows the same intensive equations.

/// @brief What a parcel in the drying tube sees. The PBM uses T_hot, the parameter w and the
/// tube coefficients; the virtual plant passes modified values for its extra mechanisms.
struct TubeEnvironment {
    double tGasK = 0;          ///< gas temperature around the parcel (PBM: T_hot)
    double wGas = 0;           ///< humidity ratio of the gas (PBM: parameter w)
    double h = 0;              ///< heat-transfer coefficient [W/(m²·K)] (PBM: h_HDT)
    double k = 0;              ///< mass-transfer coefficient [m/s] (PBM: k_HDT)
    double dryingFactor = 1.0; ///< multiplies Eq. 10 (plant's falling-rate mechanism; PBM: 1)
};

/// @brief Rates of one tube parcel and the energy terms behind them.
struct SectionRates {
    double dXdt = 0;           ///< [1/s], Eq. 11 / 13 / 18
    double dTdt = 0;           ///< [K/s], Eq. 12 / 14 / 19
    double heatIn = 0;         ///< convective heat into the parcel [W per kg dry] (negative = loss)
    double evaporation = 0;    ///< dm_evap/dt [kg/s per kg dry] (= −dX/dt)
    double heatCapacity = 0;   ///< M_dry C_p,dry + M_water C_p,w [J/K per kg dry]
    double vapourEnthalpy = 0; ///< L_v + C_p,w (T − T_ref) [J/kg]
    double waterActivity = 0;
};

/// @brief Drying-tube rates, Eqs. 7–12.
SectionRates tubeRates(double xDb, double tK, const TubeEnvironment& env, const ParameterSet& p,
                       const ModelSwitches& s);

/// @brief What a parcel in the conveyor's top layer sees.
struct AmbientEnvironment {
    double tAirK = 0;
    double rh = 0;          ///< [0..1]
    double extraUptake = 0; ///< added dX/dt [1/s] (plant's ambient re-absorption; PBM: 0)
};

/// @brief Conveyor top-layer rates, Eqs. 13–14.
SectionRates conveyorRates(double xDb, double tK, const AmbientEnvironment& env, const ParameterSet& p,
                           const ModelSwitches& s);

/// @brief Winnower rates of the transient form, Eqs. 18–19, at time @p tS after entry.
/// X_mix and T_mix are the parcel's state at entry (Eqs. 15–16).
SectionRates winnowerRates(double xDb, double tK, double tS, double xMix, double tMixK,
                           const AmbientEnvironment& env, const ParameterSet& p, const ModelSwitches& s);

/// @brief Winnower outlet moisture of the terminal-value form. Eq. (17)
double winnowerTerminalMoisture(double xMix, double tMixK, const AmbientEnvironment& env,
                                const ParameterSet& p);

/// @brief Winnower inlet mixing of the conveyor top layer and the rest of the layer. Eqs. (15–16)
struct MixState {
    double xDb = 0;
    double tK = 0;
};
MixState winnowerInletMix(double xConv, double tConv, double xHdt, double tHdt, const ParameterSet& p,
                          const ModelSwitches& s);

} // namespace drytwin::physics
