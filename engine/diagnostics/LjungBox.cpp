#include "diagnostics/LjungBox.h"

#include "diagnostics/Correlation.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

namespace drytwin::diagnostics {

LjungBoxResult ljungBox(const std::vector<double>& xIn, int lags) {
    std::vector<double> x;
    x.reserve(xIn.size());
    for (double v : xIn) {
        if (std::isfinite(v)) {
            x.push_back(v);
        }
    }
    LjungBoxResult r;
    r.lags = lags;
    const auto n = static_cast<double>(x.size());
    if (lags < 1 || x.size() <= static_cast<std::size_t>(lags) + 1) {
        r.q = std::nan("");
        r.pValue = std::nan("");
        return r;
    }
    const auto rho = autocorrelation(x, lags);
    double s = 0;
    for (int k = 1; k <= lags; ++k) {
        s += rho[static_cast<std::size_t>(k)] * rho[static_cast<std::size_t>(k)] / (n - k);
    }
    r.q = n * (n + 2) * s;
    const boost::math::chi_squared dist(lags);
    r.pValue = boost::math::cdf(boost::math::complement(dist, r.q));
    return r;
}

} // namespace drytwin::diagnostics
