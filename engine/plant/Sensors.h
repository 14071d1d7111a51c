#pragma once

#include <array>
#include <random>
#include <string_view>

namespace drytwin::plant {

/// @brief The plant's measured columns, each read through its own transmitter.
enum class SensorChannel {
    HotAir,             ///< T_hot_C: thermocouple in a thermowell at the tube inlet
    AirSpeed,           ///< air_speed_m_s: averaging pitot tube
    Feed,               ///< feed_kg_h: weigh belt
    InletMoisture,      ///< X_in_pct: NIR gauge over the feed belt
    InletTemperature,   ///< T_in_C: IR pyrometer on the feed
    AmbientTemperature, ///< T_amb_C: hall sensor in a radiation shield
    AmbientHumidity,    ///< RH_amb_pct: capacitive hygrometer
    TubeMoisture,       ///< X_hdt_pct: NIR gauge at the tube outlet
    TubeTemperature,    ///< T_hdt_C: IR pyrometer at the tube outlet
    OutletMoisture,     ///< X_out_pct: NIR gauge after the winnower
    OutletTemperature,  ///< T_out_C: IR pyrometer after the winnower
};
inline constexpr int kSensorChannelCount = 11;

/// @brief How one transmitter turns the true value into a reading. Values in the channel's
/// file unit (% wb, °C/K differences, kg/h, m/s, % RH).
struct SensorSpec {
    std::string_view column;      ///< contract column, for messages and docs
    double noiseSd = 0;           ///< standard deviation of the reading's noise
    double noiseCorrelationS = 0; ///< time constant of the noise (0: white)
    double relativeNoise = 0;     ///< further noise as a fraction of the reading (weigh belts)
    double lagS = 0;              ///< first-order time constant of the sensor
    double quantum = 0;           ///< transmitter resolution (0: continuous)
    double spikeSize = 0;         ///< typical size of a spike (a single bad sample; 0.75–1.25 times this)
};

/// @brief The realistic transmitter of each channel (docs/plant.md gives the reason for each level).
const std::array<SensorSpec, kSensorChannelCount>& realisticSensors();

/// @brief Rates of the faults every transmitter has now and then, per channel and hour.
struct SensorFaultRates {
    double spikesPerHour = 0.5;   ///< single-sample outliers (EMI, a strand stuck on a window)
    double stuckPerHour = 0.05;   ///< the value freezes for 1–10 min (frozen transmitter, lost update)
    double dropoutsPerHour = 0.5; ///< no value for 2–30 s (network, historian compression gaps)
};

/// @brief One transmitter: lag, correlated noise, quantisation and the occasional spike, stuck
/// value or dropout (NaN). Stepped once per sample (1 s). Deterministic for the random stream.
class Sensor {
public:
    Sensor() = default;
    Sensor(const SensorSpec& spec, const SensorFaultRates& faults, bool ideal);
    /// @brief The reading at this sample of a true value @p truth; NaN during a dropout.
    /// @p extraLagS adds a first-order stage (a mechanism); @p extraNoiseSd adds noise correlated
    /// over @p extraNoiseCorrelationS (a mechanism). Both draw nothing when zero.
    double read(double truth, std::mt19937_64& rng, double extraLagS = 0, double extraNoiseSd = 0,
                double extraNoiseCorrelationS = 3);
    /// @brief The last reading that was not a dropout (what a DCS shows with bad quality).
    double lastGood() const { return m_lastGood; }
    /// @brief Counts of the faults started so far (for tests and the truth file).
    struct Counts {
        long spikes = 0, stuck = 0, dropouts = 0, samples = 0;
    };
    const Counts& counts() const { return m_counts; }

private:
    SensorSpec m_spec;
    SensorFaultRates m_faults;
    bool m_ideal = true;
    bool m_started = false;
    double m_lagState = 0;
    double m_extraLagState = 0;
    double m_noise = 0;
    double m_extraNoise = 0;
    int m_stuckLeft = 0;
    double m_stuckValue = 0;
    int m_dropoutLeft = 0;
    double m_lastGood = 0;
    Counts m_counts;
    std::normal_distribution<double> m_normal{0.0, 1.0};
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
};

/// @brief Every channel's transmitter of one line.
struct SensorBank {
    SensorBank() = default;
    SensorBank(const SensorFaultRates& faults, bool ideal);
    Sensor& operator[](SensorChannel c) { return sensors[static_cast<std::size_t>(c)]; }
    std::array<Sensor, kSensorChannelCount> sensors;
};

} // namespace drytwin::plant
