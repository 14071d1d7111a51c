#pragma once

#include <cstddef>
#include <vector>

namespace drytwin::residual {

/// @brief How much of a learnt correction to add to a reference forecast, from how the
/// forecasts already realised did (issue #42's guard against a data set that is not like the
/// training data: an ambient temperature never seen, a new batch whose line behaves otherwise).
///
/// Per horizon, the forecast is r + w c: r the reference (the last error held, the PBM's change
/// taken back), c the learnt correction. w minimises the exponentially discounted squared error
/// of the forecasts whose targets are already measured, Σ λ^age (t − w c)² with t = y − r,
/// pulled towards the trained weight w₀ (1 for a correction whose κ_H is already in c; the
/// trained s_H for the blend of the two references) by @p priorRows rows' worth of evidence, and
/// held in [0, 1]: a correction that keeps missing is switched off within a few half-lives, one that
/// keeps helping stays. This is recursive least squares of one coefficient with forgetting
/// (the textbook forecast combination of Bates and Granger with discounting); hand-written
/// because it is two running sums.
///
/// With @p absoluteError, w instead minimises the discounted absolute error Σ λ^age |t − w c|
/// (plus the prior's pull, priorRows · mean|c| · |w − w₀|) over w = 0, 0.05, …, 1: the measure
/// forecasts are judged by (MAE, skill), and one that a transmitter's spike in the measured
/// output does not dominate. 21 running sums, one per candidate weight.
class RealisedWeight {
public:
    RealisedWeight(double halfLifeSteps, double priorRows, double priorWeight = 1.0,
                   bool absoluteError = false);
    /// @brief A realised forecast: @p target = measured − reference, @p correction = c.
    void add(double target, double correction);
    /// @brief w for the next forecast.
    double weight() const;

private:
    double m_decay = 1;
    double m_priorRows = 0;
    double m_priorWeight = 1;
    bool m_absolute = false;
    double m_tc = 0, m_cc = 0, m_rows = 0; ///< discounted Σ t c, Σ c², Σ 1
    double m_absC = 0;                     ///< discounted Σ |c|
    static constexpr int kGrid = 21;       ///< w = 0, 0.05, …, 1
    double m_absErr[kGrid] = {};           ///< discounted Σ |t − w c| per w of the grid
};

/// @brief Applies RealisedWeight along a series of forecasts made @p horizon steps ahead:
/// entry i is the forecast of row i (reference[i] + w_i correction[i]) where w_i uses only the
/// forecasts whose targets were measured by its origin, row i − horizon. NaN entries are
/// skipped (they neither use nor update a weight). @p weights receives w_i (may be null);
/// @p priorWeight is w₀.
void applyRealisedWeights(const std::vector<double>& reference, const std::vector<double>& correction,
                          const std::vector<double>& measured, std::size_t horizon, double halfLifeSteps,
                          double priorRows, std::vector<double>& combined,
                          std::vector<double>* weights = nullptr, double priorWeight = 1.0,
                          bool absoluteError = false);

} // namespace drytwin::residual
