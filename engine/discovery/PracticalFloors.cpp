// Practical floors (question 3): below them a cause is not worth a maintenance order, whatever
// its p-value: an offset within the instrument's accuracy, a lag a sound sensor has, an effect on
// the outlet no instrument would notice.
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Units.h"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <utility>

namespace drytwin::discovery::detail {

namespace {

/// Sum of squares of the inlet gauge's deviations from its centred 30 s mean, and their count,
/// for one batch (nothing for a batch of fewer than 60 kept readings).
std::pair<double, std::size_t> inletFastSquares(const data::SiBatch& b) {
    std::vector<double> t, x;
    for (std::size_t k = 0; k < b.rows(); ++k) {
        if (b.keep[k] && std::isfinite(b.xInDb[k])) {
            t.push_back(b.timeS[k]);
            x.push_back(units::dryToWetPct(b.xInDb[k]));
        }
    }
    if (x.size() < 60) {
        return {0.0, 0};
    }
    const auto slow = centredMovingAverage(t, x, 30);
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sum += (x[i] - slow[i]) * (x[i] - slow[i]);
    }
    return {sum, x.size()};
}

/// log of each batch's fast scatter (batches with too few readings left out).
std::vector<double> logScatterPerBatch(const Problem& pr) {
    std::vector<double> out;
    for (const auto& b : *pr.batches) {
        const auto [sum, n] = inletFastSquares(b);
        if (n > 0 && sum > 0) {
            out.push_back(0.5 * std::log(sum / static_cast<double>(n)));
        }
    }
    return out;
}

} // namespace

double inletFastScatterPct(const Problem& pr) {
    double sum = 0;
    std::size_t n = 0;
    for (const auto& b : *pr.batches) {
        const auto [s, m] = inletFastSquares(b);
        sum += s;
        n += m;
    }
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

double inletScatterRiseP(const Problem& pr, const Problem& referencePr) {
    // Welch's t on the batches' log scatter: the batches, not the readings, are the independent
    // units (a gauge's scatter differs from batch to batch with the product and the weather), so
    // the test holds its rate with two to four batches a side where a variance-ratio F test on
    // thousands of autocorrelated readings would flag any difference.
    const auto here = logScatterPerBatch(pr);
    const auto before = logScatterPerBatch(referencePr);
    if (here.size() < 2 || before.size() < 2) {
        return 1.0;
    }
    const auto meanVar = [](const std::vector<double>& v) {
        double m = 0;
        for (double x : v) {
            m += x;
        }
        m /= static_cast<double>(v.size());
        double q = 0;
        for (double x : v) {
            q += (x - m) * (x - m);
        }
        return std::pair{m, q / static_cast<double>(v.size() - 1)};
    };
    const auto [m1, v1] = meanVar(here);
    const auto [m0, v0] = meanVar(before);
    const double a = v1 / static_cast<double>(here.size()), b = v0 / static_cast<double>(before.size());
    const double se = std::sqrt(a + b);
    if (!(se > 0)) {
        return m1 > m0 ? 0.0 : 1.0;
    }
    const double df =
        (a + b) * (a + b) /
        (a * a / static_cast<double>(here.size() - 1) + b * b / static_cast<double>(before.size() - 1));
    const boost::math::students_t t(std::max(1.0, df));
    return boost::math::cdf(boost::math::complement(t, (m1 - m0) / se));
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
