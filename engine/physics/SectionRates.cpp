#include "physics/SectionRates.h"

#include <algorithm>
#include <cmath>

namespace drytwin::physics {

using properties::Param;
namespace pr = properties;

namespace {
double vapourEnthalpy(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    // L_v + C_p,w (T − T_ref), the enthalpy the evaporated water carries (Eqs. 12, 14, 19).
    return pr::latentHeat(tK, aw, p, s) + p[Param::theta_Cp2] * (tK - p[Param::T_ref]);
}
} // namespace

SectionRates tubeRates(double x, double t, const TubeEnvironment& env, const ParameterSet& p,
                       const ModelSwitches& s) {
    SectionRates r;
    const double area = (1.0 + x) / p[Param::rho_mat] * (2.0 / p[Param::r] + 2.0 / p[Param::L_t]); // Eq. (7)
    r.heatIn = env.h * area * (env.tGasK - t);                                                     // Eq. (8)
    r.waterActivity = pr::waterActivity(t, x, p, s.clampWaterActivity);
    const double rhoSurf = pr::vapourDensity(r.waterActivity * pr::saturationPressure(t), t, p); // Eq. (9)
    const double rhoGas =
        pr::vapourDensity(pr::vapourPressureOfHumidityRatio(env.wGas, p[Param::P_total]), env.tGasK, p);
    r.evaporation = env.dryingFactor * env.k * area * std::max(0.0, rhoSurf - rhoGas); // Eq. (10)
    r.dXdt = -r.evaporation;                                                           // Eq. (11)
    r.heatCapacity = pr::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (12)
    return r;
}

SectionRates conveyorRates(double x, double t, const AmbientEnvironment& env, const ParameterSet& p,
                           const ModelSwitches& s) {
    SectionRates r;
    const double xe = pr::equilibriumMoisture(env.tAirK, env.rh, p);
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

SectionRates winnowerRates(double x, double t, double tS, double xMix, double tMixK,
                           const AmbientEnvironment& env, const ParameterSet& p, const ModelSwitches& s) {
    SectionRates r;
    const double xe = pr::equilibriumMoisture(env.tAirK, env.rh, p);
    // A parcel colder than the air does not flash; the exponent then stays bounded.
    const double excess = std::max(0.0, tMixK - env.tAirK);
    const double kappa = p[Param::kappa];
    r.dXdt = -0.5 * (xMix - xe) * kappa * excess * std::exp(-kappa * excess * tS); // Eq. (18)
    r.evaporation = -r.dXdt;
    r.heatIn = -p[Param::h_winnower] * (t - env.tAirK);
    r.waterActivity = pr::waterActivity(t, x, p, s.clampWaterActivity);
    r.heatCapacity = pr::heatCapacityPerDryKg(x, p, s);
    r.vapourEnthalpy = vapourEnthalpy(t, r.waterActivity, p, s);
    r.dTdt = (r.heatIn - r.vapourEnthalpy * r.evaporation) / r.heatCapacity; // Eq. (19)
    return r;
}

double winnowerTerminalMoisture(double xMix, double tMixK, const AmbientEnvironment& env,
                                const ParameterSet& p) {
    const double xe = pr::equilibriumMoisture(env.tAirK, env.rh, p);
    const double excess = std::max(0.0, tMixK - env.tAirK);
    return xMix - (xMix - xe) * 0.5 * (1.0 - std::exp(-p[Param::kappa] * p[Param::t_W] * excess)); // Eq. (17)
}

MixState winnowerInletMix(double xConv, double tConv, double xHdt, double tHdt, const ParameterSet& p,
                          const ModelSwitches& s) {
    const double b = p[Param::beta_top];
    const double cc = pr::specificHeat(xConv, p, s);
    const double ch = pr::specificHeat(xHdt, p, s);
    MixState m;
    m.xDb = b * xConv + (1.0 - b) * xHdt;                                        // Eq. (15)
    m.tK = (b * cc * tConv + (1.0 - b) * ch * tHdt) / (b * cc + (1.0 - b) * ch); // Eq. (16)
    return m;
}

} // namespace drytwin::physics
