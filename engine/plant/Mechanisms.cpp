#include "plant/Mechanisms.h"

namespace drytwin::plant {

const std::vector<MechanismInfo>& mechanisms() {
    static const std::vector<MechanismInfo> m{
        {Mechanism::TubeWallHeatLoss, "tube_wall_heat_loss",
         "fraction of the hot-air excess over ambient lost to the wall: T_gas = T_hot - s (T_hot - T_amb)",
         "-", 0.05, 0.5},
        {Mechanism::GasPhaseCoupling, "gas_phase_coupling",
         "multiplier of the physical gas-phase energy and vapour balance along the tube (1 = full coupling)",
         "-", 0.5, 2.0},
        {Mechanism::HeatTransferFouling, "heat_transfer_fouling",
         "fractional loss of h_HDT at the end of a batch (linear build-up, reset by cleaning)", "-", 0.2,
         0.8},
        {Mechanism::MoistureMeterLag, "moisture_meter_lag", "time constant of the outlet moisture meter", "s",
         30, 600},
        {Mechanism::MoistureMeterOffset, "moisture_meter_offset",
         "constant offset of the outlet moisture meter", "% wb", 0.2, 3.0},
        {Mechanism::TransportDelayError, "transport_delay_error",
         "conveyor transport time minus its nominal value", "s", 15, 300},
        {Mechanism::FallingRateDrying, "falling_rate_drying",
         "fractional slow-down of tube drying at the equilibrium moisture, rising linearly below X_cr = 0.20 "
         "kg/kg",
         "-", 0.5, 1.0},
        {Mechanism::AmbientReabsorption, "ambient_reabsorption",
         "moisture uptake on the conveyor per unit ambient RH", "1e-4 1/s", 3, 50},
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
