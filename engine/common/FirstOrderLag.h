#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace drytwin {

/// @brief The response of a first-order lag of time constant @p tauS [s] to @p u sampled at the
/// times @p t (sorted, distinct), starting settled at u[0]: exact for an input linear between
/// samples, so that it tends to u − τ du/dt as τ → 0 and stays right on an uneven grid.
/// τ ≤ 0: @p u itself. (physics::firstOrderResponse is the actuator's: a setpoint held between
/// samples.)
inline std::vector<double> lagOfPiecewiseLinear(const std::vector<double>& t, std::vector<double> u,
                                                double tauS) {
    if (tauS <= 0 || u.empty()) {
        return u;
    }
    std::vector<double> out(u.size());
    out[0] = u[0];
    for (std::size_t h = 1; h < out.size(); ++h) {
        const double dt = t[h] - t[h - 1];
        const double a = std::exp(-dt / tauS);
        const double ramp = (u[h] - u[h - 1]) * tauS / dt;
        out[h] = u[h] - ramp + (out[h - 1] - u[h - 1] + ramp) * a;
    }
    return out;
}

} // namespace drytwin
