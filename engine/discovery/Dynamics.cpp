// When things happen: the onset of a cause that starts mid-batch, and the lag a channel's error
// shows against the simulation's rate of change (a meter's, or the line's own dynamics).
#include "discovery/DiscoveryInternal.h"

#include "common/FirstOrderLag.h"
#include "common/MovingAverage.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"

#include <algorithm>
#include <cmath>

namespace drytwin::discovery::detail {

namespace {

/// Onset search: the likelihood-ratio (in units of the residual's long-run variance) an onset
/// must reach over "from the start". A searched break point needs far more than χ²(1)'s 3.84
/// (Andrews' sup-LR critical values are 8-10 at 5 %); 15 also covers the misfit of a model that
/// is wrong everywhere a little.
constexpr double kOnsetLikelihoodRatio = 15;
constexpr double kProfileInterval = 3.84; ///< χ²(1) at 95 %: the onset's profile interval

} // namespace

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
            if (st.sinceOnsetS(static_cast<std::size_t>(i), onset) < 0) {
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

Expected<Onset> findOnsetOfEffect(const Problem& pr, const Stack& roundStack,
                                  const std::vector<int>& nuisance, int cand, Param cause,
                                  const ParameterSet& fitted) {
    // The cause's own effect at its fitted value: the fit against the same fit with the cause at 0.
    ParameterSet without = fitted;
    without[cause] = 0;
    without[Param::t_onset] = 0;
    auto at = stackAt(pr, fitted, {});
    if (!at) {
        return at.error();
    }
    auto off = stackAt(pr, without, {});
    if (!off) {
        return off.error();
    }
    // Both stacks hold the same entries as the round's (the same rows and channels) unless a
    // simulation left one out; then there is nothing to scan.
    const auto sameEntries = [&](const Stack& other) {
        return other.batch == roundStack.batch && other.row == roundStack.row &&
               other.channel == roundStack.channel;
    };
    if (!sameEntries(*at) || !sameEntries(*off)) {
        return Onset{};
    }
    Stack scan = roundStack;
    scan.s.col(cand) = off->r - at->r; // the effect, weighted as the residuals (predicted with − without)
    return findOnset(scan, nuisance, cand);
}

ChannelLag lagOnChannel(const Problem& pr, const std::vector<physics::SimulationResult>& sims, int channel,
                        double atTauS, double fromS) {
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
        const double batchFromS = pr.inputs[b].onsetS(fromS); // 0 where the change goes on from the start
        std::vector<double> t, obs, pred;
        for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
            double o = 0, p = 0, f = 1;
            if (bt.timeS[k] - bt.timeS.front() >= batchFromS &&
                channelAt(bt, sims[b], k, k, channel, o, p, f)) {
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
        // At a lag of τ the reading's error is the first-order response of the simulation minus
        // the simulation (exact for an input linear between samples, from the first row on), per
        // second of τ: −dX/dt for a short lag, its smoothed form for a long one.
        std::vector<double> effectPerS;
        if (atTauS > 0) {
            effectPerS = lagOfPiecewiseLinear(t, pred, atTauS);
            for (std::size_t i = 0; i < t.size(); ++i) {
                effectPerS[i] = (effectPerS[i] - pred[i]) / atTauS;
            }
            effectPerS = centredMovingAverage(t, effectPerS, kWindowS);
        }
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
            gb.push_back(atTauS > 0 ? effectPerS[i] : -(pred[hi] - pred[lo]) / (t[hi] - t[lo]));
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

} // namespace drytwin::discovery::detail
