#pragma once
// What the input-driven correction's files share (InputDrivenBasis.cpp, InputDrivenCorrection.cpp):
// the inputs' count and the spike filter's settings.
#include <Eigen/Dense>

#include <cstddef>
#include <limits>
#include <vector>

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

/// A contiguous run of stacked training rows that belongs to one cross-validation fold.
struct Segment {
    Eigen::Index begin = 0, end = 0;
    int fold = 0;
    std::size_t view = 0; ///< the batch (view) the rows belong to
};

/// Horizons [steps] at which the weight on the correction's own change is fitted (those of the
/// evaluation's curve and of the lifted model's κ_H).
inline const std::vector<int> kChangeHorizons{1, 2, 5, 10, 20, 30, 45, 60, 90, 120, 150, 180};

/// Per horizon of kChangeHorizons and output, the share μ ∈ [0, 1] (steps of 0.01) of the
/// correction's change over the horizon that best predicts the PBM's error's change there, by
/// least absolute error over the training rows: @p y the PBM's errors, @p heldOut the correction
/// each row got from the fit without its fold, @p rowTime each stacked row's row in its batch.
std::vector<Eigen::Vector2d> fitChangeWeights(const Eigen::MatrixXd& y, const Eigen::MatrixXd& heldOut,
                                              const std::vector<std::size_t>& rowTime,
                                              const std::vector<Segment>& segments);

} // namespace drytwin::residual::input_driven
