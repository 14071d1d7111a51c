// The line simulator's entry (physics/LineSimulator.h): what a simulation request must satisfy
// (the options, the parameters, the inputs, the rows), how the sensitivities asked for are shared
// out (the solver's own for rate parameters, the outlet's history for the outlet-only ones, whole
// runs for residence times), and the small facts about the line (proxy names, total delay). The
// stages it calls live in physics/simulator/: SensorCorrections.cpp (the inputs as the sensors
// say), SectionChain.cpp and SectionRightHandSides.cpp (the three sections and the solver),
// MeasuredOutlet.cpp (the outlet as the meter reads it), SimulateBatches.cpp (many batches on
// worker threads).

#include "physics/LineSimulator.h"

#include "physics/simulator/LineSimulatorInternal.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace drytwin::physics {

using properties::Param;
using properties::ParameterSet;
using simulator::differenceStep;
using simulator::dividedDifference;
using simulator::simulateMeasured;

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

} // namespace drytwin::physics
