#include "monitoring/DynamicPca.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace drytwin::monitoring {

namespace {

bool allFinite(const Eigen::Ref<const Eigen::VectorXd>& row) {
    for (Eigen::Index i = 0; i < row.size(); ++i) {
        if (!std::isfinite(row[i])) {
            return false;
        }
    }
    return true;
}

/// Pseudo-inverse of a small symmetric positive semi-definite matrix: a column that the kept
/// components explain completely has a (near) singular block, and then nothing to reconstruct.
Eigen::MatrixXd pseudoInverse(const Eigen::MatrixXd& a) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(a);
    const Eigen::VectorXd& e = eig.eigenvalues();
    const double tol = 1e-10 * std::max(1e-300, e.cwiseAbs().maxCoeff());
    Eigen::VectorXd inv(e.size());
    for (Eigen::Index i = 0; i < e.size(); ++i) {
        inv[i] = e[i] > tol ? 1 / e[i] : 0.0;
    }
    return eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
}

/// The lags × lags block of @p m on original column j's lagged entries (lag-major layout).
Eigen::MatrixXd columnBlock(const Eigen::MatrixXd& m, int j, int p, int lags) {
    Eigen::MatrixXd b(lags, lags);
    for (int r = 0; r < lags; ++r) {
        for (int c = 0; c < lags; ++c) {
            b(r, c) = m(r * p + j, c * p + j);
        }
    }
    return b;
}

} // namespace

Status DynamicPcaOptions::validate() const {
    if (!(blockS > 0) || !std::isfinite(blockS)) {
        return invalidOption("blockS", "the block length must be a positive number of seconds");
    }
    if (lags < 1 || lags > 100) {
        return invalidOption("lags", "the number of lags must be between 1 and 100");
    }
    if (!(varianceExplained > 0 && varianceExplained <= 1)) {
        return invalidOption("varianceExplained", "the share of variance to explain must be in (0, 1]");
    }
    if (!(confidence > 0 && confidence < 1)) {
        return invalidOption("confidence", "the confidence of the limits must be in (0, 1)");
    }
    return {};
}

int blockIndexOf(double sinceStartS, double blockS) {
    // The tolerance keeps a sample stamped 9.9999999999 s (decimal steps summed in floating
    // point) in the block a human would put it in.
    return static_cast<int>(std::floor(sinceStartS / blockS + 1e-9));
}

// How far (in the other samples' standard deviations) a block's outermost sample must lie to be
// taken for a spike. Ten and not the usual 3-6: within a 10 s block, autocorrelated noise
// spreads far less than its marginal SD, and at 6 honest samples of a smooth process were
// dropped; a transmitter's spike (the plant's: 19-30 of them) is far beyond either.
constexpr double kSpikeCutoff = 10;

double robustBlockMean(std::vector<double>& samples) {
    samples.erase(std::remove_if(samples.begin(), samples.end(), [](double v) { return !std::isfinite(v); }),
                  samples.end());
    if (samples.empty()) {
        return kNaN;
    }
    double sum = 0;
    for (double v : samples) {
        sum += v;
    }
    const auto n = static_cast<double>(samples.size());
    if (samples.size() < 4) { // too few to tell a spike from the noise
        return sum / n;
    }
    // The sample furthest from the others' mean, judged against the others' spread: a block's
    // own median absolute deviation from ten samples is too noisy a yardstick (it drops honest
    // samples of Gaussian noise), the spread of the other nine almost never is.
    std::size_t worst = 0;
    double worstDistance = -1;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double distance = std::abs(samples[i] - (sum - samples[i]) / (n - 1));
        if (distance > worstDistance) {
            worstDistance = distance;
            worst = i;
        }
    }
    const double restMean = (sum - samples[worst]) / (n - 1);
    double restSq = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (i != worst) {
            restSq += (samples[i] - restMean) * (samples[i] - restMean);
        }
    }
    const double restSd = std::sqrt(restSq / (n - 2));
    return worstDistance > kSpikeCutoff * std::max(restSd, 1e-9) ? restMean : sum / n;
}

Eigen::MatrixXd lagBlocks(const std::vector<double>& timeS, const Eigen::MatrixXd& values, double blockS,
                          int lags) {
    const Eigen::Index p = values.cols();
    const Eigen::Index rows = std::min<Eigen::Index>(values.rows(), static_cast<Eigen::Index>(timeS.size()));
    if (rows == 0 || !std::isfinite(timeS.front()) || !std::isfinite(timeS[rows - 1])) {
        return Eigen::MatrixXd(0, p * lags);
    }
    const double t0 = timeS.front();
    const int blocks = std::max(0, blockIndexOf(timeS[rows - 1] - t0, blockS) + 1);
    Eigen::MatrixXd means = Eigen::MatrixXd::Constant(blocks, p, kNaN);
    std::vector<double> samples;
    for (Eigen::Index j = 0; j < p; ++j) {
        Eigen::Index i = 0;
        while (i < rows) {
            const int b = blockIndexOf(timeS[i] - t0, blockS);
            samples.clear();
            for (; i < rows && blockIndexOf(timeS[i] - t0, blockS) == b; ++i) {
                samples.push_back(values(i, j));
            }
            if (b >= 0 && b < blocks) {
                means(b, j) = robustBlockMean(samples);
            }
        }
    }
    Eigen::MatrixXd lagged(blocks, p * lags);
    for (int b = 0; b < blocks; ++b) {
        for (int l = 0; l < lags; ++l) {
            for (Eigen::Index j = 0; j < p; ++j) {
                const int src = b - l;
                lagged(b, l * p + j) = src >= 0 ? means(src, j) : kNaN;
            }
        }
    }
    return lagged;
}

double logStatistic(double statistic) {
    return std::log(std::max(statistic, 1e-12));
}

// A window needs half its blocks: one surviving block would be far noisier than the windows the
// null was estimated on, and a dropout would then look like a change.
double windowLogMean(double sumLog, int validBlocks, int blocksPerWindow) {
    return validBlocks > 0 && 2 * validBlocks >= blocksPerWindow ? sumLog / validBlocks : kNaN;
}

void windowLogMeans(const Eigen::VectorXd& blockLogT2, const Eigen::VectorXd& blockLogSpe,
                    int blocksPerWindow, std::vector<double>& logT2, std::vector<double>& logSpe) {
    const Eigen::Index bpw = blocksPerWindow, windows = blockLogT2.size() / bpw;
    logT2.assign(static_cast<std::size_t>(windows), kNaN);
    logSpe.assign(static_cast<std::size_t>(windows), kNaN);
    for (Eigen::Index w = 0; w < windows; ++w) {
        double sumT2 = 0, sumSpe = 0;
        int valid = 0;
        for (Eigen::Index b = w * bpw; b < (w + 1) * bpw; ++b) {
            if (std::isfinite(blockLogT2[b]) && std::isfinite(blockLogSpe[b])) {
                sumT2 += blockLogT2[b];
                sumSpe += blockLogSpe[b];
                ++valid;
            }
        }
        logT2[static_cast<std::size_t>(w)] = windowLogMean(sumT2, valid, blocksPerWindow);
        logSpe[static_cast<std::size_t>(w)] = windowLogMean(sumSpe, valid, blocksPerWindow);
    }
}

LaggedMoments LaggedMoments::of(const Eigen::MatrixXd& lagged) {
    LaggedMoments m;
    std::vector<Eigen::Index> complete;
    for (Eigen::Index r = 0; r < lagged.rows(); ++r) {
        if (allFinite(lagged.row(r).transpose())) {
            complete.push_back(r);
        }
    }
    m.count = static_cast<double>(complete.size());
    m.mean = Eigen::VectorXd::Zero(lagged.cols());
    m.scatter = Eigen::MatrixXd::Zero(lagged.cols(), lagged.cols());
    if (complete.empty()) {
        return m;
    }
    Eigen::MatrixXd x(static_cast<Eigen::Index>(complete.size()), lagged.cols());
    for (std::size_t k = 0; k < complete.size(); ++k) {
        x.row(static_cast<Eigen::Index>(k)) = lagged.row(complete[k]);
    }
    m.mean = x.colwise().mean().transpose();
    x.rowwise() -= m.mean.transpose();
    m.scatter.noalias() = x.transpose() * x;
    return m;
}

void LaggedMoments::add(const LaggedMoments& other) {
    if (other.count <= 0) {
        return;
    }
    if (count <= 0) {
        *this = other;
        return;
    }
    const double n = count + other.count;
    const Eigen::VectorXd d = other.mean - mean;
    mean += d * (other.count / n);
    scatter += other.scatter + d * d.transpose() * (count * other.count / n);
    count = n;
}

Expected<DynamicPca> DynamicPca::fit(const std::vector<Eigen::MatrixXd>& laggedRuns, int originalColumns,
                                     const DynamicPcaOptions& options, const std::string& place) {
    std::vector<LaggedMoments> moments;
    moments.reserve(laggedRuns.size());
    for (const auto& run : laggedRuns) {
        moments.push_back(LaggedMoments::of(run));
    }
    return fit(moments, originalColumns, options, place);
}

Expected<DynamicPca> DynamicPca::fit(const std::vector<LaggedMoments>& runs, int originalColumns,
                                     const DynamicPcaOptions& options, const std::string& place) {
    if (Status s = options.validate(); !s) {
        return s.error();
    }
    LaggedMoments all;
    for (const auto& run : runs) {
        all.add(run);
    }
    const Eigen::Index m = all.mean.size();
    if (originalColumns < 1 || m != static_cast<Eigen::Index>(originalColumns) * options.lags || m < 2) {
        return Error{ErrorKind::BadInput, place,
                     "the lagged data must have columns × lags ≥ 2 columns; got " + std::to_string(m)};
    }
    const double n = all.count;
    if (n < static_cast<double>(m) + 2) {
        return Error{ErrorKind::BadInput,
                     place,
                     "only " + std::to_string(static_cast<long>(n)) +
                         " complete lagged block rows; the PCA needs at least " + std::to_string(m + 2) +
                         " (lagged columns + 2): give longer or more reference runs, or fewer lags",
                     ErrorCode::NotEnoughData,
                     {"complete lagged block rows", std::to_string(static_cast<long>(n))}};
    }
    DynamicPca pca;
    pca.m_options = options;
    pca.m_originalColumns = originalColumns;
    pca.m_rows = n;
    pca.m_mean = all.mean;
    pca.m_scale.resize(m);
    const Eigen::MatrixXd cov = all.scatter / (n - 1);
    for (Eigen::Index i = 0; i < m; ++i) {
        const double sd = std::sqrt(std::max(0.0, cov(i, i)));
        // A constant (stuck or unused) column would otherwise divide by ~0 and turn round-off
        // into huge scores; with SD 1 it stays 0 in the reference and a real change still shows.
        if (sd < 1e-9 * (1 + std::abs(all.mean[i]))) {
            pca.m_scale[i] = 1;
            pca.m_constantColumns.push_back(static_cast<int>(i));
        } else {
            pca.m_scale[i] = sd;
        }
    }
    const Eigen::VectorXd inv = pca.m_scale.cwiseInverse();
    const Eigen::MatrixXd corr = inv.asDiagonal() * cov * inv.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(corr);
    if (eig.info() != Eigen::Success) {
        return Error{ErrorKind::Numerical,
                     place,
                     "the eigendecomposition of the correlation matrix failed",
                     ErrorCode::SolverFailed,
                     {"pca eigendecomposition", "no convergence"}};
    }
    // Eigen sorts ascending; the monitor wants the largest first.
    pca.m_eigenvalues = eig.eigenvalues().reverse().cwiseMax(0.0);
    const Eigen::MatrixXd vectors = eig.eigenvectors().rowwise().reverse();
    const double total = pca.m_eigenvalues.sum();
    if (!(total > 0)) {
        return Error{ErrorKind::BadInput, place,
                     "every column is constant over the reference; nothing to monitor"};
    }
    int positive = 0;
    while (positive < m && pca.m_eigenvalues[positive] > 1e-12 * total) {
        ++positive;
    }
    int a = 0;
    double cumulative = 0;
    while (a < m) {
        cumulative += pca.m_eigenvalues[a++];
        if (cumulative >= options.varianceExplained * total * (1 - 1e-12)) {
            break;
        }
    }
    a = std::max(1, std::min({a, static_cast<int>(m) - 1, positive}));
    pca.m_components = a;
    pca.m_varianceExplained = pca.m_eigenvalues.head(a).sum() / total;
    pca.m_loadings = vectors.leftCols(a);
    pca.m_keptEigenvalues = pca.m_eigenvalues.head(a);

    const Eigen::MatrixXd residualProjector =
        Eigen::MatrixXd::Identity(m, m) - pca.m_loadings * pca.m_loadings.transpose();
    const Eigen::MatrixXd t2Metric =
        pca.m_loadings * pca.m_keptEigenvalues.cwiseInverse().asDiagonal() * pca.m_loadings.transpose();
    for (int j = 0; j < originalColumns; ++j) {
        pca.m_speReconstruction.push_back(
            pseudoInverse(columnBlock(residualProjector, j, originalColumns, options.lags)));
        pca.m_t2Reconstruction.push_back(
            pseudoInverse(columnBlock(t2Metric, j, originalColumns, options.lags)));
    }

    const double fq = boost::math::quantile(boost::math::fisher_f(a, n - a), options.confidence);
    pca.m_t2Limit = a * (n - 1) * (n + 1) / (n * (n - a)) * fq; // the F-based limit for a new observation
    const Eigen::VectorXd discarded = pca.m_eigenvalues.tail(m - a);
    const double theta1 = discarded.sum();
    const double theta2 = discarded.squaredNorm();
    if (theta1 > 1e-12 * total && theta2 > 0) {
        const double g = theta2 / theta1, h = theta1 * theta1 / theta2; // Box (1954)
        pca.m_speLimit = g * boost::math::quantile(boost::math::chi_squared(h), options.confidence);
    } else {
        pca.m_speLimit = 0; // the kept components span all the reference variance
    }
    return pca;
}

void DynamicPca::scoreRow(const Eigen::Ref<const Eigen::VectorXd>& lagged, double& t2, double& spe,
                          RowContributions* contributions) const {
    const int p = m_originalColumns;
    if (!allFinite(lagged)) {
        t2 = spe = kNaN;
        if (contributions) {
            contributions->t2.setConstant(p, kNaN);
            contributions->spe.setConstant(p, kNaN);
            contributions->t2Reconstruction.setConstant(p, kNaN);
            contributions->speReconstruction.setConstant(p, kNaN);
        }
        return;
    }
    const Eigen::VectorXd x = (lagged - m_mean).cwiseQuotient(m_scale);
    const Eigen::VectorXd t = m_loadings.transpose() * x;
    const Eigen::VectorXd tScaled = t.cwiseQuotient(m_keptEigenvalues);
    t2 = t.dot(tScaled);
    const Eigen::VectorXd residual = x - m_loadings * t;
    spe = residual.squaredNorm();
    if (!contributions) {
        return;
    }
    // Complete decomposition: x_j (P Λ⁻¹ Pᵀ x)_j, which sums to T² exactly.
    const Eigen::VectorXd w = m_loadings * tScaled;
    RowContributions& c = *contributions;
    c.t2.setZero(p);
    c.spe.setZero(p);
    for (Eigen::Index i = 0; i < x.size(); ++i) {
        c.t2[i % p] += x[i] * w[i];
        c.spe[i % p] += residual[i] * residual[i];
    }
    // Reconstruction along column j's lags Ξ_j: (Ξᵀ C̃ x)ᵀ (Ξᵀ C̃ Ξ)⁺ (Ξᵀ C̃ x) with C̃ x the residual,
    // and the same with P Λ⁻¹ Pᵀ x = w for T².
    const int lags = m_options.lags;
    c.t2Reconstruction.resize(p);
    c.speReconstruction.resize(p);
    Eigen::VectorXd rj(lags), wj(lags);
    for (int j = 0; j < p; ++j) {
        for (int l = 0; l < lags; ++l) {
            rj[l] = residual[l * p + j];
            wj[l] = w[l * p + j];
        }
        c.speReconstruction[j] = rj.dot(m_speReconstruction[static_cast<std::size_t>(j)] * rj);
        c.t2Reconstruction[j] = wj.dot(m_t2Reconstruction[static_cast<std::size_t>(j)] * wj);
    }
}

PcaScores DynamicPca::score(const Eigen::MatrixXd& lagged) const {
    const Eigen::Index rows = lagged.rows();
    PcaScores s;
    s.t2.resize(rows);
    s.spe.resize(rows);
    s.t2Contributions.resize(rows, m_originalColumns);
    s.speContributions.resize(rows, m_originalColumns);
    s.t2Reconstruction.resize(rows, m_originalColumns);
    s.speReconstruction.resize(rows, m_originalColumns);
    RowContributions c;
    for (Eigen::Index r = 0; r < rows; ++r) {
        scoreRow(lagged.row(r).transpose(), s.t2[r], s.spe[r], &c);
        s.t2Contributions.row(r) = c.t2.transpose();
        s.speContributions.row(r) = c.spe.transpose();
        s.t2Reconstruction.row(r) = c.t2Reconstruction.transpose();
        s.speReconstruction.row(r) = c.speReconstruction.transpose();
    }
    return s;
}

} // namespace drytwin::monitoring
