#include "plant/Mechanisms.h"

namespace drytwin::plant {

const std::vector<MechanismInfo>& mechanisms() {
    static const std::vector<MechanismInfo> m{
        {Mechanism::TubeWallHeatLoss, "tube_wall_heat_loss",
         "wall-loss NTU of the tube at 16 m/s: the gas approaches ambient as exp(-s x (16/v)^0.8) along "
         "the tube (x: fraction of the length)",
         "-", 0.1, 1.0},
        {Mechanism::GasPhaseCoupling, "gas_phase_coupling",
         "multiplier of the physical gas-phase energy and vapour balance along the tube (1 = full coupling)",
         "-", 0.5, 2.0},
        {Mechanism::HeatTransferFouling, "heat_transfer_fouling",
         "asymptotic fractional loss of h_HDT: 1 - s (1 - exp(-t/2400 s)), reset by cleaning between batches",
         "-", 0.2, 0.8},
        {Mechanism::MoistureMeterLag, "moisture_meter_lag",
         "total time constant of the outlet moisture meter (second order: two equal stages)", "s", 30, 600},
        {Mechanism::MoistureMeterOffset, "moisture_meter_offset",
         "offset of the outlet moisture meter at 55 °C (it grows 10 % per 10 K of product temperature)",
         "% wb", 0.2, 3.0},
        {Mechanism::TransportDelayError, "transport_delay_error",
         "conveyor transport time minus its nominal value (with axial dispersion growing with it)", "s", 15,
         300},
        {Mechanism::FallingRateDrying, "falling_rate_drying",
         "fractional slow-down of tube drying at the equilibrium moisture, rising as depth^0.7 below "
         "X_cr = 0.20 kg/kg",
         "-", 0.5, 1.0},
        {Mechanism::AmbientReabsorption, "ambient_reabsorption",
         "moisture uptake on the conveyor: s 1e-4 RH exp(3 (RH - 0.5)) (1 - X/0.35) [1/s]", "1e-4 1/s", 3,
         50},
        {Mechanism::InletMoistureSensorOffset, "inlet_moisture_sensor_offset",
         "offset of the inlet moisture gauge (NIR) at 22 % wb; it grows 5 % per % wb of moisture above that "
         "(a calibration slope error)",
         "% wb", 0.5, 3.0},
        {Mechanism::HotAirSensorLag, "hot_air_sensor_lag",
         "time constant of the hot-air thermocouple (first order, on top of its few seconds as new): a "
         "fouled "
         "thermowell",
         "s", 30, 300},
        {Mechanism::InletMoistureSensorNoise, "inlet_moisture_sensor_noise",
         "extra scatter of the inlet moisture gauge: standard deviation of a noise correlated over 3 s "
         "(strands of varying colour and packing under the gauge)",
         "% wb", 0.4, 2.0},
    };
    return m;
}

const MechanismInfo& info(Mechanism m) {
    return mechanisms()[static_cast<std::size_t>(m)];
}

std::optional<Mechanism> mechanismByName(std::string_view name) {
    for (const auto& i : mechanisms()) {
        if (i.name == name) {
            return i.id;
        }
    }
    return std::nullopt;
}

} // namespace drytwin::plant
