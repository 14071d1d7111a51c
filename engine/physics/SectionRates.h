#pragma once

#include "properties/Properties.h"

namespace drytwin::physics {

using properties::ModelSwitches;
using properties::ParameterSet;

// Every section is written per kilogram of dry matter (M_dry = 1 kg): Eqs. 7–19 are linear in
// M_dry, so a parcel of any size follows the same intensive equations. The rates are templates
// over the number type (double, or properties::Pack2 for two parcels at once; see Pack.h).

/// @brief What a parcel in the drying tube sees. The PBM uses T_hot, the parameter w and the
/// tube coefficients; the virtual plant passes modified values for its extra mechanisms.
template <class T> struct TubeEnvironmentT {
    T tGasK{};                                   ///< gas temperature around the parcel (PBM: T_hot)
    T wGas = properties::math::constant<T>(0.0); ///< humidity ratio of the gas (PBM: parameter w)
    // Eigen's Pack2 leaves its elements uninitialised by default: every member starts from a value.
    T h = properties::math::constant<T>(0.0); ///< heat-transfer coefficient [W/(m²·K)] (h_HDT, less fouling)
    double k = 0;                             ///< mass-transfer coefficient [m/s] (PBM: k_HDT)
    T dryingFactor = properties::math::constant<T>(1.0); ///< multiplies Eq. 10 (falling rate; paper: 1)
};
using TubeEnvironment = TubeEnvironmentT<double>;

/// @brief Rates of one parcel and the energy terms behind them.
template <class T> struct SectionRatesT {
    T dXdt{};           ///< [1/s], Eq. 11 / 13 / 18
    T dTdt{};           ///< [K/s], Eq. 12 / 14 / 19
    T heatIn{};         ///< convective heat into the parcel [W per kg dry] (negative = loss)
    T evaporation{};    ///< dm_evap/dt [kg/s per kg dry] (= −dX/dt)
    T heatCapacity{};   ///< M_dry C_p,dry + M_water C_p,w [J/K per kg dry]
    T vapourEnthalpy{}; ///< energy drawn per kg evaporated: L_v, or the paper's L_v + C_p,w (T − T_ref)
                        ///< [J/kg]
    T waterActivity{};
};
using SectionRates = SectionRatesT<double>;

/// @brief What a parcel in the conveyor's top layer or the winnower sees.
template <class T> struct AmbientEnvironmentT {
    T tAirK{};
    T rh{};                                             ///< [0..1]
    T extraUptake = properties::math::constant<T>(0.0); ///< added dX/dt [1/s] (re-absorption; paper: 0)
    /// Equilibrium moisture X_e of this air when the caller already has it (the line simulator
    /// interpolates it between samples, like the inputs it comes from; hasXe set); otherwise
    /// computed from tAirK and rh with Eq. 5.
    T xeDb{};
    bool hasXe = false;
};
using AmbientEnvironment = AmbientEnvironmentT<double>;

namespace generic {

namespace pr = properties::generic;

/// @brief How strongly air of relative humidity @p rh [0..1] loads the conveyor's surface strands
/// (the ambient_reabsorption extension: dX/dt gains θ_reabs · 1e-4 · this). A hygroscopic leaf takes
/// up water faster than linearly in RH because its sorption isotherm steepens towards saturation:
/// the drive is RH times the isotherm's own rise, X_e(RH) / X_e(0.5) = (h / (1 − h))^θ_xe3 with
/// h = RH (Eq. 5; the temperature factor cancels), so that at RH 50 % it is 0.5, as the linear form
/// RH it replaced (θ_reabs keeps its meaning there). With the linear form the estimate of θ_reabs
/// moved with each batch's humidity (a dry day's batch gave 0, a humid one's 4), and discovery
/// turned the cause down as inconsistent; docs/mechanisms.md.
template <class T> T reabsorptionDrive(const T& rh, const ParameterSet& p) {
    const T h = properties::math::minOf(properties::math::maxOf(rh, 1e-3), 0.999);
    return h * properties::math::exp(p[properties::Param::theta_xe3] * properties::math::log(h / (1.0 - h)));
}

using properties::Param;

/// Energy drawn from the parcel per kg evaporated in Eqs. 12, 14, 19: L_v in the consistent
/// energy balance, L_v + C_p,w (T − T_ref) as the paper prints it (see ModelSwitches).
template <class T> T vapourEnthalpy(const T& tK, const T& aw, const ParameterSet& p, const ModelSwitches& s) {
    const T lv = pr::latentHeat(tK, aw, p, s);
    if (s.consistentEnergyBalance) {
        return lv;
    }
    return lv + p[Param::theta_Cp2] * (tK - p[Param::T_ref]);
}

/// X_e of the air around a parcel, Eq. (5).
template <class T> T equilibriumMoistureOf(const AmbientEnvironmentT<T>& env, const ParameterSet& p) {
    return env.hasXe ? env.xeDb : pr::equilibriumMoisture(env.tAirK, env.rh, p);
}

template <class T>
SectionRatesT<T> tubeRates(const T& x, const T& t, const TubeEnvironmentT<T>& env, const ParameterSet& p,
                           const ModelSwitches& s) {
    SectionRatesT<T> r;
    const T area = (1.0 + x) / p[Param::rho_mat] * (2.0 / p[Param::r] + 2.0 / p[Param::L_t]); // Eq. (7)
    r.heatIn = env.h * area * (env.tGasK - t);                                                // Eq. (8)
    r.waterActivity = pr::waterActivity(t, x, p, s.clampWaterActivity);
    const T rhoSurf = pr::vapourDensity(T(r.waterActivity * pr::saturationPressure(t)), t, p); // Eq. (9)
    const T pvGas = pr::vapourPressureOfHumidityRatio(env.wGas, p[Param::P_total]);            // Eq. (9)
    const T rhoGas = pr::vapourDensity(pvGas, env.tGasK, p);
    r.evaporation =
        env.dryingFactor * env.k * area * properties::math::maxOf(T(rhoSurf - rhoGas), 0.0); // Eq. (10)
    r.dXdt = -r.evaporation;                                                                 // Eq. (11)
    r.heatCapacity = pr::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (12)
    return r;
}

template <class T>
SectionRatesT<T> conveyorRates(const T& x, const T& t, const AmbientEnvironmentT<T>& env,
                               const ParameterSet& p, const ModelSwitches& s) {
    SectionRatesT<T> r;
    const T xe = equilibriumMoistureOf(env, p);
    const double lChar = p[Param::L_char];
    r.dXdt = -p[Param::chi_layer] * pr::effectiveDiffusivity(t, env.rh, x, p) * (x - xe) / (lChar * lChar) +
             env.extraUptake; // Eq. (13)
    r.evaporation = -r.dXdt;
    r.heatIn = -p[Param::h_conveyor] * p[Param::A_exp] * (t - env.tAirK);
    r.waterActivity = pr::waterActivity(t, x, p, s.clampWaterActivity);
    r.heatCapacity = pr::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (14)
    return r;
}

template <class T>
SectionRatesT<T> winnowerRates(const T& x, const T& t, double tS, const T& xMix, const T& tMixK,
                               const AmbientEnvironmentT<T>& env, const ParameterSet& p,
                               const ModelSwitches& s) {
    SectionRatesT<T> r;
    const T xe = equilibriumMoistureOf(env, p);
    // A parcel colder than the air does not flash; the exponent then stays bounded.
    const T excess = properties::math::maxOf(T(tMixK - env.tAirK), 0.0);
    const double kappa = p[Param::kappa];
    r.dXdt = -0.5 * (xMix - xe) * kappa * excess * properties::math::exp(T(-kappa * excess * tS)); // Eq. (18)
    r.evaporation = -r.dXdt;
    r.heatIn = -p[Param::h_winnower] * (t - env.tAirK);
    r.waterActivity = pr::waterActivity(t, x, p, s.clampWaterActivity);
    r.heatCapacity = pr::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (19)
    return r;
}

} // namespace generic

/// @brief generic::reabsorptionDrive for one parcel.
inline double reabsorptionDrive(double rh, const ParameterSet& p) {
    return generic::reabsorptionDrive(rh, p);
}

/// @brief Energy drawn per kg evaporated (Eqs. 12, 14, 19); see ModelSwitches::consistentEnergyBalance.
inline double vapourEnthalpy(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    return generic::vapourEnthalpy(tK, aw, p, s);
}

/// @brief X_e of the air around a parcel, Eq. (5).
inline double equilibriumMoistureOf(const AmbientEnvironment& env, const ParameterSet& p) {
    return generic::equilibriumMoistureOf(env, p);
}

/// @brief Drying-tube rates, Eqs. 7–12.
inline SectionRates tubeRates(double x, double t, const TubeEnvironment& env, const ParameterSet& p,
                              const ModelSwitches& s) {
    return generic::tubeRates(x, t, env, p, s);
}

/// @brief Conveyor top-layer rates, Eqs. 13–14.
inline SectionRates conveyorRates(double x, double t, const AmbientEnvironment& env, const ParameterSet& p,
                                  const ModelSwitches& s) {
    return generic::conveyorRates(x, t, env, p, s);
}

/// @brief Winnower rates of the transient form, Eqs. 18–19, at time @p tS after entry.
/// X_mix and T_mix are the parcel's state at entry (Eqs. 15–16).
inline SectionRates winnowerRates(double x, double t, double tS, double xMix, double tMixK,
                                  const AmbientEnvironment& env, const ParameterSet& p,
                                  const ModelSwitches& s) {
    return generic::winnowerRates(x, t, tS, xMix, tMixK, env, p, s);
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
