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
    /// Checked apart from the solver: α²P − AᵀPA factors by Cholesky (positive definite).
    bool choleskyPasses = false;
    double pConditionNumber = 0; ///< λ_max(P)/λ_min(P); large means a fragile certificate
    Eigen::MatrixXd p;
};

/// @brief The weighted ridge of Eq. (30) in normal-equation form: minimise over Θ = [A B E]
/// the loss tr(Θ G Θᵀ) − 2 tr(H Θᵀ) + c, where G = RᵀWR + Λ (regressors [x, u, d] per snapshot,
/// ridge on the diagonal) and H = X₊ᵀWR. The first @p stateSize columns of Θ are A.
struct RidgeNormalEquations {
    Eigen::MatrixXd gram;    ///< G, p × p
    Eigen::MatrixXd cross;   ///< H, n_x × p
    double targetEnergy = 0; ///< c = ‖W^½X₊‖², so that the loss is the weighted squared error
    Eigen::Index stateSize = 0;
    double loss(const Eigen::MatrixXd& theta) const;
};

/// @brief Result of the constrained fit of Eq. (30).
struct ConstrainedFit {
    Eigen::MatrixXd theta; ///< [A B E] with AᵀPA ⪯ α²P
    StabilityCertificate certificate;
    int outerIterations = 0; ///< P updates
    int admmIterations = 0;  ///< in total
    bool converged = false;  ///< the last ADMM met its tolerance
};

/// @brief Eq. (30) as the paper states it: A, B, E minimise the weighted ridge loss subject to
/// AᵀPA ⪯ α²P for some P ≻ 0. For a fixed P the problem is convex: with P = LLᵀ and
/// Ã = LᵀAL⁻ᵀ the constraint is ‖Ã‖₂ ≤ α, so ADMM alternates a Sylvester solve for the loss
/// (in the eigenbases of (LᵀL)⁻¹ and the transformed Gram matrix) with clipping Ã's singular
/// values. P is then renewed from the Lyapunov equation of the new A (which keeps A feasible,
/// so the loss never rises), and the two steps alternate. Starts from a feasible
/// (@p thetaStart, @p pStart) pair, e.g. the eigenvalue-pulled fit; the result is never worse.
/// Hand-written because the packaged SDP solvers (CSDP, DSDP) take the LMI in P but not the
/// least-squares objective in A jointly, and an SDP of this size (n_x ≈ 100, so ~10⁴ variables)
/// would be far slower than the 5 s training budget.
ConstrainedFit fitUnderStabilityConstraint(const RidgeNormalEquations& problem,
                                           const Eigen::MatrixXd& thetaStart, const Eigen::MatrixXd& pStart,
                                           double alpha, int maxOuter = 3, int maxAdmm = 250);

/// @brief Solves the scaled discrete Lyapunov equation (A/α)ᵀP(A/α) − P = −I by the doubling
/// algorithm (exact for ρ(A) < α; then AᵀPA − α²P = −α²I).
Eigen::MatrixXd scaledLyapunov(const Eigen::MatrixXd& a, double alpha);

/// @brief Enforces ρ(A) < α ≤ @p alphaMax < 1 with as small a change as it can: eigenvalues
/// outside radius @p radiusMax are pulled radially onto it (A = VΛV⁻¹, phases kept), or A is
/// scaled when V is ill-conditioned; then P is found and the inequality verified.
/// The paper suggests alternating ridge and an SDP; this projection plus a Lyapunov
/// certificate is cheaper and keeps every eigenvector of the unconstrained fit.
StabilityCertificate enforceStability(Eigen::MatrixXd& a, double alphaMax = 0.999, double radiusMax = 0.995);

/// @brief Checks a certificate independently of how it was made: the eigenvalue bound, the
/// Cholesky factorisation of α²P − AᵀPA and the condition number of P.
StabilityCertificate certify(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, double alpha);

} // namespace drytwin::residual
