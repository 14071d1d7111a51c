// The distributed virtual plant: the line as the paper's §V lists what its model leaves out.
// Equations beside the model's: docs/plant.md. Written apart from physics/LineSimulator: its
// own state (stocks of dry matter, water and enthalpy per cell, layer and volume), its own
// numerics (explicit conservative finite volumes, a quasi-steady gas march), its own forms of
// every mechanism. Only the local rate laws of a strand in given surroundings (Eqs. 1–14) are
// shared with the model: they are material properties, not the structure being tested.

#include "plant/LineCore.h"

#include "common/Units.h"
#include "physics/SectionRates.h"
#include "properties/Properties.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace drytwin::plant {

using properties::Param;
using properties::ParameterSet;
namespace ph = physics;

namespace {

constexpr double kAirCp = 1006;          // J/(kg·K), dry air
constexpr double kVapourCp = 1880;       // J/(kg·K), water vapour
constexpr double kLatentAtRef = 2.501e6; // J/kg at 0 °C

/// The distributed line's design. The transfer factors and the belt's exposure were set once so
/// that its steady states lie within 0.3 % wb and 2 K of the lumped plant at the demo's operating
/// points (tests/engine/plant: distributedSteadyStatesMatchLumped); nothing here is tuned to
/// what discovery or learning achieve on its data.
struct Design {
    int tubeCells = 16;     ///< tanks in series: residence-time spread σ/τ = 1/√16 = 25 %
    double tubeStepS = 0.1; ///< explicit step of the tube's solids (cell residence ≈ 0.44 s)
    double slipSpeed = 4.0; ///< m/s: strands move at the air speed less this
    double nominalAirSpeed = 16.0;
    double airFlowKgPerS = 18.0;  ///< dry air at 16 m/s (a 1.3 m tube, 0.8 kg/m³ at 170 °C)
    double inletHumidity = 0.040; ///< kg/kg of the hot air (part recirculated)
    /// On h_HDT and k_HDT: the strands see an air that cools and humidifies along the tube, where
    /// the lumped plant keeps it at T_hot and w; these restore the lumped plant's steady states.
    double heatTransferFactor = 1.25;
    double massTransferFactor = 0.85;
    static constexpr int kBeltLayers = 5;
    /// Share of the top layer's exchange with the hall that each layer below gets: moisture and
    /// heat reach the surface through the layers above. Mass-weighted mean 0.30 = β_top.
    std::array<double, kBeltLayers> exposure{1.0, 0.32, 0.11, 0.045, 0.025};
    double layerConductance = 8.0; ///< W/K per kg of dry matter between neighbouring layers
    double beltContact = 1.5;      ///< W/K per kg of the bottom layer to the belt at ambient
    double axialExchange = 0.04;   ///< share exchanged per second with each neighbouring slice
    double winnowerHoldupS = 8.0;  ///< mixing volume's mean residence time
    double flashRate = 2.0e-4;     ///< 1/(K·s): flash evaporation per K of excess over the air
    double winnowerStepS = 0.25;
    double hfFoulingTimeS = 3000; ///< deposits approach their asymptote with this time constant
};

/// Enthalpy of humid air per kg of dry air [J/kg], 0 °C reference.
double airEnthalpy(double tK, double w) {
    const double c = tK - units::kKelvinOffset;
    return kAirCp * c + w * (kLatentAtRef + kVapourCp * c);
}
double airTemperature(double h, double w) {
    return units::kKelvinOffset + (h - w * kLatentAtRef) / (kAirCp + w * kVapourCp);
}

/// Stocks of one volume: dry matter [kg], water [kg], enthalpy C(X)(T − T_ref) [J].
struct Stock {
    double dry = 0, water = 0, enthalpy = 0;
    double x() const { return water / dry; }
};

/// A slice of the belt: what left the tube in one second, in layers of equal mass.
struct Slice {
    double enteredS = 0;
    std::array<Stock, Design::kBeltLayers> layer{};
};

class DistributedLine final : public LineCore {
public:
    DistributedLine(const PlantOptions& options, PlantDisturbances disturbances, double initialSetpointK,
                    PlantRandom& random);
    std::unique_ptr<LineCore> clone(PlantRandom& r) const override {
        auto copy = std::make_unique<DistributedLine>(*this);
        copy->rebind(r);
        return copy;
    }
    PlantSample measure() override;
    void apply(double setpointK) override;
    double hotAirK() const override { return m_tHot; }
    std::optional<LineBalance> balance() const override;

private:
    double heatCapacity(double x) const { return properties::heatCapacityPerDryKg(x, m_p, m_sw); }
    double temperature(const Stock& s) const {
        return m_p[Param::T_ref] + s.enthalpy / (s.dry * heatCapacity(s.x()));
    }
    Stock stockOf(double dry, double x, double tK) const {
        return {dry, dry * x, dry * heatCapacity(x) * (tK - m_p[Param::T_ref])};
    }
    /// Moves the whole line on by one second with the setpoint held; @p frozen keeps every input
    /// at sample 0 (the steady operation before the batch).
    void advance(double setpointK, bool frozen);
    void stepTube(double t, double dt, double hotK);
    void stepBelt(double t);
    void stepWinnower(double t, double dt, const Stock& inflowPerS);

    Design m_d;
    ParameterSet m_p;
    properties::ModelSwitches m_sw;
    double m_tHot = 0; ///< true hot-air temperature (after the actuator's lag)
    std::vector<Stock> m_cells;
    Stock m_tubeOutflow; ///< what left the tube during the current second
    std::deque<Slice> m_belt;
    Stock m_winnower;
    double m_xInFiltered = std::nan(""); // the PI's filtered inlet reading
    bool m_measured = false;
    struct PendingInputs {
        double tHotK = 0, air = 0, feed = 0, xInDb = 0, tInK = 0, tAmbK = 0, rh = 0;
    } m_pending;
    /// Stocks of the three sections: water [kg] and enthalpy [J].
    std::array<std::pair<double, double>, 3> stocks() const;
    LineBalance m_balance;
    std::array<std::pair<double, double>, 3> m_stocksAtStart{};
    bool m_accounting = false; // the balance counts from sample 0, not the warm-up
};

std::array<std::pair<double, double>, 3> DistributedLine::stocks() const {
    std::array<std::pair<double, double>, 3> s{};
    for (const auto& c : m_cells) {
        s[0].first += c.water;
        s[0].second += c.enthalpy;
    }
    for (const auto& slice : m_belt) {
        for (const auto& l : slice.layer) {
            s[1].first += l.water;
            s[1].second += l.enthalpy;
        }
    }
    s[2] = {m_winnower.water, m_winnower.enthalpy};
    return s;
}

std::optional<LineBalance> DistributedLine::balance() const {
    LineBalance b = m_balance;
    const auto now = stocks();
    SectionBalance* sections[3] = {&b.tube, &b.belt, &b.winnower};
    for (std::size_t i = 0; i < 3; ++i) {
        sections[i]->waterStockChangeKg = now[i].first - m_stocksAtStart[i].first;
        sections[i]->energyStockChangeJ = now[i].second - m_stocksAtStart[i].second;
    }
    return b;
}

DistributedLine::DistributedLine(const PlantOptions& options, PlantDisturbances disturbances,
                                 double initialSetpointK, PlantRandom& random)
    : LineCore(options, std::move(disturbances), random) {
    m_p = options.truth;
    m_tHot = initialSetpointK;
    // The tube filled with feed at the first inputs, then the line run at them until every section
    // is steady: the tube (7 s), the belt (its transport time) and the winnower (seconds).
    const double feedDry = dist.feedKgPerS[0] / (1 + dist.xInDb[0]);
    const double tauCell = m_p[Param::tau_HDT] / m_d.tubeCells;
    m_cells.assign(static_cast<std::size_t>(m_d.tubeCells),
                   stockOf(feedDry * tauCell, dist.xInDb[0], dist.tInK[0]));
    m_winnower = stockOf(feedDry * m_d.winnowerHoldupS, dist.xInDb[0], dist.tInK[0]);
    const int warmUp = static_cast<int>(m_p[Param::tau_conv]) + 120;
    for (int s = 0; s < warmUp; ++s) {
        advance(initialSetpointK, true);
    }
    m_balance = {};
    m_stocksAtStart = stocks();
    m_accounting = true;
}

void DistributedLine::stepTube(double t, double dt, double hotK) {
    const double air = seriesAt(dist.airSpeedMPerS, t);
    const double speedRatio = std::max(4.0, air) / m_d.nominalAirSpeed;
    // Strands lag the air by their slip velocity: a faster air carries them through sooner.
    const double tubeTime = m_p[Param::tau_HDT] * (m_d.nominalAirSpeed - m_d.slipSpeed) /
                            (std::max(air, m_d.slipSpeed + 2.0) - m_d.slipSpeed);
    const double tauCell = tubeTime / m_d.tubeCells;
    const double gasCoupling = effectAt(Mechanism::GasPhaseCoupling, t);
    const double gasFlow = m_d.airFlowKgPerS * speedRatio;
    // gas_phase_coupling in this plant: part of the air channels past the strands along the wall,
    // so the air that meets them is less, and it cools and humidifies more.
    const double contactFlow = gasFlow / (1.0 + gasCoupling);
    const double wallNtu = effectAt(Mechanism::TubeWallHeatLoss, t);
    const double fouling = effectAt(Mechanism::HeatTransferFouling, t);
    const double foulingGrowth =
        fouling > 0 ? 1.0 - std::exp(-(t - onsetOf(Mechanism::HeatTransferFouling)) / m_d.hfFoulingTimeS)
                    : 0.0;
    const double fallingRate = effectAt(Mechanism::FallingRateDrying, t);
    const double tAmb = seriesAt(dist.tAmbK, t);
    double gasT = hotK;
    if (o.hiddenAmplitudeK > 0) {
        gasT += o.hiddenAmplitudeK * std::sin(2 * M_PI * t / o.hiddenPeriodS);
    }
    double gasW = m_d.inletHumidity;
    double gasH = airEnthalpy(gasT, gasW);
    const double gasHIn = gasH;
    const double tRef = m_p[Param::T_ref];
    const int n = m_d.tubeCells;
    std::vector<double> heat(static_cast<std::size_t>(n)), evap(static_cast<std::size_t>(n)),
        vapourH(static_cast<std::size_t>(n));
    double wallLossW = 0;
    for (int i = 0; i < n; ++i) {
        auto& c = m_cells[static_cast<std::size_t>(i)];
        const double x = c.x();
        const double tK = temperature(c);
        ph::TubeEnvironment env;
        env.tGasK = gasT;
        env.wGas = gasW;
        // Deposits are thickest at the hot inlet and thin towards the outlet (profile mean 1).
        const double profile = 1.5 - static_cast<double>(i) / (n - 1);
        env.h = m_p[Param::h_HDT] * m_d.heatTransferFactor * std::sqrt(speedRatio) *
                std::max(0.05, 1.0 - fouling * foulingGrowth * profile);
        env.k = m_p[Param::k_HDT] * m_d.massTransferFactor * std::sqrt(speedRatio) * seriesAt(dist.kDrift, t);
        if (fallingRate > 0) {
            // Below X_cr = 0.21 the strand's inside limits drying, linearly down to X_e.
            const double xe = properties::equilibriumMoisture(tK, 1e-6, m_p);
            env.dryingFactor = 1.0 - fallingRate * std::clamp((0.21 - x) / (0.21 - xe), 0.0, 1.0);
        }
        const auto r = ph::tubeRates(x, tK, env, m_p, m_sw);
        const auto iu = static_cast<std::size_t>(i);
        heat[iu] = r.heatIn * c.dry;
        evap[iu] = r.evaporation * c.dry;
        // The water leaves the strand as vapour at the strand's temperature.
        vapourH[iu] = r.vapourEnthalpy + m_p[Param::theta_Cp2] * (tK - tRef);
        gasH += (evap[iu] * vapourH[iu] - heat[iu]) / contactFlow;
        gasW += evap[iu] / contactFlow;
        gasT = airTemperature(gasH, gasW);
        if (wallNtu > 0) {
            // The wall's loss per cell grows towards the outlet, where the lagging is older.
            const double ntu =
                wallNtu / n * std::pow(1.0 / speedRatio, 0.6) * (0.5 + static_cast<double>(i) / (n - 1));
            const double cooled = tAmb + (gasT - tAmb) * std::exp(-ntu);
            const double hAfter = airEnthalpy(cooled, gasW);
            wallLossW += contactFlow * (gasH - hAfter);
            gasH = hAfter;
            gasT = cooled;
        }
    }
    // Solids: conservative upwind fluxes between cells (tanks in series).
    const double feedDry = seriesAt(dist.feedKgPerS, t) / (1 + seriesAt(dist.xInDb, t));
    Stock inflow = stockOf(feedDry, seriesAt(dist.xInDb, t), seriesAt(dist.tInK, t)); // per second
    for (int i = 0; i < n; ++i) {
        auto& c = m_cells[static_cast<std::size_t>(i)];
        const double share = 1.0 / tauCell; // of the cell's content leaving per second
        const Stock outflow{c.dry * share, c.water * share, c.enthalpy * share};
        const auto iu = static_cast<std::size_t>(i);
        c.dry += dt * (inflow.dry - outflow.dry);
        c.water += dt * (inflow.water - outflow.water - evap[iu]);
        c.enthalpy += dt * (inflow.enthalpy - outflow.enthalpy + heat[iu] - evap[iu] * vapourH[iu]);
        inflow = outflow;
    }
    m_tubeOutflow.dry += dt * inflow.dry;
    m_tubeOutflow.water += dt * inflow.water;
    m_tubeOutflow.enthalpy += dt * inflow.enthalpy;
    if (m_accounting) {
        auto& b = m_balance.tube;
        const double feedX = seriesAt(dist.xInDb, t);
        b.waterInKg += dt * feedDry * feedX;
        b.waterOutKg += dt * inflow.water;
        b.waterToAirKg += dt * contactFlow * (gasW - m_d.inletHumidity);
        b.energyInJ += dt * stockOf(feedDry, feedX, seriesAt(dist.tInK, t)).enthalpy;
        b.energyOutJ += dt * inflow.enthalpy;
        // What the air gave up, less what its wall took: the net heat the strands received.
        b.energyFromAirJ += dt * (contactFlow * (gasHIn - gasH) - wallLossW);
        b.wallLossJ += dt * wallLossW;
    }
}

void DistributedLine::stepBelt(double t) {
    const double tAmb = seriesAt(dist.tAmbK, t);
    const double rh = seriesAt(dist.rhAmb, t);
    const double reabsorption = effectAt(Mechanism::AmbientReabsorption, t);
    const double tRef = m_p[Param::T_ref];
    double evaporated = 0;
    double heatIn = 0;
    for (auto& slice : m_belt) {
        std::array<double, Design::kBeltLayers> temp{};
        for (int j = 0; j < Design::kBeltLayers; ++j) {
            temp[static_cast<std::size_t>(j)] = temperature(slice.layer[static_cast<std::size_t>(j)]);
        }
        for (int j = 0; j < Design::kBeltLayers; ++j) {
            const auto ju = static_cast<std::size_t>(j);
            auto& l = slice.layer[ju];
            const double x = l.x();
            ph::AmbientEnvironment env{tAmb, rh, 0.0};
            if (j == 0 && reabsorption > 0) {
                // Humid air loads the surface strands, faster than linearly in RH; the top layer
                // (a fifth of the mass) takes up what the lumped plant spreads over β_top.
                env.extraUptake = 1.5 * reabsorption * 1e-4 * rh * std::exp(3.0 * (rh - 0.5)) *
                                  std::max(0.0, 1.0 - x / 0.35) / m_d.exposure[0];
            }
            const auto r = ph::conveyorRates(x, temp[ju], env, m_p, m_sw);
            const double e = m_d.exposure[ju];
            const double evap = e * r.evaporation * l.dry; // kg/s (negative: uptake)
            double q = e * r.heatIn * l.dry;
            // Heat flows through the layer to its neighbours; the bottom one also to the belt.
            if (j > 0) {
                q += m_d.layerConductance * l.dry * (temp[ju - 1] - temp[ju]);
            }
            if (j + 1 < Design::kBeltLayers) {
                q += m_d.layerConductance * l.dry * (temp[ju + 1] - temp[ju]);
            } else {
                q += m_d.beltContact * l.dry * (tAmb - temp[ju]);
            }
            const double vapourH = r.vapourEnthalpy + m_p[Param::theta_Cp2] * (temp[ju] - tRef);
            l.water -= evap;
            l.enthalpy += q - evap * vapourH;
            evaporated += evap;
            heatIn += q - evap * vapourH;
        }
    }
    // Axial mixing: neighbouring slices exchange material (strands tumble where the belt is fed
    // and at its rollers), layer by layer; a conservative swap of equal masses.
    const double delayError = effectAt(Mechanism::TransportDelayError, t);
    const double exchange = m_d.axialExchange * (1.0 + std::abs(delayError) / 20.0);
    for (std::size_t s = 0; s + 1 < m_belt.size(); ++s) {
        for (std::size_t j = 0; j < Design::kBeltLayers; ++j) {
            Stock& a = m_belt[s].layer[j];
            Stock& b = m_belt[s + 1].layer[j];
            const double m = exchange * std::min(a.dry, b.dry);
            const double dw = m * (b.x() - a.x());
            const double de = m * (b.enthalpy / b.dry - a.enthalpy / a.dry);
            a.water += dw;
            b.water -= dw;
            a.enthalpy += de;
            b.enthalpy -= de;
        }
    }
    if (m_accounting) {
        m_balance.belt.waterToAirKg += evaporated;
        m_balance.belt.energyFromAirJ += heatIn;
    }
}

void DistributedLine::stepWinnower(double t, double dt, const Stock& inflowPerS) {
    const double tAir = seriesAt(dist.tAmbK, t);
    const double rh = seriesAt(dist.rhAmb, t);
    auto& w = m_winnower;
    const double x = w.x();
    const double tK = temperature(w);
    const double xe = properties::equilibriumMoisture(tAir, rh, m_p);
    // Flash evaporation in the turbulent volume: proportional to the excess moisture and to how
    // much warmer the strands are than the air (the model's Eq. 18 decays in time instead).
    const double evap = m_d.flashRate * std::max(0.0, tK - tAir) * std::max(0.0, x - xe) * w.dry;
    const double q = -m_p[Param::h_winnower] * w.dry * (tK - tAir);
    const double aw = properties::waterActivity(tK, x, m_p, m_sw.clampWaterActivity);
    const double vapourH =
        ph::vapourEnthalpy(tK, aw, m_p, m_sw) + m_p[Param::theta_Cp2] * (tK - m_p[Param::T_ref]);
    const double share = 1.0 / m_d.winnowerHoldupS;
    const Stock out{w.dry * share, w.water * share, w.enthalpy * share};
    w.dry += dt * (inflowPerS.dry - out.dry);
    w.water += dt * (inflowPerS.water - out.water - evap);
    w.enthalpy += dt * (inflowPerS.enthalpy - out.enthalpy + q - evap * vapourH);
    if (m_accounting) {
        auto& b = m_balance.winnower;
        b.waterInKg += dt * inflowPerS.water;
        b.waterOutKg += dt * out.water;
        b.waterToAirKg += dt * evap;
        b.energyInJ += dt * inflowPerS.enthalpy;
        b.energyOutJ += dt * out.enthalpy;
        b.energyFromAirJ += dt * (q - evap * vapourH);
    }
}

void DistributedLine::advance(double setpointK, bool frozen) {
    const double t0 = frozen ? 0.0 : static_cast<double>(k);
    // Tube, with the actuator moving the hot air towards the setpoint within the second.
    m_tubeOutflow = {};
    const int tubeSteps = static_cast<int>(std::lround(1.0 / m_d.tubeStepS));
    const double a = std::exp(-m_d.tubeStepS / m_p[Param::tau_act]);
    for (int s = 0; s < tubeSteps; ++s) {
        const double tMid = frozen ? 0.0 : t0 + (s + 0.5) * m_d.tubeStepS;
        const double hotBefore = m_tHot;
        m_tHot = a * m_tHot + (1 - a) * setpointK;
        stepTube(tMid, m_d.tubeStepS, 0.5 * (hotBefore + m_tHot));
    }
    // Belt: the second's outflow of the tube lands as a new slice, in equal layers.
    const double beltT = frozen ? 0.0 : t0 + 0.5;
    stepBelt(beltT);
    if (m_tubeOutflow.dry > 0) {
        Slice slice;
        slice.enteredS = t0 + 1.0;
        for (auto& l : slice.layer) {
            l = {m_tubeOutflow.dry / Design::kBeltLayers, m_tubeOutflow.water / Design::kBeltLayers,
                 m_tubeOutflow.enthalpy / Design::kBeltLayers};
        }
        if (m_accounting) {
            m_balance.belt.waterInKg += m_tubeOutflow.water;
            m_balance.belt.energyInJ += m_tubeOutflow.enthalpy;
        }
        m_belt.push_back(slice);
    }
    // Slices whose transport time is over fall into the winnower; a frozen warm-up counts time by
    // the slices' own ages.
    const double now = frozen ? m_belt.back().enteredS : t0 + 1.0;
    const double transport = m_p[Param::tau_conv] + effectAt(Mechanism::TransportDelayError, t0);
    Stock discharged;
    while (!m_belt.empty() && now - m_belt.front().enteredS >= transport - 1e-9) {
        for (const auto& l : m_belt.front().layer) {
            discharged.dry += l.dry;
            discharged.water += l.water;
            discharged.enthalpy += l.enthalpy;
        }
        m_belt.pop_front();
    }
    if (frozen) {
        for (auto& s : m_belt) {
            s.enteredS -= 1.0; // every slice ages by the second just run
        }
    }
    if (m_accounting) {
        m_balance.belt.waterOutKg += discharged.water;
        m_balance.belt.energyOutJ += discharged.enthalpy;
    }
    const int winnowerSteps = static_cast<int>(std::lround(1.0 / m_d.winnowerStepS));
    for (int s = 0; s < winnowerSteps; ++s) {
        stepWinnower(frozen ? 0.0 : t0 + (s + 0.5) * m_d.winnowerStepS, m_d.winnowerStepS, discharged);
    }
}

PlantSample DistributedLine::measure() {
    const double t = static_cast<double>(k);
    record.timeS[k] = t;
    PlantSample s;
    const Stock& last = m_cells.back();
    const double xHdtTrue = units::dryToWetPct(last.x());
    const double tHdtTrue = temperature(last);
    s.xOutTruePct = units::dryToWetPct(m_winnower.x());
    s.tOutTrueK = temperature(m_winnower);
    s.xInTruePct = units::dryToWetPct(dist.xInDb[k]);
    // The outlet meter: a lag (two stages: sample line and sensor) and an offset that grows with
    // the product's temperature, as in the lumped plant (they are the meter's, not the line's).
    const double xOutAtMeter = outletMeterLagged(s.xOutTruePct, t) + outletMeterOffsetPct(s.tOutTrueK, t);
    s.xOutPct = readSensor(SensorChannel::OutletMoisture, xOutAtMeter);
    s.tOutK = readCelsius(SensorChannel::OutletTemperature, s.tOutTrueK);
    s.xHdtPct = readSensor(SensorChannel::TubeMoisture, xHdtTrue);
    s.tHdtK = readCelsius(SensorChannel::TubeTemperature, tHdtTrue);
    record.xHdtDb.push_back(units::wetPctToDry(s.xHdtPct));
    record.tHdtK.push_back(s.tHdtK);
    record.xOutDb.push_back(units::wetPctToDry(s.xOutPct));
    record.tOutK.push_back(s.tOutK);
    record.xOutTrueDb.push_back(units::wetPctToDry(s.xOutTruePct));
    record.tOutTrueK.push_back(s.tOutTrueK);
    // The inputs are read at the same instant; apply() records them with the setpoint.
    const double xInReadingPct =
        readSensor(SensorChannel::InletMoisture, s.xInTruePct + inletSensorOffsetPct(s.xInTruePct, t), 0,
                   effectAt(Mechanism::InletMoistureSensorNoise, t));
    m_pending.tHotK = readCelsius(SensorChannel::HotAir, m_tHot, effectAt(Mechanism::HotAirSensorLag, t));
    m_pending.air = readSensor(SensorChannel::AirSpeed, dist.airSpeedMPerS[k]);
    m_pending.feed = units::kgPerHourToKgPerS(
        readSensor(SensorChannel::Feed, units::kgPerSToKgPerHour(dist.feedKgPerS[k])));
    m_pending.xInDb = units::wetPctToDry(xInReadingPct);
    m_pending.tInK = readCelsius(SensorChannel::InletTemperature, dist.tInK[k]);
    m_pending.tAmbK = readCelsius(SensorChannel::AmbientTemperature, dist.tAmbK[k]);
    m_pending.rh =
        readSensor(SensorChannel::AmbientHumidity, units::fractionToPercent(dist.rhAmb[k])) / 100.0;
    // The plant's feedforward sees the gauge through a 10 s filter, holding it over dropouts.
    const double gauge =
        std::isnan(xInReadingPct) ? sensors[SensorChannel::InletMoisture].lastGood() : xInReadingPct;
    m_xInFiltered =
        std::isnan(m_xInFiltered) ? gauge : m_xInFiltered + (gauge - m_xInFiltered) * (1 - std::exp(-0.1));
    s.xInForControlPct = m_xInFiltered;
    if (std::isnan(s.xOutPct)) {
        s.xOutValid = false;
        s.xOutPct = sensors[SensorChannel::OutletMoisture].lastGood();
    }
    m_measured = true;
    return s;
}

void DistributedLine::apply(double setpointK) {
    if (!m_measured) {
        measure();
    }
    record.tHotSpK.push_back(setpointK);
    record.tHotK.push_back(m_pending.tHotK);
    record.airSpeedMPerS.push_back(m_pending.air);
    record.feedKgPerS.push_back(m_pending.feed);
    record.xInDb.push_back(m_pending.xInDb);
    record.tInK.push_back(m_pending.tInK);
    record.tAmbK.push_back(m_pending.tAmbK);
    record.rhAmb.push_back(m_pending.rh);
    advance(setpointK, false);
    m_measured = false;
    ++k;
}

} // namespace

std::unique_ptr<LineCore> makeDistributedLine(const PlantOptions& options, PlantDisturbances disturbances,
                                              double initialSetpointK, PlantRandom& random) {
    return std::make_unique<DistributedLine>(options, std::move(disturbances), initialSetpointK, random);
}

} // namespace drytwin::plant
