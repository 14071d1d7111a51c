#pragma once
// What the input-driven correction's files share (InputDrivenBasis.cpp, InputDrivenCorrection.cpp):
// the inputs' count and the spike filter's settings.
#include <limits>

namespace drytwin::residual::input_driven {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr int kProxyInputs = 8; ///< six proxy states and the PBM's two outlet outputs
/// Hot air, feed, inlet moisture and temperature, ambient T and RH, air speed.
inline constexpr int kMeasuredInputs = 7;
// Transmitter spikes (TrailingHampel.h): up to 10 samples long, 6 robust standard deviations
// from the last 21 samples' median and at least one standard deviation of the training data.
inline constexpr int kDespikeWindow = 21;
inline constexpr double kDespikeCutoff = 6.0;
inline constexpr double kDespikeFloor = 1.0;

} // namespace drytwin::residual::input_driven
