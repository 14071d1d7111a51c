// Question 1: what the simulation gets wrong, per measured channel; and at the end, what no
// cause explains, by its signature.
#include "discovery/DiscoveryInternal.h"

#include "common/MovingAverage.h"
#include "common/Parallel.h"
#include "common/Units.h"
#include "diagnostics/Correlation.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <optional>

namespace drytwin::discovery::detail {

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

} // namespace

/// Question 1 for every measured channel, over all kept rows of every batch.
std::vector<OutputResidual> analyse(const Problem& pr, const std::vector<physics::SimulationResult>& sims) {
    const auto& batches = *pr.batches;
    // The channels are independent: side by side, each into its own slot, gathered in channel
    // order (the same result on any number of cores). An unmeasured channel stays empty.
    std::array<std::optional<OutputResidual>, 4> perChannel;
    parallelFor(perChannel.size(), [&](std::size_t channel) {
        const int c = static_cast<int>(channel);
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
            return;
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
        perChannel[channel] = std::move(o);
    });
    std::vector<OutputResidual> out;
    for (auto& o : perChannel) {
        if (o) {
            out.push_back(std::move(*o));
        }
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

} // namespace drytwin::discovery::detail
