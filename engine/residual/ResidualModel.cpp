#include "residual/ResidualModel.h"

#include "common/Parallel.h"
#include "common/Units.h"
#include "diagnostics/Stability.h"
#include "residual/OrthogonalProjection.h"

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

namespace drytwin::residual {

namespace {

constexpr int kOutputs = 2; // outlet moisture (% wb) and temperature (°C)
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// PBM outlet changes Δŷ_{k+1}, Δŷ_k used as inputs: the next one carries what the PBM
/// already knows, the current one cancels the PBM's reaction to input noise in e_k.
constexpr int kPbmChangeLags = 2;

const std::vector<std::string> kProxyNames{"X_HDT", "T_HDT", "X_Conv", "T_Conv", "X_mix", "T_mix"};
const std::vector<std::string> kDisturbanceNames{"feed", "X_in", "T_in", "T_amb", "RH"};

std::vector<std::string> inputNames(bool proxies) {
    std::vector<std::string> n;
    if (proxies) {
        n = kProxyNames;
    }
    n.push_back("T_hot");
    n.insert(n.end(), kDisturbanceNames.begin(), kDisturbanceNames.end());
    return n;
}

nlohmann::json matrixJson(const Eigen::MatrixXd& m) {
    std::vector<double> data;
    data.reserve(static_cast<std::size_t>(m.size()));
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
        for (Eigen::Index c = 0; c < m.cols(); ++c) {
            data.push_back(m(r, c));
        }
    }
    return {{"rows", m.rows()}, {"cols", m.cols()}, {"data", data}};
}

Eigen::MatrixXd matrixFrom(const nlohmann::json& j) {
    const auto rows = j.at("rows").get<Eigen::Index>();
    const auto cols = j.at("cols").get<Eigen::Index>();
    const auto data = j.at("data").get<std::vector<double>>();
    if (static_cast<Eigen::Index>(data.size()) != rows * cols) {
        throw std::runtime_error("matrix data size does not match rows × cols");
    }
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index r = 0; r < rows; ++r) {
        for (Eigen::Index c = 0; c < cols; ++c) {
            m(r, c) = data[static_cast<std::size_t>(r * cols + c)];
        }
    }
    return m;
}

Eigen::VectorXd vectorFrom(const nlohmann::json& j) {
    const auto v = j.get<std::vector<double>>();
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

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

Status ResidualOptions::validate() const {
    if (degree < 1 || degree > 3) {
        return Error{ErrorKind::BadInput, "degree", "dictionary degree must be 1, 2 or 3"};
    }
    if (residualLags < 1 || residualLags > 60) {
        return Error{ErrorKind::BadInput, "residualLags", "must lie in [1, 60]"};
    }
    for (double l : {lambdaA, lambdaB, lambdaE, lambdaC, kappa1, kappa2, deltaPct}) {
        if (!(l >= 0 && std::isfinite(l))) {
            return Error{ErrorKind::BadInput, "ridge and weight parameters", "must be finite and ≥ 0"};
        }
    }
    if (!(moistureLowPct < moistureHighPct)) {
        return Error{ErrorKind::BadInput, "moisture constraints", "low must be below high"};
    }
    if (!(alphaMax > 0 && alphaMax < 1 && radiusMax > 0 && radiusMax < alphaMax)) {
        return Error{ErrorKind::BadInput, "alphaMax", "need 0 < radiusMax < alphaMax < 1"};
    }
    if (correctionFolds < 0 || correctionFolds > 10) {
        return Error{ErrorKind::BadInput, "correctionFolds", "must lie in [0, 10]"};
    }
    if (!(shrinkValidationFraction >= 0 && shrinkValidationFraction < 0.6)) {
        return Error{ErrorKind::BadInput, "shrinkValidationFraction", "must lie in [0, 0.6)"};
    }
    return {};
}

HybridPrediction HybridPrediction::unknown(std::size_t rows) {
    HybridPrediction p;
    p.xOutPct.assign(rows, kNaN);
    p.tOutC.assign(rows, kNaN);
    p.residualXPct.assign(rows, kNaN);
    p.residualTC.assign(rows, kNaN);
    return p;
}

bool observedResidual(const data::SiBatch& b, const physics::SimulationResult& pbm, std::size_t k, double& ex,
                      double& et) {
    ex = units::dryToWetPct(b.xOutDb[k]) - units::dryToWetPct(pbm.xOutDb[k]);
    et = b.tOutK[k] - pbm.tOutK[k];
    return std::isfinite(ex) && std::isfinite(et);
}

Eigen::VectorXd ResidualModel::inputsAt(const BatchView& v, std::size_t k) const {
    const auto& b = *v.batch;
    const auto& p = *v.pbm;
    std::vector<double> z;
    if (m_options.useProxies) {
        z = {p.proxyXHdtDb[k], p.proxyTHdtK[k],  p.proxyXConvDb[k],
             p.proxyTConvK[k], p.proxyXMixDb[k], p.proxyTMixK[k]};
    }
    z.push_back(b.tHotK[k]);
    for (double x : {b.feedKgPerS[k], b.xInDb[k], b.tInK[k], b.tAmbK[k], b.rhAmb[k]}) {
        z.push_back(x);
    }
    return Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()));
}

Eigen::Vector2d ResidualModel::basePartOf(const Eigen::VectorXd& z) const {
    Eigen::Vector2d out = Eigen::Vector2d::Zero();
    if (m_residualProjection.size() == 0) {
        return out;
    }
    const Eigen::VectorXd psi = m_dict.lift(z);
    for (std::size_t b = 0; b < m_baseIdx.size(); ++b) {
        out += psi(m_baseIdx[b]) * m_residualProjection.row(static_cast<Eigen::Index>(b)).transpose();
    }
    return out;
}

bool ResidualModel::features(const BatchView& v, std::size_t k, Eigen::VectorXd& zLin, double& u,
                             Eigen::VectorXd& d) const {
    const auto& p = *v.pbm;
    zLin = inputsAt(v, k);
    const Eigen::VectorXd s = (zLin - m_dict.mean()).cwiseQuotient(m_dict.scale());
    const Eigen::Index uIdx = m_options.useProxies ? 6 : 0;
    u = s(uIdx);
    // d = [1, standardised disturbances, standardised proxies]: the base features other than u.
    // With proxies, also the PBM's change of outlet prediction from k to k+1: the parcel that
    // reaches the outlet next is already in the line, so the PBM knows it one step ahead.
    const int lags = std::min(m_options.residualLags, kPbmChangeLags);
    // Under Eq. 27 the base features (the disturbances and proxies themselves) are not inputs.
    const Eigen::Index baseInputs = eq27() ? 0 : s.size() - 1;
    d.resize(1 + baseInputs + (m_options.useProxies ? kOutputs * lags : 0));
    d(0) = 1.0;
    Eigen::Index j = 1;
    for (Eigen::Index i = 0; i < s.size() && baseInputs > 0; ++i) {
        if (i != uIdx) {
            d(j++) = s(i);
        }
    }
    if (m_options.useProxies) {
        // … and its recent history, so that the PBM's reaction to input noise, which the
        // residual carries with the opposite sign, can be told apart from the plant's.
        for (int l = 0; l < lags; ++l) {
            const std::size_t hi =
                std::min(k + 1 >= static_cast<std::size_t>(l) ? k + 1 - l : 0, p.xOutDb.size() - 1);
            const std::size_t lo = hi > 0 ? hi - 1 : 0;
            d(j++) = (units::dryToWetPct(p.xOutDb[hi]) - units::dryToWetPct(p.xOutDb[lo])) / m_eScale(0);
            d(j++) = (p.tOutK[hi] - p.tOutK[lo]) / m_eScale(1);
        }
    }
    return zLin.allFinite();
}

Eigen::VectorXd ResidualModel::liftedResidualFeatures(const Eigen::VectorXd& z) const {
    const Eigen::VectorXd psi = m_dict.lift(z);
    Eigen::VectorXd base(static_cast<Eigen::Index>(m_baseIdx.size()));
    for (std::size_t i = 0; i < m_baseIdx.size(); ++i) {
        base(static_cast<Eigen::Index>(i)) = psi(m_baseIdx[i]);
    }
    Eigen::VectorXd res(static_cast<Eigen::Index>(m_resIdx.size()));
    for (std::size_t i = 0; i < m_resIdx.size(); ++i) {
        res(static_cast<Eigen::Index>(i)) = psi(m_resIdx[i]);
    }
    if (m_projection.size() > 0) {
        res -= m_projection.transpose() * base; // P⊥ (Eq. 27) as the fixed map learned in training
    }
    return res.cwiseQuotient(m_featureScale);
}

void ResidualModel::residualsOf(const BatchView& v, std::size_t from, std::size_t to, std::vector<double>& ex,
                                std::vector<double>& et) const {
    if (velocity()) {
        // v_k = Δe_k + s Δŷ_mech,k: what the reference missed from k−1 to k.
        const auto& pbm = *v.pbm;
        // e at k−1, carried from one row to the next.
        double ex0 = kNaN, et0 = kNaN;
        bool previousOk = from > 0 && observedResidual(*v.batch, pbm, from - 1, ex0, et0);
        for (std::size_t k = from; k < to; ++k) {
            double ex1 = kNaN, et1 = kNaN;
            const bool ok = observedResidual(*v.batch, pbm, k, ex1, et1);
            const bool both = ok && previousOk;
            const double exPrev = ex0, etPrev = et0;
            ex0 = ex1;
            et0 = et1;
            previousOk = ok;
            if (!both) {
                ex[k] = et[k] = kNaN;
                continue;
            }
            ex[k] = ex1 - exPrev +
                    m_referenceChange *
                        (units::dryToWetPct(pbm.xOutDb[k]) - units::dryToWetPct(pbm.xOutDb[k - 1]));
            et[k] = et1 - etPrev + m_referenceChange * (pbm.tOutK[k] - pbm.tOutK[k - 1]);
        }
        return;
    }
    for (std::size_t k = from; k < to; ++k) {
        observedResidual(*v.batch, *v.pbm, k, ex[k], et[k]);
        if (!eq27() || m_residualProjection.size() == 0) {
            continue;
        }
        Eigen::VectorXd z, d;
        double u = 0;
        if (!features(v, k, z, u, d)) {
            ex[k] = et[k] = kNaN;
            continue;
        }
        const Eigen::Vector2d base = basePartOf(z);
        ex[k] -= base(0);
        et[k] -= base(1);
    }
}

Eigen::Vector2d ResidualModel::restoredBasePart(const BatchView& v, std::size_t k) const {
    if (!eq27() || !m_options.restoreBasePart || m_residualProjection.size() == 0) {
        return Eigen::Vector2d::Zero();
    }
    const Eigen::VectorXd z = inputsAt(v, k);
    if (!z.allFinite()) {
        return Eigen::Vector2d::Constant(kNaN);
    }
    return basePartOf(z);
}

Eigen::Vector2d ResidualModel::levelOf(const BatchView& v, std::size_t origin, std::size_t target) const {
    if (!velocity()) {
        return restoredBasePart(v, target);
    }
    Eigen::Vector2d e;
    if (!observedResidual(*v.batch, *v.pbm, origin, e(0), e(1))) {
        return Eigen::Vector2d::Constant(kNaN);
    }
    const auto& pbm = *v.pbm;
    const Eigen::Vector2d sH = referenceChangeAt(static_cast<int>(target - origin));
    e(0) -= sH(0) * (units::dryToWetPct(pbm.xOutDb[target]) - units::dryToWetPct(pbm.xOutDb[origin]));
    e(1) -= sH(1) * (pbm.tOutK[target] - pbm.tOutK[origin]);
    return e;
}

bool ResidualModel::stateAt(const BatchView& v, std::size_t k, const std::vector<double>& ex,
                            const std::vector<double>& et, Eigen::VectorXd& x, double& u,
                            Eigen::VectorXd& d) const {
    Eigen::VectorXd z;
    return features(v, k, z, u, d) && stateFrom(z, k, ex, et, x);
}

bool ResidualModel::stateFrom(const Eigen::VectorXd& z, std::size_t k, const std::vector<double>& ex,
                              const std::vector<double>& et, Eigen::VectorXd& x) const {
    const int lags = m_options.residualLags;
    const Eigen::VectorXd phi = liftedResidualFeatures(z);
    x.resize(kOutputs * lags + phi.size());
    for (int l = 0; l < lags; ++l) {
        const std::size_t j = k >= static_cast<std::size_t>(l) ? k - static_cast<std::size_t>(l) : 0;
        if (!std::isfinite(ex[j]) || !std::isfinite(et[j])) {
            return false;
        }
        x(kOutputs * l) = ex[j] / m_eScale(0);
        x(kOutputs * l + 1) = et[j] / m_eScale(1);
    }
    x.tail(phi.size()) = phi;
    return true;
}

namespace {
/// A per-horizon pair interpolated linearly in the horizon, its ends held beyond the grid.
Eigen::Vector2d onGrid(const std::vector<int>& grid, const std::vector<Eigen::Vector2d>& values, int h) {
    if (h <= grid.front()) {
        return values.front();
    }
    for (std::size_t i = 1; i < grid.size(); ++i) {
        if (h <= grid[i]) {
            const double t = double(h - grid[i - 1]) / double(grid[i] - grid[i - 1]);
            return (1 - t) * values[i - 1] + t * values[i];
        }
    }
    return values.back();
}
} // namespace

Eigen::Vector2d ResidualModel::correctionWeight(int h) const {
    return m_shrinkHorizons.empty() ? Eigen::Vector2d::Ones() : onGrid(m_shrinkHorizons, m_shrink, h);
}

Eigen::Vector2d ResidualModel::referenceChangeAt(int h) const {
    return m_shrinkHorizons.empty() || m_referenceByHorizon.empty()
               ? Eigen::Vector2d::Constant(m_referenceChange)
               : onGrid(m_shrinkHorizons, m_referenceByHorizon, h);
}

namespace {
/// The horizons at which κ_H is fitted: those of the evaluation's curve.
const std::vector<int> kShrinkGrid{1, 2, 5, 10, 20, 30, 45, 60, 90, 120, 150, 180};
} // namespace

Expected<ResidualModel> ResidualModel::train(const std::vector<BatchView>& training,
                                             const ResidualOptions& options) {
    if (!options.nestReferences || (options.correctionFolds < 2 && options.shrinkValidationFraction <= 0)) {
        return trainOnce(training, options);
    }
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    const auto t0 = std::chrono::steady_clock::now();
    // 1. Fit on part of each batch's rows, 2. s_H and κ_H on the rest, 3. refit on all. With
    // correctionFolds ≥ 2 the parts are contiguous blocks, each held out once (blocked
    // cross-validation: drift that changes within a batch is seen in every regime); else the
    // last shrinkValidationFraction of each batch's rows.
    std::vector<std::pair<std::vector<BatchView>, std::vector<BatchView>>> folds;
    if (options.correctionFolds >= 2) {
        const auto k = static_cast<std::size_t>(options.correctionFolds);
        for (std::size_t f = 0; f < k; ++f) {
            std::vector<BatchView> fit, validation;
            for (const auto& v : training) {
                const std::size_t n = v.rows.size();
                const std::size_t lo = v.rows.begin + n * f / k, hi = v.rows.begin + n * (f + 1) / k;
                if (lo > v.rows.begin) {
                    fit.push_back({v.batch, v.pbm, {v.rows.begin, lo}});
                }
                if (hi < v.rows.end) {
                    fit.push_back({v.batch, v.pbm, {hi, v.rows.end}});
                }
                if (hi > lo) {
                    validation.push_back({v.batch, v.pbm, {lo, hi}});
                }
            }
            folds.emplace_back(std::move(fit), std::move(validation));
        }
    } else {
        std::vector<BatchView> fit, validation;
        for (const auto& v : training) {
            const auto cut =
                v.rows.begin + static_cast<std::size_t>(std::round((1.0 - options.shrinkValidationFraction) *
                                                                   double(v.rows.size())));
            if (cut > v.rows.begin) {
                fit.push_back({v.batch, v.pbm, {v.rows.begin, cut}});
            }
            if (cut < v.rows.end) {
                validation.push_back({v.batch, v.pbm, {cut, v.rows.end}});
            }
        }
        folds.emplace_back(std::move(fit), std::move(validation));
    }
    // Least squares: per horizon and output, the normal equations of t = s a + κ b: t = e_{k+H} − e_k,
    // a = −(ŷ_mech,k+H − ŷ_mech,k), b = the summed v̂ (the first fit's forecast minus its reference).
    struct Normal {
        double aa = 0, ab = 0, bb = 0, at = 0, bt = 0;
    };
    std::vector<std::array<Normal, kOutputs>> normal(kShrinkGrid.size());
    // For the absolute-error criterion every (a, b, t) is kept (floats: 12 bytes a row, horizon
    // and output; about 12 MB for the demo's 41,000 training rows).
    std::vector<std::array<std::vector<std::array<float, 3>>, kOutputs>> samples(
        options.correctionByAbsoluteError ? kShrinkGrid.size() : 0);
    for (const auto& [fit, validation] : folds) {
        auto first = trainOnce(fit, options);
        if (!first) {
            return first.error();
        }
        for (const auto& v : validation) {
            const auto predicted = first->predictHorizons(v, kShrinkGrid);
            for (std::size_t g = 0; g < kShrinkGrid.size(); ++g) {
                const auto h = static_cast<std::size_t>(kShrinkGrid[g]);
                for (std::size_t i = 0; i < v.rows.size(); ++i) {
                    const std::size_t target = v.rows.begin + i;
                    Eigen::Vector2d truth, atOrigin;
                    if (target < h || !v.batch->keep[target] ||
                        !observedResidual(*v.batch, *v.pbm, target, truth(0), truth(1)) ||
                        !observedResidual(*v.batch, *v.pbm, target - h, atOrigin(0), atOrigin(1))) {
                        continue;
                    }
                    const Eigen::Vector2d reference = first->levelOf(v, target - h, target);
                    const Eigen::Vector2d model(predicted[g].residualXPct[i], predicted[g].residualTC[i]);
                    const Eigen::Vector2d pbmChange(units::dryToWetPct(v.pbm->xOutDb[target]) -
                                                        units::dryToWetPct(v.pbm->xOutDb[target - h]),
                                                    v.pbm->tOutK[target] - v.pbm->tOutK[target - h]);
                    if (!reference.allFinite() || !model.allFinite() || !pbmChange.allFinite()) {
                        continue;
                    }
                    for (int j = 0; j < kOutputs; ++j) {
                        const double a = -pbmChange(j), b = model(j) - reference(j),
                                     t = truth(j) - atOrigin(j);
                        if (options.correctionByAbsoluteError) {
                            samples[g][static_cast<std::size_t>(j)].push_back(
                                {static_cast<float>(a), static_cast<float>(b), static_cast<float>(t)});
                            continue;
                        }
                        auto& q = normal[g][static_cast<std::size_t>(j)];
                        q.aa += a * a;
                        q.ab += a * b;
                        q.bb += b * b;
                        q.at += a * t;
                        q.bt += b * t;
                    }
                }
            }
        }
    }
    // The least-squares (s, κ) in [0, 1]²: the interior solution if it lies inside, else the best
    // on the edges (each edge a one-variable fit, clamped).
    const auto solve = [](const Normal& q) -> Eigen::Vector2d {
        const auto sse = [&](double sv, double kv) {
            return -2 * sv * q.at - 2 * kv * q.bt + sv * sv * q.aa + 2 * sv * kv * q.ab + kv * kv * q.bb;
        };
        std::vector<Eigen::Vector2d> tries;
        const double det = q.aa * q.bb - q.ab * q.ab;
        if (det > 1e-12 * (q.aa * q.bb + 1e-300)) {
            tries.emplace_back((q.at * q.bb - q.bt * q.ab) / det, (q.bt * q.aa - q.at * q.ab) / det);
        }
        for (double edge : {0.0, 1.0}) {
            tries.emplace_back(edge, q.bb > 0 ? (q.bt - edge * q.ab) / q.bb : 0.0); // s fixed
            tries.emplace_back(q.aa > 0 ? (q.at - edge * q.ab) / q.aa : 0.0, edge); // κ fixed
        }
        Eigen::Vector2d best(0, 0);
        double bestSse = sse(0, 0);
        for (Eigen::Vector2d c : tries) {
            c = c.cwiseMax(0.0).cwiseMin(1.0);
            if (c.allFinite() && sse(c(0), c(1)) < bestSse) {
                bestSse = sse(c(0), c(1));
                best = c;
            }
        }
        return best;
    };
    // The least-absolute-error (s, κ) in [0, 1]²: a grid of step 0.05, then one of step 0.005
    // about its best point. Σ|t − s a − κ b| is convex, so the refined point is the minimum to
    // within 0.005 unless its valley is long and narrow (a and b strongly correlated), where it is
    // a point of nearly the same error (no library call: a boxed two-variable L1 fit is two loops).
    const auto solveAbsolute = [](const std::vector<std::array<float, 3>>& rows) -> Eigen::Vector2d {
        Eigen::Vector2d best(0, 0);
        double bestSae = 0; // at (s, κ) = (0, 0)
        for (const auto& r : rows) {
            bestSae += std::abs(double(r[2]));
        }
        // One pass over the rows per s, every κ of the line summed side by side (each sum still
        // in row order, so the same sums and the same minimum as one pass per point; 20 times
        // fewer passes over ~12 MB, and the κ loop vectorises).
        std::vector<double> kappas, sums;
        const auto scan = [&](const Eigen::Vector2d centre, double half, double step) { // a copy: best moves
            kappas.clear();
            for (double kv = centre(1) - half; kv <= centre(1) + half + 1e-9; kv += step) {
                kappas.push_back(std::clamp(kv, 0.0, 1.0));
            }
            for (double sv = centre(0) - half; sv <= centre(0) + half + 1e-9; sv += step) {
                const double sc = std::clamp(sv, 0.0, 1.0);
                sums.assign(kappas.size(), 0.0);
                for (const auto& r : rows) {
                    const double left = double(r[2]) - sc * double(r[0]), b = double(r[1]);
                    for (std::size_t q = 0; q < kappas.size(); ++q) {
                        sums[q] += std::abs(left - kappas[q] * b);
                    }
                }
                for (std::size_t q = 0; q < kappas.size(); ++q) {
                    if (sums[q] < bestSae) {
                        bestSae = sums[q];
                        best = {sc, kappas[q]};
                    }
                }
            }
        };
        scan({0.5, 0.5}, 0.5, 0.05);
        scan(best, 0.05, 0.005);
        return best;
    };
    std::vector<std::array<Eigen::Vector2d, kOutputs>> chosen(kShrinkGrid.size());
    parallelFor(kShrinkGrid.size() * kOutputs, [&](std::size_t i) {
        const std::size_t g = i / kOutputs, j = i % kOutputs;
        chosen[g][j] = options.correctionByAbsoluteError ? solveAbsolute(samples[g][j]) : solve(normal[g][j]);
    });
    auto m = trainOnce(training, options);
    if (!m) {
        return m.error();
    }
    m->m_shrinkHorizons = kShrinkGrid;
    m->m_shrink.assign(kShrinkGrid.size(), Eigen::Vector2d::Ones());
    m->m_referenceByHorizon.assign(kShrinkGrid.size(), Eigen::Vector2d::Constant(m->m_referenceChange));
    for (std::size_t g = 0; g < kShrinkGrid.size(); ++g) {
        for (int j = 0; j < kOutputs; ++j) {
            const Eigen::Vector2d sk = chosen[g][static_cast<std::size_t>(j)];
            m->m_referenceByHorizon[g](j) = sk(0);
            m->m_shrink[g](j) = sk(1);
        }
    }
    m->m_trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return m;
}

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

HybridPrediction ResidualModel::predictOneStep(const BatchView& v) const {
    return predictAhead(v, 1);
}

HybridPrediction ResidualModel::predictAhead(const BatchView& v, int horizon) const {
    const std::size_t n = v.batch->rows();
    const std::size_t count = v.rows.size();
    HybridPrediction out = HybridPrediction::unknown(count);
    const auto h = static_cast<std::size_t>(std::max(1, horizon));
    // Residuals and exogenous inputs of the rows the predictions need, computed once: from the
    // earliest origin's oldest lag to the end of the view.
    const std::size_t back = h + static_cast<std::size_t>(m_options.residualLags);
    const std::size_t first = v.rows.begin > back ? v.rows.begin - back : 0;
    std::vector<double> ex(n, kNaN), et(n, kNaN);
    std::vector<double> us(n, kNaN);
    std::vector<Eigen::VectorXd> ds(n);
    residualsOf(v, first, v.rows.end, ex, et);
    for (std::size_t k = first; k < v.rows.end; ++k) {
        Eigen::VectorXd z;
        features(v, k, z, us[k], ds[k]);
    }
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t target = v.rows.begin + i;
        if (target < h) {
            continue;
        }
        const std::size_t origin = target - h;
        Eigen::VectorXd x;
        double u = 0;
        Eigen::VectorXd d;
        if (!stateAt(v, origin, ex, et, x, u, d)) {
            continue;
        }
        Eigen::Vector2d sum = Eigen::Vector2d::Zero(); // velocity form: Σ of the predicted v
        for (std::size_t j = origin; j < target; ++j) {
            x = m_a * x + m_b * us[j] + m_e * ds[j];
            if (velocity()) {
                sum += m_c * x;
            }
        }
        const Eigen::Vector2d e =
            velocity() ? Eigen::Vector2d(correctionWeight(static_cast<int>(h)).cwiseProduct(sum))
                       : Eigen::Vector2d(m_c * x);
        const Eigen::Vector2d base = levelOf(v, origin, target);
        out.residualXPct[i] = e(0) * m_eScale(0) + base(0);
        out.residualTC[i] = e(1) * m_eScale(1) + base(1);
        out.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[target]) + out.residualXPct[i]; // Eq. (21)
        out.tOutC[i] = v.pbm->tOutK[target] - units::kKelvinOffset + out.residualTC[i];
    }
    return out;
}

std::vector<HybridPrediction> ResidualModel::predictHorizons(const BatchView& v,
                                                             const std::vector<int>& horizons) const {
    const std::size_t count = v.rows.size();
    std::vector<HybridPrediction> out(horizons.size(), HybridPrediction::unknown(count));
    int hMax = 1;
    for (int h : horizons) {
        hMax = std::max(hMax, h);
    }
    // Which output slot each horizon fills (a horizon may be asked for twice).
    std::vector<std::vector<std::size_t>> slotsOf(static_cast<std::size_t>(hMax) + 1);
    for (std::size_t i = 0; i < horizons.size(); ++i) {
        if (horizons[i] >= 1) {
            slotsOf[static_cast<std::size_t>(horizons[i])].push_back(i);
        }
    }
    const std::size_t n = v.batch->rows();
    const std::size_t back = static_cast<std::size_t>(hMax + m_options.residualLags);
    const std::size_t first = v.rows.begin > back ? v.rows.begin - back : 0;
    // Per row: the forcing g_j = B u_j + E d_j and, where the lags are measured, the state x_j.
    std::vector<double> ex(n, kNaN), et(n, kNaN);
    residualsOf(v, first, v.rows.end, ex, et);
    const Eigen::Index nx = m_a.rows();
    Eigen::MatrixXd forcing(nx, static_cast<Eigen::Index>(v.rows.end - first));
    Eigen::MatrixXd states(nx, static_cast<Eigen::Index>(v.rows.end - first));
    std::vector<char> stateOk(v.rows.end - first, 0);
    for (std::size_t k = first; k < v.rows.end; ++k) {
        const auto col = static_cast<Eigen::Index>(k - first);
        Eigen::VectorXd z, d, x;
        double u = 0;
        // One feature evaluation per row serves both the forcing and the state.
        if (!features(v, k, z, u, d)) {
            forcing.col(col).setConstant(kNaN);
            continue;
        }
        forcing.col(col) = m_b.col(0) * u + m_e * d;
        if (stateFrom(z, k, ex, et, x)) {
            states.col(col) = x;
            stateOk[k - first] = 1;
        }
    }
    // C A^m for m = 0 … hMax.
    std::vector<Eigen::MatrixXd> cPow(static_cast<std::size_t>(hMax) + 1);
    cPow[0] = m_c;
    for (int m = 1; m <= hMax; ++m) {
        cPow[static_cast<std::size_t>(m)] = cPow[static_cast<std::size_t>(m) - 1] * m_a;
    }
    // Velocity form: the forecast sums v over the horizon, Σ_{m=1..H} C x̂_{k+m}
    // = (T_H − C) x_k + Σ_{m<H} T_m g_{k+H−1−m} with T_m = Σ_{p≤m} C A^p.
    std::vector<Eigen::MatrixXd> cSum;
    if (velocity()) {
        cSum = cPow;
        for (std::size_t m = 1; m < cSum.size(); ++m) {
            cSum[m] += cSum[m - 1];
        }
    }
    const auto& forcingGain = velocity() ? cSum : cPow;
    std::vector<Eigen::MatrixXd> stateGain = cPow;
    for (std::size_t h = 0; velocity() && h < stateGain.size(); ++h) {
        stateGain[h] = cSum[h] - cPow[0];
    }
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t target = v.rows.begin + i;
        const Eigen::Vector2d targetBase = velocity() ? Eigen::Vector2d::Zero() : restoredBasePart(v, target);
        Eigen::Vector2d forced = Eigen::Vector2d::Zero();
        for (int m = 0; m < hMax; ++m) {
            const auto h = static_cast<std::size_t>(m) + 1; // horizon once row target−1−m is added
            if (target < h || target - h < first) {
                break;
            }
            forced += forcingGain[static_cast<std::size_t>(m)] *
                      forcing.col(static_cast<Eigen::Index>(target - h - first));
            const std::size_t origin = target - h;
            if (slotsOf[h].empty() || !stateOk[origin - first]) {
                continue;
            }
            Eigen::Vector2d e = stateGain[h] * states.col(static_cast<Eigen::Index>(origin - first)) + forced;
            if (velocity()) {
                e = e.cwiseProduct(correctionWeight(static_cast<int>(h)));
            }
            const Eigen::Vector2d base = velocity() ? levelOf(v, origin, target) : targetBase;
            for (std::size_t slot : slotsOf[h]) {
                auto& p = out[slot];
                p.residualXPct[i] = e(0) * m_eScale(0) + base(0);
                p.residualTC[i] = e(1) * m_eScale(1) + base(1);
                p.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[target]) + p.residualXPct[i]; // Eq. (21)
                p.tOutC[i] = v.pbm->tOutK[target] - units::kKelvinOffset + p.residualTC[i];
            }
        }
    }
    return out;
}

HybridPrediction ResidualModel::forecastFrom(const BatchView& v, std::size_t origin, int horizon) const {
    return forecastFrom(std::vector<BatchView>{v}, origin, horizon).front();
}

std::vector<HybridPrediction> ResidualModel::forecastFrom(const std::vector<BatchView>& views,
                                                          std::size_t origin, int horizon) const {
    const auto count = static_cast<std::size_t>(std::max(0, horizon));
    std::vector<HybridPrediction> out(views.size(), HybridPrediction::unknown(count));
    const auto nv = static_cast<Eigen::Index>(views.size());
    if (views.empty() || count == 0) {
        return out;
    }
    const auto lags = static_cast<std::size_t>(m_options.residualLags);
    const std::size_t first = origin + 1 > lags ? origin + 1 - lags : 0;
    Eigen::MatrixXd x(m_a.rows(), nv), forcing(m_a.rows(), nv);
    std::size_t steps = count;
    for (Eigen::Index c = 0; c < nv; ++c) {
        const BatchView& v = views[static_cast<std::size_t>(c)];
        const std::size_t n = v.batch->rows();
        if (origin >= n) {
            return out;
        }
        steps = std::min(steps, n - origin - 1);
        std::vector<double> ex(n, kNaN), et(n, kNaN);
        residualsOf(v, first, origin + 1, ex, et);
        Eigen::VectorXd xc, d;
        double u = 0;
        if (!stateAt(v, origin, ex, et, xc, u, d)) {
            return out;
        }
        x.col(c) = xc;
        forcing.col(c) = m_b.col(0) * u + m_e * d;
    }
    Eigen::VectorXd next(m_a.rows());
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(kOutputs, nv); // velocity form: Σ of the predicted v
    for (std::size_t i = 0; i < steps; ++i) {
        const std::size_t target = origin + 1 + i;
        // One matrix-vector product per candidate: a GEMM would repack A at every step for just
        // two columns (a quarter of the MPC's time in a profile).
        for (Eigen::Index c = 0; c < nv; ++c) {
            next.noalias() = m_a * x.col(c);
            x.col(c) = next + forcing.col(c);
        }
        Eigen::MatrixXd e = m_c * x;
        if (velocity()) {
            sum += e;
            e = correctionWeight(static_cast<int>(i) + 1).asDiagonal() * sum;
        }
        for (Eigen::Index c = 0; c < nv; ++c) {
            const BatchView& v = views[static_cast<std::size_t>(c)];
            auto& o = out[static_cast<std::size_t>(c)];
            const Eigen::Vector2d base = levelOf(v, origin, target);
            o.residualXPct[i] = e(0, c) * m_eScale(0) + base(0);
            o.residualTC[i] = e(1, c) * m_eScale(1) + base(1);
            o.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[target]) + o.residualXPct[i]; // Eq. (21)
            o.tOutC[i] = v.pbm->tOutK[target] - units::kKelvinOffset + o.residualTC[i];
            Eigen::VectorXd z, d;
            double u = 0;
            if (i + 1 < steps && !features(v, target, z, u, d)) {
                return out; // inputs missing: nothing further can be forecast
            }
            if (i + 1 < steps) {
                forcing.col(c) = m_b.col(0) * u + m_e * d;
            }
        }
    }
    return out;
}

HybridPrediction ResidualModel::predictFreeRun(const BatchView& v) const {
    const std::size_t count = v.rows.size();
    HybridPrediction out = HybridPrediction::unknown(count);
    const Eigen::Index lagPart = kOutputs * m_options.residualLags;
    Eigen::VectorXd x;
    bool running = false;
    std::size_t start = 0;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero(); // velocity form: Σ of the predicted v since the start
    for (std::size_t k = 0; k < v.rows.end; ++k) {
        Eigen::VectorXd z, d;
        double u = 0;
        const bool ok = features(v, k, z, u, d);
        if (!running && ok) {
            // (Re)start: no measured residual is ever used, so the lags begin at zero.
            const Eigen::VectorXd phi = liftedResidualFeatures(z);
            x = Eigen::VectorXd::Zero(lagPart + phi.size());
            x.tail(phi.size()) = phi;
            running = true;
            start = k;
            sum.setZero();
        }
        if (running && k >= v.rows.begin) {
            // Beyond the horizons κ_H was fitted at nothing says the summed correction still
            // predicts: the free run falls back on the PBM there.
            const int ahead = static_cast<int>(k - start);
            const bool fitted = !m_shrinkHorizons.empty() && ahead <= m_shrinkHorizons.back();
            const Eigen::Vector2d e =
                velocity() ? (fitted ? Eigen::Vector2d(correctionWeight(ahead).cwiseProduct(sum))
                                     : Eigen::Vector2d::Zero())
                           : Eigen::Vector2d(m_c * x);
            // Velocity form: without any measured output the reference is the PBM itself (its
            // error at the start unknown, taken as 0, and nothing measured to hold).
            const Eigen::Vector2d base = restoredBasePart(v, k);
            const std::size_t i = k - v.rows.begin;
            out.residualXPct[i] = e(0) * m_eScale(0) + base(0);
            out.residualTC[i] = e(1) * m_eScale(1) + base(1);
            out.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[k]) + out.residualXPct[i]; // Eq. (21)
            out.tOutC[i] = v.pbm->tOutK[k] - units::kKelvinOffset + out.residualTC[i];
        }
        if (!ok) {
            running = false; // a row without inputs: start again at the next complete one
        } else if (running) {
            x = m_a * x + m_b.col(0) * u + m_e * d;
            if (velocity()) {
                sum += m_c * x;
            }
        }
    }
    return out;
}

std::vector<Eigen::VectorXd> ResidualModel::rollout(const Eigen::VectorXd& x0, const std::vector<double>& u,
                                                    const std::vector<Eigen::VectorXd>& d) const {
    std::vector<Eigen::VectorXd> xs{x0};
    for (std::size_t j = 0; j < u.size() && j < d.size(); ++j) {
        xs.push_back(m_a * xs.back() + m_b * u[j] + m_e * d[j]);
    }
    return xs;
}

std::string ResidualModel::toJson() const {
    nlohmann::json j;
    const auto& o = m_options;
    j["format_version"] = 1;
    j["options"] = {{"use_proxies", o.useProxies},
                    {"degree", o.degree},
                    {"residual_lags", o.residualLags},
                    {"orthogonal_projection", o.orthogonalProjection},
                    {"project_residual", o.projectResidual},
                    {"restore_base_part", o.restoreBasePart},
                    {"nest_references", o.nestReferences},
                    {"shrink_validation_fraction", o.shrinkValidationFraction},
                    {"correction_folds", o.correctionFolds},
                    {"correction_criterion", o.correctionByAbsoluteError ? "absolute" : "squared"},
                    {"control_consistent_weights", o.controlConsistentWeights},
                    {"stability_constraint", o.stabilityConstraint},
                    {"stability_method",
                     o.stabilityMethod == StabilityMethod::Constrained ? "constrained" : "eigenvalue_pull"},
                    {"lambda_A", o.lambdaA},
                    {"lambda_B", o.lambdaB},
                    {"lambda_E", o.lambdaE},
                    {"lambda_C", o.lambdaC},
                    {"kappa1", o.kappa1},
                    {"kappa2", o.kappa2},
                    {"delta_pct", o.deltaPct},
                    {"moisture_target_pct", o.moistureTargetPct},
                    {"moisture_low_pct", o.moistureLowPct},
                    {"moisture_high_pct", o.moistureHighPct},
                    {"alpha_max", o.alphaMax},
                    {"radius_max", o.radiusMax}};
    j["dictionary"] = {
        {"inputs", m_dict.inputNames()},
        {"mean", std::vector<double>(m_dict.mean().data(), m_dict.mean().data() + m_dict.mean().size())},
        {"scale", std::vector<double>(m_dict.scale().data(), m_dict.scale().data() + m_dict.scale().size())},
        {"features", m_dict.featureNames()}};
    j["base_features"] = m_baseIdx;
    j["residual_features"] = m_resIdx;
    j["projection_G"] = matrixJson(m_projection);
    j["residual_projection_g"] = matrixJson(m_residualProjection);
    j["feature_scale"] =
        std::vector<double>(m_featureScale.data(), m_featureScale.data() + m_featureScale.size());
    j["residual_scale"] = {m_eScale(0), m_eScale(1)};
    j["A"] = matrixJson(m_a);
    j["A_unconstrained"] = matrixJson(m_aFree);
    j["B"] = matrixJson(m_b);
    j["E"] = matrixJson(m_e);
    j["C"] = matrixJson(m_c);
    j["stability"] = {{"spectral_radius_before", m_cert.spectralRadiusBefore},
                      {"spectral_radius_after", m_cert.spectralRadiusAfter},
                      {"alpha", m_cert.alpha},
                      {"certificate_max_eig", m_cert.certificateMaxEig},
                      {"certified", m_cert.certified},
                      {"cholesky_passes", m_cert.choleskyPasses},
                      {"p_condition_number", m_cert.pConditionNumber},
                      {"P", matrixJson(m_cert.p)}};
    const auto& cmp = m_comparison;
    j["stability_comparison"] = {{"loss_unconstrained", cmp.lossUnconstrained},
                                 {"loss_eigenvalue_pull", cmp.lossEigenvaluePull},
                                 {"loss_constrained", cmp.lossConstrained},
                                 {"radius_unconstrained", cmp.radiusUnconstrained},
                                 {"radius_eigenvalue_pull", cmp.radiusEigenvaluePull},
                                 {"radius_constrained", cmp.radiusConstrained},
                                 {"admm_iterations", cmp.admmIterations},
                                 {"outer_iterations", cmp.outerIterations}};
    j["reference_change_weight"] = m_referenceChange;
    j["correction_weight_horizons"] = m_shrinkHorizons;
    nlohmann::json weights = nlohmann::json::array();
    for (const auto& k : m_shrink) {
        weights.push_back({k(0), k(1)});
    }
    j["correction_weights"] = weights;
    nlohmann::json changes = nlohmann::json::array();
    for (const auto& k : m_referenceByHorizon) {
        changes.push_back({k(0), k(1)});
    }
    j["reference_change_by_horizon"] = changes;
    j["training_snapshots"] = m_snapshots;
    j["training_seconds"] = m_trainSeconds;
    return j.dump();
}

Expected<ResidualModel> ResidualModel::fromJson(const std::string& text) {
    try {
        const auto j = nlohmann::json::parse(text);
        ResidualModel m;
        auto& o = m.m_options;
        const auto& jo = j.at("options");
        o.useProxies = jo.at("use_proxies");
        o.degree = jo.at("degree");
        o.residualLags = jo.at("residual_lags");
        o.orthogonalProjection = jo.at("orthogonal_projection");
        // Files from before Eq. 27 was implemented as written projected the features only.
        o.projectResidual = jo.value("project_residual", false);
        o.restoreBasePart = jo.value("restore_base_part", true);
        // Files from before issue #24 shrank towards zero.
        o.nestReferences = jo.value("nest_references", false);
        o.shrinkValidationFraction = jo.value("shrink_validation_fraction", 0.0);
        o.correctionFolds = jo.value("correction_folds", 0);
        o.correctionByAbsoluteError = jo.value("correction_criterion", std::string("squared")) == "absolute";
        o.controlConsistentWeights = jo.at("control_consistent_weights");
        o.stabilityConstraint = jo.at("stability_constraint");
        // Files written before Eq. (30) was solved as stated used the eigenvalue pull.
        o.stabilityMethod = jo.value("stability_method", std::string("eigenvalue_pull")) == "constrained"
                                ? StabilityMethod::Constrained
                                : StabilityMethod::EigenvaluePull;
        o.lambdaA = jo.at("lambda_A");
        o.lambdaB = jo.at("lambda_B");
        o.lambdaE = jo.at("lambda_E");
        o.lambdaC = jo.at("lambda_C");
        o.kappa1 = jo.at("kappa1");
        o.kappa2 = jo.at("kappa2");
        o.deltaPct = jo.at("delta_pct");
        o.moistureTargetPct = jo.at("moisture_target_pct");
        o.moistureLowPct = jo.at("moisture_low_pct");
        o.moistureHighPct = jo.at("moisture_high_pct");
        o.alphaMax = jo.at("alpha_max");
        o.radiusMax = jo.at("radius_max");
        if (auto st = o.validate(); !st) {
            return st.error();
        }
        m.m_dict =
            PolynomialDictionary(j.at("dictionary").at("inputs").get<std::vector<std::string>>(), o.degree);
        m.m_dict.setScaling(vectorFrom(j.at("dictionary").at("mean")),
                            vectorFrom(j.at("dictionary").at("scale")));
        m.m_baseIdx = j.at("base_features").get<std::vector<int>>();
        m.m_resIdx = j.at("residual_features").get<std::vector<int>>();
        m.m_projection = matrixFrom(j.at("projection_G"));
        if (j.contains("residual_projection_g")) {
            m.m_residualProjection = matrixFrom(j.at("residual_projection_g"));
        }
        m.m_featureScale = vectorFrom(j.at("feature_scale"));
        const auto es = j.at("residual_scale").get<std::vector<double>>();
        m.m_eScale = Eigen::Vector2d(es.at(0), es.at(1));
        m.m_a = matrixFrom(j.at("A"));
        m.m_aFree = matrixFrom(j.at("A_unconstrained"));
        m.m_b = matrixFrom(j.at("B"));
        m.m_e = matrixFrom(j.at("E"));
        m.m_c = matrixFrom(j.at("C"));
        const auto& s = j.at("stability");
        m.m_cert.spectralRadiusBefore = s.at("spectral_radius_before");
        m.m_cert.spectralRadiusAfter = s.at("spectral_radius_after");
        m.m_cert.alpha = s.at("alpha");
        m.m_cert.certificateMaxEig = s.at("certificate_max_eig");
        m.m_cert.certified = s.at("certified");
        m.m_cert.p = matrixFrom(s.at("P"));
        m.m_cert.choleskyPasses = s.value("cholesky_passes", false);
        m.m_cert.pConditionNumber = s.value("p_condition_number", 0.0);
        if (j.contains("stability_comparison")) {
            const auto& c = j.at("stability_comparison");
            auto& cmp = m.m_comparison;
            cmp.lossUnconstrained = c.at("loss_unconstrained");
            cmp.lossEigenvaluePull = c.at("loss_eigenvalue_pull");
            cmp.lossConstrained = c.at("loss_constrained");
            cmp.radiusUnconstrained = c.at("radius_unconstrained");
            cmp.radiusEigenvaluePull = c.at("radius_eigenvalue_pull");
            cmp.radiusConstrained = c.at("radius_constrained");
            cmp.admmIterations = c.at("admm_iterations");
            cmp.outerIterations = c.at("outer_iterations");
        }
        m.m_snapshots = j.value("training_snapshots", std::size_t(0));
        m.m_referenceChange = j.value("reference_change_weight", 0.0);
        if (j.contains("correction_weight_horizons")) {
            m.m_shrinkHorizons = j.at("correction_weight_horizons").get<std::vector<int>>();
            for (const auto& k : j.at("correction_weights")) {
                m.m_shrink.emplace_back(k.at(0).get<double>(), k.at(1).get<double>());
            }
            for (const auto& k : j.value("reference_change_by_horizon", nlohmann::json::array())) {
                m.m_referenceByHorizon.emplace_back(k.at(0).get<double>(), k.at(1).get<double>());
            }
            if (m.m_shrink.size() != m.m_shrinkHorizons.size() ||
                (!m.m_referenceByHorizon.empty() &&
                 m.m_referenceByHorizon.size() != m.m_shrinkHorizons.size()) ||
                !std::is_sorted(m.m_shrinkHorizons.begin(), m.m_shrinkHorizons.end())) {
                return Error{ErrorKind::BadInput, "residual model",
                             "correction weights do not match their horizons"};
            }
        }
        m.m_trainSeconds = j.value("training_seconds", 0.0);
        const Eigen::Index nx = m.m_a.rows();
        const bool shapesOk =
            m.m_a.cols() == nx && m.m_b.rows() == nx && m.m_e.rows() == nx && m.m_c.cols() == nx &&
            m.m_c.rows() == kOutputs &&
            nx == kOutputs * o.residualLags + static_cast<Eigen::Index>(m.m_resIdx.size()) &&
            m.m_e.cols() == 1 + (m.eq27() ? 0 : m.m_dict.inputCount() - 1) +
                                (o.useProxies ? kOutputs * std::min(o.residualLags, kPbmChangeLags) : 0) &&
            (!m.eq27() || (m.m_residualProjection.rows() == static_cast<Eigen::Index>(m.m_baseIdx.size()) &&
                           m.m_residualProjection.cols() == kOutputs));
        if (!shapesOk) {
            return Error{ErrorKind::BadInput, "residual model", "matrix shapes do not fit together"};
        }
        return m;
    } catch (const std::exception& e) {
        return Error{ErrorKind::BadInput, "residual model", std::string("malformed: ") + e.what()};
    }
}

} // namespace drytwin::residual
