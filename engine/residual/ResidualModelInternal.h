#pragma once
// Internals shared by the residual model's source files (not part of the engine's interface).
// ResidualModel's files, one question each: what it starts from, its options and the observed
// residual (ResidualModel.cpp); what the lifted model sees at a row: inputs, features, residuals
// and state (ResidualFeatures.cpp); how A, B, E and C are fitted, Algorithm 1 (ResidualFit.cpp);
// how far the velocity form trusts its correction at each horizon: train(), which cross-validates
// s_H and κ_H around the fit (ResidualCorrectionWeights.cpp); what it predicts
// (ResidualForecast.cpp); and how it is stored (ResidualModelFile.cpp).

#include "residual/ResidualModel.h"

#include <limits>
#include <string>
#include <vector>

namespace drytwin::residual::detail {

inline constexpr int kOutputs = 2; // outlet moisture (% wb) and temperature (°C)
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// PBM outlet changes Δŷ_{k+1}, Δŷ_k used as inputs: the next one carries what the PBM
/// already knows, the current one cancels the PBM's reaction to input noise in e_k.
inline constexpr int kPbmChangeLags = 2;

/// The names of the dictionary's inputs z, in the order inputsAt() forms them.
std::vector<std::string> inputNames(bool proxies);

} // namespace drytwin::residual::detail
