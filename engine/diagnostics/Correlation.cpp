#include "diagnostics/Correlation.h"

#include "diagnostics/Metrics.h"

#include <algorithm>
#include <cmath>

namespace drytwin::diagnostics {

// Direct O(n·maxLag) sums: for the lag counts used here (≤ a few hundred) they are exact
// and as fast as an FFT-based estimate, and they avoid FFT round-off in the fixtures' 1e-9 check.
std::vector<double> autocorrelation(const std::vector<double>& x, int maxLag, double stopBelow) {
    const std::size_t n = x.size();
    const int lags = std::max(0, std::min<int>(maxLag, static_cast<int>(n) - 1));
    std::vector<double> out(static_cast<std::size_t>(lags) + 1, 0.0);
    if (n == 0) {
        return out;
    }
    const double m = mean(x);
    double denom = 0;
    for (double v : x) {
        denom += (v - m) * (v - m);
    }
    for (int k = 0; k <= lags; ++k) {
        double s = 0;
        for (std::size_t t = 0; t + static_cast<std::size_t>(k) < n; ++t) {
            s += (x[t] - m) * (x[t + static_cast<std::size_t>(k)] - m);
        }
        out[static_cast<std::size_t>(k)] = denom > 0 ? s / denom : 0.0;
        if (k > 0 && stopBelow > 0 && !(std::abs(out[static_cast<std::size_t>(k)]) >= stopBelow)) {
            out.resize(static_cast<std::size_t>(k) + 1);
            break;
        }
    }
    return out;
}

std::vector<double> crossCorrelation(const std::vector<double>& x, const std::vector<double>& y, int maxLag,
                                     bool adjusted) {
    const std::size_t n = std::min(x.size(), y.size());
    const int lags = std::max(0, std::min<int>(maxLag, static_cast<int>(n) - 1));
    std::vector<double> out(static_cast<std::size_t>(lags) + 1, 0.0);
    if (n == 0) {
        return out;
    }
    const std::vector<double> xs(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
    const std::vector<double> ys(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n));
    const double mx = mean(xs);
    const double my = mean(ys);
    double vx = 0;
    double vy = 0;
    for (std::size_t t = 0; t < n; ++t) {
        vx += (xs[t] - mx) * (xs[t] - mx);
        vy += (ys[t] - my) * (ys[t] - my);
    }
    const double sd = std::sqrt(vx / static_cast<double>(n)) * std::sqrt(vy / static_cast<double>(n));
    for (int k = 0; k <= lags; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        double s = 0;
        for (std::size_t t = 0; t + uk < n; ++t) {
            s += (xs[t + uk] - mx) * (ys[t] - my);
        }
        const double cov = s / static_cast<double>(adjusted ? n - uk : n);
        out[uk] = sd > 0 ? cov / sd : 0.0;
    }
    return out;
}

} // namespace drytwin::diagnostics
