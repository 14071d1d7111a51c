#include "monitoring/ChangePoint.h"

#include <boost/math/distributions/chi_squared.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <tuple>

namespace drytwin::monitoring {

namespace {

/// Half-width of a 95 % likelihood interval for one parameter: χ²_1(0.95).
constexpr double kChi2Level95 = 3.841458820694124;

/// Null sequences whose tail count may reach this many and still give p ≤ α: then `value > the
/// (count+1)-th largest` and `(count+1)/(sims+1) ≤ α` say the same thing.
int allowedExceedances(const ChangePointOptions& o) {
    return static_cast<int>(std::floor(o.falseAlarmRate * (o.simulations + 1))) - 1;
}

double upperThreshold(const std::vector<double>& ascending, int exceedances) {
    if (ascending.empty()) {
        return 0;
    }
    const auto idx = static_cast<long>(ascending.size()) - 1 - exceedances;
    return ascending[static_cast<std::size_t>(std::clamp(idx, 0L, static_cast<long>(ascending.size()) - 1))];
}

/// Standard normal draws from std::mt19937 by Marsaglia's polar method, written out rather than
/// std::normal_distribution: the thresholds are then the same with every standard library, and
/// it is faster (the simulation is most of a judgement's time).
class StandardNormal {
public:
    explicit StandardNormal(unsigned seed) : m_rng(seed) {}
    double operator()() {
        if (m_hasSpare) {
            m_hasSpare = false;
            return m_spare;
        }
        double u, v, s;
        do {
            u = uniform();
            v = uniform();
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        const double f = std::sqrt(-2.0 * std::log(s) / s);
        m_spare = v * f;
        m_hasSpare = true;
        return u * f;
    }

private:
    double uniform() { return (static_cast<double>(m_rng()) + 0.5) * (2.0 / 4294967296.0) - 1.0; } // (−1, 1)
    std::mt19937 m_rng;
    double m_spare = 0;
    bool m_hasSpare = false;
};

/// Simulates models of the same runs from common random numbers: every replicate draws the
/// shared offset, then per run its level and its values, whatever the variances (even 0), so a
/// model's distribution is the same whether it is simulated alone or with others.
std::vector<std::shared_ptr<NullDistribution>> simulate(const std::vector<NullModel>& models,
                                                        const ChangePointOptions& o) {
    const std::vector<int>& runLengths = models.front().runLengths;
    const int length = models.front().length();
    const std::size_t count = models.size();
    std::vector<std::shared_ptr<NullDistribution>> out;
    std::vector<double> runSd, offsetSd;
    for (const NullModel& m : models) {
        auto d = std::make_shared<NullDistribution>();
        d->length = length;
        d->glrMaxima.reserve(static_cast<std::size_t>(o.simulations));
        d->cusumMaxima.reserve(static_cast<std::size_t>(o.simulations));
        out.push_back(d);
        runSd.push_back(std::sqrt(std::max(0.0, m.runEffectVariance)));
        offsetSd.push_back(std::sqrt(std::max(0.0, m.offsetVariance)));
    }
    StandardNormal normal(o.seed);
    std::vector<double> z(count * static_cast<std::size_t>(length)); // model-major
    const std::vector<char>& levelFree = models.front().levelFree;
    for (int s = 0; s < o.simulations; ++s) {
        const double offset = normal();
        std::size_t t = 0;
        for (std::size_t r = 0; r < runLengths.size(); ++r) {
            const int runLength = runLengths[r];
            const std::size_t first = t;
            const double level = normal();
            for (int i = 0; i < runLength; ++i, ++t) {
                const double noise = normal();
                for (std::size_t m = 0; m < count; ++m) {
                    z[m * static_cast<std::size_t>(length) + t] =
                        noise + runSd[m] * level + offsetSd[m] * offset;
                }
            }
            if (r < levelFree.size() && levelFree[r] && runLength > 0) {
                for (std::size_t m = 0; m < count; ++m) {
                    double* run = z.data() + m * static_cast<std::size_t>(length) + first;
                    double mean = 0;
                    for (int i = 0; i < runLength; ++i) {
                        mean += run[i];
                    }
                    mean /= runLength;
                    for (int i = 0; i < runLength; ++i) {
                        run[i] -= mean;
                    }
                }
            }
        }
        for (std::size_t m = 0; m < count; ++m) {
            const double* zm = z.data() + m * static_cast<std::size_t>(length);
            double cusum = 0, cusumMax = 0;
            for (int i = 0; i < length; ++i) {
                cusum = std::max(0.0, cusum + zm[i] - o.cusumK);
                cusumMax = std::max(cusumMax, cusum);
            }
            double tail = 0, glrMax = 0;
            for (int tau = length - 1; tau >= 0; --tau) {
                tail += zm[tau];
                const int segment = length - tau;
                if (segment >= o.minSegment && tail > 0) {
                    glrMax = std::max(glrMax, tail * tail / segment);
                }
            }
            out[m]->glrMaxima.push_back(glrMax);
            out[m]->cusumMaxima.push_back(cusumMax);
        }
    }
    const int allowed = allowedExceedances(o);
    for (auto& d : out) {
        std::sort(d->glrMaxima.begin(), d->glrMaxima.end());
        std::sort(d->cusumMaxima.begin(), d->cusumMaxima.end());
        d->glrThreshold = upperThreshold(d->glrMaxima, allowed);
        d->cusumThreshold = upperThreshold(d->cusumMaxima, allowed);
    }
    return out;
}

} // namespace

Status ChangePointOptions::validate() const {
    if (!(falseAlarmRate > 0 && falseAlarmRate < 0.5)) {
        return invalidOption("falseAlarmRate", "the false-alarm rate must be in (0, 0.5)");
    }
    if (minSegment < 1) {
        return invalidOption("minSegment", "the shortest segment must be at least one window");
    }
    if (!(cusumK >= 0) || !std::isfinite(cusumK)) {
        return invalidOption("cusumK", "the CUSUM reference value must be a finite number ≥ 0");
    }
    if (simulations < 100 || simulations > 1000000) {
        return invalidOption("simulations",
                             "the number of Monte Carlo sequences must be between 100 and 1e6");
    }
    if (allowedExceedances(*this) < 0) {
        return invalidOption("simulations",
                             "too few Monte Carlo sequences to resolve a false-alarm rate of " +
                                 std::to_string(falseAlarmRate) + "; use at least " +
                                 std::to_string(static_cast<int>(std::ceil(1 / falseAlarmRate))));
    }
    return {};
}

double NullDistribution::pValue(double glr) const {
    const auto below = std::lower_bound(glrMaxima.begin(), glrMaxima.end(), glr);
    const auto atOrAbove = static_cast<double>(glrMaxima.end() - below);
    return (atOrAbove + 1) / (static_cast<double>(glrMaxima.size()) + 1);
}

NullModel NullModel::iid(int length) {
    NullModel m;
    m.runLengths = {std::max(0, length)};
    return m;
}

int NullModel::length() const {
    int n = 0;
    for (int l : runLengths) {
        n += std::max(0, l);
    }
    return n;
}

std::vector<std::shared_ptr<const NullDistribution>> nullDistributions(const std::vector<NullModel>& models,
                                                                       const ChangePointOptions& options) {
    using Key =
        std::tuple<std::vector<int>, std::vector<char>, double, double, int, double, double, int, unsigned>;
    static std::mutex mutex;
    static std::map<Key, std::shared_ptr<const NullDistribution>> cache;
    std::vector<Key> keys;
    std::vector<std::shared_ptr<const NullDistribution>> out(models.size());
    // By runs (and which runs' levels are free): each group simulated together.
    std::map<std::pair<std::vector<int>, std::vector<char>>, std::vector<std::size_t>> missing;
    {
        std::lock_guard lock(mutex);
        for (std::size_t i = 0; i < models.size(); ++i) {
            std::vector<int> runs = models[i].runLengths;
            for (int& l : runs) {
                l = std::max(0, l);
            }
            keys.emplace_back(runs, models[i].levelFree, models[i].runEffectVariance,
                              models[i].offsetVariance, options.minSegment, options.falseAlarmRate,
                              options.cusumK, options.simulations, options.seed);
            if (auto it = cache.find(keys.back()); it != cache.end()) {
                out[i] = it->second;
            } else {
                missing[{runs, models[i].levelFree}].push_back(i);
            }
        }
    }
    // Simulated outside the lock: two threads asking for the same new model both compute it
    // (the same numbers, the seed is fixed) rather than one waiting on the other's lock.
    for (const auto& [runsAndLevels, indices] : missing) {
        std::vector<NullModel> group;
        for (std::size_t i : indices) {
            group.push_back(models[i]);
            group.back().runLengths = runsAndLevels.first;
        }
        const auto simulated = simulate(group, options);
        std::lock_guard lock(mutex);
        if (cache.size() >= 256) {
            cache.clear(); // a bound, not an LRU: the models of one session are few
        }
        for (std::size_t g = 0; g < indices.size(); ++g) {
            out[indices[g]] = cache.emplace(keys[indices[g]], simulated[g]).first->second;
        }
    }
    return out;
}

std::shared_ptr<const NullDistribution> nullDistribution(const NullModel& model,
                                                         const ChangePointOptions& options) {
    return nullDistributions({model}, options).front();
}

GlrScan scanGlr(const std::vector<double>& z, int minSegment, int lastOnset) {
    GlrScan s;
    const int n = static_cast<int>(z.size());
    s.glr.assign(z.size(), 0.0);
    int last = n - std::max(1, minSegment);
    if (lastOnset >= 0) {
        last = std::min(last, lastOnset);
    }
    double tail = 0;
    for (int tau = n - 1; tau >= 0; --tau) {
        tail += z[static_cast<std::size_t>(tau)];
        if (tau <= last && tail > 0) {
            s.glr[static_cast<std::size_t>(tau)] = tail * tail / (n - tau);
        }
    }
    for (int tau = 0; tau <= last; ++tau) {
        if (s.glr[static_cast<std::size_t>(tau)] > s.maximum) {
            s.maximum = s.glr[static_cast<std::size_t>(tau)];
            s.onset = tau;
        }
    }
    if (s.onset < 0) {
        return s;
    }
    const double floor = s.maximum - kChi2Level95;
    s.low = s.high = s.onset;
    while (s.low > 0 && s.glr[static_cast<std::size_t>(s.low - 1)] >= floor &&
           s.glr[static_cast<std::size_t>(s.low - 1)] > 0) {
        --s.low;
    }
    while (s.high < last && s.glr[static_cast<std::size_t>(s.high + 1)] >= floor &&
           s.glr[static_cast<std::size_t>(s.high + 1)] > 0) {
        ++s.high;
    }
    return s;
}

std::vector<double> cusumPath(const std::vector<double>& z, double k) {
    std::vector<double> path(z.size());
    double s = 0;
    for (std::size_t t = 0; t < z.size(); ++t) {
        s = std::max(0.0, s + z[t] - k);
        path[t] = s;
    }
    return path;
}

Expected<ChangePointResult> detectChangePoint(const std::vector<double>& z, const NullModel& model,
                                              const ChangePointOptions& options) {
    if (Status s = options.validate(); !s) {
        return s.error();
    }
    if (model.length() != static_cast<int>(z.size())) {
        return Error{ErrorKind::Usage, "changepoint.detect",
                     "the null model covers " + std::to_string(model.length()) + " values, the series has " +
                         std::to_string(z.size())};
    }
    const auto null = nullDistribution(model, options);
    ChangePointResult r;
    r.scan = scanGlr(z, options.minSegment);
    r.glr = r.scan.maximum;
    r.glrThreshold = null->glrThreshold;
    r.pValue = null->pValue(r.glr);
    r.changed = r.scan.onset >= 0 && r.glr > r.glrThreshold;
    r.cusum = cusumPath(z, options.cusumK);
    r.cusumThreshold = null->cusumThreshold;
    for (std::size_t t = 0; t < r.cusum.size(); ++t) {
        if (r.cusum[t] > r.cusumThreshold) {
            r.firstAlarm = static_cast<int>(t);
            break;
        }
    }
    return r;
}

Expected<LongRunNull> longRunNull(const std::vector<std::vector<double>>& runs, const std::string& place) {
    LongRunNull null;
    double sum = 0;
    std::size_t longest = 0;
    std::vector<double> runMeans;
    for (const auto& s : runs) {
        double runSum = 0;
        for (double v : s) {
            runSum += v;
        }
        sum += runSum;
        runMeans.push_back(s.empty() ? 0.0 : runSum / static_cast<double>(s.size()));
        null.windows += static_cast<int>(s.size());
        longest = std::max(longest, s.size());
    }
    if (null.windows < 2) {
        return Error{ErrorKind::BadInput,
                     place,
                     "a long-run variance needs at least two values",
                     ErrorCode::NotEnoughData,
                     {"null values", std::to_string(null.windows)}};
    }
    const double n = null.windows;
    null.mean = sum / n;
    // About each run's own mean: a run's level offset belongs to τ², not to the within-run memory.
    const int maxLag = std::max(1, std::min(static_cast<int>(longest) - 1, null.windows / 4));
    std::vector<double> gamma(static_cast<std::size_t>(maxLag) + 1, 0.0);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const auto& s = runs[k];
        for (std::size_t l = 0; l < gamma.size() && l < s.size(); ++l) {
            for (std::size_t t = l; t < s.size(); ++t) {
                gamma[l] += (s[t] - runMeans[k]) * (s[t - l] - runMeans[k]) / n;
            }
        }
    }
    if (!(gamma[0] > 0)) {
        return Error{ErrorKind::Numerical,
                     place,
                     "the statistic does not vary under the null",
                     ErrorCode::SolverFailed,
                     {"long-run null", "zero variance"}};
    }
    // The larger of the rule-of-thumb n^(1/3) and the series' own memory: a too-short window
    // underestimates σ_lr and turns a persistent but healthy wander into alarms.
    int firstSmall = maxLag;
    for (int l = 1; l <= maxLag; ++l) {
        if (std::abs(gamma[static_cast<std::size_t>(l)] / gamma[0]) < 0.05) {
            firstSmall = l;
            break;
        }
    }
    const int bandwidth = std::min(maxLag, std::max(static_cast<int>(std::lround(std::cbrt(n))), firstSmall));
    double v = gamma[0];
    for (int l = 1; l <= bandwidth; ++l) {
        v += 2.0 * (1.0 - static_cast<double>(l) / (bandwidth + 1)) * gamma[static_cast<std::size_t>(l)];
    }
    null.bandwidth = bandwidth;
    null.longRunSd = std::sqrt(std::max(v, 1e-6 * gamma[0]));

    // Between-run variance of run means, in units of σ_lr: Σ n_k (m_k − m)² / (N − Σ n_k² / N).
    // The method of moments would first subtract the K − 1 that within-run noise explains, but
    // with 2–4 runs that difference is 0 half the time and huge the other half, and the CUSUM
    // threshold swung from 10 to 200 with it. Not subtracting overstates τ² by about 1/n (a
    // run's share of within-run noise), which keeps the null conservative and stable; with
    // the subtraction, 2 reference runs gave 3 % CUSUM false alarms against 1 % asked.
    double q = 0, sumSquares = 0;
    int used = 0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const double nk = static_cast<double>(runs[k].size());
        if (nk > 0) {
            const double d = (runMeans[k] - null.mean) / null.longRunSd;
            q += nk * d * d;
            sumSquares += nk * nk;
            ++used;
        }
    }
    const double spread = n - sumSquares / n;
    null.runEffectVariance = used > 1 && spread > 0 ? q / spread : 0.0;
    // From 3-4 runs the estimate has 2-3 degrees of freedom and falls short of the truth half the
    // time; a new period then sits beyond the null's run effects by chance (healthy pairs of the
    // distributed plant: 4 of 20 alarmed with the point estimate). Its upper 75 % confidence bound,
    // (K − 1) τ̂² / χ²_{0.25, K−1}, keeps the stated rate under that uncertainty (2.5x τ̂² for 4 runs).
    if (used > 1) {
        const boost::math::chi_squared chi(static_cast<double>(used - 1));
        null.runEffectVariance *= static_cast<double>(used - 1) / boost::math::quantile(chi, 0.25);
    }
    null.offsetVariance = (n + null.runEffectVariance * sumSquares) / (n * n); // Var(mean) with run effects
    return null;
}

} // namespace drytwin::monitoring
