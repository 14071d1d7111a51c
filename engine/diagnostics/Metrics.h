#pragma once

#include <cstddef>
#include <vector>

namespace drytwin::diagnostics {

/// @brief Mean absolute error over pairs where both values are finite. NaN when none.
double meanAbsoluteError(const std::vector<double>& observed, const std::vector<double>& predicted);
/// @brief Root mean squared error over finite pairs.
double rootMeanSquaredError(const std::vector<double>& observed, const std::vector<double>& predicted);
/// @brief Coefficient of determination 1 − SS_res/SS_tot over finite pairs (can be negative).
double rSquared(const std::vector<double>& observed, const std::vector<double>& predicted);
/// @brief Mean of a series.
double mean(const std::vector<double>& x);

} // namespace drytwin::diagnostics
