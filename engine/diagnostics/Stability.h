#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace drytwin::diagnostics {

/// @brief Eigenvalues of a square matrix, sorted by decreasing modulus.
std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& a);
/// @brief Spectral radius max |λ_i(A)|.
double spectralRadius(const Eigen::MatrixXd& a);
/// @brief Lyapunov contraction rate of each mode, −ln|λ_i| per step (paper Fig. 6b);
/// +inf for λ = 0, negative for an unstable mode. Same order as eigenvalues().
std::vector<double> contractionRates(const Eigen::MatrixXd& a);
/// @brief Largest eigenvalue of the symmetric matrix AᵀPA − α²P: ≤ 0 certifies A^T P A ⪯ α² P
/// (the stability certificate of Eq. 30).
double certificateMaxEigenvalue(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, double alpha);

} // namespace drytwin::diagnostics
