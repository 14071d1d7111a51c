// The input-driven correction's guards (issue #75): where its training rows do not support it
// (leverage, the fits without each fold, the correction's range), and how much of its change over
// a horizon to trust.
#include "residual/InputDrivenCorrection.h"

#include "residual/InputDrivenInternal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drytwin::residual {

using namespace input_driven;

void InputDrivenCorrection::fitSupport(const Eigen::MatrixXd& phi, const std::vector<char>& inlier,
                                       const Eigen::MatrixXd& gram, double penalty) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
    if (eigen.info() != Eigen::Success || !(penalty > 0)) {
        return; // no guard rather than a wrong one: the correction is still held within its range
    }
    m_supportRho = 1.0 / penalty;
    std::vector<Eigen::Index> kept;
    for (Eigen::Index i = 0; i < eigen.eigenvalues().size(); ++i) {
        if (eigen.eigenvalues()(i) > 0.05 * penalty) {
            kept.push_back(i);
        }
    }
    m_supportDirections.resize(gram.rows(), static_cast<Eigen::Index>(kept.size()));
    for (std::size_t c = 0; c < kept.size(); ++c) {
        const double s = eigen.eigenvalues()(kept[c]);
        m_supportDirections.col(static_cast<Eigen::Index>(c)) =
            eigen.eigenvectors().col(kept[c]) * std::sqrt(std::max(0.0, m_supportRho - 1.0 / (s + penalty)));
    }
    // The reference leverage and the correction's range, on the training rows (every few rows
    // for the quantile: a few thousand rows fix it well enough).
    const auto rows = phi.rows();
    const Eigen::Index stride = std::max<Eigen::Index>(1, rows / 4000);
    std::vector<double> leverages;
    Eigen::MatrixXd sample(0, phi.cols());
    std::vector<Eigen::Index> sampled;
    for (Eigen::Index r = 0; r < rows; r += stride) {
        if (inlier[static_cast<std::size_t>(r)]) {
            sampled.push_back(r);
        }
    }
    sample.resize(static_cast<Eigen::Index>(sampled.size()), phi.cols());
    for (std::size_t i = 0; i < sampled.size(); ++i) {
        sample.row(static_cast<Eigen::Index>(i)) = phi.row(sampled[i]);
    }
    const Eigen::VectorXd h = leverageOf(sample);
    leverages.assign(h.data(), h.data() + h.size());
    auto& val = m_validation;
    if (leverages.empty()) {
        m_supportDirections.resize(0, 0);
        return;
    }
    const auto at = static_cast<std::ptrdiff_t>(std::clamp(m_options.supportQuantile, 0.0, 1.0) *
                                                double(leverages.size() - 1));
    std::nth_element(leverages.begin(), leverages.begin() + at, leverages.end());
    val.supportLeverage = leverages[static_cast<std::size_t>(at)];
    // The range of the correction over every inlier training row, as correct() forms it.
    const Eigen::MatrixXd out = phi * m_coefficients;
    Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d high = -low;
    for (Eigen::Index r = 0; r < rows; ++r) {
        if (inlier[static_cast<std::size_t>(r)]) {
            low = low.cwiseMin(out.row(r).transpose());
            high = high.cwiseMax(out.row(r).transpose());
        }
    }
    val.correctionLow = low;
    val.correctionHigh = high;
}

Eigen::VectorXd InputDrivenCorrection::leverageOf(const Eigen::MatrixXd& standardisedBasis) const {
    if (m_supportDirections.size() == 0) {
        return Eigen::VectorXd::Zero(standardisedBasis.rows());
    }
    const Eigen::MatrixXd projected = standardisedBasis * m_supportDirections;
    return (m_supportRho * standardisedBasis.rowwise().squaredNorm() - projected.rowwise().squaredNorm())
        .cwiseMax(0.0);
}

void InputDrivenCorrection::applyGuards(const Eigen::MatrixXd& phi, Eigen::MatrixXd& out) const {
    if (m_foldCoefficients.size() > 0) {
        // The part of the correction the fits without each fold agree on: weighed down by its
        // jackknife standard error across the folds, so that a correction resting on one batch,
        // or one the fits without one batch or another extrapolate differently, is dropped.
        const Eigen::MatrixXd byFold = phi * m_foldCoefficients;
        const auto folds = static_cast<double>(m_foldCoefficients.cols() / kCorrectedOutputs);
        for (Eigen::Index k = 0; k < out.rows(); ++k) {
            for (int o = 0; o < kCorrectedOutputs; ++o) {
                double mean = 0, spread = 0;
                for (Eigen::Index f = o; f < byFold.cols(); f += kCorrectedOutputs) {
                    mean += byFold(k, f) / folds;
                }
                for (Eigen::Index f = o; f < byFold.cols(); f += kCorrectedOutputs) {
                    spread += (byFold(k, f) - mean) * (byFold(k, f) - mean);
                }
                const double standardError = std::sqrt((folds - 1) / folds * spread);
                // c · c² / (c² + z² se²): kept whole where it stands well clear of its spread, a
                // quarter of it where it is as large as z times its spread.
                const double c = out(k, o);
                const double noise =
                    m_options.agreementZ * m_options.agreementZ * standardError * standardError;
                out(k, o) = c * c * c / std::max(c * c + noise, 1e-300);
            }
        }
    }
    if (m_supportDirections.size() > 0) {
        const Eigen::VectorXd h = leverageOf(phi);
        const auto& val = m_validation;
        for (Eigen::Index k = 0; k < out.rows(); ++k) {
            const double weight = h(k) > val.supportLeverage ? val.supportLeverage / h(k) : 1.0;
            for (int o = 0; o < kCorrectedOutputs; ++o) {
                out(k, o) = std::clamp(weight * out(k, o), std::min(0.0, val.correctionLow(o)),
                                       std::max(0.0, val.correctionHigh(o)));
            }
        }
    }
}

Eigen::Vector2d InputDrivenCorrection::changeWeight(int horizon) const {
    if (m_changeWeights.size() != kChangeHorizons.size()) {
        return Eigen::Vector2d::Ones(); // files before 2026-12-08: the change as it comes
    }
    if (horizon <= kChangeHorizons.front()) {
        return m_changeWeights.front();
    }
    for (std::size_t i = 1; i < kChangeHorizons.size(); ++i) {
        if (horizon <= kChangeHorizons[i]) {
            const double t = double(horizon - kChangeHorizons[i - 1]) /
                             double(kChangeHorizons[i] - kChangeHorizons[i - 1]);
            return (1 - t) * m_changeWeights[i - 1] + t * m_changeWeights[i];
        }
    }
    return m_changeWeights.back();
}

namespace input_driven {

std::vector<Eigen::Vector2d> fitChangeWeights(const Eigen::MatrixXd& y, const Eigen::MatrixXd& heldOut,
                                              const std::vector<std::size_t>& rowTime,
                                              const std::vector<Segment>& segments) {
    std::vector<Eigen::Vector2d> weights(kChangeHorizons.size(), Eigen::Vector2d::Zero());
    constexpr int kSteps = 100;
    for (std::size_t g = 0; g < kChangeHorizons.size(); ++g) {
        const auto h = static_cast<std::size_t>(kChangeHorizons[g]);
        // Σ |Δe − μ Δc| for μ = 0, 0.01, …, 1, per output.
        std::vector<double> cost[kCorrectedOutputs];
        for (auto& c : cost) {
            c.assign(kSteps + 1, 0.0);
        }
        for (const auto& sg : segments) {
            // Rows of a segment are in time order with gaps where a target was missing: walk a
            // second index to the row h later.
            Eigen::Index later = sg.begin;
            for (Eigen::Index r = sg.begin; r < sg.end; ++r) {
                const std::size_t target = rowTime[static_cast<std::size_t>(r)] + h;
                while (later < sg.end && rowTime[static_cast<std::size_t>(later)] < target) {
                    ++later;
                }
                if (later >= sg.end) {
                    break;
                }
                if (rowTime[static_cast<std::size_t>(later)] != target) {
                    continue;
                }
                for (int o = 0; o < kCorrectedOutputs; ++o) {
                    const double de = y(later, o) - y(r, o);
                    const double dc = heldOut(later, o) - heldOut(r, o);
                    if (!std::isfinite(de) || !std::isfinite(dc)) {
                        continue;
                    }
                    for (int q = 0; q <= kSteps; ++q) {
                        cost[o][static_cast<std::size_t>(q)] += std::abs(de - (q / double(kSteps)) * dc);
                    }
                }
            }
        }
        for (int o = 0; o < kCorrectedOutputs; ++o) {
            const auto best = std::min_element(cost[o].begin(), cost[o].end()) - cost[o].begin();
            weights[g](o) = static_cast<double>(best) / kSteps;
        }
    }
    return weights;
}

} // namespace input_driven

} // namespace drytwin::residual
