#pragma once

#include <vector>

namespace drytwin::diagnostics {

/// @brief Sample autocorrelation for lags 0..maxLag:
/// ρ_k = Σ_t (x_t − m)(x_{t+k} − m) / Σ_t (x_t − m)², as statsmodels `acf(adjusted=False)`.
std::vector<double> autocorrelation(const std::vector<double>& x, int maxLag);

/// @brief Cross-correlation for lags 0..maxLag: ccf_k = corr(x_{t+k}, y_t), the lagged sum of
/// products divided by n (or by n − k when @p adjusted) and by the population standard
/// deviations; the default reproduces statsmodels 0.13.5 `ccf` in the fixtures.
/// A peak at k > 0 means x follows y by k samples.
std::vector<double> crossCorrelation(const std::vector<double>& x, const std::vector<double>& y, int maxLag,
                                     bool adjusted = false);

} // namespace drytwin::diagnostics
