#pragma once

#include "properties/Parameters.h"

#include <algorithm>
#include <cmath>

namespace drytwin::properties {

/// @brief The paper's ablation switches of the physics (Table 3, variants 1–3).
struct ModelSwitches {
    bool clampWaterActivity = true;   ///< a_w* = min(1, max(0, a_w)) (Eq. 2)
    bool latentHeatCorrection = true; ///< bound-water factor [1 + θ_Lv,aw (1 − a_w)] (Eq. 4)
    bool moistureDependentCp = true;  ///< C_p(X) of Eq. 3; off: C_p fixed at X = kCpReferenceMoisture
};
/// Dry-basis moisture at which C_p is frozen when moistureDependentCp is off (≈ 15 % wb, the
/// middle of the line's operating range).
inline constexpr double kCpReferenceMoisture = 0.176;
inline constexpr double kKelvin = 273.15;

/// @brief Saturation vapour pressure of water [Pa], Magnus form, T in K. Eq. (1)
inline double saturationPressure(double tK) {
    const double c = tK - kKelvin;
    return 610.78 * std::exp(17.27 * c / (237.7 + c)); // Eq. (1)
}

/// @brief Sorption isotherm f(X) of Eq. (2): the modified Oswin model of Eq. (5) inverted at the
/// reference temperature 25 °C, so that Eq. 2 and Eq. 5 agree there exactly:
/// f(X) = q / (1 + q), q = (X / (θ_xe1 + θ_xe2·25))^(1/θ_xe3).
/// Chosen because it is the one f consistent with the equilibrium model the paper already uses.
inline double sorptionIsotherm(double xDb, const ParameterSet& p) {
    if (xDb <= 0) {
        return 0.0;
    }
    const double a = p[Param::theta_xe1] + p[Param::theta_xe2] * 25.0; // Oswin at 25 °C
    // exp(log(·)/n) rather than pow: the same value to a few ulp, and several times cheaper in
    // glibc, which matters because every right-hand side of every section calls it.
    const double q = std::exp(std::log(xDb / a) / p[Param::theta_xe3]);
    return q / (1.0 + q);
}

/// @brief Water activity of Eq. (2), clamped to [0, 1] when @p clamp is set.
inline double waterActivity(double tK, double xDb, const ParameterSet& p, bool clamp) {
    const double aw =
        sorptionIsotherm(xDb, p) * std::exp(p[Param::theta_aw1] * (1.0 / tK - 1.0 / 298.15)); // Eq. (2)
    return clamp ? std::min(1.0, std::max(0.0, aw)) : aw;
}

/// @brief Specific heat of the wet material per kg of wet material [J/(kg·K)]. Eq. (3)
inline double specificHeat(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    const double x = s.moistureDependentCp ? xDb : kCpReferenceMoisture;
    return (p[Param::theta_Cp1] + x * p[Param::theta_Cp2]) / (1.0 + x); // Eq. (3)
}

/// @brief Heat capacity of the material per kg of dry matter, M_dry·C_p,dry + M_water·C_p,w
/// = (1 + X)·C_p(X) [J/(K·kg dry)] (left-hand side of Eqs. 12, 14, 19).
inline double heatCapacityPerDryKg(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    return (1.0 + xDb) * specificHeat(xDb, p, s);
}

/// @brief Latent heat of vaporisation [J/kg] with the bound-water correction. Eq. (4)
inline double latentHeat(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    const double base = (2501.0 - 2.361 * (tK - kKelvin)) * 1e3; // Eq. (4)
    return s.latentHeatCorrection ? base * (1.0 + p[Param::theta_Lv_aw] * (1.0 - aw)) : base;
}

/// @brief Equilibrium moisture, dry basis, modified Oswin model with T in °C. Eq. (5)
/// (θ_xe2 is per kelvin; with T in K the App. A values would give X_e ≈ 0.04, far below
/// tobacco's 0.10–0.15 at room conditions, so T enters in °C.) RH is clamped to [0, 0.999].
inline double equilibriumMoisture(double tK, double rh, const ParameterSet& p) {
    const double h = std::clamp(rh, 0.0, 0.999);
    const double tC = tK - kKelvin;
    if (h <= 0) {
        return 0.0;
    }
    // exp(n·log(·)) rather than pow, as in sorptionIsotherm.
    return (p[Param::theta_xe1] + p[Param::theta_xe2] * tC) *
           std::exp(p[Param::theta_xe3] * std::log(h / (1.0 - h))); // Eq. (5)
}

/// @brief Effective diffusion coefficient [m²/s]. Eq. (6)
inline double effectiveDiffusivity(double tK, double rh, double xDb, const ParameterSet& p) {
    return p[Param::theta_D0] * std::exp(-p[Param::theta_Ea] / (p[Param::R_gas] * tK)) * (1.0 + 2.0 * xDb) *
           (1.0 - p[Param::theta_D_RH] * rh); // Eq. (6)
}

/// @brief Partial pressure of water vapour in air of humidity ratio w [Pa]. Eq. (9)
inline double vapourPressureOfHumidityRatio(double w, double pTotal) {
    return w * pTotal / (0.622 + w);
}

/// @brief Vapour density of an ideal gas at partial pressure pv and temperature T [kg/m³]. Eq. (9)
inline double vapourDensity(double pv, double tK, const ParameterSet& p) {
    return pv / (p[Param::R_water] * tK);
}

} // namespace drytwin::properties
