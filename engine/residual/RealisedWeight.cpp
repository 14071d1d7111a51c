// The weight of a learnt correction from the forecasts already realised (issue #42).
#include "residual/RealisedWeight.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drytwin::residual {

RealisedWeight::RealisedWeight(double halfLifeSteps, double priorRows, double priorWeight, bool absoluteError)
    : m_decay(halfLifeSteps > 0 ? std::exp(-std::log(2.0) / halfLifeSteps) : 1.0), m_priorRows(priorRows),
      m_priorWeight(std::clamp(priorWeight, 0.0, 1.0)), m_absolute(absoluteError) {}

void RealisedWeight::add(double target, double correction) {
    if (!std::isfinite(target) || !std::isfinite(correction)) {
        return;
    }
    m_tc = m_decay * m_tc + target * correction;
    m_cc = m_decay * m_cc + correction * correction;
    m_rows = m_decay * m_rows + 1;
    if (m_absolute) {
        m_absC = m_decay * m_absC + std::abs(correction);
        for (int g = 0; g < kGrid; ++g) {
            const double w = g / double(kGrid - 1);
            m_absErr[g] = m_decay * m_absErr[g] + std::abs(target - w * correction);
        }
    }
}

double RealisedWeight::weight() const {
    if (m_rows <= 0 || m_cc <= 0) {
        return m_priorWeight;
    }
    if (m_absolute) {
        const double pull = m_priorRows * m_absC / m_rows;
        double best = 0, bestCost = 0;
        for (int g = 0; g < kGrid; ++g) {
            const double w = g / double(kGrid - 1);
            const double cost = m_absErr[g] + pull * std::abs(w - m_priorWeight);
            // Ties (within round-off) go to the weight nearer w₀.
            const double tolerance = 1e-12 * std::max(cost, bestCost);
            if (g == 0 || cost < bestCost - tolerance ||
                (cost <= bestCost + tolerance &&
                 std::abs(w - m_priorWeight) < std::abs(best - m_priorWeight))) {
                best = w;
                bestCost = cost;
            }
        }
        return best;
    }
    // The prior: priorRows rows of corrections of the typical size seen so far, for each of which
    // w₀ was exactly right.
    const double prior = m_priorRows * m_cc / m_rows;
    return std::clamp((m_tc + prior * m_priorWeight) / (m_cc + prior), 0.0, 1.0);
}

void applyRealisedWeights(const std::vector<double>& reference, const std::vector<double>& correction,
                          const std::vector<double>& measured, std::size_t horizon, double halfLifeSteps,
                          double priorRows, std::vector<double>& combined, std::vector<double>* weights,
                          double priorWeight, bool absoluteError) {
    const std::size_t n = reference.size();
    combined.assign(n, std::numeric_limits<double>::quiet_NaN());
    if (weights) {
        weights->assign(n, std::numeric_limits<double>::quiet_NaN());
    }
    RealisedWeight w(halfLifeSteps, priorRows, priorWeight, absoluteError);
    std::size_t realised = 0; // forecasts [0, realised) are in w
    for (std::size_t i = 0; i < n; ++i) {
        // Row i's forecast was made at row i − horizon: every target up to there is measured.
        while (realised + horizon <= i) {
            w.add(measured[realised] - reference[realised], correction[realised]);
            ++realised;
        }
        if (!std::isfinite(reference[i]) || !std::isfinite(correction[i])) {
            continue;
        }
        const double wi = w.weight();
        combined[i] = reference[i] + wi * correction[i];
        if (weights) {
            (*weights)[i] = wi;
        }
    }
}

} // namespace drytwin::residual
