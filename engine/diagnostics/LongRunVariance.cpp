#include "diagnostics/LongRunVariance.h"

#include "diagnostics/Metrics.h"

#include <algorithm>
#include <cmath>

namespace drytwin::diagnostics {

double longRunVariance(const std::vector<double>& x, int lag, bool demean) {
    const std::size_t n = x.size();
    if (n == 0) {
        return 0;
    }
    double m = 0;
    if (demean) {
        for (double v : x) {
            m += v;
        }
        m /= static_cast<double>(n);
    }
    auto gamma = [&](std::size_t k) {
        double s = 0;
        for (std::size_t t = k; t < n; ++t) {
            s += (x[t] - m) * (x[t - k] - m);
        }
        return s / static_cast<double>(n);
    };
    double v = gamma(0);
    for (int l = 1; l <= lag && static_cast<std::size_t>(l) < n; ++l) {
        v += 2.0 * (1.0 - static_cast<double>(l) / (lag + 1)) * gamma(static_cast<std::size_t>(l));
    }
    return std::max(v, 0.0);
}

int bandwidthFromAutocorrelation(const std::vector<double>& x, double threshold, int maxLag) {
    maxLag = std::max(1, std::min(maxLag, static_cast<int>(x.size()) / 2));
    // autocorrelation()'s values lag by lag, stopping at the first below the threshold: the
    // bandwidth is usually a few lags of a maxLag in the hundreds, and discovery asks for it
    // thousands of times (it was a tenth of `drytwin discover`'s time on the demo).
    const std::size_t n = x.size();
    const int lags = std::max(0, std::min<int>(maxLag, static_cast<int>(n) - 1));
    const double m = n ? mean(x) : 0.0;
    double denom = 0;
    for (double v : x) {
        denom += (v - m) * (v - m);
    }
    for (int l = 1; l <= lags; ++l) {
        const auto k = static_cast<std::size_t>(l);
        double s = 0;
        for (std::size_t t = 0; t + k < n; ++t) {
            s += (x[t] - m) * (x[t + k] - m);
        }
        const double acf = denom > 0 ? s / denom : 0.0;
        if (!(std::abs(acf) >= threshold)) {
            return l;
        }
    }
    return maxLag;
}

} // namespace drytwin::diagnostics
