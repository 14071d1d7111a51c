#pragma once

#include "plant/VirtualPlant.h"

#include <cstddef>
#include <memory>
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
    double xInTruePct = 0; ///< true inlet moisture [% wb] (the plant's feedforward instrument)
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
/// measure(), then apply() the hot-air setpoint chosen from what was measured. The same
/// numerics as runPlant (fixed-step RK4 per parcel, the plant's own mechanism forms), which is
/// built on it. Mechanisms act from their onset in PlantOptions::effectOnsetS.
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
    /// @brief The record so far (inputs up to the last applied sample, outputs up to the last measured).
    const PlantBatch& record() const;
    PlantBatch& record();

private:
    struct Impl;
    explicit PlantLine(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::plant
