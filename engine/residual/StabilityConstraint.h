#pragma once

#include <Eigen/Dense>

namespace drytwin::residual {

/// @brief Certificate of the stability constraint of Eq. (30): P ≻ 0 and α < 1 with
/// AᵀPA ⪯ α²P, checked numerically.
struct StabilityCertificate {
    double spectralRadiusBefore = 0;
    double spectralRadiusAfter = 0;
    double alpha = 0;
    double certificateMaxEig = 0; ///< λ_max(AᵀPA − α²P); ≤ 0 certifies
    double pMinEig = 0;           ///< λ_min(P); > 0 required
    bool modified = false;        ///< A had to be changed to satisfy the constraint
    bool certified = false;
    Eigen::MatrixXd p;
};

/// @brief Solves the scaled discrete Lyapunov equation (A/α)ᵀP(A/α) − P = −I by the doubling
/// algorithm (exact for ρ(A) < α; then AᵀPA − α²P = −α²I).
Eigen::MatrixXd scaledLyapunov(const Eigen::MatrixXd& a, double alpha);

/// @brief Enforces ρ(A) < α ≤ @p alphaMax < 1 with as small a change as it can: eigenvalues
/// outside radius @p radiusMax are pulled radially onto it (A = VΛV⁻¹, phases kept), or A is
/// scaled when V is ill-conditioned; then P is found and the inequality verified.
/// The paper suggests alternating ridge and an SDP; this projection plus a Lyapunov
/// certificate is cheaper and keeps every eigenvector of the unconstrained fit.
StabilityCertificate enforceStability(Eigen::MatrixXd& a, double alphaMax = 0.999, double radiusMax = 0.995);

/// @brief Checks a certificate independently of how it was made.
StabilityCertificate certify(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, double alpha);

} // namespace drytwin::residual
