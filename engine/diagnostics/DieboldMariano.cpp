#include "diagnostics/DieboldMariano.h"

#include <boost/math/distributions/normal.hpp>
#include <cmath>

namespace drytwin::diagnostics {

Expected<DieboldMarianoResult> dieboldMariano(const std::vector<double>& e1, const std::vector<double>& e2,
                                              const DieboldMarianoOptions& options) {
    if (e1.size() != e2.size()) {
        return Error{ErrorKind::BadInput, "dieboldMariano", "the two error series differ in length"};
    }
    std::vector<double> d;
    d.reserve(e1.size());
    for (std::size_t i = 0; i < e1.size(); ++i) {
        if (!std::isfinite(e1[i]) || !std::isfinite(e2[i])) {
            continue;
        }
        d.push_back(options.loss == ForecastLoss::Squared ? e1[i] * e1[i] - e2[i] * e2[i]
                                                          : std::abs(e1[i]) - std::abs(e2[i]));
    }
    const auto n = static_cast<int>(d.size());
    if (n < 10) {
        return Error{ErrorKind::BadInput, "dieboldMariano", "fewer than 10 paired errors"};
    }
    double mean = 0;
    for (double v : d) {
        mean += v;
    }
    mean /= n;
    const int lag = options.hacLag >= 0 ? options.hacLag
                                        : static_cast<int>(std::floor(4.0 * std::pow(n / 100.0, 2.0 / 9.0)));
    auto gamma = [&](int k) {
        double s = 0;
        for (int t = k; t < n; ++t) {
            s += (d[static_cast<std::size_t>(t)] - mean) * (d[static_cast<std::size_t>(t - k)] - mean);
        }
        return s / n;
    };
    double var = gamma(0);
    for (int k = 1; k <= lag && k < n; ++k) {
        var += 2.0 * (1.0 - static_cast<double>(k) / (lag + 1)) * gamma(k);
    }
    DieboldMarianoResult r;
    r.n = n;
    r.hacLag = lag;
    r.meanDifference = mean;
    if (!(var > 0)) {
        // Identical losses everywhere: no evidence either way.
        r.statistic = 0;
        r.pValue = 1;
        return r;
    }
    r.statistic = mean / std::sqrt(var / n);
    const boost::math::normal normal;
    r.pValue = 2.0 * boost::math::cdf(boost::math::complement(normal, std::abs(r.statistic)));
    return r;
}

} // namespace drytwin::diagnostics
