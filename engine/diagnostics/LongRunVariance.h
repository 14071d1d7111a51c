#pragma once

#include <vector>

namespace drytwin::diagnostics {

/// @brief Newey-West (Bartlett kernel) long-run variance of a series: γ_0 + 2 Σ_{l=1..L}
/// (1 − l/(L+1)) γ_l, the variance of √n · mean for an autocorrelated series. With @p demean
/// false the autocovariances are taken about 0 (a score whose mean is 0 under the null).
double longRunVariance(const std::vector<double>& x, int lag, bool demean = true);

/// @brief A HAC bandwidth that respects the series' own memory: the first lag at which its
/// autocorrelation falls below @p threshold, within [1, @p maxLag]. Slowly decaying residuals
/// get a long window (conservative), white ones a short one.
int bandwidthFromAutocorrelation(const std::vector<double>& x, double threshold, int maxLag);

} // namespace drytwin::diagnostics
