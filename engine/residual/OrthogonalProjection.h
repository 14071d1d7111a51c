#pragma once

#include <Eigen/Dense>

namespace drytwin::residual {

/// @brief Coefficients G of the weighted orthogonal projection of Eq. (27):
/// P⊥Φ_res = Φ_res − Φ_base G with G = (Φ_baseᵀ W Φ_base)⁻¹ Φ_baseᵀ W Φ_res, W = diag(w).
/// Never forms the N × N matrix P⊥; rows are snapshots. A tiny ridge (1e-10 of the largest
/// diagonal) keeps a rank-deficient base set solvable.
Eigen::MatrixXd projectionCoefficients(const Eigen::MatrixXd& base, const Eigen::MatrixXd& residual,
                                       const Eigen::VectorXd& w);

} // namespace drytwin::residual
