#pragma once

#include "plant/VirtualPlant.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace drytwin::plant {

/// @brief The true disturbance series of one run, 1 s apart (SI units, dry basis). They do not
/// depend on the controller, so they are generated ahead.
struct PlantDisturbances {
    std::vector<double> feedKgPerS, xInDb, tInK, tAmbK, rhAmb, airSpeedMPerS;
    std::vector<double> kDrift; ///< factor on k_HDT (1: no unmeasured drift)
    std::size_t size() const { return feedKgPerS.size(); }
};

/// @brief The plant's own random disturbances of one batch (feed steps, inlet-moisture swings,
/// ambient by season and hour, unmeasured drift), drawn from @p rng.
PlantDisturbances randomDisturbances(const PlantOptions& options, std::mt19937_64& rng);

/// @brief The plant's randomness: one generator and its unit normal, shared by the batches of a
/// run so that a seed gives the same data whether batches are run alone or in sequence.
struct PlantRandom {
    explicit PlantRandom(unsigned seed) : engine(seed) {}
    std::mt19937_64 engine;
    std::normal_distribution<double> unitNormal{0.0, 1.0};
};

/// @brief What the plant's instruments show at one sample, and the truth behind it.
struct PlantSample {
    double xOutPct = 0; ///< measured outlet moisture [% wb]
    double tOutK = 0;   ///< measured outlet temperature
    double xHdtPct = 0; ///< measured tube-outlet moisture [% wb]
    double tHdtK = 0;
    double xOutTruePct = 0; ///< the product's true outlet moisture [% wb] (for closed-loop metrics)
    double tOutTrueK = 0;
    double xInTruePct = 0; ///< true inlet moisture [% wb]
    /// Inlet moisture the plant's own controller feeds forward [% wb]: the lumped plant's ideal
    /// feedforward instrument (the truth); on the distributed plant the inlet NIR gauge's reading,
    /// filtered over 10 s as a DCS does.
    double xInForControlPct = 0;
    /// False while the outlet moisture transmitter drops out; xOutPct then holds its last good
    /// reading, as a DCS shows a value of bad quality.
    bool xOutValid = true;
};

/// @brief The plant's own moisture controller: PI on the measured outlet moisture with the
/// inlet-moisture feedforward tobacco dryers commonly have, moving the hot-air setpoint within
/// [140, 200] °C (anti-windup by clamping). Tuned by SIMC for ≈ 80 s dead time and a 20 s
/// actuator lag (gain ≈ −0.06 %/K).
class PlantPiController {
public:
    static constexpr double kLowC = 140;
    static constexpr double kHighC = 200;
    /// @brief The setpoint for the next sample [K].
    double next(double xOutMeasuredPct, double xInPct, double targetPct);
    /// @brief Sets the integral so that the next call returns @p setpointK for the same
    /// readings: a bumpless hand-over when the loop takes over from another controller.
    void track(double setpointK, double xOutMeasuredPct, double xInPct, double targetPct);

private:
    double m_integral = 0;
};

/// @brief The virtual plant as a line that a controller drives one sample (1 s) at a time:
/// measure(), then apply() the hot-air setpoint chosen from what was measured. runPlant is
/// built on it. PlantOptions::plant chooses the lumped line (fixed-step RK4 per parcel) or the
/// distributed one (cells along the tube, a layered belt, a mixed winnower; docs/plant.md).
/// Mechanisms act from their onset in PlantOptions::effectOnsetS.
/// @brief Water and energy that crossed one section's boundary since sample 0 (distributed
/// line only), to check that its numerics conserve what they move.
struct SectionBalance {
    double waterInKg = 0, waterOutKg = 0, waterToAirKg = 0, waterStockChangeKg = 0;
    /// Enthalpies relative to liquid water and dry matter at T_ref; energyFromAirJ is the net heat
    /// the material took from the air around it (less the vapour's enthalpy it gave back).
    double energyInJ = 0, energyOutJ = 0, energyFromAirJ = 0, energyStockChangeJ = 0;
    double wallLossJ = 0; ///< heat the tube's air lost to its wall (not in the material's balance)
    /// (in − out − to the air − stock change) / in.
    double waterImbalance() const {
        return (waterInKg - waterOutKg - waterToAirKg - waterStockChangeKg) / waterInKg;
    }
    /// (in + from the air − out − stock change) / (in + |from the air|).
    double energyImbalance() const;
};
struct LineBalance {
    SectionBalance tube, belt, winnower;
};

class LineCore;

class PlantLine {
public:
    /// @brief A line about to start at sample 0 having run steadily at the first disturbances
    /// and @p initialSetpointK. Instrument noise is drawn from @p random, which must outlive the line.
    PlantLine(const PlantOptions& options, PlantDisturbances disturbances, double initialSetpointK,
              PlantRandom& random);
    ~PlantLine();
    PlantLine(PlantLine&&) noexcept;
    PlantLine& operator=(PlantLine&&) = delete;

    /// @brief The instruments at the current sample (call once per sample, before apply()).
    PlantSample measure();
    /// @brief Sets the hot-air setpoint for the current sample, records the sample's measured
    /// inputs (with their instruments' noise) and moves on to the next sample.
    void apply(double setpointK);
    std::size_t sample() const;
    std::size_t size() const;
    /// @brief True hot-air temperature at the current sample [K].
    double hotAirK() const;
    /// @brief A full copy of the line's state (a snapshot), drawing its noise from @p random,
    /// which the caller copies alongside and which must outlive the copy.
    PlantLine clone(PlantRandom& random) const;
    /// @brief Lets a mechanism act from @p onsetS [s of the line's time, not before now] at
    /// @p strength (in its unit, within its range). A mechanism already acting cannot be changed.
    Status setEffect(Mechanism m, double strength, double onsetS);
    /// @brief The strength of a mechanism at a time of the line (0 before its onset).
    double effectAt(Mechanism m, double timeS) const;
    /// @brief The water and energy balances since sample 0; empty for the lumped line, whose
    /// parcels are integrated one by one and hold no stocks.
    std::optional<LineBalance> balance() const;
    /// @brief The line's transmitters (their fault counts); idle unless the sensors are realistic.
    const SensorBank& sensors() const;
    /// @brief The record so far (inputs up to the last applied sample, outputs up to the last measured).
    const PlantBatch& record() const;
    PlantBatch& record();

private:
    explicit PlantLine(std::unique_ptr<LineCore> core);
    std::unique_ptr<LineCore> m_core;
};

} // namespace drytwin::plant
