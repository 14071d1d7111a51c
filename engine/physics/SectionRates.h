#pragma once

#include "properties/Properties.h"

namespace drytwin::physics {

using properties::ModelSwitches;
using properties::ParameterSet;

/// @brief L_v + C_p,w (T − T_ref), the enthalpy the evaporated water carries (Eqs. 12, 14, 19).
inline double vapourEnthalpy(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    return properties::latentHeat(tK, aw, p, s) +
           p[properties::Param::theta_Cp2] * (tK - p[properties::Param::T_ref]);
}

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
inline SectionRates tubeRates(double x, double t, const TubeEnvironment& env, const ParameterSet& p,
                              const ModelSwitches& s) {
    SectionRates r;
    const double area = (1.0 + x) / p[properties::Param::rho_mat] *
                        (2.0 / p[properties::Param::r] + 2.0 / p[properties::Param::L_t]); // Eq. (7)
    r.heatIn = env.h * area * (env.tGasK - t);                                             // Eq. (8)
    r.waterActivity = properties::waterActivity(t, x, p, s.clampWaterActivity);
    const double rhoSurf =
        properties::vapourDensity(r.waterActivity * properties::saturationPressure(t), t, p); // Eq. (9)
    const double rhoGas = properties::vapourDensity(
        properties::vapourPressureOfHumidityRatio(env.wGas, p[properties::Param::P_total]), env.tGasK, p);
    r.evaporation = env.dryingFactor * env.k * area * std::max(0.0, rhoSurf - rhoGas); // Eq. (10)
    r.dXdt = -r.evaporation;                                                           // Eq. (11)
    r.heatCapacity = properties::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (12)
    return r;
}

/// @brief What a parcel in the conveyor's top layer sees.
struct AmbientEnvironment {
    double tAirK = 0;
    double rh = 0;          ///< [0..1]
    double extraUptake = 0; ///< added dX/dt [1/s] (plant's ambient re-absorption; PBM: 0)
    /// Equilibrium moisture X_e of this air when the caller already has it (the line simulator
    /// interpolates it between samples, like the inputs it comes from); negative: computed
    /// from tAirK and rh with Eq. 5.
    double xeDb = -1;
};

/// @brief X_e of the air around a parcel, Eq. (5).
inline double equilibriumMoistureOf(const AmbientEnvironment& env, const ParameterSet& p) {
    return env.xeDb >= 0 ? env.xeDb : properties::equilibriumMoisture(env.tAirK, env.rh, p);
}

/// @brief Conveyor top-layer rates, Eqs. 13–14.
inline SectionRates conveyorRates(double x, double t, const AmbientEnvironment& env, const ParameterSet& p,
                                  const ModelSwitches& s) {
    SectionRates r;
    const double xe = equilibriumMoistureOf(env, p);
    const double lChar = p[properties::Param::L_char];
    r.dXdt = -p[properties::Param::chi_layer] * properties::effectiveDiffusivity(t, env.rh, x, p) * (x - xe) /
                 (lChar * lChar) +
             env.extraUptake; // Eq. (13)
    r.evaporation = -r.dXdt;
    r.heatIn = -p[properties::Param::h_conveyor] * p[properties::Param::A_exp] * (t - env.tAirK);
    r.waterActivity = properties::waterActivity(t, x, p, s.clampWaterActivity);
    r.heatCapacity = properties::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (14)
    return r;
}

/// @brief Winnower rates of the transient form, Eqs. 18–19, at time @p tS after entry.
/// X_mix and T_mix are the parcel's state at entry (Eqs. 15–16).
inline SectionRates winnowerRates(double x, double t, double tS, double xMix, double tMixK,
                                  const AmbientEnvironment& env, const ParameterSet& p,
                                  const ModelSwitches& s) {
    SectionRates r;
    const double xe = equilibriumMoistureOf(env, p);
    // A parcel colder than the air does not flash; the exponent then stays bounded.
    const double excess = std::max(0.0, tMixK - env.tAirK);
    const double kappa = p[properties::Param::kappa];
    r.dXdt = -0.5 * (xMix - xe) * kappa * excess * std::exp(-kappa * excess * tS); // Eq. (18)
    r.evaporation = -r.dXdt;
    r.heatIn = -p[properties::Param::h_winnower] * (t - env.tAirK);
    r.waterActivity = properties::waterActivity(t, x, p, s.clampWaterActivity);
    r.heatCapacity = properties::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (19)
    return r;
}

/// @brief Winnower outlet moisture of the terminal-value form. Eq. (17)
inline double winnowerTerminalMoisture(double xMix, double tMixK, const AmbientEnvironment& env,
                                       const ParameterSet& p) {
    const double xe = equilibriumMoistureOf(env, p);
    const double excess = std::max(0.0, tMixK - env.tAirK);
    return xMix - (xMix - xe) * 0.5 *
                      (1.0 - std::exp(-p[properties::Param::kappa] * p[properties::Param::t_W] *
                                      excess)); // Eq. (17)
}

/// @brief Winnower inlet mixing of the conveyor top layer and the rest of the layer. Eqs. (15–16)
struct MixState {
    double xDb = 0;
    double tK = 0;
};
inline MixState winnowerInletMix(double xConv, double tConv, double xHdt, double tHdt, const ParameterSet& p,
                                 const ModelSwitches& s) {
    const double b = p[properties::Param::beta_top];
    const double cc = properties::specificHeat(xConv, p, s);
    const double ch = properties::specificHeat(xHdt, p, s);
    MixState m;
    m.xDb = b * xConv + (1.0 - b) * xHdt;                                        // Eq. (15)
    m.tK = (b * cc * tConv + (1.0 - b) * ch * tHdt) / (b * cc + (1.0 - b) * ch); // Eq. (16)
    return m;
}

} // namespace drytwin::physics
