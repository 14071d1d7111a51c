#pragma once

#include "common/Error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::physics {

/// @brief Right-hand side of a run of parcels: ydot = f(s, y) at local time s since section
/// entry, for parcels first … first + count − 1, whose states start at @p y (and rates at
/// @p ydot). One call per solver evaluation lets the section hoist what all parcels share.
/// Returns false when a state is not physical (non-finite), so the solver can retry.
struct ParcelRhs {
    const void* context = nullptr;
    bool (*evaluate)(const void* context, double s, std::size_t first, std::size_t count, const double* y,
                     double* ydot) = nullptr;
    std::size_t parcels = 0;
    int statesPerParcel = 0;
};

/// @brief How a section is integrated.
struct IntegratorSettings {
    /// Fast: all parcels as one system (Adams, fixed-point iteration: the sections are not
    /// stiff), which amortises CVODE's per-step overhead. Reference: each parcel alone with BDF
    /// and a dense Newton solver, used to check the fast path.
    bool reference = false;
    double relTol = 1e-6;
    std::vector<double> absTol; ///< per state of a parcel
    long maxSteps = 50000;
    int maxAdamsOrder = 4;
    /// CVODE's coefficient of the nonlinear convergence test (its default is 0.1). On these
    /// non-stiff sections 0.2 saves a fifth of the right-hand sides; on the demo batch the error
    /// against a relTol 1e-9 run goes from 5e-6 to 9e-6 kg/kg and from 7e-3 to 9e-3 K. At 0.3
    /// the fast path leaves the 5e-3 K band around the reference path that the tests require.
    double nonlinearConvergenceCoefficient = 0.2;
};

/// @brief Forward sensitivities by CVODES (difference-quotient right-hand sides): the solver
/// perturbs params[plist[i]] in place, so the right-hand side must read from that array.
struct SensitivitySpec {
    double* params = nullptr;
    std::vector<int> plist;
    std::vector<double> pbar; ///< typical magnitudes, non-zero
};

/// @brief Counters of the last integration.
struct IntegratorStats {
    long steps = 0;
    long rhsEvaluations = 0;
};

/// @brief Integrates every parcel over [0, duration]. @p y holds parcels × states, in and out;
/// @p yS (one vector like y per sensitivity parameter) holds the initial sensitivities in and
/// the final ones out. Failures come back as Numerical errors naming @p section.
Status integrateParcels(const ParcelRhs& rhs, std::vector<double>& y, double duration,
                        const IntegratorSettings& settings, const SensitivitySpec* sens,
                        std::vector<std::vector<double>>* yS, const std::string& section,
                        IntegratorStats* stats = nullptr);

} // namespace drytwin::physics
