// How A, B, E and C are fitted: Algorithm 1, with the weights of Eq. (29) and the constraint of Eq. (30).
#include "residual/ResidualModelInternal.h"

#include "common/Units.h"
#include "diagnostics/Stability.h"
#include "residual/OrthogonalProjection.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace drytwin::residual {

using namespace detail;

namespace {

/// Weighted ridge: Θ minimising Σ_i w_i ‖y_i − Θ r_i‖² + Σ_j λ_j ‖Θ_{:,j}‖², rows are snapshots.
Eigen::MatrixXd weightedRidge(const Eigen::MatrixXd& r, const Eigen::MatrixXd& y, const Eigen::VectorXd& w,
                              const Eigen::VectorXd& lambda) {
    const Eigen::MatrixXd rw = r.array().colwise() * w.array();
    Eigen::MatrixXd gram = r.transpose() * rw;
    gram.diagonal() += lambda;
    const Eigen::MatrixXd rhs = rw.transpose() * y;
    return gram.ldlt().solve(rhs).transpose();
}

} // namespace

Expected<ResidualModel> ResidualModel::trainOnce(const std::vector<BatchView>& training,
                                                 const ResidualOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = o.validate(); !st) {
        return st.error();
    }
    ResidualModel m;
    m.m_options = o;
    m.m_dict = PolynomialDictionary(inputNames(o.useProxies), o.degree);
    const int lags = o.residualLags;

    // 1. Residuals and snapshot rows (k, k+1 both in the training range with valid lags).
    struct Snapshot {
        std::size_t view;
        std::size_t k;
    };
    std::vector<Snapshot> snaps;
    std::vector<std::vector<double>> ex(training.size()), et(training.size());
    for (std::size_t vi = 0; vi < training.size(); ++vi) {
        const auto& v = training[vi];
        const std::size_t n = v.batch->rows();
        if (v.pbm->xOutDb.size() != n) {
            return Error{ErrorKind::BadInput, "residual training",
                         "the PBM run must cover every row of the batch"};
        }
        ex[vi].assign(n, kNaN);
        et[vi].assign(n, kNaN);
        for (std::size_t k = 0; k < n; ++k) {
            observedResidual(*v.batch, *v.pbm, k, ex[vi][k], et[vi][k]);
        }
    }
    if (o.nestReferences) {
        // s of the reference: the share of the PBM's one-step change that the next error gives
        // back, by least squares over the training rows, each output in units of its own
        // one-step change (s = 1: persistence, 0: the PBM's last error held).
        std::array<double, kOutputs> cross{}, pbmEnergy{}, errorEnergy{};
        for (std::size_t vi = 0; vi < training.size(); ++vi) {
            const auto& v = training[vi];
            for (std::size_t k = v.rows.begin + 1; k < v.rows.end; ++k) {
                const double de[kOutputs] = {ex[vi][k] - ex[vi][k - 1], et[vi][k] - et[vi][k - 1]};
                const double dy[kOutputs] = {units::dryToWetPct(v.pbm->xOutDb[k]) -
                                                 units::dryToWetPct(v.pbm->xOutDb[k - 1]),
                                             v.pbm->tOutK[k] - v.pbm->tOutK[k - 1]};
                if (!v.batch->keep[k] || !v.batch->keep[k - 1] || !std::isfinite(de[0]) ||
                    !std::isfinite(de[1]) || !std::isfinite(dy[0]) || !std::isfinite(dy[1])) {
                    continue;
                }
                for (int j = 0; j < kOutputs; ++j) {
                    cross[j] += de[j] * dy[j];
                    pbmEnergy[j] += dy[j] * dy[j];
                    errorEnergy[j] += de[j] * de[j];
                }
            }
        }
        double num = 0, den = 0;
        for (int j = 0; j < kOutputs; ++j) {
            if (errorEnergy[j] > 0) {
                num -= cross[j] / errorEnergy[j];
                den += pbmEnergy[j] / errorEnergy[j];
            }
        }
        m.m_referenceChange = den > 0 ? std::clamp(num / den, 0.0, 1.0) : 0.0;
        for (std::size_t vi = 0; vi < training.size(); ++vi) {
            std::vector<double> vx(ex[vi].size(), kNaN), vt = vx;
            m.residualsOf(training[vi], 0, ex[vi].size(), vx, vt);
            ex[vi] = std::move(vx);
            et[vi] = std::move(vt);
        }
    }
    for (std::size_t vi = 0; vi < training.size(); ++vi) {
        const auto& v = training[vi];
        for (std::size_t k = v.rows.begin + static_cast<std::size_t>(lags - 1); k + 1 < v.rows.end; ++k) {
            // Both rows kept, and measured residuals at k+1 and at every lag k … k−L+1.
            bool ok = v.batch->keep[k] && v.batch->keep[k + 1];
            for (std::size_t j = k + 1 - static_cast<std::size_t>(lags); ok && j <= k + 1; ++j) {
                ok = std::isfinite(ex[vi][j]) && std::isfinite(et[vi][j]);
            }
            if (ok) {
                snaps.push_back({vi, k});
            }
        }
    }
    const auto n = static_cast<Eigen::Index>(snaps.size());
    if (n < 200) {
        return Error{ErrorKind::BadInput, "residual training",
                     "only " + std::to_string(n) + " usable snapshot pairs; need at least 200"};
    }
    m.m_snapshots = snaps.size();

    // 2. Dictionary scaling on the training inputs.
    const int nz = m.m_dict.inputCount();
    Eigen::MatrixXd zNow(n, nz), zNext(n, nz);
    {
        double u = 0;
        Eigen::VectorXd d, z;
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto& s = snaps[static_cast<std::size_t>(i)];
            m.features(training[s.view], s.k, z, u, d);
            zNow.row(i) = z.transpose();
            m.features(training[s.view], s.k + 1, z, u, d);
            zNext.row(i) = z.transpose();
        }
    }
    m.m_dict.fitScaling(zNow);
    if (o.inputRangeMargin > 0) {
        const Eigen::VectorXd low = zNow.colwise().minCoeff().transpose();
        const Eigen::VectorXd high = zNow.colwise().maxCoeff().transpose();
        m.m_inputLow = low - o.inputRangeMargin * (high - low);
        m.m_inputHigh = high + o.inputRangeMargin * (high - low);
    }

    // 3. Control-consistent weights, Eq. (29): ℓ = (X_out − target)², margin to [low, high].
    Eigen::VectorXd w = Eigen::VectorXd::Ones(n);
    if (o.controlConsistentWeights) {
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto& s = snaps[static_cast<std::size_t>(i)];
            const double y = units::dryToWetPct(training[s.view].batch->xOutDb[s.k]);
            const double dl = 2.0 * std::abs(y - o.moistureTargetPct);
            const double margin = std::min(y - o.moistureLowPct, o.moistureHighPct - y);
            w(i) = 1.0 + o.kappa1 * dl + o.kappa2 * std::max(0.0, o.deltaPct - margin);
        }
    }
    const double wSum = w.sum();

    // 4. Lifting and orthogonal projection, Eq. (27), without the N × N matrix:
    //    Φ̃_res = Φ_res − Φ_base G, G = (Φ_bᵀ W Φ_b)⁻¹ Φ_bᵀ W Φ_res.
    const Eigen::MatrixXd psiNow = m.m_dict.lift(zNow);
    const Eigen::MatrixXd psiNext = m.m_dict.lift(zNext);
    if (o.baseFeatures.empty()) {
        m.m_baseIdx = m.m_dict.constantAndLinear();
    } else {
        const auto names = m.m_dict.featureNames();
        for (const auto& b : o.baseFeatures) {
            const auto it = std::find(names.begin(), names.end(), b);
            if (it == names.end()) {
                std::string known;
                for (const auto& n : names) {
                    known += " " + n;
                }
                return Error{ErrorKind::BadInput, "base feature '" + b + "'",
                             "not in the dictionary; known:" + known};
            }
            m.m_baseIdx.push_back(static_cast<int>(it - names.begin()));
        }
    }
    for (int f = 0; f < m.m_dict.featureCount(); ++f) {
        if (std::find(m.m_baseIdx.begin(), m.m_baseIdx.end(), f) == m.m_baseIdx.end()) {
            m.m_resIdx.push_back(f);
        }
    }
    auto columns = [](const Eigen::MatrixXd& a, const std::vector<int>& idx) {
        Eigen::MatrixXd out(a.rows(), static_cast<Eigen::Index>(idx.size()));
        for (std::size_t i = 0; i < idx.size(); ++i) {
            out.col(static_cast<Eigen::Index>(i)) = a.col(idx[i]);
        }
        return out;
    };
    const Eigen::MatrixXd baseNow = columns(psiNow, m.m_baseIdx);
    Eigen::MatrixXd resNow = columns(psiNow, m.m_resIdx);
    Eigen::MatrixXd resNext = columns(psiNext, m.m_resIdx);
    if (o.orthogonalProjection && resNow.cols() > 0) {
        m.m_projection = projectionCoefficients(baseNow, resNow, w);
        resNow -= baseNow * m.m_projection;
        resNext -= columns(psiNext, m.m_baseIdx) * m.m_projection;
    }
    if (m.eq27()) {
        // ẽ = P⊥e (Eq. 27) with the same weighted projection, applied to every row's residual so
        // that the lagged residuals in the state are projected too.
        Eigen::MatrixXd eNow(n, kOutputs);
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto& s = snaps[static_cast<std::size_t>(i)];
            eNow(i, 0) = ex[s.view][s.k];
            eNow(i, 1) = et[s.view][s.k];
        }
        m.m_residualProjection = projectionCoefficients(baseNow, eNow, w);
        for (std::size_t vi = 0; vi < training.size(); ++vi) {
            const auto& v = training[vi];
            const std::size_t from = v.rows.begin;
            m.residualsOf(v, from, v.rows.end, ex[vi], et[vi]);
        }
    }
    m.m_featureScale = Eigen::VectorXd::Ones(resNow.cols());
    for (Eigen::Index c = 0; c < resNow.cols(); ++c) {
        const double sd = std::sqrt(resNow.col(c).squaredNorm() / static_cast<double>(n));
        m.m_featureScale(c) = sd > 1e-12 ? sd : 1.0;
    }
    resNow = resNow * m.m_featureScale.cwiseInverse().asDiagonal();
    resNext = resNext * m.m_featureScale.cwiseInverse().asDiagonal();

    // 5. Snapshot matrices X−, X+, U−, D− (rows are snapshots).
    for (int j = 0; j < kOutputs; ++j) {
        double s2 = 0;
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto& s = snaps[static_cast<std::size_t>(i)];
            const double v = j == 0 ? ex[s.view][s.k] : et[s.view][s.k];
            s2 += std::isfinite(v) ? v * v : 0.0;
        }
        const double sd = std::sqrt(s2 / static_cast<double>(n));
        m.m_eScale(j) = sd > 1e-12 ? sd : 1.0;
    }
    const Eigen::Index nx = kOutputs * lags + resNow.cols();
    const Eigen::Index nd = [&] { // [1, (z without u unless Eq. 27), PBM outlet changes]
        double u = 0;
        Eigen::VectorXd z, d;
        m.features(training[snaps[0].view], snaps[0].k, z, u, d);
        return d.size();
    }();
    Eigen::MatrixXd xm(n, nx), xp(n, nx), um(n, 1), dm(n, nd);
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto& s = snaps[static_cast<std::size_t>(i)];
        for (int l = 0; l < lags; ++l) {
            xm(i, kOutputs * l) = ex[s.view][s.k - static_cast<std::size_t>(l)] / m.m_eScale(0);
            xm(i, kOutputs * l + 1) = et[s.view][s.k - static_cast<std::size_t>(l)] / m.m_eScale(1);
            xp(i, kOutputs * l) = ex[s.view][s.k + 1 - static_cast<std::size_t>(l)] / m.m_eScale(0);
            xp(i, kOutputs * l + 1) = et[s.view][s.k + 1 - static_cast<std::size_t>(l)] / m.m_eScale(1);
        }
        xm.row(i).tail(resNow.cols()) = resNow.row(i);
        xp.row(i).tail(resNow.cols()) = resNext.row(i);
        double u = 0;
        Eigen::VectorXd d, z;
        m.features(training[s.view], s.k, z, u, d);
        um(i, 0) = u;
        dm.row(i) = d.transpose();
        // A lag whose projected residual could not be formed (its inputs were missing) leaves
        // the snapshot out rather than poisoning the fit.
        if (!xm.row(i).allFinite() || !xp.row(i).allFinite() || !dm.row(i).allFinite()) {
            xm.row(i).setZero();
            xp.row(i).setZero();
            dm.row(i).setZero();
            um(i, 0) = 0;
            w(i) = 0;
        }
    }

    // 6. CC-EDMDc, Eq. (30): the weighted ridge for [A B E] in normal-equation form.
    Eigen::MatrixXd r(n, nx + 1 + nd);
    r << xm, um, dm;
    Eigen::VectorXd lambda(r.cols());
    lambda.head(nx).setConstant(o.lambdaA * wSum);
    lambda(nx) = o.lambdaB * wSum;
    lambda.tail(nd).setConstant(o.lambdaE * wSum);
    RidgeNormalEquations normal;
    {
        const Eigen::MatrixXd rw = r.array().colwise() * w.array();
        normal.gram = r.transpose() * rw;
        normal.gram.diagonal() += lambda;
        normal.cross = xp.transpose() * rw;
        normal.targetEnergy = (xp.array().square().colwise() * w.array()).sum();
        normal.stateSize = nx;
    }

    const Eigen::LDLT<Eigen::MatrixXd> gramLdlt(normal.gram);
    const Eigen::MatrixXd thetaFree = gramLdlt.solve(normal.cross.transpose()).transpose();
    // B, E that minimise the loss for a given A (the A block of Θ held fixed).
    const Eigen::MatrixXd gramBe = normal.gram.bottomRightCorner(1 + nd, 1 + nd);
    const Eigen::LDLT<Eigen::MatrixXd> gramBeLdlt(gramBe);
    const auto withBestInputs = [&](const Eigen::MatrixXd& a) {
        Eigen::MatrixXd theta(nx, nx + 1 + nd);
        theta.leftCols(nx) = a;
        const Eigen::MatrixXd rhs =
            normal.cross.rightCols(1 + nd) - a * normal.gram.topRightCorner(nx, 1 + nd);
        theta.rightCols(1 + nd) = gramBeLdlt.solve(rhs.transpose()).transpose();
        return theta;
    };
    Eigen::MatrixXd theta = thetaFree;
    m.m_aFree = thetaFree.leftCols(nx);
    auto& cmp = m.m_comparison;
    cmp.lossUnconstrained = normal.loss(thetaFree) / wSum;
    cmp.radiusUnconstrained = diagnostics::spectralRadius(m.m_aFree);

    // 7. Stability constraint with a certificate.
    if (o.stabilityConstraint) {
        Eigen::MatrixXd aPulled = m.m_aFree;
        const StabilityCertificate pulled = enforceStability(aPulled, o.alphaMax, o.radiusMax);
        const Eigen::MatrixXd thetaPulled = pulled.modified ? withBestInputs(aPulled) : thetaFree;
        cmp.lossEigenvaluePull = normal.loss(thetaPulled) / wSum;
        cmp.radiusEigenvaluePull = diagnostics::spectralRadius(aPulled);
        m.m_cert = pulled;
        theta = thetaPulled;
        if (o.stabilityMethod == StabilityMethod::Constrained && pulled.certified) {
            // Eq. (30) as stated, from the feasible pulled fit: never a higher loss than it.
            const bool alreadyStable = cmp.radiusUnconstrained < o.alphaMax * (1.0 - 1e-4);
            if (alreadyStable) {
                m.m_cert = certify(m.m_aFree,
                                   scaledLyapunov(m.m_aFree, 0.5 * (cmp.radiusUnconstrained + o.alphaMax)),
                                   o.alphaMax);
                theta = thetaFree;
            } else {
                const auto fit = fitUnderStabilityConstraint(normal, thetaPulled, pulled.p, o.alphaMax);
                theta = withBestInputs(fit.theta.leftCols(nx));
                // The refit of B, E never raises the loss; keep the solver's certificate for A.
                m.m_cert = fit.certificate;
                cmp.admmIterations = fit.admmIterations;
                cmp.outerIterations = fit.outerIterations;
            }
            m.m_cert.modified = !alreadyStable;
        }
        m.m_cert.spectralRadiusBefore = cmp.radiusUnconstrained;
        m.m_cert.spectralRadiusAfter = diagnostics::spectralRadius(theta.leftCols(nx));
    } else {
        const double rho = cmp.radiusUnconstrained;
        m.m_cert = rho < o.alphaMax ? certify(m.m_aFree, scaledLyapunov(m.m_aFree, 0.5 * (rho + o.alphaMax)),
                                              0.5 * (rho + o.alphaMax))
                                    : StabilityCertificate{};
        m.m_cert.spectralRadiusBefore = rho;
        m.m_cert.spectralRadiusAfter = rho;
        cmp.lossEigenvaluePull = cmp.lossUnconstrained;
        cmp.radiusEigenvaluePull = rho;
    }
    cmp.lossConstrained = normal.loss(theta) / wSum;
    cmp.radiusConstrained = diagnostics::spectralRadius(theta.leftCols(nx));
    m.m_a = theta.leftCols(nx);
    m.m_b = theta.middleCols(nx, 1);
    m.m_e = theta.rightCols(nd);

    // 8. Output matrix C (Algorithm 1, step 15): ê_k ≈ C x_k.
    Eigen::MatrixXd eNow(n, kOutputs);
    eNow.col(0) = xm.col(0);
    eNow.col(1) = xm.col(1);
    m.m_c = weightedRidge(xm, eNow, w, Eigen::VectorXd::Constant(nx, o.lambdaC * wSum));
    m.m_trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return m;
}

} // namespace drytwin::residual
