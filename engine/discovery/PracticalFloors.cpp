// Practical floors (question 3): below them a cause is not worth a maintenance order, whatever
// its p-value: an offset within the instrument's accuracy, a lag a sound sensor has, an effect on
// the outlet no instrument would notice.
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Units.h"

#include <cmath>

namespace drytwin::discovery::detail {

double inletFastScatterPct(const Problem& pr) {
    double sum = 0;
    std::size_t n = 0;
    for (const auto& b : *pr.batches) {
        std::vector<double> t, x;
        for (std::size_t k = 0; k < b.rows(); ++k) {
            if (b.keep[k] && std::isfinite(b.xInDb[k])) {
                t.push_back(b.timeS[k]);
                x.push_back(units::dryToWetPct(b.xInDb[k]));
            }
        }
        if (x.size() < 60) {
            continue;
        }
        const auto slow = centredMovingAverage(t, x, 30);
        for (std::size_t i = 0; i < x.size(); ++i) {
            sum += (x[i] - slow[i]) * (x[i] - slow[i]);
            ++n;
        }
    }
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

bool hasOwnFloor(Param p) {
    return p == Param::tau_meter || p == Param::X_meter_offset || p == Param::X_in_offset ||
           p == Param::tau_hot_sensor || p == Param::phi_X_in_scatter || p == Param::dtau_conv ||
           p == Param::theta_foul;
}

std::string belowFloor(const Problem& pr, Param p, double value, double meanBatchHours, const HeldOut& before,
                       const HeldOut& after) {
    const auto& f = pr.options.floors;
    const double twoSteps = 2 * pr.samplingStepS;
    switch (p) {
    case Param::tau_meter:
        if (value < twoSteps) {
            return format("a meter lag of %.2g s is below two sampling steps (%.2g s)", value, twoSteps);
        }
        break;
    case Param::X_meter_offset:
        if (std::abs(value) < f.outletMeterAccuracyPct) {
            return format("an outlet-meter offset of %.2g %% wb is within the meter's accuracy (%.2g %% wb)",
                          value, f.outletMeterAccuracyPct);
        }
        break;
    case Param::X_in_offset:
        if (std::abs(value) < f.inletGaugeAccuracyPct) {
            return format("an inlet-gauge offset of %.2g %% wb is within the gauge's accuracy (%.2g %% wb)",
                          value, f.inletGaugeAccuracyPct);
        }
        break;
    case Param::tau_hot_sensor:
        if (value < std::max(twoSteps, f.hotAirSensorLagS)) {
            return format("a hot-air sensor time constant of %.2g s is what a sound thermocouple has (up to "
                          "%.2g s)",
                          value, std::max(twoSteps, f.hotAirSensorLagS));
        }
        break;
    case Param::phi_X_in_scatter: {
        const double scatter = inletFastScatterPct(pr);
        if (value < 0.2 || scatter < f.inletGaugeScatterPct) {
            return format("the inlet gauge's fast scatter (%.2g %% wb, 1σ about its 30 s mean; %.0f %% of it "
                          "scatter) is within what a sound gauge shows (%.2g %% wb)",
                          scatter, 100 * value, f.inletGaugeScatterPct);
        }
        break;
    }
    case Param::dtau_conv:
        if (std::abs(value) < std::max(twoSteps, f.transportTimeS)) {
            return format("a transport-time error of %.2g s is below %.2g s", value,
                          std::max(twoSteps, f.transportTimeS));
        }
        break;
    case Param::theta_foul:
        if (value * meanBatchHours < f.foulingShare) {
            return format("fouling that costs %.2g %% of h_HDT over a batch is below %.2g %%",
                          100 * value * meanBatchHours, 100 * f.foulingShare);
        }
        break;
    default:
        break;
    }
    if (hasOwnFloor(p)) {
        return {};
    }
    // The others: the cause itself (the fit with it against the same fit without it) must move
    // what is measured by more than an instrument would notice.
    double dx = 0, dt = 0;
    for (std::size_t i = 0; i < before.predX.size() && i < after.predX.size(); ++i) {
        dx += (after.predX[i] - before.predX[i]) * (after.predX[i] - before.predX[i]);
    }
    for (std::size_t i = 0; i < before.predT.size() && i < after.predT.size(); ++i) {
        dt += (after.predT[i] - before.predT[i]) * (after.predT[i] - before.predT[i]);
    }
    dx = before.predX.empty() ? 0 : std::sqrt(dx / static_cast<double>(before.predX.size()));
    dt = before.predT.empty() ? 0 : std::sqrt(dt / static_cast<double>(before.predT.size()));
    if (dx < f.moistureEffectPct && dt < f.temperatureEffectK) {
        return format(
            "it moves the predicted outlet by %.2g %% wb and %.2g K (rms), below %.2g %% wb and %.2g K", dx,
            dt, f.moistureEffectPct, f.temperatureEffectK);
    }
    return {};
}

} // namespace drytwin::discovery::detail
