#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "plant/Mechanisms.h"
#include "plant/Sensors.h"
#include "properties/Parameters.h"

#include <map>
#include <string>
#include <vector>

namespace drytwin::plant {

/// @brief Which plant writes the data.
enum class PlantKind {
    /// Today's plant of the paper's base equations: plug-flow tube with the gas at T_hot, a top
    /// layer that mixes back with β_top, the winnower of Eq. 18 (byte-identical to earlier versions).
    Lumped,
    /// The line as the paper's §V says it really is: a 1D co-current gas–solid tube with a gas
    /// phase and a residence-time distribution, a belt layer with depth and axial mixing, a mixed
    /// winnower (docs/plant.md).
    Distributed,
};
/// @brief How the plant's instruments read.
enum class SensorMode {
    Default,   ///< lumped: its built-in small noise (as before); distributed: Realistic
    Realistic, ///< every column through its transmitter (noise, lag, quantisation, faults)
    Ideal,     ///< true values (mechanisms that are sensor faults still act)
};
std::string_view plantKindName(PlantKind k);
std::string_view sensorModeName(SensorMode m);

/// @brief Options of the virtual plant. Deterministic for a seed.
struct PlantOptions {
    /// The engine's default stays the lumped plant so that code written for it keeps its data;
    /// `generate`, `--demo` and the GUI default to the distributed one.
    PlantKind plant = PlantKind::Lumped;
    SensorMode sensors = SensorMode::Default;
    SensorFaultRates sensorFaults; ///< used when the sensors are realistic
    /// True when every column goes through its realistic transmitter.
    bool realisticSensors() const {
        return sensors == SensorMode::Realistic ||
               (sensors == SensorMode::Default && plant == PlantKind::Distributed);
    }
    unsigned seed = 1;
    int batches = 10;
    int samples = 6300; ///< per batch, 1 s apart
    std::map<Mechanism, double> effects;
    /// Time from which a mechanism acts [s since the batch start]; absent: from the start. A
    /// fouling that sets in grows from its onset; the others switch on at it (what-if scenarios).
    std::map<Mechanism, double> effectOnsetS;
    /// Unmeasured slow drift of the leaf's drying behaviour (k_HDT wanders ±5 %), as in the demo.
    bool unmeasuredDrift = false;
    double targetXOutPct = 13.0; ///< setpoint of the plant's own moisture controller
    double noiseScale = 1.0;     ///< multiplies every instrument's noise (0: ideal instruments)
    /// An unmeasured periodic swing of the gas temperature the material sees (say, steam-pressure
    /// cycling in the heat exchanger), matching no mechanism of CONTRACT.md §4: discovery must
    /// report it as unexplained. Period [s] and amplitude [K]; amplitude 0: none.
    double hiddenPeriodS = 600;
    double hiddenAmplitudeK = 0;
    /// The plant's true parameters. Defaults: the model table with h_HDT and k_HDT of this
    /// plant (72 W/(m²·K), 0.0236 m/s), which a calibration must find.
    properties::ParameterSet truth = defaultTruth();
    Status validate() const;
    static properties::ParameterSet defaultTruth();
    /// @brief The bundled demo: a realistic mix of mechanisms and unmeasured drift, on the
    /// distributed plant with realistic sensors unless @p kind says otherwise.
    static PlantOptions demo(unsigned seed = 2025, PlantKind kind = PlantKind::Distributed);
};

/// @brief One batch as the plant's instruments recorded it (SI units, dry basis).
struct PlantBatch {
    std::string id;
    std::vector<double> timeS, tHotSpK, tHotK, airSpeedMPerS, feedKgPerS, xInDb, tInK, tAmbK, rhAmb;
    std::vector<double> xHdtDb, tHdtK, xOutDb, tOutK;
    /// The outlet's true moisture (dry basis) and temperature [K] beside what its transmitters
    /// read: for studies that need the instruments' floor (how close any simulator can come to
    /// the measured values). Never written to batch files.
    std::vector<double> xOutTrueDb, tOutTrueK;
};

/// @brief Everything the plant produced, and the truth behind it.
struct PlantResult {
    std::vector<PlantBatch> batches;
    PlantKind plant = PlantKind::Lumped;
    SensorMode sensors = SensorMode::Default;
    /// Faults the transmitters had, summed over batches, per channel (realistic sensors only).
    std::array<Sensor::Counts, kSensorChannelCount> sensorFaultCounts{};
    properties::ParameterSet truth;
    std::map<Mechanism, double> effects;
    double elapsedSeconds = 0;
};

/// @brief Runs the virtual plant: the line with its own parameters, mechanisms, sensor noise,
/// disturbances, a PI controller moving the hot-air setpoint, and cleaning between batches.
/// Integrates with fixed-step RK4 (its own numerics, independent of the model's CVODE path).
/// @brief The id (and file name stem) of the plant's batch number @p oneBased: B01, B02, ...
std::string batchId(int oneBased);
Expected<PlantResult> runPlant(const PlantOptions& options, const Progress& progress = {});

} // namespace drytwin::plant
