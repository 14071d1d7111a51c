#pragma once

#include <Eigen/Dense>

namespace drytwin::residual {

/// @brief A causal Hampel filter on columns of a series: a value further than
/// @p cutoff robust standard deviations (1.4826 × the median absolute deviation) of the
/// @p window values before it from their median, and further than @p floor in absolute terms,
/// is taken for a transmitter spike and replaced by that median.
///
/// Why trailing and not centred: the input-driven correction is a simulator, fed the inputs
/// as they come (the MPC's plan, a live line), so it must not look ahead. The price: a genuine
/// step larger than the cut-off is held back for up to window / 2 samples, until most of the
/// window has seen it; for a correction with dynamics of minutes a delay of seconds is noise.
/// A spike shorter than window / 2 samples never reaches the median. Returns how many values
/// it replaced.
Eigen::Index despikeTrailing(Eigen::MatrixXd& series, Eigen::Index columns, int window, double cutoff,
                             double floor);

} // namespace drytwin::residual
