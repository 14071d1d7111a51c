#pragma once

#include "common/Error.h"
#include "plant/VirtualPlant.h"

#include <string>
#include <vector>

namespace drytwin::control {

/// @brief A measured input a scenario moves.
enum class ScenarioInput { Feed, InletMoisture, Ambient, Humidity };

/// @brief A step (duration 0) or a ramp of one input, from its value at @p atS to @p to over
/// @p durationS seconds, in the input's file unit (kg/h, % wb, °C, % RH).
struct InputChange {
    ScenarioInput input = ScenarioInput::Feed;
    double atS = 0;
    double durationS = 0;
    double to = 0;
};

/// @brief A step of the outlet-moisture setpoint [% wb].
struct SetpointStep {
    double atS = 0;
    double toPct = 0;
};

/// @brief A mechanism of CONTRACT.md §4 in the plant, hidden from every controller, acting from
/// @p atS (0: from the start; before the scored part when negative is not allowed).
struct HiddenMechanism {
    plant::Mechanism mechanism = plant::Mechanism::HeatTransferFouling;
    double strength = 0;
    double atS = 0;
};

/// @brief A closed-loop what-if scenario (schema in docs/mpc.md). Times are seconds from the
/// start of the scored part, which follows a warm-up under the plant's own PI loop.
struct Scenario {
    std::string name;
    std::string description;
    unsigned seed = 1;
    int lengthS = 1000;        ///< scored steps (1 s each)
    int warmupS = 300;         ///< PI warm-up before the scored part (gives models their history)
    int controlIntervalS = 2;  ///< an MPC decides every this many seconds and holds in between
    double setpointPct = 13.0; ///< initial outlet-moisture setpoint [% wb]
    double bandPct = 0.5;      ///< the product is in specification within setpoint ± band [% wb]
    double feedKgH = 6200;     ///< initial levels of the measured inputs
    double xInPct = 22.0;
    double tInC = 25.0;
    double tAmbC = 22.0;
    double rhPct = 50.0;
    double airSpeedMPerS = 16.0;
    double fluctuation = 1.0; ///< scale of the inputs' random fluctuations (0: none)
    double noiseScale = 1.0;  ///< scale of the lumped plant's built-in instruments' noise (0: ideal)
    /// The plant the controllers run against (file key "plant"; files without it: the lumped plant,
    /// which every scenario ran on before the distributed plant existed).
    plant::PlantKind plant = plant::PlantKind::Lumped;
    plant::SensorMode sensors = plant::SensorMode::Default; ///< file key "sensors": realistic | ideal
    /// The instruments the scenario's plant reads with, as a word: "realistic", "ideal", or
    /// "builtin" (the lumped plant's own small noise), so that a result says which line it ran on.
    std::string_view instrumentsName() const;
    bool unmeasuredDrift = true;
    std::vector<SetpointStep> setpointSteps;
    std::vector<InputChange> inputChanges;
    std::vector<HiddenMechanism> mechanisms; ///< in the plant from the start or switched on later

    Status validate() const;
    /// @brief The setpoint at time t of the scored part [% wb].
    double setpointAt(double t) const;
};

/// @brief Reads a scenario file. Syntax errors and wrong values name the file and line
/// ("file:line: reason"); ErrorKind::BadInput.
Expected<Scenario> loadScenario(const std::string& path);
/// @brief Parses scenario JSON text; @p place names it in errors.
Expected<Scenario> parseScenario(const std::string& text, const std::string& place);

} // namespace drytwin::control
