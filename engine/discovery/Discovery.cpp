#include "discovery/Discovery.h"

#include "common/MovingAverage.h"
#include "common/Parallel.h"
#include "common/Units.h"
#include "diagnostics/Correlation.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"
#include "diagnostics/WelchPsd.h"
#include "physics/LineInputs.h"
#include "physics/LineSimulator.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <boost/math/distributions/normal.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdarg>
#include <cstdio>
#include <numeric>
#include <optional>
#include <thread>

namespace drytwin::discovery {

using properties::Param;
using properties::ParameterSet;

namespace {

// Thresholds of the "unexplained" signatures. They are deliberately strict: structure is
// reported only when a colleague would see it on the plot at once, never forced onto a name.
constexpr double kPeriodicPowerRatio = 12; // spectral line over its local background
constexpr double kDriftZ = 6;              // within-batch trend over its HAC standard error
constexpr double kBatchShiftZ = 6;         // batch mean off the median batch, in standard errors
constexpr double kLaggedInputCcf = 0.35;   // |ccf| of differenced residual and input
// A shift or drift must also be large beside the residual's own spread within batches: what is
// statistically clear but far below the scatter is not structure anyone would act on.
constexpr double kPracticalSpreads = 1.0;
constexpr double kHacAcfThreshold = 0.05; // bandwidth: first lag whose |ACF| falls below this

double upperTail(double z) {
    const boost::math::normal n;
    return boost::math::cdf(boost::math::complement(n, z));
}

/// The measured channels: outlet moisture and temperature, tube-outlet ones where measured.
enum Channel { kXOut = 0, kTOut = 1, kXHdt = 2, kTHdt = 3 };
constexpr const char* kChannelName[] = {"X_out", "T_out", "X_hdt", "T_hdt"};
constexpr const char* kChannelUnit[] = {"% wb", "°C", "% wb", "°C"};

/// Measured and simulated values of a channel at row k (simulation index j), in file units,
/// and the factor from a dry-basis (or kelvin) sensitivity to file units. False when missing.
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

/// Residuals and output sensitivities of the training subset, stacked: one entry per
/// (row, measured channel), weighted by √w so that Σ r² is the calibration loss's sum.
struct Stack {
    Eigen::MatrixXd s;      ///< entries × parameters, file units per parameter unit, weighted
    Eigen::VectorXd r;      ///< weighted residuals
    std::vector<int> batch; ///< per entry
    std::vector<int> row;   ///< per entry: position of its row in the batch's subset
};

struct Problem {
    const std::vector<data::SiBatch>* batches = nullptr;
    std::vector<physics::LineInputs> inputs;
    std::vector<data::RowRange> train, test;
    std::vector<std::vector<std::size_t>> subset; ///< per batch, training rows in the tests and fits
    std::vector<data::RowRef> subsetRefs;
    physics::SimulationOptions simulation;
    DiscoveryOptions options;
};

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

struct ScoreResult {
    double z = 0;
    double estimate = 0;
    double se = 0;
    double reduction = 0; ///< (s̃ᵀr)² / s̃ᵀs̃: the sum of squares one linearised step removes
};

/// Score (Lagrange-multiplier) test of column @p cand of the stack against the nuisance columns:
/// the candidate's sensitivity is projected off the nuisance ones, U = s̃ᵀr, and its variance is
/// HAC so that autocorrelated residuals do not inflate the evidence.
ScoreResult scoreTest(const Stack& st, const std::vector<int>& nuisance, int cand) {
    Eigen::VectorXd sc = st.s.col(cand);
    if (!nuisance.empty()) {
        Eigen::MatrixXd n(st.s.rows(), static_cast<Eigen::Index>(nuisance.size()));
        for (std::size_t i = 0; i < nuisance.size(); ++i) {
            n.col(static_cast<Eigen::Index>(i)) = st.s.col(nuisance[i]);
        }
        const Eigen::VectorXd beta = n.colPivHouseholderQr().solve(sc);
        sc -= n * beta;
    }
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

/// Held-out errors of a parameter set: per test batch, the X_out and T_out errors and the
/// weighted squared error of every measured channel, per kept row.
struct HeldOut {
    std::vector<std::vector<double>> loss; ///< per test batch, per row
    std::vector<double> obsX, predX, obsT, predT;
    std::vector<double> residualX; ///< concatenated, % wb
    /// Per test batch, per channel: the time and the error scaled by the square root of the
    /// channel's weight (so that its square adds up to `loss`), for the fast-band share.
    struct Series {
        std::vector<double> timeS, weightedError;
    };
    std::vector<std::array<Series, 4>> channels;
};

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

/// Sum of the squared fast part of the held-out error: each channel's weighted error minus its
/// centred moving average over `windowS`, per batch (no window across batches).
double fastBandSquaredError(const HeldOut& h, double windowS) {
    double sum = 0;
    for (const auto& batch : h.channels) {
        for (const auto& series : batch) {
            const auto slow = centredMovingAverage(series.timeS, series.weightedError, windowS);
            for (std::size_t i = 0; i < slow.size(); ++i) {
                const double fast = series.weightedError[i] - slow[i];
                sum += fast * fast;
            }
        }
    }
    return sum;
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
    // One-sided Diebold-Mariano on the weighted squared error: d = L_before − L_after.
    std::vector<std::vector<double>> d(before.loss.size());
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t b = 0; b < before.loss.size(); ++b) {
        for (std::size_t i = 0; i < before.loss[b].size() && i < after.loss[b].size(); ++i) {
            d[b].push_back(before.loss[b][i] - after.loss[b][i]);
            sum += d[b].back();
            ++n;
        }
    }
    const double var = hacVarianceOfSum(d, true);
    g.pValue = var > 0 && n > 0 ? upperTail(sum / std::sqrt(var)) : 1.0;
    return g;
}

/// Linear detrend of a series in place.
void detrend(std::vector<double>& x) {
    const std::size_t n = x.size();
    if (n < 3) {
        return;
    }
    double st = 0, sx = 0, stt = 0, stx = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i);
        st += t;
        sx += x[i];
        stt += t * t;
        stx += t * x[i];
    }
    const double dn = static_cast<double>(n);
    const double slope = (dn * stx - st * sx) / (dn * stt - st * st);
    const double icpt = (sx - slope * st) / dn;
    for (std::size_t i = 0; i < n; ++i) {
        x[i] -= icpt + slope * static_cast<double>(i);
    }
}

/// The strongest spectral line of detrended residuals (1 s sampling, batches as separate
/// records, powers summed): periodogram on a fine log grid of periods from 60 s to a quarter of
/// the shortest batch, over the median of its neighbourhood [f/2, 2f] away from the line itself.
void spectralPeak(const std::vector<std::vector<double>>& records, double& periodS, double& ratio) {
    periodS = 0;
    ratio = 0;
    std::size_t shortest = SIZE_MAX;
    for (const auto& r : records) {
        shortest = std::min(shortest, r.size());
    }
    if (records.empty() || shortest < 480) {
        return;
    }
    const double longest = static_cast<double>(shortest) / 4.0;
    const int grid = 600;
    std::vector<double> freq(grid), power(grid, 0.0);
    for (int g = 0; g < grid; ++g) {
        const double period = 60.0 * std::pow(longest / 60.0, static_cast<double>(g) / (grid - 1));
        freq[static_cast<std::size_t>(g)] = 1.0 / period;
    }
    for (const auto& rec : records) {
        std::vector<double> x = rec;
        detrend(x);
        const double n = static_cast<double>(x.size());
        for (int g = 0; g < grid; ++g) {
            const double w = 2 * M_PI * freq[static_cast<std::size_t>(g)];
            // Rotate a phasor instead of calling sin/cos per sample.
            const std::complex<double> step(std::cos(w), -std::sin(w));
            std::complex<double> phasor(1.0, 0.0);
            std::complex<double> acc(0.0, 0.0);
            for (double v : x) {
                acc += v * phasor;
                phasor *= step;
            }
            power[static_cast<std::size_t>(g)] += std::norm(acc) / n;
        }
    }
    const double resolution = 1.0 / static_cast<double>(shortest);
    for (int g = 0; g < grid; ++g) {
        const double f = freq[static_cast<std::size_t>(g)];
        std::vector<double> background;
        for (int h = 0; h < grid; ++h) {
            const double f2 = freq[static_cast<std::size_t>(h)];
            if (f2 >= f / 2 && f2 <= 2 * f && std::abs(f2 - f) > 3 * resolution) {
                background.push_back(power[static_cast<std::size_t>(h)]);
            }
        }
        if (background.size() < 10) {
            continue;
        }
        std::nth_element(background.begin(), background.begin() + static_cast<long>(background.size() / 2),
                         background.end());
        const double bg = background[background.size() / 2];
        const double rr = bg > 0 ? power[static_cast<std::size_t>(g)] / bg : 0;
        if (rr > ratio) {
            ratio = rr;
            periodS = 1.0 / f;
        }
    }
}

/// Question 1 for every measured channel, over all kept rows of every batch.
std::vector<OutputResidual> analyse(const Problem& pr, const std::vector<physics::SimulationResult>& sims) {
    const auto& batches = *pr.batches;
    std::vector<OutputResidual> out;
    for (int c = 0; c < 4; ++c) {
        OutputResidual o;
        o.output = kChannelName[c];
        o.unit = kChannelUnit[c];
        std::vector<std::vector<double>> perBatch;   // kept residuals, for bias and HAC
        std::vector<std::vector<double>> records;    // full 1 s records (missing → 0), for the spectrum
        std::vector<std::vector<double>> trendScore; // (t − t̄) e per row
        double sxx = 0, sxy = 0;
        double within = 0;
        double hours = 0;
        std::vector<double> all;
        std::vector<double> diffResidual10;           // differenced, every 10 s, batches joined
        std::vector<std::vector<double>> diffInput10; // per correlate column
        const std::vector<std::pair<std::string, int>> columns = {
            {"T_hot_C", 0},     {"feed_kg_h", 1},    {"X_in_pct", 2},      {"T_in_C", 3},
            {"T_amb_C", 4},     {"RH_amb_pct", 5},   {"air_speed_m_s", 6}, {"proxy_X_HDT", 7},
            {"proxy_T_HDT", 8}, {"proxy_X_Conv", 9}, {"proxy_T_Conv", 10}};
        diffInput10.resize(columns.size());
        std::vector<std::vector<double>> regionX(5), regionR(5);
        for (std::size_t b = 0; b < batches.size(); ++b) {
            const auto& bt = batches[b];
            const auto& sim = sims[b];
            std::vector<double> kept, keptT, record(bt.rows(), 0.0);
            OutputResidual::BatchBias bb;
            bb.batch = bt.id;
            double prevR = std::nan("");
            std::vector<double> prevIn(columns.size(), std::nan(""));
            for (std::size_t k = 0; k < bt.rows(); ++k) {
                double obs = 0, pred = 0, f = 1;
                if (!channelAt(bt, sim, k, k, c, obs, pred, f)) {
                    continue;
                }
                const double e = obs - pred;
                kept.push_back(e);
                keptT.push_back(bt.timeS[k] - bt.timeS.front());
                record[k] = e;
                all.push_back(e);
                if (k % 60 == 0) {
                    o.seriesBatch.push_back(bt.id);
                    o.seriesTimeS.push_back(bt.timeS[k] - bt.timeS.front());
                    o.seriesValue.push_back(e);
                }
                const double regionValue[5] = {
                    units::kelvinToCelsius(bt.tHotK[k]), units::kgPerSToKgPerHour(bt.feedKgPerS[k]),
                    units::dryToWetPct(bt.xInDb[k]), units::kelvinToCelsius(bt.tAmbK[k]),
                    units::fractionToPercent(bt.rhAmb[k])};
                for (int g = 0; g < 5; ++g) {
                    regionX[static_cast<std::size_t>(g)].push_back(regionValue[g]);
                    regionR[static_cast<std::size_t>(g)].push_back(e);
                }
                if (k % 10 == 0) {
                    const double inputs[11] = {bt.tHotK[k],         bt.feedKgPerS[k],   bt.xInDb[k],
                                               bt.tInK[k],          bt.tAmbK[k],        bt.rhAmb[k],
                                               bt.airSpeedMPerS[k], sim.proxyXHdtDb[k], sim.proxyTHdtK[k],
                                               sim.proxyXConvDb[k], sim.proxyTConvK[k]};
                    if (std::isfinite(prevR)) {
                        diffResidual10.push_back(e - prevR);
                        for (std::size_t q = 0; q < columns.size(); ++q) {
                            diffInput10[q].push_back(inputs[q] - prevIn[q]);
                        }
                    }
                    prevR = e;
                    for (std::size_t q = 0; q < columns.size(); ++q) {
                        prevIn[q] = inputs[q];
                    }
                }
            }
            if (kept.size() < 10) {
                continue;
            }
            o.rows += kept.size();
            bb.mean = diagnostics::mean(kept);
            const int lag = diagnostics::bandwidthFromAutocorrelation(kept, kHacAcfThreshold,
                                                                      static_cast<int>(kept.size()) / 3);
            bb.se =
                std::sqrt(diagnostics::longRunVariance(kept, lag, true) / static_cast<double>(kept.size()));
            o.perBatch.push_back(bb);
            perBatch.push_back(kept);
            records.push_back(record);
            const double tMean = diagnostics::mean(keptT);
            const double eMean = bb.mean;
            for (double e : kept) {
                within += (e - eMean) * (e - eMean);
            }
            hours += (keptT.back() - keptT.front()) / 3600.0;
            std::vector<double> score;
            for (std::size_t i = 0; i < kept.size(); ++i) {
                const double dt = (keptT[i] - tMean) / 3600.0;
                sxx += dt * dt;
                sxy += dt * (kept[i] - eMean);
                score.push_back(dt * (kept[i] - eMean));
            }
            trendScore.push_back(std::move(score));
        }
        if (o.rows == 0) {
            continue;
        }
        o.bias = diagnostics::mean(all);
        o.withinBatchSd = std::sqrt(within / static_cast<double>(o.rows));
        o.meanBatchHours = hours / static_cast<double>(o.perBatch.size());
        o.biasSe = std::sqrt(hacVarianceOfSum(perBatch, true)) / static_cast<double>(o.rows);
        if (sxx > 0) {
            o.trendPerHour = sxy / sxx;
            o.trendSe = std::sqrt(hacVarianceOfSum(trendScore, true)) / sxx;
        }
        o.ljungBoxP = diagnostics::ljungBox(all, 20).pValue;
        spectralPeak(records, o.peakPeriodS, o.peakPowerRatio);
        // Cross-correlation of changes over lags 0..300 s.
        const double n = static_cast<double>(diffResidual10.size());
        if (n > 50) {
            for (std::size_t q = 0; q < columns.size(); ++q) {
                const auto ccf = diagnostics::crossCorrelation(diffResidual10, diffInput10[q], 30);
                OutputResidual::Correlate best;
                best.column = columns[q].first;
                for (std::size_t l = 0; l < ccf.size(); ++l) {
                    if (std::isfinite(ccf[l]) && std::abs(ccf[l]) > std::abs(best.ccf)) {
                        best.ccf = ccf[l];
                        best.lagS = 10.0 * static_cast<double>(l);
                    }
                }
                best.significant = std::abs(best.ccf) > 4.0 / std::sqrt(n);
                o.correlates.push_back(best);
            }
            std::sort(o.correlates.begin(), o.correlates.end(),
                      [](const auto& a, const auto& b) { return std::abs(a.ccf) > std::abs(b.ccf); });
            o.correlates.resize(std::min<std::size_t>(o.correlates.size(), 3));
        }
        // Bias by operating region: quintiles of each operating variable.
        const char* regionName[5] = {"T_hot_C", "feed_kg_h", "X_in_pct", "T_amb_C", "RH_amb_pct"};
        const char* regionUnit[5] = {"°C", "kg/h", "% wb", "°C", "%"};
        for (int g = 0; g < 5; ++g) {
            auto xs = regionX[static_cast<std::size_t>(g)];
            const auto& rs = regionR[static_cast<std::size_t>(g)];
            if (xs.size() < 50) {
                continue;
            }
            std::vector<double> sorted = xs;
            std::sort(sorted.begin(), sorted.end());
            OutputResidual::RegionBias rb;
            rb.column = regionName[g];
            rb.unit = regionUnit[g];
            for (int q = 1; q <= 5; ++q) {
                rb.binUpper.push_back(
                    sorted[std::min(sorted.size() - 1, sorted.size() * static_cast<std::size_t>(q) / 5)]);
            }
            std::vector<double> sum(5, 0.0), count(5, 0.0);
            for (std::size_t i = 0; i < xs.size(); ++i) {
                const auto bin = static_cast<std::size_t>(
                    std::lower_bound(rb.binUpper.begin(), rb.binUpper.end(), xs[i]) - rb.binUpper.begin());
                const std::size_t bi = std::min<std::size_t>(bin, 4);
                sum[bi] += rs[i];
                count[bi] += 1;
            }
            for (int q = 0; q < 5; ++q) {
                rb.mean.push_back(count[static_cast<std::size_t>(q)] > 0
                                      ? sum[static_cast<std::size_t>(q)] / count[static_cast<std::size_t>(q)]
                                      : std::nan(""));
            }
            o.regions.push_back(rb);
        }
        out.push_back(std::move(o));
    }
    return out;
}

/// What is left that matches no mechanism, by signature.
std::vector<Signature> signatures(const std::vector<OutputResidual>& residuals) {
    std::vector<Signature> out;
    Signature best; // the strongest spectral line, if any passes
    for (const auto& o : residuals) {
        if (o.output != "X_out" && o.output != "T_out") {
            continue;
        }
        if (o.peakPowerRatio > kPeriodicPowerRatio && o.peakPowerRatio > best.strength) {
            best = Signature{};
            best.type = "periodic";
            best.output = o.output;
            best.periodS = o.peakPeriodS;
            best.strength = o.peakPowerRatio;
        }
    }
    if (!best.type.empty()) {
        out.push_back(best);
    }
    for (const auto& o : residuals) {
        if (o.output != "X_out" && o.output != "T_out") {
            continue;
        }
        if (o.trendSe > 0 && std::abs(o.trendPerHour / o.trendSe) > kDriftZ &&
            std::abs(o.trendPerHour) * o.meanBatchHours > kPracticalSpreads * o.withinBatchSd) {
            Signature s;
            s.type = "drift";
            s.output = o.output;
            s.strength = o.trendPerHour;
            out.push_back(s);
        }
        if (o.perBatch.size() >= 3) {
            std::vector<double> means;
            for (const auto& b : o.perBatch) {
                means.push_back(b.mean);
            }
            std::vector<double> sorted = means;
            std::sort(sorted.begin(), sorted.end());
            const double median = sorted[sorted.size() / 2];
            Signature s;
            s.type = "batch_shift";
            s.output = o.output;
            for (const auto& b : o.perBatch) {
                if (b.se > 0 && std::abs(b.mean - median) > kBatchShiftZ * b.se &&
                    std::abs(b.mean - median) > kPracticalSpreads * o.withinBatchSd) {
                    s.batches.push_back(b.batch);
                    s.strength = std::max(s.strength, std::abs(b.mean - median));
                }
            }
            // A shift of most batches is a bias, not a shift of some.
            if (!s.batches.empty() && s.batches.size() * 2 < o.perBatch.size() + 1) {
                out.push_back(s);
            }
        }
        for (const auto& c : o.correlates) {
            if (c.significant && std::abs(c.ccf) > kLaggedInputCcf && c.column.rfind("proxy_", 0) != 0) {
                Signature s;
                s.type = "lagged_input";
                s.output = o.output;
                s.column = c.column;
                s.lagS = c.lagS;
                s.strength = std::abs(c.ccf);
                out.push_back(s);
            }
        }
    }
    return out;
}

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return buf;
}

/// What a colleague should look for on the residual plots for each cause.
const char* lookFor(Param p) {
    switch (p) {
    case Param::theta_wall:
        return "the outlet-temperature error grows with the hot-air excess over ambient "
               "(bias by T_amb and T_hot)";
    case Param::theta_gas:
        return "the errors grow with feed rate and inlet moisture (bias by feed_kg_h and X_in_pct)";
    case Param::theta_foul:
        return "the error drifts within every batch and resets at each batch start";
    case Param::tau_meter:
        return "the outlet-moisture error follows the rate of change of the simulated outlet moisture, "
               "and the tube-outlet error does not";
    case Param::X_meter_offset:
        return "a steady outlet-moisture bias that the tube-outlet moisture does not share";
    case Param::dtau_conv:
        return "the outlet error correlates with tube-outlet changes at a shifted lag";
    case Param::theta_fall:
        return "the tube-outlet and outlet moisture are wetter than simulated, "
               "most where the tube dries furthest";
    case Param::theta_reabs:
        return "the outlet-moisture error grows with ambient humidity while the tube-outlet error does not";
    default:
        return "";
    }
}

} // namespace

Status DiscoveryOptions::validate() const {
    if (!(trainFraction > 0.2 && trainFraction < 0.95)) {
        return invalidOption("train fraction", "must lie in (0.2, 0.95)");
    }
    if (!(screenAlpha > 0 && screenAlpha < 0.5) || !(gainAlpha > 0 && gainAlpha < 0.5) ||
        !(minExplainedFraction >= 0 && minExplainedFraction < 1)) {
        return invalidOption("alpha", "test levels must lie in (0, 0.5), the explained share in [0, 1)");
    }
    if (!(fastBandWindowS == 0 || (fastBandWindowS >= 10 && fastBandWindowS <= 1e5))) {
        return invalidOption("fast-band window", "must be 0 (off) or lie in [10, 1e5] s");
    }
    if (maxCauses < 0 || candidatesToFit < 1 || maxEvaluationsPerFit < 10) {
        return invalidOption("discovery limits",
                             "max causes ≥ 0, candidates to fit ≥ 1, evaluations per fit ≥ 10");
    }
    return {};
}

Expected<DiscoveryResult> discover(const std::vector<data::SiBatch>& batches,
                                   const hybrid::HybridModel& model, const DiscoveryOptions& options,
                                   const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (batches.empty()) {
        return Error{
            ErrorKind::BadInput, "discover", "no batches", ErrorCode::NotEnoughData, {"batches", "0"}};
    }
    Problem pr;
    pr.batches = &batches;
    pr.options = options;
    pr.simulation = model.simulationOptions();
    std::vector<std::size_t> rowsPerBatch;
    for (const auto& b : batches) {
        pr.inputs.push_back(physics::toLineInputs(b));
        rowsPerBatch.push_back(b.rows());
    }
    const auto split = data::chronologicalSplit(rowsPerBatch, options.trainFraction);
    pr.train = split.train;
    pr.test = split.test;
    pr.subset.resize(batches.size());
    std::size_t keptTrain = 0, keptTest = 0;
    std::size_t stride = options.subsetStride;
    if (stride == 0) {
        std::size_t kept = 0;
        for (std::size_t b = 0; b < batches.size(); ++b) {
            for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
                kept += batches[b].keep[k];
            }
        }
        stride = std::max<std::size_t>(5, kept / 1000);
    }
    for (std::size_t b = 0; b < batches.size(); ++b) {
        std::size_t seen = 0;
        for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
            if (batches[b].keep[k]) {
                ++keptTrain;
                if (seen++ % stride == 0) {
                    pr.subset[b].push_back(k);
                    pr.subsetRefs.push_back({b, k});
                }
            }
        }
        for (std::size_t k = pr.test[b].begin; k < pr.test[b].end; ++k) {
            keptTest += batches[b].keep[k];
        }
    }
    if (pr.subsetRefs.size() < 100 || keptTest < 100) {
        return Error{ErrorKind::BadInput,
                     "discover",
                     "too few rows: " + std::to_string(pr.subsetRefs.size()) +
                         " training rows in the tests (need 100) and " + std::to_string(keptTest) +
                         " held-out rows (need 100) pass the cleaning rules",
                     ErrorCode::NotEnoughData,
                     {"rows", std::to_string(keptTrain + keptTest)}};
    }
    double fraction = 0; // of the whole discovery, for the fits' progress
    const auto stop = [&](double f, const std::string& detail) {
        fraction = f;
        return reportProgress(progress, "discover", f, detail);
    };
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };

    // The starting model, its h_HDT and k_HDT refitted on the training rows (locally when the
    // model was calibrated, globally and locally when not).
    std::vector<Param> nuisance{Param::h_HDT, Param::k_HDT};
    for (Param m : properties::mechanismParams()) {
        if (model.parameters[m] != 0) {
            nuisance.push_back(m); // extensions the model already holds stay free
        }
    }
    auto refit = [&](const ParameterSet& start, const std::vector<Param>& free,
                     bool global) -> Expected<calibration::CalibrationResult> {
        calibration::CalibrationOptions co;
        co.freeParameters = free;
        co.rows = pr.subsetRefs;
        co.weights = options.weights;
        co.maxEvaluations = options.maxEvaluationsPerFit * (global ? 2 : 1);
        co.globalSearch = global;
        co.intervals = false;
        co.simulation = pr.simulation;
        // The fit's own progress reaches the user as discovery's; any stop cancels discovery.
        return calibration::calibrate(batches, start, co, [&](const ProgressInfo& info) {
            return progress && progress(ProgressInfo{"discover", fraction, "fitting: " + info.detail}) !=
                                   ProgressAction::Continue
                       ? ProgressAction::Stop
                       : ProgressAction::Continue;
        });
    };
    if (stop(0.02, "refitting h_HDT and k_HDT on the training part")) {
        return cancelledError("discover");
    }
    auto base = refit(model.parameters, nuisance, !model.calibration.has_value());
    if (!base) {
        return base.error();
    }
    ParameterSet current = base->parameters;
    double currentLoss = base->after.loss;

    DiscoveryResult result;
    result.baseParameters = current;
    {
        bool xHdt = false, tHdt = false;
        for (const auto& b : batches) {
            xHdt = xHdt || b.hasXHdt;
            tHdt = tHdt || b.hasTHdt;
        }
        if (!xHdt) {
            result.notes.push_back(
                "X_hdt_pct is not measured: the tube-outlet moisture cannot separate meter and "
                "conveyor causes from tube causes; outlet channels only");
        }
        if (!tHdt) {
            result.notes.push_back("T_hdt_C is not measured: tube-outlet temperature not used");
        }
        bool airVaries = false;
        for (const auto& b : batches) {
            for (double v : b.airSpeedMPerS) {
                airVaries = airVaries || v != b.airSpeedMPerS.front();
            }
        }
        if (!airVaries) {
            result.notes.push_back(
                "air_speed_m_s is constant (not measured?): gas_phase_coupling works with that one "
                "value and cannot use the air speed's variation");
        }
    }
    result.trainingRows = keptTrain;
    result.heldOutRows = keptTest;
    auto full = physics::simulateBatches(pr.inputs, current, pr.simulation);
    if (!full) {
        return full.error();
    }
    result.residuals = analyse(pr, *full);
    // The residual analysis of the model as it stands (before each round, and at the end).
    std::vector<OutputResidual> currentResiduals = result.residuals;
    auto currentHeld = heldOut(pr, current);
    if (!currentHeld) {
        return currentHeld.error();
    }

    std::vector<Param> remaining;
    for (Param m : properties::mechanismParams()) {
        if (std::find(nuisance.begin(), nuisance.end(), m) == nuisance.end()) {
            remaining.push_back(m);
        }
    }
    for (int round = 0; round < options.maxCauses && !remaining.empty(); ++round) {
        const double frac0 = 0.1 + 0.8 * round / std::max(1, options.maxCauses);
        if (stop(frac0, "score tests, round " + std::to_string(round + 1))) {
            return cancelledError("discover");
        }
        std::vector<Param> sens = nuisance;
        sens.insert(sens.end(), remaining.begin(), remaining.end());
        auto st = stackAt(pr, current, sens);
        if (!st) {
            return st.error();
        }
        std::vector<int> nuisanceCols(nuisance.size());
        std::iota(nuisanceCols.begin(), nuisanceCols.end(), 0);
        std::vector<Candidate> cands;
        for (std::size_t i = 0; i < remaining.size(); ++i) {
            const auto sc = scoreTest(*st, nuisanceCols, static_cast<int>(nuisance.size() + i));
            Candidate c;
            c.parameter = remaining[i];
            c.cause = std::string(*properties::mechanismOf(remaining[i]));
            c.score = sc.z;
            c.linearEstimate = sc.estimate;
            c.linearSe = sc.se;
            c.predictedReduction = st->r.squaredNorm() > 0 ? sc.reduction / st->r.squaredNorm() : 0;
            const bool twoSided = properties::info(remaining[i]).lower < 0;
            c.pValue = twoSided ? 2 * upperTail(std::abs(sc.z)) : upperTail(sc.z);
            cands.push_back(c);
        }
        // Holm's step-down correction over the candidates of this round.
        std::vector<std::size_t> order(cands.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](auto a, auto b) { return cands[a].pValue < cands[b].pValue; });
        double running = 0;
        for (std::size_t i = 0; i < order.size(); ++i) {
            running = std::max(running,
                               std::min(1.0, static_cast<double>(order.size() - i) * cands[order[i]].pValue));
            cands[order[i]].pHolm = running;
        }
        // Fit the leading candidates that pass the screen, largest predicted reduction first.
        std::sort(cands.begin(), cands.end(), [&](const auto& a, const auto& b) {
            const bool pa = a.pValue < options.screenAlpha;
            const bool pb = b.pValue < options.screenAlpha;
            return pa != pb ? pa : a.predictedReduction > b.predictedReduction;
        });
        int fitted = 0;
        std::optional<std::size_t> bestIndex;
        ParameterSet bestParams;
        for (std::size_t i = 0; i < cands.size() && fitted < options.candidatesToFit; ++i) {
            if (cands[i].pValue >= options.screenAlpha) {
                break;
            }
            if (stop(frac0 + 0.05 * (fitted + 1), "fitting " + cands[i].cause)) {
                return cancelledError("discover");
            }
            std::vector<Param> free = nuisance;
            free.push_back(cands[i].parameter);
            ParameterSet start = current;
            // Start at the one-step estimate when it lies inside the range; BOBYQA refines it.
            const auto& info = properties::info(cands[i].parameter);
            start[cands[i].parameter] = std::clamp(cands[i].linearEstimate, info.lower, info.upper);
            auto fit = refit(start, free, false);
            ++fitted;
            if (!fit) {
                if (fit.error().kind == ErrorKind::Cancelled) {
                    return fit.error();
                }
                continue; // a fit that fails counts as no evidence for this cause
            }
            cands[i].fitted = true;
            cands[i].fitLossBefore = currentLoss;
            cands[i].fitLossAfter = fit->after.loss;
            if (!bestIndex || fit->after.loss < cands[*bestIndex].fitLossAfter) {
                bestIndex = i;
                bestParams = fit->parameters;
            }
        }
        Round record;
        record.candidates = cands;
        // The ranking a user reads: fitted causes by training loss removed, then the rest by evidence.
        std::stable_sort(record.candidates.begin(), record.candidates.end(),
                         [](const auto& a, const auto& b) {
                             if (a.fitted != b.fitted) {
                                 return a.fitted;
                             }
                             if (a.fitted) {
                                 return a.fitLossAfter < b.fitLossAfter;
                             }
                             return a.pValue < b.pValue;
                         });
        if (round == 0) {
            result.ranking = record.candidates;
        }
        if (!bestIndex || !(cands[*bestIndex].fitLossAfter < currentLoss)) {
            record.reason = bestIndex ? "no fitted candidate lowers the training loss"
                                      : "no candidate passes the screening test (p < " +
                                            format("%.2g", options.screenAlpha) + ")";
            result.rounds.push_back(record);
            break;
        }
        record.best = cands[*bestIndex].cause;
        const Candidate& chosen = cands[*bestIndex];
        auto afterHeld = heldOut(pr, bestParams);
        if (!afterHeld) {
            return afterHeld.error();
        }
        Gain gain = gainOf(*currentHeld, *afterHeld);
        const double lossBefore = meanOf(currentHeld->loss);
        const double lossAfter = meanOf(afterHeld->loss);
        const double explained = lossBefore > 0 ? 1.0 - lossAfter / lossBefore : 0;
        double explainedFast = 0;
        if (options.fastBandWindowS > 0) {
            const double fastBefore = fastBandSquaredError(*currentHeld, options.fastBandWindowS);
            const double fastAfter = fastBandSquaredError(*afterHeld, options.fastBandWindowS);
            explainedFast = fastBefore > 0 ? 1.0 - fastAfter / fastBefore : 0;
        }
        record.heldOutPValue = gain.pValue;
        record.explainedFraction = explained;
        record.explainedFractionFast = explainedFast;
        const double level = options.gainAlpha; // fixed-sequence testing (DiscoveryOptions::gainAlpha)
        if (!(gain.pValue < level && std::max(explained, explainedFast) >= options.minExplainedFraction)) {
            // It fits the training part but does not predict clearly better: not a cause.
            record.reason =
                gain.pValue >= level
                    ? format("held-out gain not significant (p = %.2g, needs < %.2g)", gain.pValue, level)
                    : format("removes only %.0f %% of the held-out error left and %.0f %% of its fast "
                             "part (needs %.0f %% of either)",
                             100 * explained, 100 * explainedFast, 100 * options.minExplainedFraction);
            result.rounds.push_back(record);
            break;
        }
        record.named = true;
        result.rounds.push_back(record);
        // Interval: the sandwich (HAC) standard error at the fit, from the score of the fitted model.
        std::vector<Param> sensAt = nuisance;
        sensAt.push_back(chosen.parameter);
        double se = chosen.linearSe;
        if (auto at = stackAt(pr, bestParams, sensAt); at) {
            std::vector<int> others(nuisance.size());
            std::iota(others.begin(), others.end(), 0);
            const auto sc = scoreTest(*at, others, static_cast<int>(nuisance.size()));
            if (sc.se > 0) {
                se = sc.se;
            }
        }
        Finding f;
        f.cause = chosen.cause;
        f.parameter = chosen.parameter;
        f.value = bestParams[chosen.parameter];
        f.ci95Low = f.value - 1.96 * se;
        f.ci95High = f.value + 1.96 * se;
        f.explainedFraction = lossBefore > 0 ? 1.0 - lossAfter / lossBefore : 0;
        f.gain = gain;
        // The output it helps most, and what its residual looked like before.
        const bool moistureHelped =
            gain.maeMoistureBefore > 0 &&
            (gain.maeMoistureBefore - gain.maeMoistureAfter) / gain.maeMoistureBefore >=
                (gain.maeTemperatureBefore - gain.maeTemperatureAfter) /
                    std::max(1e-12, gain.maeTemperatureBefore);
        const OutputResidual* before = nullptr;
        for (const auto& o : currentResiduals) {
            if (o.output == (moistureHelped ? "X_out" : "T_out")) {
                before = &o;
            }
        }
        const auto& info = properties::info(chosen.parameter);
        f.output = moistureHelped ? "X_out" : "T_out";
        f.biasBefore = before ? before->bias : 0.0;
        f.trendPerHourBefore = before ? before->trendPerHour : 0.0;
        f.fastPartCounted = explained < options.minExplainedFraction;
        f.explainedFractionFast = explainedFast;
        // The fast part is quoted when it is what made the cause count.
        const std::string share =
            !f.fastPartCounted
                ? format("it removes %.0f %% of the held-out squared error", 100 * f.explainedFraction)
                : format("it removes %.0f %% of the held-out squared error and %.0f %% of its fast part (the "
                         "error about its %.0f-minute average, where slow drift does not hide it)",
                         100 * f.explainedFraction, 100 * explainedFast, options.fastBandWindowS / 60);
        f.evidence = format(
            "%s error before: bias %+.3g %s, within-batch trend %+.3g %s/h. With %s (%s = %.4g %s, 95 %% CI "
            "[%.3g, %.3g]) and h_HDT, k_HDT refitted, the held-out MAE of X_out falls from %.3f to %.3f %% "
            "wb and of T_out from %.2f to %.2f °C (Diebold-Mariano p = %.2g); %s. Check on the plots: %s.",
            moistureHelped ? "Outlet-moisture" : "Outlet-temperature", f.biasBefore,
            moistureHelped ? "% wb" : "°C", f.trendPerHourBefore, moistureHelped ? "% wb" : "°C",
            f.cause.c_str(), std::string(info.symbol).c_str(), f.value, std::string(info.unit).c_str(),
            f.ci95Low, f.ci95High, gain.maeMoistureBefore, gain.maeMoistureAfter, gain.maeTemperatureBefore,
            gain.maeTemperatureAfter, gain.pValue, share.c_str(), lookFor(chosen.parameter));
        result.findings.push_back(f);
        auto sims = physics::simulateBatches(pr.inputs, bestParams, pr.simulation);
        if (!sims) {
            return sims.error();
        }
        currentResiduals = analyse(pr, *sims);
        current = bestParams;
        currentLoss = chosen.fitLossAfter;
        *currentHeld = std::move(*afterHeld);
        nuisance.push_back(chosen.parameter);
        remaining.erase(std::find(remaining.begin(), remaining.end(), chosen.parameter));
    }

    if (stop(0.95, "what is left")) {
        return cancelledError("discover");
    }
    // Later rounds refit the causes named before: report every cause at the extended model's
    // value, with its interval from the score of the final fit (the others held as nuisance).
    if (result.findings.size() > 1) {
        if (auto at = stackAt(pr, current, nuisance); at) {
            for (auto& f : result.findings) {
                const auto col = static_cast<int>(std::find(nuisance.begin(), nuisance.end(), f.parameter) -
                                                  nuisance.begin());
                std::vector<int> others;
                for (int i = 0; i < static_cast<int>(nuisance.size()); ++i) {
                    if (i != col) {
                        others.push_back(i);
                    }
                }
                const auto sc = scoreTest(*at, others, col);
                f.value = current[f.parameter];
                const double se = sc.se > 0 ? sc.se : 0.5 * (f.ci95High - f.ci95Low) / 1.96;
                f.ci95Low = f.value - 1.96 * se;
                f.ci95High = f.value + 1.96 * se;
            }
        }
    }
    // Bounds for what was tested last and not named: that round's score tests ran at the final
    // model. (When selection ended on a named cause, no round tested the rest at that model.)
    if (!result.rounds.empty() && !result.rounds.back().named) {
        for (const auto& c : result.rounds.back().candidates) {
            const auto& info = properties::info(c.parameter);
            Bound b;
            b.cause = c.cause;
            b.parameter = c.parameter;
            b.estimate = c.linearEstimate;
            b.ci95Low = std::clamp(c.linearEstimate - 1.96 * c.linearSe, info.lower, info.upper);
            b.ci95High = std::clamp(c.linearEstimate + 1.96 * c.linearSe, info.lower, info.upper);
            result.bounds.push_back(b);
        }
    }
    // The residual of the extended model was analysed when its last cause was added (or is the
    // starting model's, when none was): no further simulation.
    result.residualsAfter = currentResiduals;
    result.unexplained = signatures(result.residualsAfter);
    result.parameters = current;
    result.verdict = !result.findings.empty()      ? "cause_found"
                     : !result.unexplained.empty() ? "unexplained_structure"
                                                   : "no_structural_cause";
    reportProgress(progress, "discover", 1.0, "done");
    result.ending = {Termination::Completed,
                     std::to_string(result.findings.size()) + " cause(s) named, " +
                         std::to_string(result.unexplained.size()) + " unexplained signature(s)",
                     elapsed()};
    return result;
}

} // namespace drytwin::discovery
