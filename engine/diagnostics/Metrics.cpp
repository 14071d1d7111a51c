#include "diagnostics/Metrics.h"

#include <cmath>
#include <limits>

namespace drytwin::diagnostics {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
bool finitePair(double a, double b) {
    return std::isfinite(a) && std::isfinite(b);
}
} // namespace

double mean(const std::vector<double>& x) {
    if (x.empty()) {
        return kNaN;
    }
    double s = 0;
    for (double v : x) {
        s += v;
    }
    return s / static_cast<double>(x.size());
}

double meanAbsoluteError(const std::vector<double>& observed, const std::vector<double>& predicted) {
    double s = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < observed.size() && i < predicted.size(); ++i) {
        if (finitePair(observed[i], predicted[i])) {
            s += std::abs(observed[i] - predicted[i]);
            ++n;
        }
    }
    return n ? s / static_cast<double>(n) : kNaN;
}

double rootMeanSquaredError(const std::vector<double>& observed, const std::vector<double>& predicted) {
    double s = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < observed.size() && i < predicted.size(); ++i) {
        if (finitePair(observed[i], predicted[i])) {
            const double d = observed[i] - predicted[i];
            s += d * d;
            ++n;
        }
    }
    return n ? std::sqrt(s / static_cast<double>(n)) : kNaN;
}

double rSquared(const std::vector<double>& observed, const std::vector<double>& predicted) {
    double m = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < observed.size() && i < predicted.size(); ++i) {
        if (finitePair(observed[i], predicted[i])) {
            m += observed[i];
            ++n;
        }
    }
    if (n < 2) {
        return kNaN;
    }
    m /= static_cast<double>(n);
    double ssRes = 0;
    double ssTot = 0;
    for (std::size_t i = 0; i < observed.size() && i < predicted.size(); ++i) {
        if (finitePair(observed[i], predicted[i])) {
            ssRes += (observed[i] - predicted[i]) * (observed[i] - predicted[i]);
            ssTot += (observed[i] - m) * (observed[i] - m);
        }
    }
    return ssTot > 0 ? 1.0 - ssRes / ssTot : kNaN;
}

} // namespace drytwin::diagnostics
