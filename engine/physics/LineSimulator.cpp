#include "physics/LineSimulator.h"

#include "common/FirstOrderLag.h"
#include "common/MovingAverage.h"
#include "common/Units.h"
#include "physics/SectionRates.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>
#include <type_traits>

namespace drytwin::physics {

using properties::Pack2;
using properties::Param;
using properties::ParameterSet;

namespace {

struct SectionContext {
    const LineInputs* in = nullptr;
    const ParameterSet* p = nullptr;
    const properties::ModelSwitches* sw = nullptr;
    const std::vector<double>* entry = nullptr; ///< absolute entry time of each parcel [s]
    mutable std::vector<std::size_t> hint;      ///< per-parcel interpolation hints
    /// X_e (Eq. 5) at the sample times, interpolated like the inputs it comes from (saves a log
    /// and an exp per right-hand side); null when X_e must follow parameters CVODES perturbs.
    const std::vector<double>* xeSeries = nullptr;
    /// Winnower inlet mix per parcel when it is not carried as solver states (no sensitivities).
    const double* xMix = nullptr;
    const double* tMixK = nullptr;
    /// Uniform sampling (the normal case, 1 s): the segment is found by arithmetic.
    bool uniform = false;
    double t0 = 0;
    double invDt = 1; ///< 1 / sampling step [1/s]
    /// Where parcel @p parcel is in the input series at local time @p s; one look-up serves
    /// every input the section reads.
    SamplePoint locate(std::size_t parcel, double s) const {
        const double t = (*entry)[parcel] + s;
        if (!uniform) {
            return locateFrom(in->timeS, t, hint[parcel]);
        }
        const double u = (t - t0) * invDt;
        if (u <= 0) {
            return {0, 0.0};
        }
        const auto last = in->timeS.size() - 1;
        if (u >= static_cast<double>(last)) {
            return {last - 1, 1.0};
        }
        const auto j = static_cast<std::size_t>(u);
        return {j, u - static_cast<double>(j)};
    }
};

/// True when the time index is uniform to 1e-9 of its step.
bool isUniform(const std::vector<double>& t) {
    const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (std::abs(t[i] - (t.front() + static_cast<double>(i) * dt)) > 1e-9 * dt) {
            return false;
        }
    }
    return true;
}

SectionContext makeContext(const LineInputs& in, const ParameterSet& p, const properties::ModelSwitches& sw,
                           const std::vector<double>& entry, bool uniform) {
    SectionContext c{&in, &p, &sw, &entry, std::vector<std::size_t>(entry.size(), 0)};
    c.uniform = uniform;
    c.t0 = in.timeS.front();
    c.invDt = static_cast<double>(in.timeS.size() - 1) / (in.timeS.back() - in.timeS.front());
    return c;
}

/// The parcels one evaluation of the rates works on: one (T = double) or two consecutive ones
/// (T = Pack2, one per lane), with their solver states.
template <class T> struct Lanes {
    static constexpr int width = std::is_same_v<T, double> ? 1 : 2;
    std::size_t parcel = 0; ///< the first lane's parcel
    const double* y = nullptr;
    int statesPerParcel = 2;
    /// Packs one value per lane.
    static T load(const double* v) {
        if constexpr (width == 1) {
            return v[0];
        } else {
            return T(v[0], v[1]);
        }
    }
    /// State @p m of every lane.
    T state(int m) const {
        const double v[2] = {y[m], width == 2 ? y[statesPerParcel + m] : 0.0};
        return load(v);
    }
    /// A per-parcel series (the winnower's entry mix) for every lane.
    T of(const double* perParcel) const { return load(perParcel + parcel); }
};

/// Lane @p lane of a value: the value itself for one parcel, its element for two.
inline double laneOf(double v, int) {
    return v;
}
inline double laneOf(const Pack2& v, int lane) {
    return v[lane];
}

/// Runs @p rates over a run of parcels, two at a time where the target has Pack2. The
/// parameters and switches are copied once per call: the rate stores cannot alias the copies,
/// so the compiler may keep what all parcels share out of the loop. CVODES perturbs the
/// parameters in place between calls, so the copy is fresh each time.
template <int States, class Rates>
bool forParcels(const void* c, std::size_t first, std::size_t count, const double* y, double* ydot,
                Rates rates) {
    const auto& ctx = *static_cast<const SectionContext*>(c);
    const ParameterSet p = *ctx.p;
    const properties::ModelSwitches sw = *ctx.sw;
    bool finite = true;
    // Stores one evaluation's rates for each of its lanes; the winnower's carried entry mix
    // (states 2 and 3) has zero rates.
    auto store = [&](const auto& r, std::size_t k, int width) {
        double* d = ydot + k * States;
        for (int lane = 0; lane < width; ++lane) {
            const double dX = laneOf(r.dXdt, lane);
            const double dT = laneOf(r.dTdt, lane);
            d[lane * States] = dX;
            d[lane * States + 1] = dT;
            for (int m = 2; m < States; ++m) {
                d[lane * States + m] = 0;
            }
            finite &= std::isfinite(dX) & std::isfinite(dT);
        }
    };
    std::size_t k = 0;
#if DRYTWIN_HAVE_PACK2
    for (; k + 2 <= count; k += 2) {
        store(rates(ctx, p, sw, Lanes<Pack2>{first + k, y + k * States, States}), k, 2);
    }
#endif
    for (; k < count; ++k) {
        store(rates(ctx, p, sw, Lanes<double>{first + k, y + k * States, States}), k, 1);
    }
    return finite;
}

// Engineering constants of the gas-phase extension (model side; the plant has its own).
constexpr double kModelAirHeatCapacity = 1010;        // J/(kg·K)
constexpr double kModelAirMassPerSpeed = 0.8 * 0.283; // kg/s of hot air per m/s (0.6 m tube, 0.8 kg/m³)
constexpr double kModelLatentHeat = 2.3e6;            // J/kg, for the gas cooling only
constexpr double kModelCriticalMoisture = 0.25;       // X_cr of the falling-rate extension [kg/kg dry]

bool tubeEval(const void* c, double s, std::size_t first, std::size_t count, const double* y, double* ydot) {
    return forParcels<2>(
        c, first, count, y, ydot,
        [s](const SectionContext& x, const ParameterSet& p, const properties::ModelSwitches& sw,
            const auto& l) {
            using T = std::decay_t<decltype(l.state(0))>;
            const double wall = p[Param::theta_wall];
            const double gasCoupling = p[Param::theta_gas];
            const double fouling = p[Param::theta_foul];
            const double falling = p[Param::theta_fall];
            double gas[2] = {0, 0};
            double hours[2] = {0, 0};      // since the batch started
            double gasCooling[2] = {0, 0}; // K per kg/kg evaporated
            double xEntry[2] = {0, 0};
            double fallingLane[2] = {0, 0};
            const double onset = p[Param::t_onset];
            for (int lane = 0; lane < l.width; ++lane) {
                const std::size_t parcel = l.parcel + static_cast<std::size_t>(lane);
                const SamplePoint where = x.locate(parcel, s);
                const double tHot = where.of(x.in->tHotK);
                gas[lane] = tHot;
                // The mechanisms act from their onset on (t_onset, since the batch started).
                const double sinceStart = (*x.entry)[parcel] + s - x.t0;
                if (onset > 0 && sinceStart < onset) {
                    continue;
                }
                fallingLane[lane] = falling;
                if (wall != 0) { // tube_wall_heat_loss, simple form
                    gas[lane] = tHot - wall * (tHot - where.of(x.in->tAmbK));
                }
                if (fouling != 0) {
                    hours[lane] = (sinceStart - onset) / 3600.0;
                }
                if (gasCoupling != 0) { // conditions at the parcel's entry
                    const SamplePoint in0 = x.locate(parcel, 0.0);
                    xEntry[lane] = in0.of(x.in->xInDb);
                    const double dryFeed = in0.of(x.in->feedKgPerS) / (1 + xEntry[lane]);
                    const double air = std::max(1.0, in0.of(x.in->airSpeedMPerS));
                    gasCooling[lane] =
                        kModelLatentHeat * dryFeed / (kModelAirHeatCapacity * kModelAirMassPerSpeed * air);
                }
            }
            TubeEnvironmentT<T> env;
            env.tGasK = l.load(gas);
            if (gasCoupling != 0) { // gas_phase_coupling, simple form
                env.tGasK = env.tGasK - gasCoupling * l.load(gasCooling) * (l.load(xEntry) - l.state(0));
            }
            env.wGas = p[Param::w];
            env.h = properties::math::constant<T>(p[Param::h_HDT]);
            if (fouling != 0) { // heat_transfer_fouling, simple form
                env.h = p[Param::h_HDT] * properties::math::maxOf(T(1.0 - fouling * l.load(hours)), 0.05);
            }
            env.k = p[Param::k_HDT];
            if (falling != 0) { // falling_rate_drying, simple form
                const T depth = properties::math::minOf(
                    properties::math::maxOf(T((kModelCriticalMoisture - l.state(0)) / kModelCriticalMoisture),
                                            0.0),
                    1.0);
                env.dryingFactor = 1.0 - l.load(fallingLane) * depth;
            }
            return generic::tubeRates(l.state(0), l.state(1), env, p, sw);
        });
}

/// The air around every lane's parcel, one input look-up per parcel for all series.
template <class T> AmbientEnvironmentT<T> ambientAt(const SectionContext& x, const Lanes<T>& l, double s) {
    double tAir[2] = {0, 0};
    double rh[2] = {0, 0};
    double xe[2] = {0, 0};
    for (int lane = 0; lane < l.width; ++lane) {
        const SamplePoint where = x.locate(l.parcel + static_cast<std::size_t>(lane), s);
        tAir[lane] = where.of(x.in->tAmbK);
        rh[lane] = where.of(x.in->rhAmb);
        if (x.xeSeries) {
            xe[lane] = where.of(*x.xeSeries);
        }
    }
    AmbientEnvironmentT<T> env;
    env.tAirK = l.load(tAir);
    env.rh = l.load(rh);
    env.xeDb = l.load(xe);
    env.hasXe = x.xeSeries != nullptr;
    return env;
}

bool conveyorEval(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                  double* ydot) {
    return forParcels<2>(c, first, count, y, ydot,
                         [s](const SectionContext& x, const ParameterSet& p,
                             const properties::ModelSwitches& sw, const auto& l) {
                             auto env = ambientAt(x, l, s);
                             if (const double reabsorption = p[Param::theta_reabs]; reabsorption != 0) {
                                 // ambient_reabsorption, from its onset on (with none, also for the
                                 // parcels that entered before the batch started, as the tube's
                                 // mechanisms)
                                 const double onset = p[Param::t_onset];
                                 double active[2] = {0, 0};
                                 for (int lane = 0; lane < l.width; ++lane) {
                                     const std::size_t parcel = l.parcel + static_cast<std::size_t>(lane);
                                     active[lane] = onset <= 0 || (*x.entry)[parcel] + s - x.t0 >= onset;
                                 }
                                 env.extraUptake = reabsorption * 1e-4 * env.rh * l.load(active);
                             }
                             return generic::conveyorRates(l.state(0), l.state(1), env, p, sw);
                         });
}

bool winnowerEval(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                  double* ydot) {
    // States: X and T; the entry mix (X_mix, T_mix) comes from the context.
    return forParcels<2>(c, first, count, y, ydot,
                         [s](const SectionContext& x, const ParameterSet& p,
                             const properties::ModelSwitches& sw, const auto& l) {
                             return generic::winnowerRates(l.state(0), l.state(1), s, l.of(x.xMix),
                                                           l.of(x.tMixK), ambientAt(x, l, s), p, sw);
                         });
}

bool winnowerEvalWithMixStates(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                               double* ydot) {
    // States: X, T, and the entry mix (X_mix, T_mix) carried as constants so that their
    // sensitivities flow into Eq. 18.
    return forParcels<4>(c, first, count, y, ydot,
                         [s](const SectionContext& x, const ParameterSet& p,
                             const properties::ModelSwitches& sw, const auto& l) {
                             return generic::winnowerRates(l.state(0), l.state(1), s, l.state(2), l.state(3),
                                                           ambientAt(x, l, s), p, sw);
                         });
}

IntegratorSettings settingsFor(const SimulationOptions& o, int states) {
    IntegratorSettings s;
    s.reference = o.reference;
    s.maxSteps = o.maxStepsPerSection;
    s.relTol = o.relTol;
    // Absolute tolerances per state (moisture in kg/kg, temperature in K), shrinking with the
    // relative tolerance.
    const double atolX = std::min(1e-6, o.relTol * 1e-2);
    const double atolT = std::min(1e-2, o.relTol * 1e2);
    s.absTol =
        states == 2 ? std::vector<double>{atolX, atolT} : std::vector<double>{atolX, atolT, atolX, atolT};
    return s;
}

/// Core simulation; sensitivities only for rate (non-duration) parameters. Rows flagged in
/// @p outletOnly (same length as @p rows; empty: none) are wanted for the line's outlet alone, as
/// the meter lag's history is: their tube-outlet values (X_HDT, T_HDT and their sensitivities) are
/// NaN, and the tube integrates one parcel for them instead of two.
Expected<SimulationResult> simulateCore(const LineInputs& in, const ParameterSet& params,
                                        const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                        const std::vector<Param>& odeSens,
                                        const std::vector<std::uint8_t>& outletOnly = {}) {
    SimulationResult res;
    res.rows = rows;
    const bool uniform = isUniform(in.timeS);
    const std::size_t n = rows.size();
    ParameterSet p = params; // CVODES perturbs this copy in place
    const double tauH = p[Param::tau_HDT];
    const double tauC = p[Param::tau_conv] + p[Param::dtau_conv]; // transport_delay_error
    const double tW = p[Param::t_W];

    SensitivitySpec spec;
    const bool withSens = !odeSens.empty();
    const std::size_t ns = odeSens.size();
    for (Param q : odeSens) {
        spec.plist.push_back(static_cast<int>(q));
        const double v = std::abs(p[q]);
        spec.pbar.push_back(v > 0 ? v : 1.0);
    }
    spec.params = p.data();

    // Tube: the parcel that leaves the line at row k (set A) and the one that leaves the tube at
    // row k (set B). With delays that are whole sample steps most set-A parcels are set-B parcels
    // of earlier rows, so equal entry times share one integration.
    std::vector<double> entryTube;
    entryTube.reserve(2 * n);
    constexpr std::size_t kNoParcel = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> tubeOfA(n);
    std::vector<std::size_t> tubeOfB(n, kNoParcel);
    const auto wantsTubeOutlet = [&](std::size_t j) { return outletOnly.empty() || !outletOnly[j]; };
    {
        std::vector<std::pair<double, std::size_t>> wanted; // (entry time, slot: j for A, n + j for B)
        wanted.reserve(2 * n);
        for (std::size_t j = 0; j < n; ++j) {
            const double tOut = in.timeS[rows[j]];
            wanted.emplace_back(tOut - (tauH + tauC + tW), j);
            if (wantsTubeOutlet(j)) {
                wanted.emplace_back(tOut - tauH, n + j);
            }
        }
        std::sort(wanted.begin(), wanted.end());
        for (const auto& [t, slot] : wanted) {
            if (entryTube.empty() || t - entryTube.back() > 1e-9) {
                entryTube.push_back(t);
            }
            (slot < n ? tubeOfA[slot] : tubeOfB[slot - n]) = entryTube.size() - 1;
        }
    }
    const std::size_t nTube = entryTube.size();
    std::vector<double> y(2 * nTube);
    for (std::size_t j = 0; j < nTube; ++j) {
        y[2 * j] = interpolate(in.timeS, in.xInDb, entryTube[j]);
        y[2 * j + 1] = interpolate(in.timeS, in.tInK, entryTube[j]);
    }
    std::vector<std::vector<double>> yS(ns, std::vector<double>(2 * nTube, 0.0));
    std::vector<double> xeSeries;
    const bool xeMoves = std::any_of(odeSens.begin(), odeSens.end(), [](Param q) {
        return q == Param::theta_xe1 || q == Param::theta_xe2 || q == Param::theta_xe3;
    });
    if (!xeMoves) {
        xeSeries.resize(in.size());
        for (std::size_t k = 0; k < in.size(); ++k) {
            xeSeries[k] = properties::equilibriumMoisture(in.tAmbK[k], in.rhAmb[k], p);
        }
    }
    // One section: every parcel (entry times, states) integrated over the section's duration.
    using Evaluate = bool (*)(const void*, double, std::size_t, std::size_t, const double*, double*);
    auto runSection = [&](Evaluate evaluate, const std::vector<double>& entry, int states, double duration,
                          std::vector<double>& state, std::vector<std::vector<double>>& sens,
                          const char* name) {
        SectionContext ctx = makeContext(in, p, o.switches, entry, uniform);
        ctx.xMix = res.proxyXMixDb.data();
        ctx.tMixK = res.proxyTMixK.data();
        ctx.xeSeries = xeMoves ? nullptr : &xeSeries;
        const ParcelRhs rhs{&ctx, evaluate, entry.size(), states};
        return integrateParcels(rhs, state, duration, settingsFor(o, states), withSens ? &spec : nullptr,
                                withSens ? &sens : nullptr, name, &res.stats);
    };
    if (auto st = runSection(tubeEval, entryTube, 2, tauH, y, yS, "drying tube"); !st) {
        return st.error();
    }
    res.xHdtDb.resize(n);
    res.tHdtK.resize(n);
    res.proxyXHdtDb.resize(n);
    res.proxyTHdtK.resize(n);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t j = 0; j < n; ++j) {
        res.proxyXHdtDb[j] = y[2 * tubeOfA[j]];
        res.proxyTHdtK[j] = y[2 * tubeOfA[j] + 1];
        const bool b = tubeOfB[j] != kNoParcel;
        res.xHdtDb[j] = b ? y[2 * tubeOfB[j]] : nan;
        res.tHdtK[j] = b ? y[2 * tubeOfB[j] + 1] : nan;
    }
    for (std::size_t q = 0; q < ns; ++q) {
        OutputSensitivity os;
        os.param = odeSens[q];
        os.dXHdt.resize(n);
        os.dTHdt.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
            const bool b = tubeOfB[j] != kNoParcel;
            os.dXHdt[j] = b ? yS[q][2 * tubeOfB[j]] : nan;
            os.dTHdt[j] = b ? yS[q][2 * tubeOfB[j] + 1] : nan;
        }
        res.sensitivities.push_back(std::move(os));
    }

    // Conveyor: the top layer of set A.
    std::vector<double> entryConv(n);
    std::vector<double> yc(2 * n);
    std::vector<std::vector<double>> ySc(ns, std::vector<double>(2 * n));
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t a = tubeOfA[j];
        entryConv[j] = entryTube[a] + tauH;
        yc[2 * j] = y[2 * a];
        yc[2 * j + 1] = y[2 * a + 1];
        for (std::size_t q = 0; q < ns; ++q) {
            ySc[q][2 * j] = yS[q][2 * a];
            ySc[q][2 * j + 1] = yS[q][2 * a + 1];
        }
    }
    if (auto st = runSection(conveyorEval, entryConv, 2, tauC, yc, ySc, "conveyor"); !st) {
        return st.error();
    }

    // Winnower inlet mix, Eqs. 15–16, and its Jacobian for the sensitivities (the mix is
    // algebraic, so central differences are accurate to ~1e-9 here).
    std::vector<double> entryWin(n);
    // With sensitivities the mix rides along as two constant states (so that its sensitivities
    // reach Eq. 18); without, it is read from the proxies, which halves the winnower's system.
    const std::size_t wm = withSens ? 4 : 2;
    std::vector<double> yw(wm * n);
    std::vector<std::vector<double>> ySw(ns, std::vector<double>(4 * n));
    res.proxyXConvDb.resize(n);
    res.proxyTConvK.resize(n);
    res.proxyXMixDb.resize(n);
    res.proxyTMixK.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
        const double xc = yc[2 * j];
        const double tc = yc[2 * j + 1];
        const double xh = y[2 * tubeOfA[j]];
        const double th = y[2 * tubeOfA[j] + 1];
        const MixState mix = winnowerInletMix(xc, tc, xh, th, p, o.switches);
        entryWin[j] = entryConv[j] + tauC;
        res.proxyXConvDb[j] = xc;
        res.proxyTConvK[j] = tc;
        res.proxyXMixDb[j] = mix.xDb;
        res.proxyTMixK[j] = mix.tK;
        yw[wm * j] = mix.xDb;
        yw[wm * j + 1] = mix.tK;
        if (!withSens) {
            continue;
        }
        yw[4 * j + 2] = mix.xDb;
        yw[4 * j + 3] = mix.tK;
        const double in4[4] = {xc, tc, xh, th};
        double jac[2][4];
        for (int a = 0; a < 4; ++a) {
            double up[4] = {in4[0], in4[1], in4[2], in4[3]};
            double dn[4] = {in4[0], in4[1], in4[2], in4[3]};
            const double h = 1e-6 * std::max(1.0, std::abs(in4[a]));
            up[a] += h;
            dn[a] -= h;
            const MixState mu = winnowerInletMix(up[0], up[1], up[2], up[3], p, o.switches);
            const MixState md = winnowerInletMix(dn[0], dn[1], dn[2], dn[3], p, o.switches);
            jac[0][a] = (mu.xDb - md.xDb) / (2 * h);
            jac[1][a] = (mu.tK - md.tK) / (2 * h);
        }
        for (std::size_t q = 0; q < ns; ++q) {
            const double d4[4] = {ySc[q][2 * j], ySc[q][2 * j + 1], yS[q][2 * tubeOfA[j]],
                                  yS[q][2 * tubeOfA[j] + 1]};
            double dx = 0;
            double dt = 0;
            for (int a = 0; a < 4; ++a) {
                dx += jac[0][a] * d4[a];
                dt += jac[1][a] * d4[a];
            }
            // Direct dependence of the mix on the parameter (β_top, θ_Cp1, θ_Cp2).
            ParameterSet pp = p;
            const double v = p[odeSens[q]];
            const double h = 1e-6 * std::max(1e-3, std::abs(v));
            pp[odeSens[q]] = v + h;
            const MixState mu = winnowerInletMix(xc, tc, xh, th, pp, o.switches);
            pp[odeSens[q]] = v - h;
            const MixState md = winnowerInletMix(xc, tc, xh, th, pp, o.switches);
            dx += (mu.xDb - md.xDb) / (2 * h);
            dt += (mu.tK - md.tK) / (2 * h);
            ySw[q][4 * j] = dx;
            ySw[q][4 * j + 1] = dt;
            ySw[q][4 * j + 2] = dx;
            ySw[q][4 * j + 3] = dt;
        }
    }

    res.xOutDb.resize(n);
    res.tOutK.resize(n);
    if (o.winnower == WinnowerForm::Transient) {
        if (auto st = runSection(withSens ? winnowerEvalWithMixStates : winnowerEval, entryWin,
                                 static_cast<int>(wm), tW, yw, ySw, "winnower");
            !st) {
            return st.error();
        }
        for (std::size_t j = 0; j < n; ++j) {
            res.xOutDb[j] = yw[wm * j];
            res.tOutK[j] = yw[wm * j + 1];
        }
        for (std::size_t q = 0; q < ns; ++q) {
            auto& os = res.sensitivities[q];
            os.dXOut.resize(n);
            os.dTOut.resize(n);
            for (std::size_t j = 0; j < n; ++j) {
                os.dXOut[j] = ySw[q][4 * j];
                os.dTOut[j] = ySw[q][4 * j + 1];
            }
        }
    } else {
        for (std::size_t j = 0; j < n; ++j) {
            const double xm = res.proxyXMixDb[j];
            const double tm = res.proxyTMixK[j];
            const AmbientEnvironment env{interpolate(in.timeS, in.tAmbK, entryWin[j]),
                                         interpolate(in.timeS, in.rhAmb, entryWin[j]), 0.0};
            const double xOut = winnowerTerminalMoisture(xm, tm, env, p); // Eq. (17)
            // Eq. (19) over t_W as one explicit step with the evaporated mass of Eq. 17.
            const auto r = winnowerRates(xm, tm, 0.0, xm, tm, env, p, o.switches);
            res.xOutDb[j] = xOut;
            res.tOutK[j] = tm + (r.heatIn * tW - r.vapourEnthalpy * (xm - xOut)) / r.heatCapacity;
        }
    }
    return res;
}

/// Each input column averaged over a centred window of @p windowS (time-based, per batch).
LineInputs boxSmoothed(const LineInputs& in, double windowS) {
    LineInputs out = in;
    const auto& t = in.timeS;
    for (auto [src, dst] : {std::pair{&in.tHotK, &out.tHotK},
                            {&in.xInDb, &out.xInDb},
                            {&in.tInK, &out.tInK},
                            {&in.tAmbK, &out.tAmbK},
                            {&in.rhAmb, &out.rhAmb},
                            {&in.feedKgPerS, &out.feedKgPerS},
                            {&in.airSpeedMPerS, &out.airSpeedMPerS}}) {
        if (src->size() == t.size()) {
            *dst = centredMovingAverage(t, *src, windowS);
        }
    }
    return out;
}

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

/// The sensor causes (CONTRACT.md §4): the measured inputs corrected as the parameters say,
/// before the line sees them, from the onset on. Null when every one is 0 (the inputs as measured).
std::optional<LineInputs> correctedInputs(const LineInputs& in, const ParameterSet& p) {
    const double offsetPct = p[Param::X_in_offset];
    const double hotLagS = p[Param::tau_hot_sensor];
    const double scatterShare = p[Param::phi_X_in_scatter];
    if (offsetPct == 0 && hotLagS == 0 && scatterShare == 0) {
        return std::nullopt;
    }
    const double onset = in.timeS.front() + p[Param::t_onset];
    LineInputs out = in;
    if (scatterShare > 0) { // inlet_moisture_sensor_noise: remove that share of the fast variation
        const auto smooth = zeroPhaseFilter(in.timeS, in.xInDb, kInletScatterFilterS);
        for (std::size_t i = 0; i < out.size(); ++i) {
            if (in.timeS[i] >= onset) {
                out.xInDb[i] = in.xInDb[i] + scatterShare * (smooth[i] - in.xInDb[i]);
            }
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

/// The moisture_meter_offset extension: a constant offset in % wb on the predicted X_out and,
/// by the chain rule through wet basis, on its sensitivities.
void applyMeterOffset(SimulationResult& res, double offsetPct, const std::vector<double>& timeS,
                      double onsetS) {
    for (std::size_t j = 0; j < res.xOutDb.size(); ++j) {
        if (timeS[res.rows[j]] < onsetS) {
            continue;
        }
        const double x = res.xOutDb[j];
        const double wet = units::dryToWetPct(x) + offsetPct;
        const double shifted = units::wetPctToDry(wet);
        // Chain rule through wet basis: dX'/dX = (dX'/dw)(dw/dX).
        const double slope = (100.0 / ((100.0 - wet) * (100.0 - wet))) * (100.0 / ((1 + x) * (1 + x)));
        res.xOutDb[j] = shifted;
        for (auto& sens : res.sensitivities) {
            sens.dXOut[j] *= slope;
        }
    }
}

/// ∂X_out/∂X_meter_offset of the reading after the offset: dX/dw = 100/(100 − w)² per % wb from
/// the onset on, 0 before it.
OutputSensitivity meterOffsetSensitivity(const SimulationResult& res, const std::vector<double>& timeS,
                                         double onsetS) {
    const std::size_t n = res.xOutDb.size();
    OutputSensitivity os{Param::X_meter_offset, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
                         std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
    for (std::size_t j = 0; j < n; ++j) {
        if (timeS[res.rows[j]] >= onsetS) {
            const double wet = units::dryToWetPct(res.xOutDb[j]);
            os.dXOut[j] = 100.0 / ((100.0 - wet) * (100.0 - wet));
        }
    }
    return os;
}

/// The meter's offset on a simulated outlet reading (from the onset on), and the offset's own
/// sensitivity where it is asked for.
void readThroughMeterOffset(SimulationResult& res, double offsetPct, bool withSensitivity,
                            const std::vector<double>& timeS, double onsetS) {
    if (offsetPct != 0) {
        applyMeterOffset(res, offsetPct, timeS, onsetS);
    }
    if (withSensitivity) {
        res.sensitivities.push_back(meterOffsetSensitivity(res, timeS, onsetS));
    }
}

/// The two values of a parameter at @p v a sensitivity's difference is taken between, and their
/// span: central, one-sided at the parameter's lower bound @p lower (a meter lag of 0).
struct DifferenceStep {
    double up, down, span;
};
DifferenceStep differenceStep(double v, double lower) {
    const double h = 1e-3 * std::max(1.0, std::abs(v));
    const bool oneSided = v - h < lower;
    return {v + h, oneSided ? v : v - h, oneSided ? h : 2 * h};
}

/// (up − down) / span, element by element.
std::vector<double> dividedDifference(const std::vector<double>& up, const std::vector<double>& down,
                                      double span) {
    std::vector<double> d(up.size());
    for (std::size_t j = 0; j < d.size(); ++j) {
        d[j] = (up[j] - down[j]) / span;
    }
    return d;
}

/// The outlet as measured: the line's outlet mixing (tau_mix, a first-order lag on X_out and
/// T_out), then the moisture_meter_lag and moisture_meter_offset extensions (first-order lag, then
/// a constant offset in % wb) on X_out, each applied to the prediction and its sensitivities.
/// @p outputSens (tau_mix, tau_meter, X_meter_offset) act on the outlet only: their sensitivities
/// come from this one run's outlet history (differences of the lags, the offset's slope) instead
/// of two more runs of the line each, and carry no solver noise.
Expected<SimulationResult> simulateMeasured(const LineInputs& measured, const ParameterSet& params,
                                            const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                            const std::vector<Param>& odeSens,
                                            const std::vector<Param>& outputSens) {
    const auto corrected = correctedInputs(measured, params);
    const LineInputs& in = corrected ? *corrected : measured;
    const double tauMeter = params[Param::tau_meter];
    const double tauMix = params[Param::tau_mix];
    const double offsetPct = params[Param::X_meter_offset];
    const double onsetS = in.timeS.front() + params[Param::t_onset];
    const auto wants = [&](Param q) {
        return std::find(outputSens.begin(), outputSens.end(), q) != outputSens.end();
    };
    const bool lagged = tauMeter > 0 || tauMix > 0;
    if ((!lagged && !wants(Param::tau_meter) && !wants(Param::tau_mix)) || rows.empty()) {
        auto res = simulateCore(in, params, o, rows, odeSens);
        if (res) {
            readThroughMeterOffset(*res, offsetPct, wants(Param::X_meter_offset), in.timeS, onsetS);
        }
        return res;
    }
    // The lag needs the output's history from the first row on. Between the wanted rows it comes
    // from a grid of meterGridS on inputs averaged over the same span: computing every row costs
    // as many parcels as the whole batch (44× the rows of a discovery fit), and the meter's own
    // lag averages what happens within a grid step. Sampled raw, the sample-to-sample noise of
    // the inputs would alias into the filtered value; averaged, the grid stays within 0.0015 % wb
    // rms of every row (tests/engine/physics). The grid does not depend on τ, so the loss stays
    // smooth in τ for the fits. meterGridS = 0, or every row wanted: every row, exact.
    std::vector<std::size_t> order(rows.size()); // wanted rows by time
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return rows[a] < rows[b]; });
    const std::size_t last = rows[order.back()];
    bool everyRow = true;
    for (std::size_t j = 0; j < rows.size() && everyRow; ++j) {
        everyRow = rows[j] == j;
    }
    // Without a lag (a lag's sensitivity at 0 alone) the history that counts is the wanted row and
    // the sample before it: a lag of the difference step (1 ms) forgets anything older (e^-1000 a
    // second back), so the grid is not run.
    const bool rawTailOnly = !lagged && !everyRow;
    const bool onGrid = o.meterGridS > 0 && !everyRow && !rawTailOnly;
    // The history: the grid on averaged inputs, and the wanted row and the one before it on the
    // raw inputs. So the filtered value tends to the raw output as τ → 0 (the score test's
    // difference at τ = 0 is then −dX/dt of the raw output); a longer raw tail measured no more
    // accurate (tests/engine/physics).
    constexpr double kRawTailS = 2;
    enum : std::uint8_t { kNone = 0, kGrid = 1, kRaw = 2 };
    std::vector<std::uint8_t> kind(last + 1, onGrid || rawTailOnly ? kNone : kRaw);
    if (onGrid || rawTailOnly) {
        double lastGridTime = -std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j <= last && onGrid; ++j) {
            if (in.timeS[j] - lastGridTime >= o.meterGridS - 1e-9) {
                kind[j] = kGrid;
                lastGridTime = in.timeS[j];
            }
        }
        double nextWantedTime = std::numeric_limits<double>::infinity();
        std::size_t pending = order.size(); // wanted rows at or after j are order[pending..]
        for (std::size_t j = last + 1; j-- > 0;) {
            while (pending > 0 && rows[order[pending - 1]] >= j) {
                nextWantedTime = in.timeS[rows[order[--pending]]];
            }
            if (nextWantedTime - in.timeS[j] < kRawTailS - 1e-9) {
                kind[j] = kRaw;
            }
        }
        for (std::size_t r : rows) {
            if (rawTailOnly && r > 0) {
                kind[r - 1] = kRaw; // the sample before, however far back
            }
        }
    }
    std::vector<std::size_t> historyRows, rawRows, gridRows;
    std::vector<std::uint8_t> historyKind;
    std::vector<std::size_t> historyIndex; // into rawRows or gridRows
    for (std::size_t j = 0; j <= last; ++j) {
        if (kind[j] != kNone) {
            historyRows.push_back(j);
            historyKind.push_back(kind[j]);
            auto& list = kind[j] == kRaw ? rawRows : gridRows;
            historyIndex.push_back(list.size());
            list.push_back(j);
        }
    }
    // Only the wanted rows need the tube's outlet; the raw tail before each and the grid are
    // there for the outlet's history.
    std::vector<std::uint8_t> tailOnly(rawRows.size(), 1);
    for (std::size_t r : rows) {
        tailOnly[static_cast<std::size_t>(std::lower_bound(rawRows.begin(), rawRows.end(), r) -
                                          rawRows.begin())] = 0;
    }
    auto raw = simulateCore(in, params, o, rawRows, odeSens, tailOnly);
    if (!raw) {
        return raw;
    }
    // Without a lag the rate parameters' outlet sensitivities are the wanted rows' own, so the
    // grid, there only for the lags' differences, is run without them.
    std::optional<Expected<SimulationResult>> grid;
    if (!gridRows.empty()) {
        grid.emplace(simulateCore(boxSmoothed(in, o.meterGridS), params, o, gridRows,
                                  lagged ? odeSens : std::vector<Param>{},
                                  std::vector<std::uint8_t>(gridRows.size(), 1)));
        if (!*grid) {
            return grid->error();
        }
    }
    const auto historyOf = [&](auto member) {
        std::vector<double> u(historyRows.size());
        for (std::size_t h = 0; h < u.size(); ++h) {
            u[h] = member(historyKind[h] == kRaw ? *raw : grid->value())[historyIndex[h]];
        }
        return u;
    };
    std::vector<double> historyTimeS(historyRows.size());
    for (std::size_t h = 0; h < historyRows.size(); ++h) {
        historyTimeS[h] = in.timeS[historyRows[h]];
    }
    // Exact first-order response to an input linear between history points: as τ → 0 it tends to
    // the input minus τ times its slope, so the sensitivity at τ = 0 is −dX/dt, not 0.
    const auto lagOver = [&](const std::vector<double>& u, double tau) {
        return lagOfPiecewiseLinear(historyTimeS, u, tau);
    };
    // The line's outlet mixing acts on both outlet channels; the meter's lag on top of it, on X_out.
    const auto xOutHistory = historyOf([](const SimulationResult& r) -> const auto& { return r.xOutDb; });
    const auto tOutHistory = historyOf([](const SimulationResult& r) -> const auto& { return r.tOutK; });
    const auto xOutMixed = lagOver(xOutHistory, tauMix);
    const auto tOutMixed = lagOver(tOutHistory, tauMix);
    std::vector<std::vector<double>> sensXMixed, sensTMixed;
    for (std::size_t q = 0; q < raw->sensitivities.size() && lagged; ++q) {
        sensXMixed.push_back(lagOver(
            historyOf([q](const SimulationResult& r) -> const auto& { return r.sensitivities[q].dXOut; }),
            tauMix));
        sensTMixed.push_back(lagOver(
            historyOf([q](const SimulationResult& r) -> const auto& { return r.sensitivities[q].dTOut; }),
            tauMix));
    }
    SimulationResult res = std::move(*raw);
    std::vector<std::size_t> atRaw(rows.size()), atHistory(rows.size());
    for (std::size_t j = 0; j < rows.size(); ++j) {
        atRaw[j] = static_cast<std::size_t>(std::lower_bound(rawRows.begin(), rawRows.end(), rows[j]) -
                                            rawRows.begin());
        atHistory[j] = static_cast<std::size_t>(
            std::lower_bound(historyRows.begin(), historyRows.end(), rows[j]) - historyRows.begin());
    }
    const auto pick = [&](std::vector<double>& v) {
        std::vector<double> out(rows.size());
        for (std::size_t j = 0; j < rows.size(); ++j) {
            out[j] = v[atRaw[j]];
        }
        v = std::move(out);
    };
    const auto atWanted = [&](const std::vector<double>& history) {
        std::vector<double> out(rows.size());
        for (std::size_t j = 0; j < rows.size(); ++j) {
            out[j] = history[atHistory[j]];
        }
        return out;
    };
    // Before the onset the meter reads without its lag (the mixed outlet at the wanted rows).
    const auto meterReading = [&](const std::vector<double>& mixedHistory, double tau) {
        auto out = atWanted(lagOver(mixedHistory, tau));
        if (tau > 0 && onsetS > in.timeS.front()) {
            const auto mixed = atWanted(mixedHistory);
            for (std::size_t j = 0; j < rows.size(); ++j) {
                if (in.timeS[rows[j]] < onsetS) {
                    out[j] = mixed[j];
                }
            }
        }
        return out;
    };
    for (std::size_t q = 0; q < res.sensitivities.size(); ++q) {
        auto& sens = res.sensitivities[q];
        if (lagged) {
            sens.dXOut = meterReading(sensXMixed[q], tauMeter);
            sens.dTOut = atWanted(sensTMixed[q]);
        } else {
            pick(sens.dXOut);
            pick(sens.dTOut);
        }
        pick(sens.dXHdt);
        pick(sens.dTHdt);
    }
    for (auto* v : {&res.xHdtDb, &res.tHdtK, &res.proxyXHdtDb, &res.proxyTHdtK, &res.proxyXConvDb,
                    &res.proxyTConvK, &res.proxyXMixDb, &res.proxyTMixK}) {
        pick(*v);
    }
    res.xOutDb = meterReading(xOutMixed, tauMeter);
    res.tOutK = atWanted(tOutMixed);
    const auto zeros = std::vector<double>(rows.size(), 0.0);
    if (wants(Param::tau_mix)) {
        const auto s = differenceStep(tauMix, properties::info(Param::tau_mix).lower);
        res.sensitivities.push_back(
            {Param::tau_mix,
             dividedDifference(meterReading(lagOver(xOutHistory, s.up), tauMeter),
                               meterReading(lagOver(xOutHistory, s.down), tauMeter), s.span),
             dividedDifference(atWanted(lagOver(tOutHistory, s.up)), atWanted(lagOver(tOutHistory, s.down)),
                               s.span),
             zeros, zeros});
    }
    if (wants(Param::tau_meter)) {
        const auto s = differenceStep(tauMeter, properties::info(Param::tau_meter).lower);
        res.sensitivities.push_back(
            {Param::tau_meter,
             dividedDifference(meterReading(xOutMixed, s.up), meterReading(xOutMixed, s.down), s.span), zeros,
             zeros, zeros});
    }
    res.rows = rows;
    readThroughMeterOffset(res, offsetPct, wants(Param::X_meter_offset), in.timeS, onsetS);
    return res;
}

} // namespace

Status SimulationOptions::validate() const {
    if (maxStepsPerSection < 1) {
        return Error{ErrorKind::BadInput, "maxStepsPerSection", "must be at least 1"};
    }
    if (!(relTol >= 1e-12 && relTol <= 1e-2)) {
        return Error{ErrorKind::BadInput, "relTol", "must lie in [1e-12, 1e-2]"};
    }
    if (!(meterGridS >= 0 && meterGridS <= 60)) {
        return Error{ErrorKind::BadInput, "meterGridS", "must lie in [0, 60] s"};
    }
    for (Param q : sensitivities) {
        if (properties::info(q).fixed) {
            return Error{ErrorKind::BadInput, std::string(properties::info(q).symbol),
                         "is a physical constant; no sensitivity"};
        }
    }
    if (!sensitivities.empty() && winnower == WinnowerForm::Terminal) {
        return Error{ErrorKind::BadInput, "sensitivities", "need the transient winnower form (Eqs. 18-19)"};
    }
    return {};
}

const std::vector<std::string>& proxyNames() {
    static const std::vector<std::string> names{"X_HDT", "T_HDT", "X_Conv", "T_Conv", "X_mix", "T_mix"};
    return names;
}

double totalDelay(const ParameterSet& p) {
    return p[Param::tau_HDT] + p[Param::tau_conv] + p[Param::dtau_conv] + p[Param::t_W];
}

Expected<SimulationResult> simulateLine(const LineInputs& inputs, const ParameterSet& params,
                                        const SimulationOptions& options,
                                        const std::vector<std::size_t>& rowsIn) {
    const auto start = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (auto st = params.validate(); !st) {
        return st.error();
    }
    if (params[Param::tau_conv] + params[Param::dtau_conv] < 1.0) {
        return Error{ErrorKind::BadInput, "dtau_conv",
                     "the conveyor transport time tau_conv + dtau_conv must be at least 1 s"};
    }
    if (auto st = inputs.validate(); !st) {
        return st.error();
    }
    std::vector<std::size_t> rows = rowsIn;
    if (rows.empty()) {
        rows.resize(inputs.size());
        for (std::size_t i = 0; i < rows.size(); ++i) {
            rows[i] = i;
        }
    }
    for (std::size_t r : rows) {
        if (r >= inputs.size()) {
            return Error{ErrorKind::BadInput, "rows",
                         "row " + std::to_string(r) + " is past the end of the batch"};
        }
    }
    std::vector<Param> odeSens, outputSens, durationSens;
    for (Param q : options.sensitivities) {
        const bool outletOnly = q == Param::tau_mix || q == Param::tau_meter || q == Param::X_meter_offset;
        (outletOnly ? outputSens : properties::info(q).duration ? durationSens : odeSens).push_back(q);
    }
    auto res = simulateMeasured(inputs, params, options, rows, odeSens, outputSens);
    if (!res) {
        return res;
    }
    // Residence times move the windows the parcels see: central differences of whole runs.
    for (Param q : durationSens) {
        SimulationOptions plain = options;
        plain.sensitivities.clear();
        // Solver noise divided by the step would swamp the difference: tighten the tolerance.
        plain.relTol = std::min(options.relTol, 1e-9);
        const auto step = differenceStep(params[q], properties::info(q).lower);
        ParameterSet up = params;
        ParameterSet dn = params;
        up[q] = step.up;
        dn[q] = step.down;
        auto ru = simulateMeasured(inputs, up, plain, rows, {}, {});
        auto rd = simulateMeasured(inputs, dn, plain, rows, {}, {});
        if (!ru || !rd) {
            return ru ? rd.error() : ru.error();
        }
        OutputSensitivity os;
        os.param = q;
        os.dXOut = dividedDifference(ru->xOutDb, rd->xOutDb, step.span);
        os.dTOut = dividedDifference(ru->tOutK, rd->tOutK, step.span);
        os.dXHdt = dividedDifference(ru->xHdtDb, rd->xHdtDb, step.span);
        os.dTHdt = dividedDifference(ru->tHdtK, rd->tHdtK, step.span);
        res->sensitivities.push_back(std::move(os));
    }
    // Report sensitivities in the order they were asked for.
    std::vector<OutputSensitivity> ordered;
    for (Param q : options.sensitivities) {
        for (auto& s : res->sensitivities) {
            if (s.param == q) {
                ordered.push_back(std::move(s));
                break;
            }
        }
    }
    res->sensitivities = std::move(ordered);
    res->elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
}

Expected<std::vector<SimulationResult>> simulateBatches(const std::vector<LineInputs>& batches,
                                                        const ParameterSet& params,
                                                        const SimulationOptions& options, unsigned threads,
                                                        const Progress& progress) {
    const std::size_t nb = batches.size();
    std::vector<std::optional<Expected<SimulationResult>>> results(nb);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex mutex;
    std::condition_variable finished;
    std::size_t done = 0;
    auto work = [&] {
        for (;;) {
            const std::size_t i = next++;
            if (i >= nb || stop) {
                return;
            }
            auto r = simulateLine(batches[i], params, options);
            std::lock_guard lock(mutex);
            results[i].emplace(std::move(r));
            ++done;
            finished.notify_all();
        }
    };
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(nb, 1)));
    std::vector<std::thread> pool;
    for (unsigned t = 0; threads > 1 && t < threads; ++t) {
        pool.emplace_back(work);
    }
    if (threads == 1) {
        for (std::size_t i = 0; i < nb && !stop; ++i) {
            if (reportProgress(progress, "simulate", static_cast<double>(i) / static_cast<double>(nb),
                               std::to_string(i) + "/" + std::to_string(nb) + " batches")) {
                stop = true;
                break;
            }
            results[i].emplace(simulateLine(batches[i], params, options));
        }
    } else {
        // The calling thread reports progress while the pool works.
        std::unique_lock lock(mutex);
        std::size_t reported = 0;
        while (done < nb && !(stop && pool.empty())) {
            finished.wait_for(lock, std::chrono::milliseconds(50),
                              [&] { return done != reported || done == nb; });
            if (done != reported) {
                reported = done;
                lock.unlock();
                if (reportProgress(progress, "simulate",
                                   static_cast<double>(reported) / static_cast<double>(nb),
                                   std::to_string(reported) + "/" + std::to_string(nb) + " batches")) {
                    stop = true;
                }
                lock.lock();
            }
            if (stop) {
                break;
            }
        }
    }
    for (auto& t : pool) {
        t.join();
    }
    if (stop) {
        return cancelledError("simulate");
    }
    std::vector<SimulationResult> out;
    out.reserve(nb);
    for (std::size_t i = 0; i < nb; ++i) {
        if (!results[i] || !*results[i]) {
            Error e =
                results[i] ? results[i]->error() : Error{ErrorKind::Numerical, "simulate", "batch not run"};
            if (e.place.rfind("batch ", 0) != 0) { // LineInputs::validate names the batch itself
                const std::string& id = batches[i].batchId;
                e.place = "batch " + (id.empty() ? std::to_string(i + 1) : id) + ": " + e.place;
            }
            return e;
        }
        out.push_back(std::move(results[i]->value()));
    }
    return out;
}

} // namespace drytwin::physics
