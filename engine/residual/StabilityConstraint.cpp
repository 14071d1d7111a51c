#include "residual/StabilityConstraint.h"

#include "diagnostics/Stability.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace drytwin::residual {

Eigen::MatrixXd scaledLyapunov(const Eigen::MatrixXd& a, double alpha) {
    // P = Σ_j (Ãᵀ)^j Ã^j with Ã = A/α, summed by doubling: P ← P + ÃₖᵀPÃₖ, Ãₖ ← Ãₖ².
    Eigen::MatrixXd at = a / alpha;
    Eigen::MatrixXd p = Eigen::MatrixXd::Identity(a.rows(), a.cols());
    for (int it = 0; it < 60; ++it) {
        const Eigen::MatrixXd next = p + at.transpose() * p * at;
        const double change = (next - p).norm() / std::max(1.0, next.norm());
        p = next;
        at = at * at;
        if (change < 1e-15 || at.norm() < 1e-300) {
            break;
        }
    }
    return 0.5 * (p + p.transpose());
}

StabilityCertificate certify(const Eigen::MatrixXd& a, const Eigen::MatrixXd& p, double alpha) {
    StabilityCertificate c;
    c.alpha = alpha;
    c.p = p;
    c.spectralRadiusAfter = diagnostics::spectralRadius(a);
    c.certificateMaxEig = diagnostics::certificateMaxEigenvalue(a, p, alpha);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (p + p.transpose()), Eigen::EigenvaluesOnly);
    c.pMinEig = es.eigenvalues().minCoeff();
    // Relative round-off allowance: the certificate is a difference of O(‖P‖) terms.
    c.certified = alpha < 1 && c.pMinEig > 0 && c.certificateMaxEig <= 1e-12 * p.norm();
    return c;
}

StabilityCertificate enforceStability(Eigen::MatrixXd& a, double alphaMax, double radiusMax) {
    const double before = diagnostics::spectralRadius(a);
    bool modified = false;
    if (before > radiusMax) {
        Eigen::EigenSolver<Eigen::MatrixXd> es(a);
        const Eigen::MatrixXcd v = es.eigenvectors();
        Eigen::VectorXcd lambda = es.eigenvalues();
        Eigen::FullPivLU<Eigen::MatrixXcd> lu(v);
        const double cond = lu.rcond();
        if (lu.isInvertible() && cond > 1e-10) {
            for (Eigen::Index i = 0; i < lambda.size(); ++i) {
                const double m = std::abs(lambda(i));
                if (m > radiusMax) {
                    lambda(i) *= radiusMax / m;
                }
            }
            const Eigen::MatrixXcd pulled = v * lambda.asDiagonal() * lu.inverse();
            a = pulled.real();
        } else {
            a *= radiusMax / before;
        }
        // Round-off in VΛV⁻¹ may leave the radius a hair above the target: scale the rest away.
        const double after = diagnostics::spectralRadius(a);
        if (after > radiusMax) {
            a *= radiusMax / after;
        }
        modified = true;
    }
    const double rho = diagnostics::spectralRadius(a);
    // α halfway between ρ(A) and alphaMax keeps P well conditioned.
    double alpha = std::min(alphaMax, 0.5 * (rho + std::max(alphaMax, rho + 1e-6)));
    StabilityCertificate c;
    for (int attempt = 0; attempt < 5; ++attempt) {
        c = certify(a, scaledLyapunov(a, alpha), alpha);
        if (c.certified) {
            break;
        }
        alpha = std::min(alphaMax, alpha + 0.5 * (alphaMax - alpha));
    }
    c.spectralRadiusBefore = before;
    c.modified = modified;
    return c;
}

} // namespace drytwin::residual
