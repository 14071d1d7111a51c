#include "plant/PlantLine.h"

#include "plant/LineCore.h"

#include "common/Units.h"
#include "physics/SectionRates.h"
#include "properties/Properties.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace drytwin::plant {

using properties::Param;
using properties::ParameterSet;
namespace ph = physics;

namespace {

// The plant's own forms of the mechanisms (docs/mechanisms.md sets them beside the model's).
constexpr double kCriticalMoisture = 0.20; // X_cr of the falling-rate mechanism [kg/kg dry]
constexpr double kFoulingTimeS = 2400;     // deposits approach their asymptote with this time constant
constexpr double kNominalAirSpeed = 16.0;  // m/s, where the wall-loss NTU is given
constexpr double kAirHeatCapacity = 1010;  // J/(kg·K)
constexpr double kTubeAreaM2 = 0.283;      // 0.6 m tube diameter

/// Ornstein-Uhlenbeck noise with time constant tau [s] and stationary standard deviation sigma.
class OrnsteinUhlenbeck {
public:
    OrnsteinUhlenbeck(double tauS, double sigma)
        : m_a(std::exp(-1.0 / tauS)), m_s(sigma * std::sqrt(1 - m_a * m_a)) {}
    double next(std::mt19937_64& rng) {
        m_x = m_a * m_x + m_s * m_n(rng);
        return m_x;
    }

private:
    double m_a;
    double m_s;
    double m_x = 0;
    std::normal_distribution<double> m_n{0.0, 1.0};
};

/// Generic fixed-step RK4 over a small state vector.
template <int N, class F> void rk4(double* y, double t0, double duration, int steps, F&& f) {
    const double h = duration / steps;
    double k1[N], k2[N], k3[N], k4[N], tmp[N];
    for (int s = 0; s < steps; ++s) {
        const double t = t0 + s * h;
        f(t, y, k1);
        for (int i = 0; i < N; ++i) {
            tmp[i] = y[i] + 0.5 * h * k1[i];
        }
        f(t + 0.5 * h, tmp, k2);
        for (int i = 0; i < N; ++i) {
            tmp[i] = y[i] + 0.5 * h * k2[i];
        }
        f(t + 0.5 * h, tmp, k3);
        for (int i = 0; i < N; ++i) {
            tmp[i] = y[i] + h * k3[i];
        }
        f(t + h, tmp, k4);
        for (int i = 0; i < N; ++i) {
            y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        }
    }
}

struct ParcelOutcome {
    double xHdt = 0, tHdt = 0, xOut = 0, tOut = 0;
};

} // namespace

PlantDisturbances randomDisturbances(const PlantOptions& o, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> uniform(0, 1);
    const auto n = static_cast<std::size_t>(o.samples);
    PlantDisturbances d;
    auto& feed = d.feedKgPerS;
    auto& xIn = d.xInDb;
    auto& tIn = d.tInK;
    auto& tAmb = d.tAmbK;
    auto& rh = d.rhAmb;
    auto& air = d.airSpeedMPerS;
    feed.resize(n);
    xIn.resize(n);
    tIn.resize(n);
    tAmb.resize(n);
    rh.resize(n);
    air.resize(n);
    d.kDrift.assign(n, 1.0);
    const double ambBase = 10.0 + 25.0 * uniform(rng); // season and hall: 10–35 °C
    const double rhBase = 0.25 + 0.5 * uniform(rng);   // 25–75 %
    const double dayPhase = 2 * M_PI * uniform(rng);
    double feedLevel = 6000 + 400 * uniform(rng);
    OrnsteinUhlenbeck feedNoise(120, 25), xInWalk(900, 0.0045), tInNoise(600, 0.8), rhNoise(1200, 0.03),
        tAmbNoise(1800, 0.6), airNoise(60, 0.1), drift(2400, 0.05);
    const double xInPhase = 2 * M_PI * uniform(rng);
    const double xInBase = 0.22 + 0.015 * (uniform(rng) - 0.5);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k);
        if (uniform(rng) < 1.0 / 1200.0) { // a feed step about every 20 min
            feedLevel = std::clamp(feedLevel + 250 * (uniform(rng) < 0.5 ? -1 : 1) * (0.5 + uniform(rng)),
                                   5850.0, 6550.0);
        }
        feed[k] = units::kgPerHourToKgPerS(std::clamp(feedLevel + feedNoise.next(rng), 5800.0, 6600.0));
        const double xWb = std::clamp(
            xInBase + 0.008 * std::sin(2 * M_PI * t / 1800 + xInPhase) + xInWalk.next(rng), 0.20, 0.24);
        xIn[k] = xWb / (1 - xWb);
        tIn[k] = units::kKelvinOffset + 25 + tInNoise.next(rng);
        tAmb[k] =
            units::kKelvinOffset +
            std::clamp(ambBase + 3.0 * std::sin(2 * M_PI * t / 86400 * 4 + dayPhase) + tAmbNoise.next(rng),
                       10.0, 35.0);
        rh[k] = std::clamp(rhBase + 0.08 * std::sin(2 * M_PI * t / 7200 + dayPhase) + rhNoise.next(rng), 0.2,
                           0.8);
        air[k] = 16.0 + airNoise.next(rng);
        if (o.unmeasuredDrift) {
            d.kDrift[k] = 1.0 + drift.next(rng);
        }
    }
    return d;
}

namespace {
constexpr double kPiGain = 2.0;        // K per % wb
constexpr double kPiIntegralS = 30.0;  // s
constexpr double kPiFeedforward = 8.0; // K per % wb of inlet moisture
constexpr double kPiInletRefPct = 22.0;
constexpr double kPiBiasC = 170.0;
} // namespace

void PlantPiController::track(double setpointK, double xOutMeasuredPct, double xInPct, double targetPct) {
    const double e = xOutMeasuredPct - targetPct;
    const double ff = kPiFeedforward * (xInPct - kPiInletRefPct);
    m_integral = (setpointK - units::kKelvinOffset - kPiBiasC - ff) / kPiGain - e - e / kPiIntegralS;
}

double PlantPiController::next(double xOutMeasuredPct, double xInPct, double targetPct) {
    const double kc = kPiGain;
    const double ti = kPiIntegralS;
    const double e = xOutMeasuredPct - targetPct;
    m_integral += e / ti;
    const double ff = kPiFeedforward * (xInPct - kPiInletRefPct);
    double sp = units::kKelvinOffset + kPiBiasC + ff + kc * (e + m_integral);
    const double lo = units::kKelvinOffset + kLowC;
    const double hi = units::kKelvinOffset + kHighC;
    if (sp > hi || sp < lo) {
        m_integral -= e / ti;
        sp = std::clamp(sp, lo, hi);
    }
    return sp;
}

LineCore::LineCore(const PlantOptions& options, PlantDisturbances disturbances, PlantRandom& r)
    : o(options), dist(std::move(disturbances)), random(&r), n(dist.size()),
      realistic(options.realisticSensors()), sensors(options.sensorFaults, !realistic) {
    record.timeS.resize(n);
}

double LineCore::effectAt(Mechanism m, double t) const {
    const auto it = o.effects.find(m);
    if (it == o.effects.end()) {
        return 0.0;
    }
    const auto on = o.effectOnsetS.find(m);
    return on == o.effectOnsetS.end() || t >= on->second ? it->second : 0.0;
}

double LineCore::readCelsius(SensorChannel c, double trueK, double extraLagS) {
    return units::celsiusToKelvin(readSensor(c, units::kelvinToCelsius(trueK), extraLagS));
}

double LineCore::outletMeterLagged(double xOutPct, double t) {
    const double meterLag = effectAt(Mechanism::MoistureMeterLag, t);
    if (meterLag <= 0) {
        m_meterStage1 = m_meterStage2 = std::nan("");
        return xOutPct;
    }
    // Second order: a sample line and the sensor, each with half the time constant.
    const double a = 1 - std::exp(-2.0 / meterLag);
    if (std::isnan(m_meterStage1)) {
        m_meterStage1 = m_meterStage2 = xOutPct;
    }
    m_meterStage1 += (xOutPct - m_meterStage1) * a;
    m_meterStage2 += (m_meterStage1 - m_meterStage2) * a;
    return m_meterStage2;
}

double LineCore::outletMeterOffsetPct(double tOutK, double t) const {
    // The offset of a meter calibrated at 55 °C grows with the product's temperature.
    return effectAt(Mechanism::MoistureMeterOffset, t) *
           (1.0 + 0.1 * (units::kelvinToCelsius(tOutK) - 55.0) / 10.0);
}

double LineCore::inletSensorOffsetPct(double xInTruePct, double t) const {
    const double offset = effectAt(Mechanism::InletMoistureSensorOffset, t);
    // A gauge set up at 22 % wb: its slope error makes the offset grow with the moisture.
    return offset == 0 ? 0.0 : offset * (1.0 + 0.05 * (xInTruePct - 22.0));
}

double LineCore::onsetOf(Mechanism m) const {
    const auto on = o.effectOnsetS.find(m);
    return on == o.effectOnsetS.end() ? 0.0 : on->second;
}

Status LineCore::setEffect(Mechanism m, double strength, double onsetS) {
    const auto& mi = info(m);
    if (!std::isfinite(strength) || strength < 0 || strength > mi.maxStrength) {
        return Error{ErrorKind::BadInput, std::string(mi.name),
                     "strength must be within [0, " + std::to_string(mi.maxStrength) + "] " +
                         std::string(mi.unit)};
    }
    // Parcels already through the tube keep what they saw: an onset in the past would rewrite them.
    const double now = static_cast<double>(k);
    if (!std::isfinite(onsetS) || onsetS < now) {
        return Error{ErrorKind::BadInput, std::string(mi.name),
                     "the onset must not lie before the line's current time (" + std::to_string(k) + " s)"};
    }
    if (o.effects.count(m) && effectAt(m, now) > 0) {
        return Error{ErrorKind::BadInput, std::string(mi.name), "already acts on the line"};
    }
    o.effects[m] = strength;
    o.effectOnsetS[m] = onsetS;
    return Status{};
}

namespace {

/// The lumped line: each parcel integrated through the three sections (RK4) as the paper's
/// base equations describe them, with the plant's own forms of the mechanisms.
class LumpedLine final : public LineCore {
public:
    LumpedLine(const PlantOptions& options, PlantDisturbances disturbances, double initialSetpointK,
               PlantRandom& random);
    std::unique_ptr<LineCore> clone(PlantRandom& r) const override {
        auto copy = std::make_unique<LumpedLine>(*this);
        copy->rebind(r);
        return copy;
    }
    PlantSample measure() override;
    void apply(double setpointK) override;
    double hotAirK() const override { return tHot[std::min(k, n - 1)]; }

    ParameterSet p0;
    properties::ModelSwitches sw;
    double tauH = 0, tW = 0;
    bool measured = false;
    std::vector<double> tHot, tHotSp;
    std::vector<ParcelOutcome> parcel; // parcel entering the tube at sample j
    std::size_t nextParcel = 0;
    ParcelOutcome preStart;
    double sp = 0;

    double normal() { return (realistic ? 0.0 : o.noiseScale) * random->unitNormal(random->engine); }

    /// Belt transport time at time t: the model's plus the transport-delay error once it acts.
    double conveyorTime(double t) const {
        return p0[Param::tau_conv] + effectAt(Mechanism::TransportDelayError, t);
    }
    double onset(Mechanism m) const { return onsetOf(m); }

    // Parcel j enters the tube at sample j. The pre-start parcel stands for the steady
    // operation before the batch: it sees the first inputs throughout, as the model assumes.
    ParcelOutcome simulateParcel(std::size_t j, bool frozen) {
        const auto& feed = dist.feedKgPerS;
        const auto& xIn = dist.xInDb;
        const auto& tAmb = dist.tAmbK;
        const auto& rh = dist.rhAmb;
        const auto& air = dist.airSpeedMPerS;
        const double tEntry = static_cast<double>(j);
        const auto when = [&](double t) { return frozen ? 0.0 : t; };
        const auto hotAt = [&](double t) { return frozen ? sp : seriesAt(tHot, t); };
        const double wallLoss = effectAt(Mechanism::TubeWallHeatLoss, tEntry);
        const double gasCoupling = effectAt(Mechanism::GasPhaseCoupling, tEntry);
        const double fouling = effectAt(Mechanism::HeatTransferFouling, tEntry);
        const double fallingRate = effectAt(Mechanism::FallingRateDrying, tEntry);
        const double reabsorption = effectAt(Mechanism::AmbientReabsorption, tEntry);
        double y[4] = {xIn[j], dist.tInK[j], hotAt(tEntry), p0[Param::w]}; // X, T, gas T, gas humidity
        // Deposits grow towards an asymptotic loss of h; cleaning between batches resets them.
        const double foulingFactor =
            1.0 -
            fouling * (1.0 - std::exp(-(tEntry - onset(Mechanism::HeatTransferFouling)) / kFoulingTimeS));
        const double gasFlow = 0.8 * seriesAt(air, when(tEntry)) * kTubeAreaM2; // kg/s of hot air
        const double loadRatio = seriesAt(feed, when(tEntry)) / (1.0 + xIn[j]) / gasFlow;
        rk4<4>(y, 0.0, tauH, static_cast<int>(std::ceil(tauH / 0.25)),
               [&](double s, const double* v, double* d) {
                   const double t = when(tEntry + s);
                   const double tHotNow = hotAt(t);
                   ph::TubeEnvironment env;
                   // Gas around the parcel: the inlet air (less the wall loss) minus the cooling by
                   // the material so far, carried in v[2] relative to the inlet temperature.
                   // The wall takes heat along the tube: the gas approaches ambient exponentially
                   // with the distance travelled, faster at low air speed (less turbulent
                   // transport to the wall is outweighed by the longer contact per kg of air).
                   double tWallGas = tHotNow;
                   if (wallLoss > 0) {
                       const double ntu = wallLoss * (s / tauH) *
                                          std::pow(kNominalAirSpeed / std::max(4.0, seriesAt(air, t)), 0.8);
                       tWallGas = seriesAt(tAmb, t) + (tHotNow - seriesAt(tAmb, t)) * std::exp(-ntu);
                   }
                   env.tGasK = tWallGas + (v[2] - hotAt(tEntry));
                   if (o.hiddenAmplitudeK > 0) {
                       env.tGasK += o.hiddenAmplitudeK * std::sin(2 * M_PI * t / o.hiddenPeriodS);
                   }
                   env.wGas = v[3];
                   env.h = p0[Param::h_HDT] * foulingFactor;
                   env.k = p0[Param::k_HDT] * seriesAt(dist.kDrift, t);
                   if (fallingRate > 0) {
                       const double xe = properties::equilibriumMoisture(v[1], 1e-6, p0);
                       const double depth =
                           std::clamp((kCriticalMoisture - v[0]) / (kCriticalMoisture - xe), 0.0, 1.0);
                       env.dryingFactor = 1.0 - fallingRate * std::pow(depth, 0.7);
                   }
                   const auto r = ph::tubeRates(v[0], v[1], env, p0, sw);
                   d[0] = r.dXdt;
                   d[1] = r.dTdt;
                   // Co-current gas phase: energy and vapour balances per kg of air.
                   d[2] = -gasCoupling * loadRatio * r.heatIn / kAirHeatCapacity;
                   d[3] = gasCoupling * loadRatio * r.evaporation;
               });
        ParcelOutcome out;
        out.xHdt = y[0];
        out.tHdt = y[1];
        const double tConvIn = tEntry + tauH;
        const double tauC = conveyorTime(tConvIn);
        double c[2] = {y[0], y[1]};
        rk4<2>(c, 0.0, tauC, static_cast<int>(std::ceil(tauC / 2.0)),
               [&](double s, const double* v, double* d) {
                   const double t = when(tConvIn + s);
                   // Humid air loads the surface faster than linearly in RH, and a drier leaf
                   // takes up more.
                   const double rhNow = seriesAt(rh, t);
                   const double uptake = reabsorption * 1e-4 * rhNow * std::exp(3.0 * (rhNow - 0.5)) *
                                         std::max(0.0, 1.0 - v[0] / 0.35);
                   ph::AmbientEnvironment env{seriesAt(tAmb, t), rhNow, uptake};
                   const auto r = ph::conveyorRates(v[0], v[1], env, p0, sw);
                   d[0] = r.dXdt;
                   d[1] = r.dTdt;
               });
        const ph::MixState mix = ph::winnowerInletMix(c[0], c[1], y[0], y[1], p0, sw);
        const double tWinIn = tConvIn + tauC;
        double w[2] = {mix.xDb, mix.tK};
        rk4<2>(w, 0.0, tW, static_cast<int>(std::ceil(tW / 0.25)), [&](double s, const double* v, double* d) {
            const double t = when(tWinIn + s);
            ph::AmbientEnvironment env{seriesAt(tAmb, t), seriesAt(rh, t), 0.0};
            const auto r = ph::winnowerRates(v[0], v[1], s, mix.xDb, mix.tK, env, p0, sw);
            d[0] = r.dXdt;
            d[1] = r.dTdt;
        });
        out.xOut = w[0];
        out.tOut = w[1];
        return out;
    }

    // What leaves a section at time t: the parcel that entered at t − delay, interpolated
    // between neighbouring parcels (the instrument sees a blend of adjacent material).
    ParcelOutcome outcomeAt(double t, double delay) const {
        const double e = t - delay;
        const auto parcelAt = [&](double j) {
            return j < 0 ? preStart : parcel[static_cast<std::size_t>(j)];
        };
        const double j0 = std::floor(e);
        const double w = e - j0;
        const ParcelOutcome a = parcelAt(j0);
        if (w < 1e-12) {
            return a;
        }
        const ParcelOutcome b = parcelAt(j0 + 1);
        ParcelOutcome m;
        m.xHdt = (1 - w) * a.xHdt + w * b.xHdt;
        m.tHdt = (1 - w) * a.tHdt + w * b.tHdt;
        m.xOut = (1 - w) * a.xOut + w * b.xOut;
        m.tOut = (1 - w) * a.tOut + w * b.tOut;
        return m;
    }
};

LumpedLine::LumpedLine(const PlantOptions& options, PlantDisturbances disturbances, double initialSetpointK,
                       PlantRandom& random)
    : LineCore(options, std::move(disturbances), random) {
    p0 = options.truth;
    tauH = p0[Param::tau_HDT];
    tW = p0[Param::t_W];
    tHot.assign(n, 0.0);
    tHotSp.assign(n, 0.0);
    parcel.resize(n);
    sp = initialSetpointK;
    if (options.sensors == SensorMode::Ideal) {
        o.noiseScale = 0;
    }
}

} // namespace

PlantSample LumpedLine::measure() {
    auto& im = *this;
    const std::size_t k = im.k;
    const double t = static_cast<double>(k);
    im.record.timeS[k] = t;
    // Actuator: T_hot follows the setpoint with the plant's lag.
    if (k == 0) {
        im.tHot[k] = im.sp;
        im.preStart = im.simulateParcel(0, true);
    } else {
        const double a = std::exp(-1.0 / im.p0[Param::tau_act]);
        im.tHot[k] = a * im.tHot[k - 1] + (1 - a) * im.tHotSp[k - 1];
    }
    // Every parcel whose tube passage is over by now can be finished: later sections
    // need only ambient conditions, which do not depend on the controller.
    while (im.nextParcel < im.n && static_cast<double>(im.nextParcel) + im.tauH <= t + 1e-9) {
        im.parcel[im.nextParcel] = im.simulateParcel(im.nextParcel, false);
        ++im.nextParcel;
    }
    const ParcelOutcome hdt = im.outcomeAt(t, im.tauH);
    const double tauTotal = im.tauH + im.conveyorTime(t) + im.tW;
    ParcelOutcome out = im.outcomeAt(t, tauTotal);
    const double delayError = im.effectAt(Mechanism::TransportDelayError, t);
    if (delayError != 0) {
        // A belt whose transport time is off also spreads the material: the outlet sees
        // a moving average over a window that widens with the error (axial dispersion).
        const double halfWidth = 2.0 + 0.15 * std::abs(delayError);
        const int points = 9;
        ParcelOutcome sum;
        for (int i = 0; i < points; ++i) {
            const double shift = halfWidth * (2.0 * i / (points - 1) - 1.0);
            const ParcelOutcome o2 = im.outcomeAt(std::max(0.0, t + shift), tauTotal);
            sum.xOut += o2.xOut / points;
            sum.tOut += o2.tOut / points;
        }
        out.xOut = sum.xOut;
        out.tOut = sum.tOut;
    }
    PlantSample s;
    s.xOutTruePct = 100 * out.xOut / (1 + out.xOut);
    s.tOutTrueK = out.tOut;
    s.xInTruePct = 100 * im.dist.xInDb[k] / (1 + im.dist.xInDb[k]);
    // Instruments.
    double xOutMeasPct = outletMeterLagged(s.xOutTruePct, t);
    xOutMeasPct += outletMeterOffsetPct(out.tOut, t) + 0.02 * im.normal();
    s.xOutPct = xOutMeasPct;
    s.tOutK = out.tOut + 0.03 * im.normal();
    s.xHdtPct = 100 * hdt.xHdt / (1 + hdt.xHdt) + 0.03 * im.normal();
    s.tHdtK = hdt.tHdt + 0.05 * im.normal();
    s.xInForControlPct = s.xInTruePct;
    if (im.realistic) {
        // The built-in noise above was zero; the transmitters read the true values instead.
        s.xOutPct = readSensor(SensorChannel::OutletMoisture, s.xOutPct);
        s.tOutK = readCelsius(SensorChannel::OutletTemperature, s.tOutK);
        s.xHdtPct = readSensor(SensorChannel::TubeMoisture, s.xHdtPct);
        s.tHdtK = readCelsius(SensorChannel::TubeTemperature, s.tHdtK);
    }
    im.record.xHdtDb.push_back(units::wetPctToDry(s.xHdtPct));
    im.record.tHdtK.push_back(s.tHdtK);
    im.record.xOutDb.push_back(units::wetPctToDry(s.xOutPct));
    im.record.tOutK.push_back(s.tOutK);
    im.record.xOutTrueDb.push_back(units::wetPctToDry(s.xOutTruePct));
    im.record.tOutTrueK.push_back(s.tOutTrueK);
    if (std::isnan(s.xOutPct)) {
        s.xOutValid = false;
        s.xOutPct = sensors[SensorChannel::OutletMoisture].lastGood();
    }
    im.measured = true;
    return s;
}

void LumpedLine::apply(double setpointK) {
    auto& im = *this;
    if (!im.measured) {
        measure(); // a sample is always measured before it is left
    }
    const std::size_t k = im.k;
    const auto normal = [&] { return im.normal(); };
    im.sp = setpointK;
    im.tHotSp[k] = setpointK;
    // Measured inputs carry their own small noise.
    auto& pb = im.record;
    const auto& d = im.dist;
    pb.tHotSpK.push_back(setpointK);
    const double t = static_cast<double>(k);
    const double xInTruePct = units::dryToWetPct(d.xInDb[k]);
    const double hotAirLag = effectAt(Mechanism::HotAirSensorLag, t);
    const double inletOffsetPct = inletSensorOffsetPct(xInTruePct, t);
    const double inletNoisePct = effectAt(Mechanism::InletMoistureSensorNoise, t);
    if (im.realistic) {
        pb.tHotK.push_back(readCelsius(SensorChannel::HotAir, im.tHot[k], hotAirLag));
        pb.airSpeedMPerS.push_back(readSensor(SensorChannel::AirSpeed, d.airSpeedMPerS[k]));
        pb.feedKgPerS.push_back(units::kgPerHourToKgPerS(
            readSensor(SensorChannel::Feed, units::kgPerSToKgPerHour(d.feedKgPerS[k]))));
        pb.xInDb.push_back(units::wetPctToDry(
            readSensor(SensorChannel::InletMoisture, xInTruePct + inletOffsetPct, 0, inletNoisePct)));
        pb.tInK.push_back(readCelsius(SensorChannel::InletTemperature, d.tInK[k]));
        pb.tAmbK.push_back(readCelsius(SensorChannel::AmbientTemperature, d.tAmbK[k]));
        pb.rhAmb.push_back(readSensor(SensorChannel::AmbientHumidity, units::fractionToPercent(d.rhAmb[k])) /
                           100.0);
        im.measured = false;
        ++im.k;
        return;
    }
    // The sensor mechanisms through the line's ideal transmitters (their lag and scatter alone);
    // untouched while no mechanism acts, so that the lumped plant's files stay as they were.
    const double tHotReading =
        hotAirLag > 0 ? readCelsius(SensorChannel::HotAir, im.tHot[k], hotAirLag) : im.tHot[k];
    pb.tHotK.push_back(tHotReading + 0.1 * normal());
    pb.airSpeedMPerS.push_back(d.airSpeedMPerS[k] + 0.02 * normal());
    pb.feedKgPerS.push_back(d.feedKgPerS[k] + units::kgPerHourToKgPerS(5.0) * normal());
    double xInWb = d.xInDb[k] / (1 + d.xInDb[k]) + 0.0001 * normal();
    if (inletOffsetPct != 0 || inletNoisePct > 0) {
        const double reading =
            readSensor(SensorChannel::InletMoisture, xInTruePct + inletOffsetPct, 0, inletNoisePct);
        xInWb += (reading - xInTruePct) / 100.0;
    }
    pb.xInDb.push_back(xInWb / (1 - xInWb));
    pb.tInK.push_back(d.tInK[k] + 0.1 * normal());
    pb.tAmbK.push_back(d.tAmbK[k] + 0.1 * normal());
    pb.rhAmb.push_back(std::clamp(d.rhAmb[k] + 0.005 * normal(), 0.0, 1.0));
    im.measured = false;
    ++im.k;
}

std::unique_ptr<LineCore> makeLumpedLine(const PlantOptions& options, PlantDisturbances disturbances,
                                         double initialSetpointK, PlantRandom& random) {
    return std::make_unique<LumpedLine>(options, std::move(disturbances), initialSetpointK, random);
}

PlantLine::PlantLine(const PlantOptions& options, PlantDisturbances disturbances, double initialSetpointK,
                     PlantRandom& random)
    : m_core(options.plant == PlantKind::Distributed
                 ? makeDistributedLine(options, std::move(disturbances), initialSetpointK, random)
                 : makeLumpedLine(options, std::move(disturbances), initialSetpointK, random)) {}

PlantLine::PlantLine(std::unique_ptr<LineCore> core) : m_core(std::move(core)) {}
PlantLine::~PlantLine() = default;
PlantLine::PlantLine(PlantLine&&) noexcept = default;

PlantLine PlantLine::clone(PlantRandom& random) const {
    return PlantLine(m_core->clone(random));
}
Status PlantLine::setEffect(Mechanism m, double strength, double onsetS) {
    return m_core->setEffect(m, strength, onsetS);
}
double PlantLine::effectAt(Mechanism m, double timeS) const {
    return m_core->effectAt(m, timeS);
}
PlantSample PlantLine::measure() {
    return m_core->measure();
}
void PlantLine::apply(double setpointK) {
    m_core->apply(setpointK);
}
std::size_t PlantLine::sample() const {
    return m_core->sample();
}
std::size_t PlantLine::size() const {
    return m_core->size();
}
double PlantLine::hotAirK() const {
    return m_core->hotAirK();
}
const PlantBatch& PlantLine::record() const {
    return m_core->record;
}
const SensorBank& PlantLine::sensors() const {
    return m_core->sensors;
}
std::optional<LineBalance> PlantLine::balance() const {
    return m_core->balance();
}
double SectionBalance::energyImbalance() const {
    return (energyInJ + energyFromAirJ - energyOutJ - energyStockChangeJ) /
           (energyInJ + std::abs(energyFromAirJ));
}
PlantBatch& PlantLine::record() {
    return m_core->record;
}

} // namespace drytwin::plant
