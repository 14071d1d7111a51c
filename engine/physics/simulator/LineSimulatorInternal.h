#pragma once

// What the pieces of the line simulator (physics/LineSimulator.cpp and physics/simulator/) share
// and nobody else needs: the context a section's right-hand side reads, the right-hand sides
// themselves, and the stages simulateLine() calls in turn (inputs as the sensors say, the three
// sections, the outlet as measured), with the finite differences the sensitivities use. Not part
// of the engine's public API.

#include "common/Error.h"
#include "physics/LineInputs.h"
#include "physics/LineSimulator.h"
#include "properties/Properties.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace drytwin::physics::simulator {

using properties::Param;
using properties::ParameterSet;

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

// The right-hand sides of the three sections (physics/simulator/SectionRightHandSides.cpp), in the
// form ParcelRhs::evaluate takes; @p c is a SectionContext.
bool tubeEval(const void* c, double s, std::size_t first, std::size_t count, const double* y, double* ydot);
bool conveyorEval(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                  double* ydot);
bool winnowerEval(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                  double* ydot);
bool winnowerEvalWithMixStates(const void* c, double s, std::size_t first, std::size_t count, const double* y,
                               double* ydot);

/// Core simulation; sensitivities only for rate (non-duration) parameters. Rows flagged in
/// @p outletOnly (same length as @p rows; empty: none) are wanted for the line's outlet alone, as
/// the meter lag's history is: their tube-outlet values (X_HDT, T_HDT and their sensitivities) are
/// NaN, and the tube integrates one parcel for them instead of two.
Expected<SimulationResult> simulateCore(const LineInputs& in, const ParameterSet& params,
                                        const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                        const std::vector<Param>& odeSens,
                                        const std::vector<std::uint8_t>& outletOnly = {});

/// The sensor causes (CONTRACT.md §4): the measured inputs corrected as the parameters say,
/// before the line sees them, from the onset on. Null when every one is 0 (the inputs as measured).
std::optional<LineInputs> correctedInputs(const LineInputs& in, const ParameterSet& p);

/// The outlet as measured: the line's outlet mixing (tau_mix, a first-order lag on X_out and
/// T_out), then the moisture_meter_lag and moisture_meter_offset extensions (first-order lag, then
/// a constant offset in % wb) on X_out, each applied to the prediction and its sensitivities.
/// @p outputSens (tau_mix, tau_meter, X_meter_offset) act on the outlet only: their sensitivities
/// come from this one run's outlet history (differences of the lags, the offset's slope) instead
/// of two more runs of the line each, and carry no solver noise.
Expected<SimulationResult> simulateMeasured(const LineInputs& measured, const ParameterSet& params,
                                            const SimulationOptions& o, const std::vector<std::size_t>& rows,
                                            const std::vector<Param>& odeSens,
                                            const std::vector<Param>& outputSens);

/// The two values of a parameter at @p v a sensitivity's difference is taken between, and their
/// span: central, one-sided at the parameter's lower bound @p lower (a meter lag of 0).
struct DifferenceStep {
    double up, down, span;
};
DifferenceStep differenceStep(double v, double lower);

/// (up − down) / span, element by element.
std::vector<double> dividedDifference(const std::vector<double>& up, const std::vector<double>& down,
                                      double span);

} // namespace drytwin::physics::simulator
