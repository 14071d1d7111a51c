// The input-driven correction's dictionary (issue #42): which inputs it reads, despiked, and the
// basis it builds from them (lagged inputs, a filter bank, or both), with the memory that needs.
#include "residual/InputDrivenCorrection.h"

#include "common/Units.h"
#include "residual/InputDrivenInternal.h"
#include "residual/TrailingHampel.h"

#include <algorithm>
#include <cmath>

namespace drytwin::residual {

using namespace input_driven;

int InputDrivenCorrection::inputCount() const {
    return kMeasuredInputs + (m_options.useProxies ? kProxyInputs : 0);
}

Eigen::MatrixXd InputDrivenCorrection::inputSeries(const data::SiBatch& b,
                                                   const physics::SimulationResult& p) const {
    const std::size_t rows = std::min(b.rows(), p.xOutDb.size());
    const int n = inputCount();
    Eigen::MatrixXd z(static_cast<Eigen::Index>(rows), n);
    for (std::size_t k = 0; k < rows; ++k) {
        std::vector<double> row{m_options.manipulatedInput ? b.tHotK[k] : 0.0,
                                b.feedKgPerS[k],
                                b.xInDb[k],
                                b.tInK[k],
                                b.tAmbK[k],
                                b.rhAmb[k],
                                b.airSpeedMPerS[k]};
        if (m_options.useProxies) {
            for (double x :
                 {p.proxyXHdtDb[k], p.proxyTHdtK[k], p.proxyXConvDb[k], p.proxyTConvK[k], p.proxyXMixDb[k],
                  p.proxyTMixK[k], units::dryToWetPct(p.xOutDb[k]), p.tOutK[k]}) {
                row.push_back(x);
            }
        }
        for (int j = 0; j < n; ++j) {
            z(static_cast<Eigen::Index>(k), j) = row[static_cast<std::size_t>(j)];
        }
    }
    // A dropout holds the last value (the first finite one before it), as a simulator must.
    for (int j = 0; j < n; ++j) {
        double last = kNaN;
        for (Eigen::Index k = 0; k < z.rows(); ++k) {
            if (std::isfinite(z(k, j))) {
                last = z(k, j);
                break;
            }
        }
        for (Eigen::Index k = 0; k < z.rows(); ++k) {
            if (std::isfinite(z(k, j))) {
                last = z(k, j);
            } else {
                z(k, j) = last;
            }
        }
    }
    return z;
}

Eigen::MatrixXd InputDrivenCorrection::basisOf(const Eigen::MatrixXd& raw, double stepS,
                                               Eigen::VectorXd* inRange) const {
    const Eigen::Index rows = raw.rows(), n = raw.cols();
    Eigen::MatrixXd z(rows, n);
    for (Eigen::Index k = 0; k < rows; ++k) {
        z.row(k) = (raw.row(k).transpose() - m_inputMean).cwiseQuotient(m_inputScale).transpose();
    }
    // Transmitter spikes in the measured inputs (not the PBM's proxies, which are smooth): a
    // lag basis would carry a spike's full height for as many rows as it has lags.
    despikeTrailing(z, kMeasuredInputs, kDespikeWindow, kDespikeCutoff, kDespikeFloor);
    if (inRange) {
        // 1 inside the training range, falling linearly to 0 at the clip range's edge (the margin
        // beyond it), the smallest over the inputs: how far the row is from what was seen.
        const double margin = m_options.rangeMargin;
        const Eigen::VectorXd span = (m_inputHigh - m_inputLow) / (1 + 2 * margin);
        const Eigen::VectorXd low = m_inputLow + margin * span, high = m_inputHigh - margin * span;
        inRange->setOnes(rows);
        for (Eigen::Index k = 0; k < rows; ++k) {
            for (Eigen::Index j = 0; j < n; ++j) {
                const double beyond = std::max({0.0, low(j) - z(k, j), z(k, j) - high(j)});
                const double fade = margin * span(j) > 0 ? beyond / (margin * span(j)) : (beyond > 0 ? 1.0 : 0.0);
                (*inRange)(k) = std::min((*inRange)(k), std::max(0.0, 1.0 - fade));
            }
        }
    }
    for (Eigen::Index k = 0; k < rows; ++k) {
        z.row(k) = z.row(k).cwiseMax(m_inputLow.transpose()).cwiseMin(m_inputHigh.transpose());
    }
    const bool bank = m_options.basis != InputBasis::LaggedInputs;
    const bool lagged = m_options.basis != InputBasis::FilterBank;
    const int stages = m_options.cascadeOrder;
    const auto taus = bank ? static_cast<Eigen::Index>(m_options.timeConstantsS.size()) : 0;
    const int lags = lagged ? static_cast<int>(std::floor(m_options.maxLagS / m_options.lagStrideS)) + 1 : 0;
    Eigen::MatrixXd phi(rows, featureCountFor(n));
    phi.col(0).setOnes();
    Eigen::Index at = 1;
    if (bank) {
        phi.middleCols(at, n) = z;
        at += n;
        for (Eigen::Index t = 0; t < taus; ++t, at += stages * n) {
            const double a = std::exp(-stepS / m_options.timeConstantsS[static_cast<std::size_t>(t)]);
            // Each stage starts settled at the first inputs: the line ran before the batch began.
            Eigen::MatrixXd state = z.row(0).replicate(stages, 1);
            for (Eigen::Index k = 0; k < rows; ++k) {
                Eigen::RowVectorXd in = z.row(k);
                for (int s = 0; s < stages; ++s) {
                    state.row(s) = a * state.row(s) + (1 - a) * in;
                    in = state.row(s);
                    phi.row(k).segment(at + s * n, n) = state.row(s);
                }
            }
        }
    }
    const auto stride = std::max<Eigen::Index>(1, std::lround(m_options.lagStrideS / stepS));
    for (int l = 0; l < lags; ++l, at += n) {
        for (Eigen::Index k = 0; k < rows; ++k) {
            // Before the batch's first row the line is taken to have stood at its first inputs.
            phi.row(k).segment(at, n) = z.row(std::max<Eigen::Index>(0, k - l * stride));
        }
    }
    return phi;
}

std::size_t InputDrivenCorrection::memoryRows() const {
    const double step = m_stepS > 0 ? m_stepS : 1.0;
    double memoryS = 0;
    if (m_options.basis != InputBasis::FilterBank) {
        memoryS = std::max(memoryS, m_options.maxLagS);
    }
    if (m_options.basis != InputBasis::LaggedInputs && !m_options.timeConstantsS.empty()) {
        // A cascade of n first-order stages forgets a step to 0.5 % after about (n + 5) τ
        // (n = 2: (1 + t/τ) e^{−t/τ} = 0.005 at t ≈ 7.4 τ).
        const double slowest =
            *std::max_element(m_options.timeConstantsS.begin(), m_options.timeConstantsS.end());
        memoryS = std::max(memoryS, (m_options.cascadeOrder + 5.5) * slowest);
    }
    return static_cast<std::size_t>(std::ceil(memoryS / step)) + kDespikeWindow;
}

Eigen::Index InputDrivenCorrection::featureCountFor(int n) const {
    const auto& o = m_options;
    const Eigen::Index bank =
        o.basis == InputBasis::LaggedInputs
            ? 0
            : n + static_cast<Eigen::Index>(o.timeConstantsS.size()) * o.cascadeOrder * n;
    const Eigen::Index lagged =
        o.basis == InputBasis::FilterBank
            ? 0
            : n * (static_cast<Eigen::Index>(std::floor(o.maxLagS / o.lagStrideS)) + 1);
    return 1 + bank + lagged;
}

} // namespace drytwin::residual
