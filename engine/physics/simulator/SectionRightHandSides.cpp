// The right-hand sides the solver integrates, one per section: the drying tube with the
// mechanism extensions' simple forms (Eqs. 9–12), the conveyor's top layer (Eqs. 13–14) and the
// winnower (Eqs. 18–19), each run over the parcels four or two at a time where the target packs
// four (AVX2) or two doubles. The rates themselves are physics/SectionRates.h's templates; this file says
// where each parcel is in the inputs and what it sees there. The hot loop of every simulation: it stays in
// one translation unit with the templates it inlines (and physics/*/*.cpp keep -O3).

#include "physics/SectionRates.h"
#include "physics/simulator/LineSimulatorInternal.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace drytwin::physics::simulator {

using properties::Pack2;
using properties::Pack4;

namespace {

/// Most lanes one evaluation packs (the per-lane scratch arrays' size).
constexpr int kMaxLanes = 4;

/// The parcels one evaluation of the rates works on: one (T = double), two (T = Pack2) or four
/// (T = Pack4) consecutive ones, one per lane, with their solver states.
template <class T> struct Lanes {
    static constexpr int width = std::is_same_v<T, double> ? 1 : std::is_same_v<T, Pack2> ? 2 : 4;
    std::size_t parcel = 0; ///< the first lane's parcel
    const double* y = nullptr;
    int statesPerParcel = 2;
    /// Packs one value per lane.
    static T load(const double* v) {
        if constexpr (width == 1) {
            return v[0];
        } else if constexpr (width == 2) {
            return T(v[0], v[1]);
        } else {
            return T(v[0], v[1], v[2], v[3]);
        }
    }
    /// State @p m of every lane.
    T state(int m) const {
        double v[kMaxLanes] = {};
        for (int lane = 0; lane < width; ++lane) {
            v[lane] = y[lane * statesPerParcel + m];
        }
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
inline double laneOf(const Pack4& v, int lane) {
    return v[lane];
}

/// Runs @p rates over a run of parcels, four or two at a time where the target has Pack4 or Pack2. The
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
#if DRYTWIN_HAVE_PACK4
    for (; k + 4 <= count; k += 4) {
        store(rates(ctx, p, sw, Lanes<Pack4>{first + k, y + k * States, States}), k, 4);
    }
#endif
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

/// The air around every lane's parcel, one input look-up per parcel for all series.
template <class T> AmbientEnvironmentT<T> ambientAt(const SectionContext& x, const Lanes<T>& l, double s) {
    double tAir[kMaxLanes] = {};
    double rh[kMaxLanes] = {};
    double xe[kMaxLanes] = {};
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

} // namespace

bool tubeEval(const void* c, double s, std::size_t first, std::size_t count, const double* y, double* ydot) {
    return forParcels<2>(
        c, first, count, y, ydot,
        [s](const SectionContext& x, const ParameterSet& p, const properties::ModelSwitches& sw,
            const auto& l) {
            using T = std::decay_t<decltype(l.state(0))>;
            const double wall = p[Param::theta_wall];
            const double tubeResidenceS = std::max(p[Param::tau_HDT], 1e-6);
            const double gasCoupling = p[Param::theta_gas];
            const double fouling = p[Param::theta_foul];
            const double falling = p[Param::theta_fall];
            double gas[kMaxLanes] = {};
            double hours[kMaxLanes] = {};      // since the batch started
            double gasCooling[kMaxLanes] = {}; // K per kg/kg evaporated
            double gasLoad[kMaxLanes] = {};    // kg dry product per kg of air
            double xEntry[kMaxLanes] = {};
            double tEntry[kMaxLanes] = {};
            double fallingLane[kMaxLanes] = {};
            const double onset = x.in->onsetS(p[Param::t_onset]);
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
                    // The gas loses heat to the wall as it passes, so it approaches ambient
                    // exponentially along the tube: θ is the wall's number of transfer units over
                    // the whole tube (the mean loss is about θ/2 of the excess over ambient).
                    // Constant along the tube (T_hot − θ (T_hot − T_amb), the form until
                    // 2026-11-27), it matched the line's wall loss less well than the gas
                    // coupling, whose cooling also grows as the parcels dry, and a wall loss of
                    // 0.15 was named as gas coupling alone (seeds 102, 322).
                    const double along = std::clamp(s / tubeResidenceS, 0.0, 1.0);
                    const double ambient = where.of(x.in->tAmbK);
                    gas[lane] = ambient + (tHot - ambient) * std::exp(-wall * along);
                }
                if (fouling != 0) {
                    hours[lane] = (sinceStart - onset) / 3600.0;
                }
                if (gasCoupling != 0) { // conditions at the parcel's entry
                    const SamplePoint in0 = x.locate(parcel, 0.0);
                    xEntry[lane] = in0.of(x.in->xInDb);
                    tEntry[lane] = in0.of(x.in->tInK);
                    const double dryFeed = in0.of(x.in->feedKgPerS) / (1 + xEntry[lane]);
                    const double air = std::max(1.0, in0.of(x.in->airSpeedMPerS));
                    gasLoad[lane] = dryFeed / (kModelAirMassPerSpeed * air);
                    gasCooling[lane] = kModelLatentHeat * gasLoad[lane] / kModelAirHeatCapacity;
                }
            }
            TubeEnvironmentT<T> env;
            env.tGasK = l.load(gas);
            if (gasCoupling != 0) { // gas_phase_coupling, simple form
                // The air gives up the heat the parcels took so far: the latent heat of what they
                // evaporated and the sensible heat that warmed them from their entry temperature
                // (until 2026-11-27 the latent part alone; the warming, largest near the inlet,
                // was then taken up by a second cause, a wall loss or a falling rate).
                const T sensible = properties::generic::heatCapacityPerDryKg(l.state(0), p, sw) *
                                   (l.state(1) - l.load(tEntry)) / kModelLatentHeat;
                env.tGasK =
                    env.tGasK - gasCoupling * l.load(gasCooling) * (l.load(xEntry) - l.state(0) + sensible);
            }
            env.wGas = properties::math::constant<T>(p[Param::w]);
            if (gasCoupling != 0) {
                // The same balance's vapour side: the air takes up what the parcels evaporated.
                // Both plants couple both balances; with the cooling alone (the form until
                // 2026-11-27) a wall loss fitted a weaker coupling better than the coupling did.
                env.wGas = env.wGas + gasCoupling * l.load(gasLoad) *
                                          properties::math::maxOf(T(l.load(xEntry) - l.state(0)), 0.0);
            }
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
                                 const double onset = x.in->onsetS(p[Param::t_onset]);
                                 double active[kMaxLanes] = {};
                                 for (int lane = 0; lane < l.width; ++lane) {
                                     const std::size_t parcel = l.parcel + static_cast<std::size_t>(lane);
                                     active[lane] = onset <= 0 || (*x.entry)[parcel] + s - x.t0 >= onset;
                                 }
                                 env.extraUptake = reabsorption * 1e-4 *
                                                   generic::reabsorptionDrive(env.rh, p) * l.load(active);
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

} // namespace drytwin::physics::simulator
