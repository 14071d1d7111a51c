#pragma once

#include "properties/Parameters.h"

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
double saturationPressure(double tK);

/// @brief Sorption isotherm f(X) of Eq. (2): the modified Oswin model of Eq. (5) inverted at the
/// reference temperature 25 °C, so that Eq. 2 and Eq. 5 agree there exactly:
/// f(X) = q / (1 + q), q = (X / (θ_xe1 + θ_xe2·25))^(1/θ_xe3).
/// Chosen because it is the one f consistent with the equilibrium model the paper already uses.
double sorptionIsotherm(double xDb, const ParameterSet& p);

/// @brief Water activity of Eq. (2), clamped to [0, 1] when @p clamp is set.
double waterActivity(double tK, double xDb, const ParameterSet& p, bool clamp);

/// @brief Specific heat of the wet material per kg of wet material [J/(kg·K)]. Eq. (3)
double specificHeat(double xDb, const ParameterSet& p, const ModelSwitches& s);

/// @brief Heat capacity of the material per kg of dry matter, M_dry·C_p,dry + M_water·C_p,w
/// = (1 + X)·C_p(X) [J/(K·kg dry)] (left-hand side of Eqs. 12, 14, 19).
double heatCapacityPerDryKg(double xDb, const ParameterSet& p, const ModelSwitches& s);

/// @brief Latent heat of vaporisation [J/kg] with the bound-water correction. Eq. (4)
double latentHeat(double tK, double aw, const ParameterSet& p, const ModelSwitches& s);

/// @brief Equilibrium moisture, dry basis, modified Oswin model with T in °C. Eq. (5)
/// (θ_xe2 is per kelvin; with T in K the App. A values would give X_e ≈ 0.04, far below
/// tobacco's 0.10–0.15 at room conditions, so T enters in °C.) RH is clamped to [0, 0.999].
double equilibriumMoisture(double tK, double rh, const ParameterSet& p);

/// @brief Effective diffusion coefficient [m²/s]. Eq. (6)
double effectiveDiffusivity(double tK, double rh, double xDb, const ParameterSet& p);

/// @brief Partial pressure of water vapour in air of humidity ratio w [Pa]. Eq. (9)
double vapourPressureOfHumidityRatio(double w, double pTotal);

/// @brief Vapour density of an ideal gas at partial pressure pv and temperature T [kg/m³]. Eq. (9)
double vapourDensity(double pv, double tK, const ParameterSet& p);

} // namespace drytwin::properties
