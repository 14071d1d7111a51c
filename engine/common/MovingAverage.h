#pragma once

#include <cstddef>
#include <vector>

namespace drytwin {

/// @brief Centred moving average of @p v over a window of @p windowS in the time @p t (sorted):
/// each value is the mean of the samples within ±windowS/2 of its time. O(n), two pointers.
inline std::vector<double> centredMovingAverage(const std::vector<double>& t, const std::vector<double>& v,
                                                double windowS) {
    std::vector<double> out(v.size());
    std::size_t lo = 0, hi = 0;
    double sum = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        while (hi < v.size() && t[hi] <= t[i] + windowS / 2) {
            sum += v[hi++];
        }
        while (t[lo] < t[i] - windowS / 2) {
            sum -= v[lo++];
        }
        out[i] = sum / static_cast<double>(hi - lo);
    }
    return out;
}

} // namespace drytwin
