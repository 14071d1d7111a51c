#include "plant/Sensors.h"

#include <cmath>

namespace drytwin::plant {

const std::array<SensorSpec, kSensorChannelCount>& realisticSensors() {
    // Levels and reasons: docs/plant.md, "Sensors". Order as SensorChannel.
    static const std::array<SensorSpec, kSensorChannelCount> specs{{
        {"T_hot_C", 0.3, 0, 0, 4.0, 0.1, 8.0},
        {"air_speed_m_s", 0.08, 2, 0, 2.0, 0.01, 1.5},
        {"feed_kg_h", 0, 5, 0.005, 2.0, 1.0, 600.0},
        {"X_in_pct", 0.15, 2, 0, 0.0, 0.01, 3.0},
        {"T_in_C", 0.3, 0, 0, 5.0, 0.1, 8.0},
        {"T_amb_C", 0.2, 0, 0, 20.0, 0.1, 5.0},
        {"RH_amb_pct", 1.5, 30, 0, 15.0, 0.1, 20.0},
        {"X_hdt_pct", 0.08, 2, 0, 0.0, 0.01, 2.0},
        {"T_hdt_C", 0.5, 0, 0, 3.0, 0.1, 8.0},
        {"X_out_pct", 0.05, 2, 0, 0.0, 0.01, 1.5},
        {"T_out_C", 0.3, 0, 0, 5.0, 0.1, 8.0},
    }};
    return specs;
}

Sensor::Sensor(const SensorSpec& spec, const SensorFaultRates& faults, bool ideal)
    : m_spec(spec), m_faults(faults), m_ideal(ideal) {}

namespace {
/// One step of an AR(1) noise with stationary standard deviation @p sd and time constant @p tauS.
double arStep(double state, double sd, double tauS, double unitNormal) {
    if (tauS <= 0) {
        return sd * unitNormal;
    }
    const double a = std::exp(-1.0 / tauS);
    return a * state + sd * std::sqrt(1 - a * a) * unitNormal;
}
/// First-order lag over one second, exact for a value held over the step.
double lagStep(double state, double input, double tauS) {
    return tauS <= 0 ? input : input + (state - input) * std::exp(-1.0 / tauS);
}
} // namespace

double Sensor::read(double truth, std::mt19937_64& rng, double extraLagS, double extraNoiseSd,
                    double extraNoiseCorrelationS) {
    ++m_counts.samples;
    if (!m_started) {
        // A transmitter that has been on for a while: its lags sit at the first value.
        m_lagState = m_extraLagState = m_lastGood = truth;
        m_started = true;
    }
    double v = truth;
    // Mechanisms first: they are part of what the plant does, whatever the instruments.
    if (extraLagS > 0) {
        m_extraLagState = lagStep(m_extraLagState, v, extraLagS);
        v = m_extraLagState;
    } else {
        m_extraLagState = v;
    }
    if (extraNoiseSd > 0) {
        m_extraNoise = arStep(m_extraNoise, extraNoiseSd, extraNoiseCorrelationS, m_normal(rng));
        v += m_extraNoise;
    }
    if (m_ideal) {
        m_lastGood = v;
        return v;
    }
    m_lagState = lagStep(m_lagState, v, m_spec.lagS);
    v = m_lagState;
    if (m_spec.noiseSd > 0) {
        m_noise = arStep(m_noise, m_spec.noiseSd, m_spec.noiseCorrelationS, m_normal(rng));
        v += m_noise;
    }
    if (m_spec.relativeNoise > 0) {
        v += m_spec.relativeNoise * std::abs(truth) * m_normal(rng);
    }
    // Faults: each starts as a Poisson event; their lengths are drawn when they start.
    const double spikeDraw = m_uniform(rng);
    const double stuckDraw = m_uniform(rng);
    const double dropoutDraw = m_uniform(rng);
    if (m_stuckLeft == 0 && stuckDraw < m_faults.stuckPerHour / 3600.0) {
        m_stuckLeft = 60 + static_cast<int>(540 * m_uniform(rng));
        m_stuckValue = m_lastGood;
        ++m_counts.stuck;
    }
    if (m_stuckLeft > 0) {
        --m_stuckLeft;
        v = m_stuckValue;
    } else if (spikeDraw < m_faults.spikesPerHour / 3600.0) {
        const double sign = m_uniform(rng) < 0.5 ? -1.0 : 1.0;
        v += sign * m_spec.spikeSize * (0.75 + 0.5 * m_uniform(rng));
        ++m_counts.spikes;
    }
    if (m_spec.quantum > 0) {
        v = m_spec.quantum * std::round(v / m_spec.quantum);
    }
    if (m_dropoutLeft == 0 && dropoutDraw < m_faults.dropoutsPerHour / 3600.0) {
        m_dropoutLeft = 2 + static_cast<int>(29 * m_uniform(rng));
        ++m_counts.dropouts;
    }
    if (m_dropoutLeft > 0) {
        --m_dropoutLeft;
        return std::nan("");
    }
    m_lastGood = v;
    return v;
}

SensorBank::SensorBank(const SensorFaultRates& faults, bool ideal) {
    const auto& specs = realisticSensors();
    for (std::size_t c = 0; c < sensors.size(); ++c) {
        sensors[c] = Sensor(specs[c], faults, ideal);
    }
}

} // namespace drytwin::plant
