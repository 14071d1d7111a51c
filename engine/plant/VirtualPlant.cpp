#include "plant/VirtualPlant.h"

#include "common/Units.h"
#include "physics/SectionRates.h"
#include "properties/Properties.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

namespace drytwin::plant {

using properties::Param;
using properties::ParameterSet;
namespace ph = physics;

namespace {

constexpr double kKelvin = units::kKelvinOffset;
// The plant's own forms of the mechanisms (docs/mechanisms.md sets them beside the model's).
constexpr double kCriticalMoisture = 0.20; // X_cr of the falling-rate mechanism [kg/kg dry]
constexpr double kFoulingTimeS = 2400;     // deposits approach their asymptote with this time constant
constexpr double kNominalAirSpeed = 16.0;  // m/s, where the wall-loss NTU is given
constexpr double kAirHeatCapacity = 1010;  // J/(kg·K)
constexpr double kTubeAreaM2 = 0.283;      // 0.6 m tube diameter

double effect(const PlantOptions& o, Mechanism m) {
    const auto it = o.effects.find(m);
    return it == o.effects.end() ? 0.0 : it->second;
}

/// Ornstein-Uhlenbeck noise with time constant tau [s] and stationary standard deviation sigma.
class OrnsteinUhlenbeck {
public:
    OrnsteinUhlenbeck(double tauS, double sigma)
        : m_a(std::exp(-1.0 / tauS)), m_s(sigma * std::sqrt(1 - m_a * m_a)) {}
    double next(std::mt19937_64& rng) {
        m_x = m_a * m_x + m_s * m_n(rng);
        return m_x;
    }
    void set(double x) { m_x = x; }

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

/// Sample-and-hold-free linear interpolation in a uniformly sampled series (1 s), held at the ends.
double at(const std::vector<double>& v, double t) {
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

struct ParcelOutcome {
    double xHdt = 0, tHdt = 0, xOut = 0, tOut = 0;
};

} // namespace

ParameterSet PlantOptions::defaultTruth() {
    ParameterSet p;
    p[Param::h_HDT] = 72.0;
    p[Param::k_HDT] = 0.0236;
    return p;
}

PlantOptions PlantOptions::demo(unsigned seed) {
    PlantOptions o;
    o.seed = seed;
    o.effects[Mechanism::HeatTransferFouling] = 0.1;
    o.effects[Mechanism::GasPhaseCoupling] = 0.1;
    o.effects[Mechanism::TubeWallHeatLoss] = 0.03; // NTU: about 1.5 % of the excess lost on average
    o.effects[Mechanism::MoistureMeterLag] = 20;
    o.unmeasuredDrift = true;
    return o;
}

Status PlantOptions::validate() const {
    if (batches < 1 || batches > 1000) {
        return Error{ErrorKind::Usage, "batches", "must lie in [1, 1000]"};
    }
    if (samples < 200 || samples > 1000000) {
        return Error{ErrorKind::Usage, "samples", "must lie in [200, 1000000]"};
    }
    for (const auto& [m, s] : effects) {
        if (!(s >= 0 && s <= info(m).maxStrength)) {
            return Error{ErrorKind::Usage, std::string(info(m).name),
                         "strength must lie in [0, " + std::to_string(info(m).maxStrength) + "] " +
                             std::string(info(m).unit)};
        }
    }
    if (auto st = truth.validate(); !st) {
        return st;
    }
    const double tauH = truth[Param::tau_HDT];
    if (std::abs(tauH - std::round(tauH)) > 1e-9) {
        return Error{ErrorKind::Usage, "tau_HDT", "the plant needs a whole number of seconds"};
    }
    if (!(hiddenPeriodS >= 10 && hiddenPeriodS <= 1e5) ||
        !(hiddenAmplitudeK >= 0 && hiddenAmplitudeK <= 30)) {
        return Error{ErrorKind::Usage, "hidden periodic disturbance",
                     "period must lie in [10, 1e5] s and amplitude in [0, 30] K"};
    }
    if (!(noiseScale >= 0 && noiseScale <= 10)) {
        return Error{ErrorKind::Usage, "noiseScale", "must lie in [0, 10]"};
    }
    if (!(targetXOutPct > 5 && targetXOutPct < 30)) {
        return Error{ErrorKind::Usage, "targetXOutPct", "must lie in (5, 30) % wb"};
    }
    return {};
}

Expected<PlantResult> runPlant(const PlantOptions& o, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto st = o.validate(); !st) {
        return st.error();
    }
    PlantResult result;
    result.truth = o.truth;
    result.effects = o.effects;
    const ParameterSet& p0 = o.truth;
    const properties::ModelSwitches sw;
    std::mt19937_64 rng(o.seed);
    std::normal_distribution<double> unitNormal(0, 1);
    const auto normal = [&](std::mt19937_64& g) { return o.noiseScale * unitNormal(g); };
    std::uniform_real_distribution<double> uniform(0, 1);

    const double wallLoss = effect(o, Mechanism::TubeWallHeatLoss);
    const double gasCoupling = effect(o, Mechanism::GasPhaseCoupling);
    const double fouling = effect(o, Mechanism::HeatTransferFouling);
    const double meterLag = effect(o, Mechanism::MoistureMeterLag);
    const double meterOffset = effect(o, Mechanism::MoistureMeterOffset);
    const double delayError = effect(o, Mechanism::TransportDelayError);
    const double fallingRate = effect(o, Mechanism::FallingRateDrying);
    const double reabsorption = effect(o, Mechanism::AmbientReabsorption);

    const double tauH = p0[Param::tau_HDT];
    const double tauC = p0[Param::tau_conv] + delayError;
    const double tW = p0[Param::t_W];
    const double tauTotal = tauH + tauC + tW;
    const auto n = static_cast<std::size_t>(o.samples);

    for (int b = 0; b < o.batches; ++b) {
        if (reportProgress(progress, "generate", static_cast<double>(b) / o.batches,
                           "batch " + std::to_string(b + 1) + "/" + std::to_string(o.batches))) {
            return cancelledError("generate");
        }
        PlantBatch pb;
        char id[16];
        std::snprintf(id, sizeof id, "B%02d", b + 1);
        pb.id = id;
        // --- Disturbances (true values), generated ahead: they do not depend on the controller.
        std::vector<double> feed(n), xIn(n), tIn(n), tAmb(n), rh(n), air(n), kDrift(n, 1.0);
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
            tIn[k] = kKelvin + 25 + tInNoise.next(rng);
            tAmb[k] = kKelvin + std::clamp(ambBase + 3.0 * std::sin(2 * M_PI * t / 86400 * 4 + dayPhase) +
                                               tAmbNoise.next(rng),
                                           10.0, 35.0);
            rh[k] = std::clamp(rhBase + 0.08 * std::sin(2 * M_PI * t / 7200 + dayPhase) + rhNoise.next(rng),
                               0.2, 0.8);
            air[k] = 16.0 + airNoise.next(rng);
            if (o.unmeasuredDrift) {
                kDrift[k] = 1.0 + drift.next(rng);
            }
        }
        // --- Closed loop, sample by sample.
        std::vector<double> tHot(n), tHotSp(n);
        std::vector<ParcelOutcome> parcel(n); // parcel entering the tube at sample j
        std::size_t nextParcel = 0;
        double sp = kKelvin + 170 + 10 * (uniform(rng) - 0.5);
        double integral = 0;
        double meterState = std::nan("");
        double meterState2 = std::nan("");
        // PI tuned by SIMC for ≈ 80 s dead time and a 20 s actuator lag (gain ≈ −0.06 %/K),
        // with the inlet-moisture feedforward tobacco dryers commonly have.
        const double kc = 2.0;  // K per % wb
        const double ti = 30.0; // s
        const double kff = 8.0; // K per % wb of inlet moisture
        const double xInRefPct = 22.0;
        pb.timeS.resize(n);

        // Parcel j enters the tube at sample j. The pre-start parcel stands for the steady
        // operation before the batch: it sees the first inputs throughout, as the model assumes.
        ParcelOutcome preStart;
        auto simulateParcel = [&](std::size_t j, bool frozen) {
            const double tEntry = static_cast<double>(j);
            const auto when = [&](double t) { return frozen ? 0.0 : t; };
            const auto hotAt = [&](double t) { return frozen ? sp : at(tHot, t); };
            double y[4] = {xIn[j], tIn[j], hotAt(tEntry), p0[Param::w]}; // X, T, gas T, gas humidity
            // Deposits grow towards an asymptotic loss of h; cleaning between batches resets them.
            const double foulingFactor = 1.0 - fouling * (1.0 - std::exp(-tEntry / kFoulingTimeS));
            const double gasFlow = 0.8 * at(air, when(tEntry)) * kTubeAreaM2; // kg/s of hot air
            const double loadRatio = at(feed, when(tEntry)) / (1.0 + xIn[j]) / gasFlow;
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
                                              std::pow(kNominalAirSpeed / std::max(4.0, at(air, t)), 0.8);
                           tWallGas = at(tAmb, t) + (tHotNow - at(tAmb, t)) * std::exp(-ntu);
                       }
                       env.tGasK = tWallGas + (v[2] - hotAt(tEntry));
                       if (o.hiddenAmplitudeK > 0) {
                           env.tGasK += o.hiddenAmplitudeK * std::sin(2 * M_PI * t / o.hiddenPeriodS);
                       }
                       env.wGas = v[3];
                       env.h = p0[Param::h_HDT] * foulingFactor;
                       env.k = p0[Param::k_HDT] * at(kDrift, t);
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
            double c[2] = {y[0], y[1]};
            rk4<2>(c, 0.0, tauC, static_cast<int>(std::ceil(tauC / 2.0)),
                   [&](double s, const double* v, double* d) {
                       const double t = when(tConvIn + s);
                       // Humid air loads the surface faster than linearly in RH, and a drier leaf
                       // takes up more.
                       const double rhNow = at(rh, t);
                       const double uptake = reabsorption * 1e-4 * rhNow * std::exp(3.0 * (rhNow - 0.5)) *
                                             std::max(0.0, 1.0 - v[0] / 0.35);
                       ph::AmbientEnvironment env{at(tAmb, t), rhNow, uptake};
                       const auto r = ph::conveyorRates(v[0], v[1], env, p0, sw);
                       d[0] = r.dXdt;
                       d[1] = r.dTdt;
                   });
            const ph::MixState mix = ph::winnowerInletMix(c[0], c[1], y[0], y[1], p0, sw);
            const double tWinIn = tConvIn + tauC;
            double w[2] = {mix.xDb, mix.tK};
            rk4<2>(w, 0.0, tW, static_cast<int>(std::ceil(tW / 0.25)),
                   [&](double s, const double* v, double* d) {
                       const double t = when(tWinIn + s);
                       ph::AmbientEnvironment env{at(tAmb, t), at(rh, t), 0.0};
                       const auto r = ph::winnowerRates(v[0], v[1], s, mix.xDb, mix.tK, env, p0, sw);
                       d[0] = r.dXdt;
                       d[1] = r.dTdt;
                   });
            out.xOut = w[0];
            out.tOut = w[1];
            return out;
        };
        // What leaves a section at time t: the parcel that entered at t − delay, interpolated
        // between neighbouring parcels (the instrument sees a blend of adjacent material).
        auto outcomeAt = [&](double t, double delay) {
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
        };

        for (std::size_t k = 0; k < n; ++k) {
            const double t = static_cast<double>(k);
            pb.timeS[k] = t;
            // Actuator: T_hot follows the setpoint with the plant's lag.
            if (k == 0) {
                tHot[k] = sp;
                preStart = simulateParcel(0, true);
            } else {
                const double a = std::exp(-1.0 / p0[Param::tau_act]);
                tHot[k] = a * tHot[k - 1] + (1 - a) * tHotSp[k - 1];
            }
            // Every parcel whose tube passage is over by now can be finished: later sections
            // need only ambient conditions, which do not depend on the controller.
            while (nextParcel < n && static_cast<double>(nextParcel) + tauH <= t + 1e-9) {
                parcel[nextParcel] = simulateParcel(nextParcel, false);
                ++nextParcel;
            }
            const ParcelOutcome hdt = outcomeAt(t, tauH);
            ParcelOutcome out = outcomeAt(t, tauTotal);
            if (delayError != 0) {
                // A belt whose transport time is off also spreads the material: the outlet sees
                // a moving average over a window that widens with the error (axial dispersion).
                const double halfWidth = 2.0 + 0.15 * std::abs(delayError);
                const int points = 9;
                ParcelOutcome sum;
                for (int i = 0; i < points; ++i) {
                    const double shift = halfWidth * (2.0 * i / (points - 1) - 1.0);
                    const ParcelOutcome o2 = outcomeAt(std::max(0.0, t + shift), tauTotal);
                    sum.xOut += o2.xOut / points;
                    sum.tOut += o2.tOut / points;
                }
                out.xOut = sum.xOut;
                out.tOut = sum.tOut;
            }
            // Instruments.
            double xOutMeasPct = 100 * out.xOut / (1 + out.xOut);
            if (meterLag > 0) {
                // Second order: a sample line and the sensor, each with half the time constant.
                const double a = 1 - std::exp(-2.0 / meterLag);
                if (std::isnan(meterState)) {
                    meterState = meterState2 = xOutMeasPct;
                }
                meterState += (xOutMeasPct - meterState) * a;
                meterState2 += (meterState - meterState2) * a;
                xOutMeasPct = meterState2;
            }
            // The offset of a meter calibrated at 55 °C grows with the product's temperature.
            xOutMeasPct += meterOffset * (1.0 + 0.1 * (units::kelvinToCelsius(out.tOut) - 55.0) / 10.0) +
                           0.02 * normal(rng);
            const double tOutMeas = out.tOut + 0.03 * normal(rng);
            const double xHdtPct = 100 * hdt.xHdt / (1 + hdt.xHdt) + 0.03 * normal(rng);
            const double tHdtMeas = hdt.tHdt + 0.05 * normal(rng);
            // The plant's PI controller moves the hot-air setpoint (anti-windup by clamping).
            const double e = xOutMeasPct - o.targetXOutPct;
            integral += e / ti;
            const double ff = kff * (100 * xIn[k] / (1 + xIn[k]) - xInRefPct);
            double newSp = kKelvin + 170 + ff + kc * (e + integral);
            const double lo = kKelvin + 140;
            const double hi = kKelvin + 200;
            if (newSp > hi || newSp < lo) {
                integral -= e / ti;
                newSp = std::clamp(newSp, lo, hi);
            }
            sp = newSp;
            tHotSp[k] = sp;
            // Measured inputs carry their own small noise.
            pb.tHotSpK.push_back(sp);
            pb.tHotK.push_back(tHot[k] + 0.1 * normal(rng));
            pb.airSpeedMPerS.push_back(air[k] + 0.02 * normal(rng));
            pb.feedKgPerS.push_back(feed[k] + units::kgPerHourToKgPerS(5.0) * normal(rng));
            const double xInWb = xIn[k] / (1 + xIn[k]) + 0.0001 * normal(rng);
            pb.xInDb.push_back(xInWb / (1 - xInWb));
            pb.tInK.push_back(tIn[k] + 0.1 * normal(rng));
            pb.tAmbK.push_back(tAmb[k] + 0.1 * normal(rng));
            pb.rhAmb.push_back(std::clamp(rh[k] + 0.005 * normal(rng), 0.0, 1.0));
            pb.xHdtDb.push_back(units::wetPctToDry(xHdtPct));
            pb.tHdtK.push_back(tHdtMeas);
            pb.xOutDb.push_back(units::wetPctToDry(xOutMeasPct));
            pb.tOutK.push_back(tOutMeas);
        }
        result.batches.push_back(std::move(pb));
    }
    reportProgress(progress, "generate", 1.0);
    result.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace drytwin::plant
