#include "residual/StabilityConstraint.h"

#include "diagnostics/Stability.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

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
    c.pConditionNumber =
        c.pMinEig > 0 ? es.eigenvalues().maxCoeff() / c.pMinEig : std::numeric_limits<double>::infinity();
    const Eigen::MatrixXd margin = alpha * alpha * p - a.transpose() * p * a;
    c.choleskyPasses =
        Eigen::LLT<Eigen::MatrixXd>(0.5 * (margin + margin.transpose())).info() == Eigen::Success;
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

double RidgeNormalEquations::loss(const Eigen::MatrixXd& theta) const {
    return (theta * gram).cwiseProduct(theta).sum() - 2.0 * cross.cwiseProduct(theta).sum() + targetEnergy;
}

namespace {

/// Clips the singular values of @p m at @p alpha: the Frobenius-nearest matrix of norm ≤ α.
/// Through the eigen-decomposition MᵀM = VS²Vᵀ (several times faster than an SVD at n ≈ 100):
/// M V diag(min(1, α/s)) Vᵀ scales exactly the singular directions beyond α.
Eigen::MatrixXd clipSingularValues(const Eigen::MatrixXd& m, double alpha) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(m.transpose() * m);
    const Eigen::VectorXd s2 = es.eigenvalues();
    if (s2.maxCoeff() <= alpha * alpha) {
        return m;
    }
    Eigen::VectorXd factor(s2.size());
    for (Eigen::Index i = 0; i < s2.size(); ++i) {
        factor(i) = s2(i) > alpha * alpha ? alpha / std::sqrt(s2(i)) : 1.0;
    }
    const Eigen::MatrixXd& v = es.eigenvectors();
    return m * (v * factor.asDiagonal() * v.transpose());
}

/// The same clipping inside the ADMM loop, where M changes little from one iteration to the next
/// and only a few singular values exceed α: a block power (subspace) iteration on MᵀM, warm
/// started from the last iteration's right singular vectors, finds them at O(n² k) instead of
/// O(n³). When the block is too small to hold every singular value above α, it grows; when it
/// does not settle it falls back to the exact clip. The final iterate is always clipped exactly.
class FastClipper {
public:
    explicit FastClipper(Eigen::Index n) : m_n(n) {}

    Eigen::MatrixXd clip(const Eigen::MatrixXd& m, double alpha) {
        const Eigen::Index k = std::min<Eigen::Index>(m_n, m_block);
        if (m_basis.cols() != k) {
            m_basis = Eigen::MatrixXd::Identity(m_n, k);
        }
        Eigen::MatrixXd q = m_basis;
        Eigen::VectorXd sigma2;
        Eigen::MatrixXd v;
        for (int it = 0; it < 6; ++it) {
            q = Eigen::HouseholderQR<Eigen::MatrixXd>(m.transpose() * (m * q)).householderQ() *
                Eigen::MatrixXd::Identity(m_n, k);
            // Rayleigh–Ritz on the block.
            const Eigen::MatrixXd mq = m * q;
            const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(mq.transpose() * mq);
            sigma2 = es.eigenvalues();
            v = q * es.eigenvectors();
            const Eigen::MatrixXd resid = m.transpose() * (m * v) - v * sigma2.asDiagonal();
            if (resid.norm() < 1e-10 * std::max(1.0, sigma2.maxCoeff())) {
                break;
            }
        }
        m_basis = v;
        // The smallest Ritz value must be below α², or the block may miss one above it.
        if (sigma2.minCoeff() > alpha * alpha && k < m_n) {
            m_block = std::min<Eigen::Index>(m_n, 2 * m_block);
            m_basis.resize(0, 0);
            return clipSingularValues(m, alpha);
        }
        Eigen::MatrixXd out = m;
        for (Eigen::Index i = 0; i < sigma2.size(); ++i) {
            if (sigma2(i) > alpha * alpha) {
                // M − (1 − α/σ) M v vᵀ scales the singular value σ of direction v to α.
                const Eigen::VectorXd vi = v.col(i);
                out -= (1.0 - alpha / std::sqrt(sigma2(i))) * (m * vi) * vi.transpose();
            }
        }
        return out;
    }

private:
    Eigen::Index m_n;
    Eigen::Index m_block = 8;
    Eigen::MatrixXd m_basis;
};

} // namespace

ConstrainedFit fitUnderStabilityConstraint(const RidgeNormalEquations& prob,
                                           const Eigen::MatrixXd& thetaStart, const Eigen::MatrixXd& pStart,
                                           double alpha, int maxOuter, int maxAdmm) {
    const Eigen::Index nx = prob.stateSize;
    const Eigen::Index np = prob.gram.rows();
    ConstrainedFit best;
    best.theta = thetaStart;
    double bestLoss = prob.loss(thetaStart);
    Eigen::MatrixXd p = pStart;
    // The fit keeps a margin below α so that the certificate at α is strict (Cholesky passes).
    const double alphaFit = alpha * (1.0 - 1e-4);
    for (int outer = 0; outer < maxOuter; ++outer) {
        // Coordinates x̃ = Lᵀx: Θ = L⁻ᵀΘ̃T with T = blockdiag(Lᵀ, I); the loss becomes
        // tr(Q(Θ̃G̃Θ̃ᵀ − 2Θ̃H̃ᵀ)) with Q = (LᵀL)⁻¹, G̃ = TGTᵀ, H̃ = LᵀHTᵀ.
        const double pScale = p.diagonal().mean();
        const Eigen::LLT<Eigen::MatrixXd> llt(p / pScale);
        if (llt.info() != Eigen::Success) {
            break;
        }
        const Eigen::MatrixXd l = llt.matrixL();
        const Eigen::MatrixXd lt = l.transpose();
        const Eigen::MatrixXd ltInv =
            lt.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(nx, nx));
        Eigen::MatrixXd t = Eigen::MatrixXd::Identity(np, np);
        t.topLeftCorner(nx, nx) = lt;
        const Eigen::MatrixXd gT = t * prob.gram * t.transpose();
        const Eigen::MatrixXd hT = lt * prob.cross * t.transpose();
        const Eigen::MatrixXd q = (lt * l).inverse();
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eq(0.5 * (q + q.transpose()));
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eg(0.5 * (gT + gT.transpose()));
        const Eigen::MatrixXd& uq = eq.eigenvectors();
        const Eigen::MatrixXd& ug = eg.eigenvectors();
        const Eigen::VectorXd lq = eq.eigenvalues().cwiseMax(0);
        const Eigen::VectorXd lg = eg.eigenvalues().cwiseMax(0);
        // ρ near the geometric middle of the curvature spectrum balances the two ADMM residuals.
        double rho = 2.0 * std::sqrt(lq.maxCoeff() * lq.minCoeff()) *
                     std::sqrt(lg.maxCoeff() * std::max(lg.minCoeff(), 1e-12 * lg.maxCoeff()));
        const Eigen::MatrixXd rhsFixed = uq.transpose() * (2.0 * q * hT) * ug;

        // Start: the best feasible Θ so far, in the new coordinates (feasible here too, below).
        Eigen::MatrixXd thetaT = lt * best.theta;
        thetaT.leftCols(nx) = lt * best.theta.leftCols(nx) * ltInv;
        Eigen::MatrixXd z = thetaT;
        z.leftCols(nx) = clipSingularValues(z.leftCols(nx), alphaFit);
        Eigen::MatrixXd dual = Eigen::MatrixXd::Zero(nx, np);
        FastClipper clipper(nx);
        bool converged = false;
        int it = 0;
        for (; it < maxAdmm; ++it) {
            // Θ̃-step: 2QΘ̃G̃ + ρΘ̃ = 2QH̃ + ρ(Z − U), diagonal in the eigenbases of Q and G̃.
            Eigen::MatrixXd rhs = rhsFixed + rho * (uq.transpose() * (z - dual) * ug);
            for (Eigen::Index i = 0; i < nx; ++i) {
                for (Eigen::Index j = 0; j < np; ++j) {
                    rhs(i, j) /= 2.0 * lq(i) * lg(j) + rho;
                }
            }
            thetaT = uq * rhs * ug.transpose();
            // Z-step: project onto {‖Ã‖₂ ≤ α} (B̃, Ẽ unconstrained).
            const Eigen::MatrixXd zOld = z;
            z = thetaT + dual;
            z.leftCols(nx) = clipper.clip(z.leftCols(nx), alphaFit);
            dual += thetaT - z;
            const double primal = (thetaT - z).norm();
            const double dualRes = rho * (z - zOld).norm();
            const double scale = std::max(1.0, z.norm());
            if (primal < 1e-6 * scale && dualRes < 1e-6 * scale) {
                converged = true;
                ++it;
                break;
            }
            // Residual balancing (Boyd et al., §3.4.1): keep both residuals of one order.
            if (primal > 10 * dualRes) {
                rho *= 2;
                dual /= 2;
            } else if (dualRes > 10 * primal) {
                rho /= 2;
                dual *= 2;
            }
        }
        best.admmIterations += it;
        best.outerIterations = outer + 1;
        best.converged = converged;
        // Back to the original coordinates from the iterate Z, clipped exactly (feasible).
        z.leftCols(nx) = clipSingularValues(z.leftCols(nx), alphaFit);
        Eigen::MatrixXd theta = ltInv * z;
        theta.leftCols(nx) = ltInv * z.leftCols(nx) * lt;
        const double loss = prob.loss(theta);
        const double improvement = bestLoss - loss;
        if (loss < bestLoss) {
            best.theta = theta;
            bestLoss = loss;
        }
        // Renew P for the new A: the Lyapunov solution at a level between ρ(A) and α keeps this A
        // strictly feasible, so the next fit can only lower the loss.
        const Eigen::MatrixXd a = best.theta.leftCols(nx);
        const double rho_a = diagnostics::spectralRadius(a);
        if (!(rho_a < alphaFit) || improvement < 1e-6 * std::abs(bestLoss)) {
            break;
        }
        p = scaledLyapunov(a, 0.5 * (rho_a + alphaFit));
    }
    // Certificate: with the P the fit used at the end, or a Lyapunov one if that fails.
    const Eigen::MatrixXd a = best.theta.leftCols(nx);
    best.certificate = certify(a, p, alpha);
    if (!best.certificate.certified || !best.certificate.choleskyPasses) {
        const double rho_a = diagnostics::spectralRadius(a);
        if (rho_a < alpha) {
            best.certificate = certify(a, scaledLyapunov(a, 0.5 * (rho_a + alpha)), alpha);
        }
    }
    return best;
}

} // namespace drytwin::residual
