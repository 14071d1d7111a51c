#include "properties/Properties.h"

#include <algorithm>
#include <cmath>

namespace drytwin::properties {

double saturationPressure(double tK) {
    const double c = tK - kKelvin;
    return 610.78 * std::exp(17.27 * c / (237.7 + c)); // Eq. (1)
}

double sorptionIsotherm(double xDb, const ParameterSet& p) {
    if (xDb <= 0) {
        return 0.0;
    }
    const double a = p[Param::theta_xe1] + p[Param::theta_xe2] * 25.0; // Oswin at 25 °C
    const double q = std::pow(xDb / a, 1.0 / p[Param::theta_xe3]);
    return q / (1.0 + q);
}

double waterActivity(double tK, double xDb, const ParameterSet& p, bool clamp) {
    const double aw =
        sorptionIsotherm(xDb, p) * std::exp(p[Param::theta_aw1] * (1.0 / tK - 1.0 / 298.15)); // Eq. (2)
    return clamp ? std::min(1.0, std::max(0.0, aw)) : aw;
}

double specificHeat(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    const double x = s.moistureDependentCp ? xDb : kCpReferenceMoisture;
    return (p[Param::theta_Cp1] + x * p[Param::theta_Cp2]) / (1.0 + x); // Eq. (3)
}

double heatCapacityPerDryKg(double xDb, const ParameterSet& p, const ModelSwitches& s) {
    return (1.0 + xDb) * specificHeat(xDb, p, s);
}

double latentHeat(double tK, double aw, const ParameterSet& p, const ModelSwitches& s) {
    const double base = (2501.0 - 2.361 * (tK - kKelvin)) * 1e3; // Eq. (4)
    return s.latentHeatCorrection ? base * (1.0 + p[Param::theta_Lv_aw] * (1.0 - aw)) : base;
}

double equilibriumMoisture(double tK, double rh, const ParameterSet& p) {
    const double h = std::clamp(rh, 0.0, 0.999);
    const double tC = tK - kKelvin;
    return (p[Param::theta_xe1] + p[Param::theta_xe2] * tC) *
           std::pow(h / (1.0 - h), p[Param::theta_xe3]); // Eq. (5)
}

double effectiveDiffusivity(double tK, double rh, double xDb, const ParameterSet& p) {
    return p[Param::theta_D0] * std::exp(-p[Param::theta_Ea] / (p[Param::R_gas] * tK)) * (1.0 + 2.0 * xDb) *
           (1.0 - p[Param::theta_D_RH] * rh); // Eq. (6)
}

double vapourPressureOfHumidityRatio(double w, double pTotal) {
    return w * pTotal / (0.622 + w);
} // Eq. (9)

double vapourDensity(double pv, double tK, const ParameterSet& p) {
    return pv / (p[Param::R_water] * tK);
} // Eq. (9)

} // namespace drytwin::properties
