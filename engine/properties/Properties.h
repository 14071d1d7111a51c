#pragma once

#include "common/Units.h"
#include "properties/Pack.h"
#include "properties/Parameters.h"

#include <algorithm>
#include <cmath>

namespace drytwin::properties {

/// @brief The paper's ablation switches of the physics (Table 3, variants 1–3).
struct ModelSwitches {
    bool clampWaterActivity = true;   ///< a_w* = min(1, max(0, a_w)) (Eq. 2)
    bool latentHeatCorrection = true; ///< bound-water factor [1 + θ_Lv,aw (1 − a_w)] (Eq. 4)
    bool moistureDependentCp = true;  ///< C_p(X) of Eq. 3; off: C_p fixed at X = kCpReferenceMoisture
    /// Energy drawn per kg evaporated in Eqs. 12, 14, 19. The paper prints L_v + C_p,w (T − T_ref);
    /// but the left side (M_dry C_p,dry + M_w C_p,w) dT/dt already follows from
    /// d/dt[(M_dry C_p,dry + M_w C_p,w)(T − T_ref)] = Q − ṁ (L_v + C_p,w (T − T_ref)) with
    /// dM_w/dt = −ṁ, where the sensible terms cancel and leave Q − L_v ṁ. The printed form counts
    /// C_p,w (T − T_ref) twice (about 10 % of the evaporative cooling at T_ref = 0 °C).
    /// true: L_v only (consistent, DryTwin's default); false: the paper's printed form.
    bool consistentEnergyBalance = true;
};
/// Dry-basis moisture at which C_p is frozen when moistureDependentCp is off (≈ 15 % wb, the
/// middle of the line's operating range).
inline constexpr double kCpReferenceMoisture = 0.176;
inline constexpr double kKelvin = units::kKelvinOffset;

// Each equation is a template over the number type (double, or Pack2 for two parcels at once;
// see Pack.h), in namespace `generic`; the double functions below it are the public API.
namespace generic {

template <class T> T saturationPressure(const T& tK) {
    const T c = tK - kKelvin;
    return 610.78 * math::exp(17.27 * c / (237.7 + c)); // Eq. (1)
}

template <class T> T sorptionIsotherm(const T& xDb, const ParameterSet& p) {
    const double a = p[Param::theta_xe1] + p[Param::theta_xe2] * 25.0; // Oswin at 25 °C
    // exp(log(·)/n) rather than pow: the same value to a few ulp, and several times cheaper in
    // glibc, which matters because every right-hand side of every section calls it.
    const T q = math::exp(math::log(xDb / a) / p[Param::theta_xe3]);
    return math::ifPositive(xDb, T(q / (1.0 + q)));
}

template <class T> T waterActivity(const T& tK, const T& xDb, const ParameterSet& p, bool clamp) {
    const T aw =
        sorptionIsotherm(xDb, p) * math::exp(p[Param::theta_aw1] * (1.0 / tK - 1.0 / 298.15)); // Eq. (2)
    return clamp ? math::minOf(math::maxOf(aw, 0.0), 1.0) : aw;
}

template <class T> T specificHeat(const T& xDb, const ParameterSet& p, const ModelSwitches& s) {
    const T x = s.moistureDependentCp ? xDb : math::constant<T>(kCpReferenceMoisture);
    return (p[Param::theta_Cp1] + x * p[Param::theta_Cp2]) / (1.0 + x); // Eq. (3)
}

template <class T> T heatCapacityPerDryKg(const T& xDb, const ParameterSet& p, const ModelSwitches& s) {
    return (1.0 + xDb) * specificHeat(xDb, p, s);
}

template <class T> T latentHeat(const T& tK, const T& aw, const ParameterSet& p, const ModelSwitches& s) {
    const T base = (2501.0 - 2.361 * (tK - kKelvin)) * 1e3; // Eq. (4)
    if (!s.latentHeatCorrection) {
        return base;
    }
    return base * (1.0 + p[Param::theta_Lv_aw] * (1.0 - aw));
}

template <class T> T equilibriumMoisture(const T& tK, const T& rh, const ParameterSet& p) {
    const T h = math::minOf(math::maxOf(rh, 0.0), 0.999);
    const T tC = tK - kKelvin;
    // exp(n·log(·)) rather than pow, as in sorptionIsotherm.
    const T xe = (p[Param::theta_xe1] + p[Param::theta_xe2] * tC) *
                 math::exp(p[Param::theta_xe3] * math::log(h / (1.0 - h))); // Eq. (5)
    return math::ifPositive(h, xe);
}

template <class T> T effectiveDiffusivity(const T& tK, const T& rh, const T& xDb, const ParameterSet& p) {
    return p[Param::theta_D0] * math::exp(-p[Param::theta_Ea] / (p[Param::R_gas] * tK)) * (1.0 + 2.0 * xDb) *
           (1.0 - p[Param::theta_D_RH] * rh); // Eq. (6)
}

template <class T> T vapourDensity(const T& pv, const T& tK, const ParameterSet& p) {
    return pv / (p[Param::R_water] * tK); // Eq. (9)
}

/// Partial pressure of water vapour in air of humidity ratio w [Pa] (each parcel's own w where
/// the gas-phase coupling humidifies the air).
template <class T> T vapourPressureOfHumidityRatio(const T& w, double pTotal) {
    return w * pTotal / (0.622 + w); // Eq. (9)
}

} // namespace generic

/// @brief Saturation vapour pressure of water [Pa], Magnus form, T in K. Eq. (1)
inline double saturationPressure(double tK) {
    return generic::saturationPressure(tK);
}

/// @brief Sorption isotherm f(X) of Eq. (2): the modified Oswin model of Eq. (5) inverted at the
/// reference temperature 25 °C, so that Eq. 2 and Eq. 5 agree there exactly:
/// f(X) = q / (1 + q), q = (X / (θ_xe1 + θ_xe2·25))^(1/θ_xe3); 0 for X ≤ 0.
/// Chosen because it is the one f consistent with the equilibrium model the paper already uses.
inline double sorptionIsotherm(double xDb, const ParameterSet& p) {
    return generic::sorptionIsotherm(xDb, p);
}

/// @brief Water activity of Eq. (2), clamped to [0, 1] when @p clamp is set.
inline double waterActivity(double tK, double xDb, const ParameterSet& p, bool clamp) {
    return generic::waterActivity(tK, xDb, p, clamp);
}

/// @brief Specific heat of the wet material per kg of wet material [J/(kg·K)]. Eq. (3)
inline double specificHeat(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    return generic::specificHeat(xDb, p, s);
}

/// @brief Heat capacity of the material per kg of dry matter, M_dry·C_p,dry + M_water·C_p,w
/// = (1 + X)·C_p(X) [J/(K·kg dry)] (left-hand side of Eqs. 12, 14, 19).
inline double heatCapacityPerDryKg(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    return generic::heatCapacityPerDryKg(xDb, p, s);
}

/// @brief Latent heat of vaporisation [J/kg] with the bound-water correction. Eq. (4)
inline double latentHeat(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    return generic::latentHeat(tK, aw, p, s);
}

/// @brief Equilibrium moisture, dry basis, modified Oswin model with T in °C. Eq. (5)
/// (θ_xe2 is per kelvin; with T in K the App. A values would give X_e ≈ 0.04, far below
/// tobacco's 0.10–0.15 at room conditions, so T enters in °C.) RH is clamped to [0, 0.999].
inline double equilibriumMoisture(double tK, double rh, const ParameterSet& p) {
    return generic::equilibriumMoisture(tK, rh, p);
}

/// @brief Effective diffusion coefficient [m²/s]. Eq. (6)
inline double effectiveDiffusivity(double tK, double rh, double xDb, const ParameterSet& p) {
    return generic::effectiveDiffusivity(tK, rh, xDb, p);
}

/// @brief Partial pressure of water vapour in air of humidity ratio w [Pa]. Eq. (9)
inline double vapourPressureOfHumidityRatio(double w, double pTotal) {
    return generic::vapourPressureOfHumidityRatio(w, pTotal);
}

/// @brief Vapour density of an ideal gas at partial pressure pv and temperature T [kg/m³]. Eq. (9)
inline double vapourDensity(double pv, double tK, const ParameterSet& p) {
    return generic::vapourDensity(pv, tK, p);
}

} // namespace drytwin::properties
