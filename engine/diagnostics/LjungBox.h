#pragma once

#include <vector>

namespace drytwin::diagnostics {

/// @brief Ljung-Box portmanteau test result.
struct LjungBoxResult {
    double q = 0;      ///< Q = n(n+2) Σ_{k=1..h} ρ_k² / (n − k)
    double pValue = 1; ///< P(χ²_h > Q)
    int lags = 0;
};

/// @brief Ljung-Box test of whiteness over @p lags lags (statsmodels `acorr_ljungbox`, no df
/// correction). NaN values are dropped first. The χ² tail comes from Boost.Math.
LjungBoxResult ljungBox(const std::vector<double>& x, int lags);

} // namespace drytwin::diagnostics
