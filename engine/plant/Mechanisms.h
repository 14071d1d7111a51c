#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::plant {

/// @brief The mechanisms of CONTRACT.md §4 that the base model leaves out. Strength 0 gives
/// back the base model.
enum class Mechanism {
    TubeWallHeatLoss,
    GasPhaseCoupling,
    HeatTransferFouling,
    MoistureMeterLag,
    MoistureMeterOffset,
    TransportDelayError,
    FallingRateDrying,
    AmbientReabsorption,
    InletMoistureSensorOffset,
    HotAirSensorLag,
    InletMoistureSensorNoise,
};
inline constexpr int kMechanismCount = 11;

/// @brief Static description of a mechanism: contract name, what the strength means.
struct MechanismInfo {
    Mechanism id;
    std::string_view name; ///< contract name, e.g. "heat_transfer_fouling"
    std::string_view strengthMeaning;
    std::string_view unit;
    double defaultStrength; ///< used for `--effect NAME` without a value
    double maxStrength;
};

const std::vector<MechanismInfo>& mechanisms();
const MechanismInfo& info(Mechanism m);
std::optional<Mechanism> mechanismByName(std::string_view name);

} // namespace drytwin::plant
