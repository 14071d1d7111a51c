#pragma once

#include <vector>

namespace drytwin::diagnostics {

/// @brief Sample autocorrelation for lags 0..maxLag:
/// ρ_k = Σ_t (x_t − m)(x_{t+k} − m) / Σ_t (x_t − m)², as statsmodels `acf(adjusted=False)`.
/// With @p stopBelow > 0 the lags end at the first k ≥ 1 with |ρ_k| < stopBelow (included): a
/// bandwidth search needs no more, and maxLag is often a hundred times further.
std::vector<double> autocorrelation(const std::vector<double>& x, int maxLag, double stopBelow = 0);

/// @brief Cross-correlation for lags 0..maxLag: ccf_k = corr(x_{t+k}, y_t), the lagged sum of
/// products divided by n (or by n − k when @p adjusted) and by the population standard
/// deviations; the default reproduces statsmodels 0.13.5 `ccf` in the fixtures.
/// A peak at k > 0 means x follows y by k samples.
std::vector<double> crossCorrelation(const std::vector<double>& x, const std::vector<double>& y, int maxLag,
                                     bool adjusted = false);

} // namespace drytwin::diagnostics
