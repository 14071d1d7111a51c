#pragma once

#include "plant/PlantLine.h"

#include <limits>
#include <memory>
#include <vector>

namespace drytwin::plant {

/// @brief Linear interpolation in a series sampled every second, held at its ends.
inline double seriesAt(const std::vector<double>& v, double t) {
    if (t <= 0) {
        return v.front();
    }
    const double last = static_cast<double>(v.size() - 1);
    if (t >= last) {
        return v.back();
    }
    const auto i = static_cast<std::size_t>(t);
    const double w = t - static_cast<double>(i);
    return v[i] + w * (v[i + 1] - v[i]);
}

/// @brief What the lumped and the distributed line share behind PlantLine: the options, the
/// disturbances, the mechanisms' schedule, the record, the sample counter. Internal to plant/.
class LineCore {
public:
    LineCore(const PlantOptions& options, PlantDisturbances disturbances, PlantRandom& random);
    virtual ~LineCore() = default;
    LineCore(const LineCore&) = default;
    LineCore& operator=(const LineCore&) = delete;

    /// @brief A full copy drawing its noise from @p random.
    virtual std::unique_ptr<LineCore> clone(PlantRandom& random) const = 0;
    virtual PlantSample measure() = 0;
    virtual void apply(double setpointK) = 0;
    /// @brief True hot-air temperature at the current sample [K].
    virtual double hotAirK() const = 0;
    virtual std::optional<LineBalance> balance() const { return std::nullopt; }

    std::size_t sample() const { return k; }
    std::size_t size() const { return n; }
    /// @brief Strength of a mechanism at time @p t (0 before its onset).
    double effectAt(Mechanism m, double t) const;
    /// @brief The onset of a mechanism [s] (0 when it acts from the start).
    double onsetOf(Mechanism m) const;
    Status setEffect(Mechanism m, double strength, double onsetS);
    void rebind(PlantRandom& r) { random = &r; }
    /// @brief A true value in its file unit read through the channel's transmitter (with the
    /// mechanisms' extra lag and noise); NaN during a dropout.
    double readSensor(SensorChannel c, double truth, double extraLagS = 0, double extraNoiseSd = 0) {
        return sensors[c].read(truth, random->engine, extraLagS, extraNoiseSd);
    }
    /// @brief A true temperature [K] read by a transmitter that works in °C; NaN during a dropout.
    double readCelsius(SensorChannel c, double trueK, double extraLagS = 0);
    /// @brief The outlet moisture meter's reading of @p xOutPct [% wb] through moisture_meter_lag
    /// (two first-order stages of half its time constant each; the meter's, so shared by both lines).
    double outletMeterLagged(double xOutPct, double t);
    /// @brief moisture_meter_offset at a product temperature [% wb]: it grows 10 % per 10 K above 55 °C.
    double outletMeterOffsetPct(double tOutK, double t) const;
    /// @brief The inlet gauge's offset at a true inlet moisture (inlet_moisture_sensor_offset) [% wb].
    double inletSensorOffsetPct(double xInTruePct, double t) const;

    PlantOptions o;
    PlantDisturbances dist;
    PlantRandom* random = nullptr;
    std::size_t n = 0;
    std::size_t k = 0;
    PlantBatch record;
    bool realistic = false; ///< every column through its transmitter
    /// The transmitters: realistic ones, or ideal ones that carry only the sensor mechanisms.
    SensorBank sensors;

private:
    double m_meterStage1 = std::numeric_limits<double>::quiet_NaN(); ///< moisture_meter_lag's stages
    double m_meterStage2 = std::numeric_limits<double>::quiet_NaN();
};

/// @brief The lumped line (PlantKind::Lumped).
std::unique_ptr<LineCore> makeLumpedLine(const PlantOptions& options, PlantDisturbances disturbances,
                                         double initialSetpointK, PlantRandom& random);
/// @brief The distributed line (PlantKind::Distributed).
std::unique_ptr<LineCore> makeDistributedLine(const PlantOptions& options, PlantDisturbances disturbances,
                                              double initialSetpointK, PlantRandom& random);

} // namespace drytwin::plant
