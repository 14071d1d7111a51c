// Question 3, its second half: is a cause that predicts better also specific? Per-part
// estimates, transfer between operating regions, the line's own dynamics against a meter's lag,
// onsets, and practical floors in physical units.
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Units.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace drytwin::discovery::detail {

namespace {

/// Onset search: the likelihood-ratio (in units of the residual's long-run variance) an onset
/// must reach over "from the start". A searched break point needs far more than χ²(1)'s 3.84
/// (Andrews' sup-LR critical values are 8-10 at 5 %); 15 also covers the misfit of a model that
/// is wrong everywhere a little.
constexpr double kOnsetLikelihoodRatio = 15;
constexpr double kProfileInterval = 3.84; ///< χ²(1) at 95 %: the onset's profile interval

/// The part of each stack entry: its batch when there are three or more batches, else a third
/// of its batch's training span (a single recording still shows whether a cause holds throughout).
std::vector<int> partOfEntries(const Stack& st, int batches, std::vector<std::string>& names,
                               const std::vector<data::SiBatch>& data) {
    std::vector<int> part(st.batch.size());
    std::vector<double> span(static_cast<std::size_t>(batches), 0.0);
    for (std::size_t i = 0; i < st.batch.size(); ++i) {
        auto& s = span[static_cast<std::size_t>(st.batch[i])];
        s = std::max(s, st.timeS[i]);
    }
    int used = 0;
    for (double s : span) {
        used += s > 0;
    }
    const bool thirds = used < 3;
    names.clear();
    std::map<int, int> index;
    for (std::size_t i = 0; i < st.batch.size(); ++i) {
        const int b = st.batch[i];
        int key = b;
        if (thirds) {
            const double s = span[static_cast<std::size_t>(b)];
            const int third = s > 0 ? std::min(2, static_cast<int>(3 * st.timeS[i] / s)) : 0;
            key = 3 * b + third;
        }
        auto [it, fresh] = index.emplace(key, static_cast<int>(names.size()));
        if (fresh) {
            const std::string& id = data[static_cast<std::size_t>(b)].id;
            names.push_back(thirds ? id + ", part " + std::to_string(key % 3 + 1) + "/3" : id);
        }
        part[i] = it->second;
    }
    return part;
}

/// HAC variance of Σ u over the entries of one part (per-row sums, the part's rows in order).
double partVariance(const Stack& st, const Eigen::VectorXd& u, const std::vector<int>& part, int which) {
    std::vector<std::vector<double>> series(1);
    int lastRow = -1, lastBatch = -1;
    for (std::size_t i = 0; i < part.size(); ++i) {
        if (part[i] != which) {
            continue;
        }
        if (st.row[i] != lastRow || st.batch[i] != lastBatch) {
            series.back().push_back(0.0);
            lastRow = st.row[i];
            lastBatch = st.batch[i];
        }
        series.back().back() += u(static_cast<Eigen::Index>(i));
    }
    return hacVarianceOfSum(series, false);
}

} // namespace

Consistency consistencyAt(const Problem& pr, const Stack& atFit, const std::vector<int>& nuisance, int cand,
                          double pooled, double tolerance) {
    Consistency out;
    const Eigen::VectorXd sc = projectedColumn(atFit, nuisance, cand);
    std::vector<std::string> names;
    const auto part = partOfEntries(atFit, static_cast<int>(pr.batches->size()), names, *pr.batches);
    const Eigen::VectorXd u = sc.cwiseProduct(atFit.r);
    int strays = 0, informed = 0;
    for (int p = 0; p < static_cast<int>(names.size()); ++p) {
        double info = 0, score = 0;
        for (std::size_t i = 0; i < part.size(); ++i) {
            if (part[i] == p) {
                info += sc(static_cast<Eigen::Index>(i)) * sc(static_cast<Eigen::Index>(i));
                score += u(static_cast<Eigen::Index>(i));
            }
        }
        if (!(info > 0)) {
            continue;
        }
        PartEstimate e;
        e.part = names[static_cast<std::size_t>(p)];
        e.value = pooled + score / info; // one Gauss-Newton step from the pooled fit, this part alone
        e.se = std::sqrt(std::max(0.0, partVariance(atFit, u, part, p))) / info;
        out.parts.push_back(e);
        ++informed;
        const bool opposite = e.value * pooled < 0 && std::abs(e.value) > 1.96 * e.se;
        const bool far = std::abs(e.value - pooled) > 1.96 * e.se + tolerance * std::abs(pooled);
        strays += opposite || far;
        out.opposite = out.opposite || opposite;
    }
    // One part in four may stray (a batch with a trouble of its own); a significantly opposite
    // sign anywhere is not the same cause.
    out.consistent = !out.opposite && strays <= informed / 4;
    out.strays = strays;
    return out;
}

Transfer transferBetweenRegions(const Problem& pr, const Stack& atStart, const std::vector<int>& nuisance,
                                int cand) {
    Transfer out;
    std::vector<std::string> names;
    const auto part = partOfEntries(atStart, static_cast<int>(pr.batches->size()), names, *pr.batches);
    const auto parts = static_cast<int>(names.size());
    if (parts < 2) {
        return out;
    }
    // The operating region of each part: its mean hot-air temperature.
    std::vector<double> hot(static_cast<std::size_t>(parts), 0.0),
        count(static_cast<std::size_t>(parts), 0.0);
    for (std::size_t i = 0; i < part.size(); ++i) {
        const auto& b = (*pr.batches)[static_cast<std::size_t>(atStart.batch[i])];
        const std::size_t k =
            pr.subset[static_cast<std::size_t>(atStart.batch[i])][static_cast<std::size_t>(atStart.row[i])];
        hot[static_cast<std::size_t>(part[i])] += b.tHotK[k];
        count[static_cast<std::size_t>(part[i])] += 1;
    }
    for (int p = 0; p < parts; ++p) {
        hot[static_cast<std::size_t>(p)] /= std::max(1.0, count[static_cast<std::size_t>(p)]);
    }
    std::vector<double> sorted = hot;
    std::sort(sorted.begin(), sorted.end());
    const double median = 0.5 * (sorted[static_cast<std::size_t>((parts - 1) / 2)] +
                                 sorted[static_cast<std::size_t>(parts / 2)]);
    // Regions must differ by a couple of kelvins, else "cooler" and "warmer" are one region.
    if (sorted.back() - sorted.front() < 2.0) {
        return out;
    }
    const Eigen::VectorXd sc = projectedColumn(atStart, nuisance, cand);
    double infoCool = 0, scoreCool = 0, infoWarm = 0, scoreWarm = 0, lossWarm = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        const auto ii = static_cast<Eigen::Index>(i);
        if (hot[static_cast<std::size_t>(part[i])] <= median) {
            infoCool += sc(ii) * sc(ii);
            scoreCool += sc(ii) * atStart.r(ii);
        } else {
            infoWarm += sc(ii) * sc(ii);
            scoreWarm += sc(ii) * atStart.r(ii);
            lossWarm += atStart.r(ii) * atStart.r(ii);
        }
    }
    if (!(infoCool > 0 && infoWarm > 0 && lossWarm > 0)) {
        return out;
    }
    const double cool = scoreCool / infoCool; // fitted on the cooler half (one step from 0)
    out.checked = true;
    out.reduction = (2 * cool * scoreWarm - cool * cool * infoWarm) / lossWarm;
    return out;
}

ChannelLag lagOnChannel(const Problem& pr, const std::vector<physics::SimulationResult>& sims, int channel) {
    ChannelLag out;
    const auto& batches = *pr.batches;
    // Over a window of 30 s: the sample-to-sample scatter of the inputs passes through the
    // simulation into its rate of change but not into the measured error, and would shrink the
    // estimate towards 0; a lag of tens of seconds shows over tens of seconds.
    constexpr double kWindowS = 30;
    std::vector<std::vector<double>> scoreSeries;
    std::vector<double> g, e;
    std::vector<std::size_t> batchOf;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const auto& bt = batches[b];
        std::vector<double> t, obs, pred;
        for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
            double o = 0, p = 0, f = 1;
            if (channelAt(bt, sims[b], k, k, channel, o, p, f)) {
                t.push_back(bt.timeS[k]);
                obs.push_back(o);
                pred.push_back(p);
            }
        }
        if (t.size() < 120) {
            continue;
        }
        std::vector<double> err(t.size());
        for (std::size_t i = 0; i < t.size(); ++i) {
            err[i] = obs[i] - pred[i];
        }
        const auto smoothErr = centredMovingAverage(t, err, kWindowS);
        std::vector<double> gb, eb;
        std::size_t lo = 0, hi = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
            while (t[lo] < t[i] - kWindowS / 2) {
                ++lo;
            }
            hi = std::max(hi, i);
            while (hi + 1 < t.size() && t[hi + 1] <= t[i] + kWindowS / 2) {
                ++hi;
            }
            if (t[hi] - t[lo] < 0.8 * kWindowS) {
                continue; // at the edges and across gaps
            }
            // A first-order lag τ on the reading: measured ≈ simulated − τ d(simulated)/dt.
            gb.push_back(-(pred[hi] - pred[lo]) / (t[hi] - t[lo]));
            eb.push_back(smoothErr[i]);
        }
        if (eb.size() < 60) {
            continue;
        }
        const double mean = diagnostics::mean(eb); // a bias is not a lag
        for (double& v : eb) {
            v -= mean;
        }
        g.insert(g.end(), gb.begin(), gb.end());
        e.insert(e.end(), eb.begin(), eb.end());
        batchOf.insert(batchOf.end(), eb.size(), b);
    }
    double gg = 0, ge = 0, ee = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
        gg += g[i] * g[i];
        ge += g[i] * e[i];
        ee += e[i] * e[i];
    }
    if (!(gg > 0 && ee > 0)) {
        return out;
    }
    out.tauS = ge / gg;
    std::size_t last = SIZE_MAX;
    for (std::size_t i = 0; i < g.size(); ++i) {
        if (batchOf[i] != last) {
            scoreSeries.emplace_back();
            last = batchOf[i];
        }
        scoreSeries.back().push_back(g[i] * (e[i] - out.tauS * g[i]));
    }
    out.se = std::sqrt(std::max(0.0, hacVarianceOfSum(scoreSeries, false))) / gg;
    out.z = out.se > 0 ? out.tauS / out.se : 0;
    out.share = out.tauS * out.tauS * gg / ee;
    out.ok = true;
    return out;
}

std::optional<Signature> dynamicsSignature(const Problem& pr,
                                           const std::vector<physics::SimulationResult>& sims, int channel) {
    const ChannelLag lag = lagOnChannel(pr, sims, channel);
    if (!lag.ok || std::abs(lag.z) <= 6 || std::abs(lag.tauS) <= 2 * pr.samplingStepS || lag.share < 0.1) {
        return std::nullopt;
    }
    Signature s;
    s.type = "dynamics";
    s.output = kChannelName[channel];
    s.lagS = lag.tauS;
    s.strength = lag.share;
    return s;
}

Onset findOnset(const Stack& st, const std::vector<int>& nuisance, int cand) {
    Onset out;
    const auto n = st.s.rows();
    double span = 0;
    for (double t : st.timeS) {
        span = std::max(span, t);
    }
    if (n < 100 || span < 1200) {
        return out;
    }
    // The nuisance directions once (thin Q), then each onset's column projected off them.
    Eigen::MatrixXd q;
    if (!nuisance.empty()) {
        Eigen::MatrixXd nm(n, static_cast<Eigen::Index>(nuisance.size()));
        for (std::size_t i = 0; i < nuisance.size(); ++i) {
            nm.col(static_cast<Eigen::Index>(i)) = st.s.col(nuisance[i]);
        }
        Eigen::HouseholderQR<Eigen::MatrixXd> qr(nm);
        q = qr.householderQ() * Eigen::MatrixXd::Identity(n, nm.cols());
    }
    const auto reductionFrom = [&](double onset) {
        Eigen::VectorXd c = st.s.col(cand);
        for (Eigen::Index i = 0; i < n; ++i) {
            if (st.timeS[static_cast<std::size_t>(i)] < onset) {
                c(i) = 0;
            }
        }
        if (q.size() > 0) {
            c -= q * (q.transpose() * c);
        }
        const double info = c.squaredNorm();
        const double u = c.dot(st.r);
        return info > 0 ? u * u / info : 0.0;
    };
    // The residual's variance per entry, scaled by its long-run (autocorrelated) variance.
    const auto series = perRowSeries(st, st.r);
    double plain = 0;
    for (const auto& s : series) {
        if (s.size() > 2) {
            plain += static_cast<double>(s.size()) * diagnostics::longRunVariance(s, 0, true);
        }
    }
    const double longRun = hacVarianceOfSum(series, true);
    const double sigma2 = st.r.squaredNorm() / static_cast<double>(n) * (plain > 0 ? longRun / plain : 1.0);
    if (!(sigma2 > 0)) {
        return out;
    }
    const double step = std::max(60.0, span / 120);
    std::vector<double> grid, reduction;
    for (double g = 0; g <= 0.9 * span; g += step) {
        grid.push_back(g);
        reduction.push_back(reductionFrom(g));
    }
    const auto best =
        static_cast<std::size_t>(std::max_element(reduction.begin(), reduction.end()) - reduction.begin());
    out.likelihoodRatio = (reduction[best] - reduction.front()) / sigma2;
    if (best == 0 || out.likelihoodRatio < kOnsetLikelihoodRatio) {
        return out;
    }
    out.found = true;
    out.s = grid[best];
    std::size_t lo = best, hi = best;
    while (lo > 0 && reduction[lo - 1] >= reduction[best] - kProfileInterval * sigma2) {
        --lo;
    }
    while (hi + 1 < grid.size() && reduction[hi + 1] >= reduction[best] - kProfileInterval * sigma2) {
        ++hi;
    }
    out.lowS = std::max(0.0, grid[lo] - step / 2);
    out.highS = grid[hi] + step / 2;
    return out;
}

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
