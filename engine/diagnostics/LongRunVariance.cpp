#include "diagnostics/LongRunVariance.h"

#include "diagnostics/Correlation.h"

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
    // Computed only up to the first lag below the threshold (discovery asks for this thousands of
    // times; the whole autocorrelation up to maxLag was a tenth of `drytwin discover`'s time).
    const auto acf = autocorrelation(x, maxLag, threshold);
    for (int l = 1; l < static_cast<int>(acf.size()); ++l) {
        if (!(std::abs(acf[static_cast<std::size_t>(l)]) >= threshold)) {
            return l;
        }
    }
    return maxLag;
}

} // namespace drytwin::diagnostics
