// What the line sees of its inputs when the sensors that measured them are among the causes
// (CONTRACT.md §4): the inlet moisture gauge's offset and fast scatter, and the hot-air
// thermocouple's lag, each undone from its onset on as the parameters say, before the tube gets
// the series. With all three at 0 the measured inputs go through unchanged.

#include "common/MovingAverage.h"
#include "common/Units.h"
#include "physics/simulator/LineSimulatorInternal.h"

#include <algorithm>
#include <cmath>

namespace drytwin::physics::simulator {

namespace {

/// Width of the smoothing under the hot-air sensor's inverse lag [s]: the derivative of a raw
/// thermocouple reading (0.3 K noise, 0.1 K steps) times a time constant of minutes would add
/// kelvins of noise; over 20 s it adds a few tenths, far below what a lag of 30 s or more hides
/// at a setpoint step. Fixed, so that the loss stays linear in tau_hot_sensor.
constexpr double kHotSensorSmoothingS = 20;

/// Zero-phase first-order filter (forward, then backward) of time constant @p tauS: the slow part
/// of a reading without the lag a causal filter would add to the line's input.
std::vector<double> zeroPhaseFilter(const std::vector<double>& t, const std::vector<double>& v, double tauS) {
    std::vector<double> out = v;
    for (std::size_t i = 1; i < out.size(); ++i) {
        const double a = std::exp(-(t[i] - t[i - 1]) / tauS);
        out[i] = a * out[i - 1] + (1 - a) * out[i];
    }
    for (std::size_t i = out.size() - 1; i-- > 0;) {
        const double a = std::exp(-(t[i + 1] - t[i]) / tauS);
        out[i] = a * out[i + 1] + (1 - a) * out[i];
    }
    return out;
}

/// Time constant of the zero-phase filter that separates the inlet gauge's fast scatter from
/// the moisture's own variation [s]: the gauge's scatter is correlated over a few seconds, the
/// inlet moisture changes over minutes (the conditioning cylinder's mixing).
constexpr double kInletScatterFilterS = 20;

} // namespace

/// The sensor causes (CONTRACT.md §4): the measured inputs corrected as the parameters say,
/// before the line sees them, from the onset on. Null when every one is 0 (the inputs as measured).
std::optional<LineInputs> correctedInputs(const LineInputs& in, const ParameterSet& p) {
    const double offsetPct = p[Param::X_in_offset];
    const double hotLagS = p[Param::tau_hot_sensor];
    const double scatterShare = p[Param::phi_X_in_scatter];
    if (offsetPct == 0 && hotLagS == 0 && scatterShare == 0) {
        return std::nullopt;
    }
    const double onset = in.timeS.front() + in.onsetS(p[Param::t_onset]);
    LineInputs out = in;
    if (scatterShare > 0) { // inlet_moisture_sensor_noise: remove that share of the fast variation
        // Throughout, not from the onset: the share is the gauge's normal scatter, fitted with h_HDT
        // and k_HDT before any cause (discovery's start, a reference's commissioning). Gated by a
        // later cause's onset, the first minutes of every batch lost it, and a 60 s meter lag from
        // 11 min predicted the held-out part worse than none (distributed plant, 0 of 6 named).
        const auto smooth = zeroPhaseFilter(in.timeS, in.xInDb, kInletScatterFilterS);
        for (std::size_t i = 0; i < out.size(); ++i) {
            out.xInDb[i] = in.xInDb[i] + scatterShare * (smooth[i] - in.xInDb[i]);
        }
    }
    if (offsetPct != 0) { // inlet_moisture_sensor_offset: the gauge reads true + offset
        for (std::size_t i = 0; i < out.size(); ++i) {
            if (in.timeS[i] >= onset) {
                const double wet = std::clamp(units::dryToWetPct(out.xInDb[i]) - offsetPct, 0.5, 90.0);
                out.xInDb[i] = units::wetPctToDry(wet);
            }
        }
    }
    if (hotLagS > 0 && in.size() > 2) { // hot_air_sensor_lag: true = measured + tau d(measured)/dt
        const auto smooth = centredMovingAverage(in.timeS, in.tHotK, kHotSensorSmoothingS);
        const std::size_t n = in.size();
        const double half = kHotSensorSmoothingS / 2;
        std::size_t a = 0, b = 0; // the samples within ±half of row i
        for (std::size_t i = 0; i < n; ++i) {
            while (in.timeS[a] < in.timeS[i] - half) {
                ++a;
            }
            b = std::max(b, i);
            while (b + 1 < n && in.timeS[b + 1] <= in.timeS[i] + half) {
                ++b;
            }
            if (in.timeS[i] < onset) {
                continue;
            }
            const double span = in.timeS[b] - in.timeS[a];
            const double slope = span > 0 ? (smooth[b] - smooth[a]) / span : 0.0;
            // A correction beyond ±60 K is a fit that left the physics; the bound keeps the tube's
            // rates finite while the optimiser finds its way back.
            out.tHotK[i] = in.tHotK[i] + std::clamp(hotLagS * slope, -60.0, 60.0);
        }
    }
    return out;
}

} // namespace drytwin::physics::simulator
