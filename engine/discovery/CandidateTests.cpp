// Question 2: which cause could explain what the simulation gets wrong, and how large it is.
// Score tests with HAC variances, held-out losses and Diebold-Mariano comparisons.
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Parallel.h"
#include "common/Units.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"
#include "diagnostics/WelchPsd.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <optional>

namespace drytwin::discovery::detail {

double upperTail(double z) {
    const boost::math::normal n;
    return boost::math::cdf(boost::math::complement(n, z));
}

bool twoSided(Param p) {
    return properties::info(p).lower < 0;
}

double changeP(Param p, double z) {
    return twoSided(p) ? 2 * upperTail(std::abs(z)) : upperTail(z);
}

bool channelAt(const data::SiBatch& b, const physics::SimulationResult& r, std::size_t j, std::size_t k,
               int c, double& obs, double& pred, double& toFile) {
    if (!b.keep[k]) {
        return false;
    }
    double o = 0;
    double p = 0;
    bool moisture = false;
    switch (c) {
    case kXOut:
        o = b.xOutDb[k];
        p = r.xOutDb[j];
        moisture = true;
        break;
    case kTOut:
        o = b.tOutK[k];
        p = r.tOutK[j];
        break;
    case kXHdt:
        if (!b.hasXHdt) {
            return false;
        }
        o = b.xHdtDb[k];
        p = r.xHdtDb[j];
        moisture = true;
        break;
    default:
        if (!b.hasTHdt) {
            return false;
        }
        o = b.tHdtK[k];
        p = r.tHdtK[j];
        break;
    }
    if (!std::isfinite(o) || !std::isfinite(p)) {
        return false;
    }
    if (moisture) {
        obs = units::dryToWetPct(o);
        pred = units::dryToWetPct(p);
        toFile = 100.0 / ((1 + p) * (1 + p));
    } else {
        obs = units::kelvinToCelsius(o);
        pred = units::kelvinToCelsius(p);
        toFile = 1.0;
    }
    return true;
}

double channelWeight(const calibration::LossWeights& w, int c) {
    switch (c) {
    case kXOut:
        return w.xOut;
    case kTOut:
        return w.tOut;
    case kXHdt:
        return w.xHdt;
    default:
        return w.tHdt;
    }
}

Expected<Stack> stackAt(const Problem& pr, const ParameterSet& p, const std::vector<Param>& sens) {
    const auto& batches = *pr.batches;
    std::vector<std::optional<Expected<physics::SimulationResult>>> sims(batches.size());
    physics::SimulationOptions so = pr.simulation;
    so.sensitivities = sens;
    parallelFor(batches.size(), [&](std::size_t b) {
        if (!pr.subset[b].empty()) {
            sims[b].emplace(physics::simulateLine(pr.inputs[b], p, so, pr.subset[b]));
        }
    });
    std::vector<double> r;
    std::vector<std::vector<double>> s(sens.size());
    Stack st;
    for (const auto& in : pr.inputs) {
        st.batchFromStart.push_back(in.mechanismsFromStart ? 1 : 0);
    }
    for (std::size_t b = 0; b < batches.size(); ++b) {
        if (!sims[b]) {
            continue;
        }
        if (!*sims[b]) {
            return sims[b]->error();
        }
        const auto& sim = sims[b]->value();
        for (std::size_t j = 0; j < pr.subset[b].size(); ++j) {
            const std::size_t k = pr.subset[b][j];
            for (int c = 0; c < 4; ++c) {
                double obs = 0, pred = 0, toFile = 1;
                if (!channelAt(batches[b], sim, j, k, c, obs, pred, toFile)) {
                    continue;
                }
                const double w = std::sqrt(channelWeight(pr.options.weights, c));
                if (w == 0) {
                    continue;
                }
                r.push_back(w * (obs - pred));
                for (std::size_t q = 0; q < sens.size(); ++q) {
                    const auto& os = sim.sensitivities[q];
                    const double d = c == kXOut   ? os.dXOut[j]
                                     : c == kTOut ? os.dTOut[j]
                                     : c == kXHdt ? os.dXHdt[j]
                                                  : os.dTHdt[j];
                    s[q].push_back(w * toFile * d);
                }
                st.batch.push_back(static_cast<int>(b));
                st.row.push_back(static_cast<int>(j));
                st.channel.push_back(c);
                st.timeS.push_back(batches[b].timeS[k] - batches[b].timeS.front());
            }
        }
    }
    st.r = Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
    st.s.resize(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(sens.size()));
    for (std::size_t q = 0; q < sens.size(); ++q) {
        st.s.col(static_cast<Eigen::Index>(q)) =
            Eigen::Map<Eigen::VectorXd>(s[q].data(), static_cast<Eigen::Index>(s[q].size()));
    }
    return st;
}

/// Σ of @p contribution per (batch, row), as one time series per batch.
std::vector<std::vector<double>> perRowSeries(const Stack& st, const Eigen::VectorXd& contribution) {
    std::vector<std::vector<double>> series;
    int lastBatch = -1;
    int lastRow = -1;
    for (Eigen::Index i = 0; i < contribution.size(); ++i) {
        const int b = st.batch[static_cast<std::size_t>(i)];
        const int row = st.row[static_cast<std::size_t>(i)];
        if (b != lastBatch) {
            series.emplace_back();
            lastBatch = b;
            lastRow = -1;
        }
        if (row != lastRow) {
            series.back().push_back(0.0);
            lastRow = row;
        }
        series.back().back() += contribution(i);
    }
    return series;
}

/// Variance of Σ_t u_t with batches independent and a Newey-West window per batch that follows
/// the series' own memory. Autocovariances about 0 (a score) or about the mean.
double hacVarianceOfSum(const std::vector<std::vector<double>>& series, bool demean) {
    double v = 0;
    for (const auto& u : series) {
        if (u.size() < 3) {
            continue;
        }
        const int lag =
            diagnostics::bandwidthFromAutocorrelation(u, kHacAcfThreshold, static_cast<int>(u.size()) / 3);
        v += static_cast<double>(u.size()) * diagnostics::longRunVariance(u, lag, demean);
    }
    return v;
}

/// Score (Lagrange-multiplier) test of column @p cand of the stack against the nuisance columns:
/// the candidate's sensitivity is projected off the nuisance ones, U = s̃ᵀr, and its variance is
/// HAC so that autocorrelated residuals do not inflate the evidence.
Eigen::VectorXd projectedColumn(const Stack& st, const std::vector<int>& nuisance, int cand) {
    Eigen::VectorXd sc = st.s.col(cand);
    if (!nuisance.empty()) {
        Eigen::MatrixXd n(st.s.rows(), static_cast<Eigen::Index>(nuisance.size()));
        for (std::size_t i = 0; i < nuisance.size(); ++i) {
            n.col(static_cast<Eigen::Index>(i)) = st.s.col(nuisance[i]);
        }
        const Eigen::VectorXd beta = n.colPivHouseholderQr().solve(sc);
        sc -= n * beta;
    }
    return sc;
}

ScoreResult scoreTest(const Stack& st, const std::vector<int>& nuisance, int cand) {
    const Eigen::VectorXd sc = projectedColumn(st, nuisance, cand);
    ScoreResult res;
    const double info = sc.squaredNorm();
    if (!(info > 0)) {
        return res;
    }
    const Eigen::VectorXd u = sc.cwiseProduct(st.r);
    const double sumU = u.sum();
    const double var = hacVarianceOfSum(perRowSeries(st, u), false);
    if (!(var > 0)) {
        return res;
    }
    res.z = sumU / std::sqrt(var);
    res.reduction = sumU * sumU / info;
    res.estimate = sumU / info;
    res.se = std::sqrt(var) / info;
    return res;
}

Expected<HeldOut> heldOut(const Problem& pr, const ParameterSet& p) {
    const auto& batches = *pr.batches;
    std::vector<std::size_t> which;
    std::vector<physics::LineInputs> inputs;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        if (pr.test[b].size() > 0) {
            which.push_back(b);
            inputs.push_back(pr.inputs[b]);
        }
    }
    auto sims = physics::simulateBatches(inputs, p, pr.simulation);
    if (!sims) {
        return sims.error();
    }
    HeldOut h;
    for (std::size_t i = 0; i < which.size(); ++i) {
        const auto& b = batches[which[i]];
        const auto& sim = (*sims)[i];
        std::vector<double> loss;
        std::array<HeldOut::Series, 4> channels;
        for (std::size_t k = pr.test[which[i]].begin; k < pr.test[which[i]].end; ++k) {
            double l = 0;
            bool any = false;
            for (int c = 0; c < 4; ++c) {
                double obs = 0, pred = 0, f = 1;
                if (!channelAt(b, sim, k, k, c, obs, pred, f)) {
                    continue;
                }
                any = true;
                const double weight = channelWeight(pr.options.weights, c);
                l += weight * (obs - pred) * (obs - pred);
                channels[c].timeS.push_back(b.timeS[k]);
                channels[c].weightedError.push_back(std::sqrt(weight) * (obs - pred));
                if (c == kXOut) {
                    h.obsX.push_back(obs);
                    h.predX.push_back(pred);
                    h.residualX.push_back(obs - pred);
                } else if (c == kTOut) {
                    h.obsT.push_back(obs);
                    h.predT.push_back(pred);
                }
            }
            if (any) {
                loss.push_back(l);
            }
        }
        h.loss.push_back(std::move(loss));
        h.channels.push_back(std::move(channels));
    }
    return h;
}

namespace {
/// The squared error of some channels (nullptr: of all): whole, or its fast part when windowS > 0
/// (the error minus its centred moving average over that window).
double channelSquaredError(const HeldOut& h, const std::array<bool, 4>* channels, double windowS) {
    double sum = 0;
    for (const auto& batch : h.channels) {
        for (std::size_t c = 0; c < batch.size(); ++c) {
            if (channels && !(*channels)[c]) {
                continue;
            }
            const auto& series = batch[c];
            if (windowS <= 0) {
                for (double e : series.weightedError) {
                    sum += e * e;
                }
                continue;
            }
            const auto slow = centredMovingAverage(series.timeS, series.weightedError, windowS);
            for (std::size_t i = 0; i < slow.size(); ++i) {
                const double fast = series.weightedError[i] - slow[i];
                sum += fast * fast;
            }
        }
    }
    return sum;
}

double shareRemoved(double before, double after) {
    return before > 0 ? 1.0 - after / before : 0;
}
} // namespace

/// Sum of the squared fast part of the held-out error: each channel's weighted error minus its
/// centred moving average over `windowS`, per batch (no window across batches).
double fastBandSquaredError(const HeldOut& h, double windowS) {
    return channelSquaredError(h, nullptr, windowS);
}

double meanOf(const std::vector<std::vector<double>>& series) {
    double s = 0;
    std::size_t n = 0;
    for (const auto& v : series) {
        for (double x : v) {
            s += x;
            ++n;
        }
    }
    return n ? s / static_cast<double>(n) : 0.0;
}

Gain gainOf(const HeldOut& before, const HeldOut& after) {
    Gain g;
    g.maeMoistureBefore = diagnostics::meanAbsoluteError(before.obsX, before.predX);
    g.maeMoistureAfter = diagnostics::meanAbsoluteError(after.obsX, after.predX);
    g.maeTemperatureBefore = diagnostics::meanAbsoluteError(before.obsT, before.predT);
    g.maeTemperatureAfter = diagnostics::meanAbsoluteError(after.obsT, after.predT);
    g.r2MoistureBefore = diagnostics::rSquared(before.obsX, before.predX);
    g.r2MoistureAfter = diagnostics::rSquared(after.obsX, after.predX);
    g.r2TemperatureBefore = diagnostics::rSquared(before.obsT, before.predT);
    g.r2TemperatureAfter = diagnostics::rSquared(after.obsT, after.predT);
    g.ljungBoxPMoistureBefore = diagnostics::ljungBox(before.residualX, 20).pValue;
    g.ljungBoxPMoistureAfter = diagnostics::ljungBox(after.residualX, 20).pValue;
    if (auto psd = diagnostics::welchPsd(before.residualX); psd) {
        g.lowFrequencyShareBefore = diagnostics::lowFrequencyShare(*psd, 0.01);
    }
    if (auto psd = diagnostics::welchPsd(after.residualX); psd) {
        g.lowFrequencyShareAfter = diagnostics::lowFrequencyShare(*psd, 0.01);
    }
    g.pValue = heldOutPValue(before, after);
    return g;
}

std::pair<double, double> explainedShares(const HeldOut& before, const HeldOut& after,
                                          const DiscoveryOptions& options) {
    const double lossBefore = meanOf(before.loss);
    const double lossAfter = meanOf(after.loss);
    const double whole = lossBefore > 0 ? 1.0 - lossAfter / lossBefore : 0;
    double fast = 0;
    if (options.fastBandWindowS > 0) {
        const double fastBefore = fastBandSquaredError(before, options.fastBandWindowS);
        const double fastAfter = fastBandSquaredError(after, options.fastBandWindowS);
        fast = fastBefore > 0 ? 1.0 - fastAfter / fastBefore : 0;
    }
    return {whole, fast};
}

std::pair<double, double> explainedSharesOnChannels(const HeldOut& before, const HeldOut& after,
                                                    const std::array<bool, 4>& channels,
                                                    const DiscoveryOptions& options) {
    const double whole =
        shareRemoved(channelSquaredError(before, &channels, 0), channelSquaredError(after, &channels, 0));
    const double fast = options.fastBandWindowS > 0
                            ? shareRemoved(channelSquaredError(before, &channels, options.fastBandWindowS),
                                           channelSquaredError(after, &channels, options.fastBandWindowS))
                            : 0;
    return {whole, fast};
}

double shareOfChange(const Problem& pr, const HeldOut& before, const HeldOut& after) {
    if (!pr.reference || !pr.reference->changeDetected || !pr.options.shareOfChangeOnceDetected ||
        !(pr.reference->normalHeldLoss > 0)) {
        return 0;
    }
    const double lossBefore = meanOf(before.loss);
    const double excess = lossBefore - pr.reference->normalHeldLoss;
    // Only a clear excess: a share of a difference near 0 is noise.
    if (!(excess > 0.1 * pr.reference->normalHeldLoss)) {
        return 0;
    }
    return std::min(1.0, (lossBefore - meanOf(after.loss)) / excess);
}

std::vector<int> columnsBut(int count, int skip) {
    std::vector<int> out;
    for (int i = 0; i < count; ++i) {
        if (i != skip) {
            out.push_back(i);
        }
    }
    return out;
}

double heldOutPValue(const HeldOut& worse, const HeldOut& better) {
    // One-sided Diebold-Mariano on the weighted squared error: d = L_worse − L_better.
    std::vector<std::vector<double>> d(worse.loss.size());
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t b = 0; b < worse.loss.size(); ++b) {
        for (std::size_t i = 0; i < worse.loss[b].size() && i < better.loss[b].size(); ++i) {
            d[b].push_back(worse.loss[b][i] - better.loss[b][i]);
            sum += d[b].back();
            ++n;
        }
    }
    const double var = hacVarianceOfSum(d, true);
    return var > 0 && n > 0 ? upperTail(sum / std::sqrt(var)) : 1.0;
}

std::array<ChannelChange, 4> channelChanges(const HeldOut& before, const HeldOut& after) {
    std::array<ChannelChange, 4> out;
    for (int c = 0; c < 4; ++c) {
        std::vector<std::vector<double>> d;
        double sumBefore = 0, sumAfter = 0, sumD = 0;
        std::size_t n = 0;
        for (std::size_t b = 0; b < before.channels.size() && b < after.channels.size(); ++b) {
            const auto& e0 = before.channels[b][static_cast<std::size_t>(c)].weightedError;
            const auto& e1 = after.channels[b][static_cast<std::size_t>(c)].weightedError;
            d.emplace_back();
            for (std::size_t i = 0; i < e0.size() && i < e1.size(); ++i) {
                d.back().push_back(e1[i] * e1[i] - e0[i] * e0[i]);
                sumBefore += e0[i] * e0[i];
                sumAfter += e1[i] * e1[i];
                sumD += d.back().back();
                ++n;
            }
        }
        auto& ch = out[static_cast<std::size_t>(c)];
        ch.measured = n > 0;
        if (!ch.measured) {
            continue;
        }
        ch.mseBefore = sumBefore / static_cast<double>(n);
        ch.mseAfter = sumAfter / static_cast<double>(n);
        const double var = hacVarianceOfSum(d, true);
        ch.pWorse = var > 0 ? upperTail(sumD / std::sqrt(var)) : (sumD > 0 ? 0.0 : 1.0);
        ch.changeSe = var > 0 ? std::sqrt(var) / static_cast<double>(n) : 0.0;
    }
    return out;
}

double unimprovedChannelP(const ChannelChange& change, double effectMeanSquare) {
    if (!(change.changeSe > 0)) {
        return 0.0;
    }
    // Right on this channel, the cause's effect d would remove itself from the error: the mean
    // square falls by about mean(d²) (the rest of the error being unrelated to d).
    const double expectedChange = -effectMeanSquare;
    return upperTail((change.mseAfter - change.mseBefore - expectedChange) / change.changeSe);
}

namespace {

/// Holm's step-down correction over the candidates of a round.
void holm(std::vector<Candidate>& cands) {
    std::vector<std::size_t> order(cands.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return cands[a].pValue < cands[b].pValue; });
    double running = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        running =
            std::max(running, std::min(1.0, static_cast<double>(order.size() - i) * cands[order[i]].pValue));
        cands[order[i]].pHolm = running;
    }
}

} // namespace

std::vector<Candidate> scoreCandidates(const Stack& st, const std::vector<int>& nuisance,
                                       const std::vector<Param>& remaining) {
    std::vector<Candidate> cands;
    for (std::size_t i = 0; i < remaining.size(); ++i) {
        const Param m = remaining[i];
        const auto sc = scoreTest(st, nuisance, static_cast<int>(nuisance.size() + i));
        Candidate c;
        c.parameter = m;
        c.cause = std::string(*properties::mechanismOf(m));
        c.score = sc.z;
        c.linearEstimate = sc.estimate;
        c.linearSe = sc.se;
        c.predictedReduction = st.r.squaredNorm() > 0 ? sc.reduction / st.r.squaredNorm() : 0;
        c.pValue = changeP(m, sc.z);
        cands.push_back(c);
    }
    holm(cands);
    return cands;
}

} // namespace drytwin::discovery::detail
