#pragma once

#include "common/Error.h"

#include <vector>

namespace drytwin::diagnostics {

/// @brief Loss applied to forecast errors before they are compared.
enum class ForecastLoss { Squared, Absolute };

/// @brief Options of the Diebold-Mariano test.
struct DieboldMarianoOptions {
    ForecastLoss loss = ForecastLoss::Absolute;
    /// Bartlett (Newey-West) lag of the HAC variance; < 0 picks floor(4 (n/100)^(2/9)).
    int hacLag = -1;
};

/// @brief Result: a negative statistic means model 1 has the smaller loss.
struct DieboldMarianoResult {
    double statistic = 0;
    double pValue = 1;         ///< two-sided, standard normal
    double meanDifference = 0; ///< mean of L(e1) − L(e2)
    int hacLag = 0;
    int n = 0;
};

/// @brief Diebold-Mariano test of equal predictive accuracy of two error series of the same
/// length, with a HAC (Newey-West) variance of the loss differential. Pairs with a NaN are dropped.
Expected<DieboldMarianoResult> dieboldMariano(const std::vector<double>& errors1,
                                              const std::vector<double>& errors2,
                                              const DieboldMarianoOptions& options = {});

} // namespace drytwin::diagnostics
