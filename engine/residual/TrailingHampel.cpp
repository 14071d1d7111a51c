#include "residual/TrailingHampel.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace drytwin::residual {

namespace {

double medianOf(std::vector<double>& v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

Eigen::Index despikeTrailing(Eigen::MatrixXd& series, Eigen::Index columns, int window, double cutoff,
                             double floor) {
    Eigen::Index replaced = 0;
    std::vector<double> past, deviation;
    for (Eigen::Index j = 0; j < std::min(columns, series.cols()); ++j) {
        // The window holds the raw values: a genuine step must become its median after window / 2
        // samples (a window of cleaned values would hold the old level for ever).
        const Eigen::VectorXd raw = series.col(j);
        for (Eigen::Index k = window; k < series.rows(); ++k) {
            past.assign(raw.data() + (k - window), raw.data() + k);
            const double middle = medianOf(past);
            deviation.resize(past.size());
            for (std::size_t i = 0; i < past.size(); ++i) {
                deviation[i] = std::abs(past[i] - middle);
            }
            const double spread = 1.4826 * medianOf(deviation);
            const double x = raw(k);
            if (std::isfinite(x) && std::isfinite(spread) &&
                std::abs(x - middle) > std::max(cutoff * spread, floor)) {
                series(k, j) = middle;
                ++replaced;
            }
        }
    }
    return replaced;
}

} // namespace drytwin::residual
