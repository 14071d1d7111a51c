// How the lifted model sits on the input-driven correction (issue #42): training on the corrected
// base, the corrected views every forecast starts from, and the realised-weight guard.
#include "residual/RealisedWeight.h"
#include "residual/ResidualModelInternal.h"

#include "common/Units.h"

#include <array>
#include <chrono>

namespace drytwin::residual {

using namespace detail;

Expected<std::shared_ptr<const InputDrivenCorrection>>
ResidualModel::fitInputDriven(const std::vector<BatchView>& training, const ResidualOptions& options) {
    if (!options.inputDriven) {
        return std::shared_ptr<const InputDrivenCorrection>{};
    }
    InputDrivenOptions inputOptions = options.inputDrivenOptions;
    inputOptions.useProxies = options.useProxies;
    auto correction = InputDrivenCorrection::train(training, inputOptions);
    if (!correction) {
        return correction.error();
    }
    return std::make_shared<const InputDrivenCorrection>(std::move(*correction));
}

Expected<ResidualModel> ResidualModel::train(const std::vector<BatchView>& training,
                                             const ResidualOptions& options) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    const auto t0 = std::chrono::steady_clock::now();
    auto correction = fitInputDriven(training, options);
    if (!correction) {
        return correction.error();
    }
    auto m = trainWith(training, options, std::move(*correction));
    if (m) {
        m->m_trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return m;
}

Expected<ResidualModel> ResidualModel::trainWith(const std::vector<BatchView>& training,
                                                 const ResidualOptions& options,
                                                 std::shared_ptr<const InputDrivenCorrection> correction) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (!correction) {
        return trainOnBase(training, options);
    }
    const auto t0 = std::chrono::steady_clock::now();
    ResidualModel withCorrection;
    withCorrection.m_inputDriven = std::move(correction);
    std::vector<physics::SimulationResult> runs;
    auto m = trainOnBase(withCorrection.correctedViews(training, runs), options);
    if (!m) {
        return m.error();
    }
    m->m_inputDriven = std::move(withCorrection.m_inputDriven);
    m->m_trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return m;
}

std::vector<BatchView> ResidualModel::correctedViews(const std::vector<BatchView>& views,
                                                     std::vector<physics::SimulationResult>& runs) const {
    std::vector<BatchView> out = views;
    if (!m_inputDriven || !m_inputDriven->used()) {
        return out;
    }
    // One corrected run per distinct batch (a batch may appear in several views).
    std::vector<std::pair<const physics::SimulationResult*, std::size_t>> done;
    runs.clear();
    runs.reserve(views.size());
    for (auto& v : out) {
        if (v.baseCorrected) {
            continue;
        }
        std::size_t index = runs.size();
        for (const auto& [pbm, i] : done) {
            if (pbm == v.pbm) {
                index = i;
            }
        }
        if (index == runs.size()) {
            runs.push_back(m_inputDriven->corrected(*v.batch, *v.pbm));
            done.emplace_back(v.pbm, index);
        }
        v.pbm = &runs[index];
        v.baseCorrected = true;
    }
    return out;
}

void ResidualModel::residualAgainstPbm(const BatchView& v, HybridPrediction& p) {
    for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const std::size_t k = v.rows.begin + i;
        p.residualXPct[i] = p.xOutPct[i] - units::dryToWetPct(v.pbm->xOutDb[k]);
        p.residualTC[i] = p.tOutC[i] - units::kelvinToCelsius(v.pbm->tOutK[k]);
    }
}

void ResidualModel::weighByRealisedSkill(const BatchView& v, std::size_t horizon,
                                         const std::vector<double>& learnedX,
                                         const std::vector<double>& learnedT, HybridPrediction& p,
                                         const physics::SimulationResult* rawPbm) const {
    if (!velocity()) {
        return;
    }
    const std::size_t count = v.rows.size();
    const Eigen::Vector2d trainedDecay = decayAt(static_cast<int>(horizon));
    if (m_options.realisedWeightHalfLifeSteps <= 0) {
        // No realised weights: the trained share of the held error let go, as it is.
        for (std::size_t i = 0; i < count && trainedDecay.any(); ++i) {
            const std::size_t k = v.rows.begin + i;
            Eigen::Vector2d held;
            if (k < horizon || !observedResidual(*v.batch, *v.pbm, k - horizon, held(0), held(1))) {
                continue;
            }
            p.residualXPct[i] -= trainedDecay(0) * held(0);
            p.residualTC[i] -= trainedDecay(1) * held(1);
            p.xOutPct[i] -= trainedDecay(0) * held(0);
            p.tOutC[i] -= trainedDecay(1) * held(1);
        }
        return;
    }
    const Eigen::Vector2d trainedBlend = referenceChangeAt(static_cast<int>(horizon));
    // Per row and output, read once for both outputs: the measured error, the error held at the
    // forecast's origin and the PBM's change since.
    std::array<std::vector<double>, kOutputs> measuredOf, heldOf, changeOf, correctionChangeOf;
    for (int j = 0; j < kOutputs; ++j) {
        measuredOf[j].assign(count, kNaN);
        heldOf[j].assign(count, kNaN);
        changeOf[j].assign(count, kNaN);
        correctionChangeOf[j].assign(count, kNaN);
    }
    const bool correctionChange = m_options.realisedCorrectionChange && rawPbm != nullptr;
    // The input-driven correction at row k: the corrected base minus the PBM's own run.
    const auto correctionAt = [&](std::size_t k) -> Eigen::Vector2d {
        return {units::dryToWetPct(v.pbm->xOutDb[k]) - units::dryToWetPct(rawPbm->xOutDb[k]),
                v.pbm->tOutK[k] - rawPbm->tOutK[k]};
    };
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t k = v.rows.begin + i;
        Eigen::Vector2d e;
        if (observedResidual(*v.batch, *v.pbm, k, e(0), e(1))) {
            measuredOf[0][i] = e(0);
            measuredOf[1][i] = e(1);
        }
        if (k >= horizon && observedResidual(*v.batch, *v.pbm, k - horizon, e(0), e(1))) {
            const Eigen::Vector2d change = pbmChange(v, k - horizon, k);
            const Eigen::Vector2d correction =
                correctionChange ? Eigen::Vector2d(correctionAt(k) - correctionAt(k - horizon))
                                 : Eigen::Vector2d::Constant(kNaN);
            for (int j = 0; j < kOutputs; ++j) {
                heldOf[j][i] = e(j);
                changeOf[j][i] = change(j);
                correctionChangeOf[j][i] = correction(j);
            }
        }
    }
    // The prior is worth realisedWeightPriorRows independent forecasts; forecasts H steps ahead
    // from consecutive origins share H − 1 steps, so as many independent ones take H times the rows.
    const double priorRows = m_options.realisedWeightPriorRows *
                             (m_options.realisedPriorPerHorizon ? static_cast<double>(horizon) : 1.0);
    for (int j = 0; j < kOutputs; ++j) {
        auto& residual = j == 0 ? p.residualXPct : p.residualTC;
        const auto& learned = j == 0 ? learnedX : learnedT;
        const auto& measured = measuredOf[j];
        // reference = held − s_H · change: the last error held, less s_H of the PBM's change since.
        std::vector<double> reference(count), held = heldOf[j], change = changeOf[j];
        for (std::size_t i = 0; i < count; ++i) {
            reference[i] = residual[i] - learned[i];
            if (!std::isfinite(reference[i])) { // no forecast here: nothing held to weigh either
                held[i] = kNaN;
                change[i] = kNaN;
            }
        }
        // Each step adds w · correction to the forecast so far, w from the forecasts already
        // realised (pulled towards w₀); rows without a finite result keep what they had.
        const auto weighOnTop = [&](std::vector<double>& forecast, const std::vector<double>& correction,
                                    double priorWeight, std::vector<double>* weights = nullptr) {
            std::vector<double> combined;
            applyRealisedWeights(forecast, correction, measured, horizon,
                                 m_options.realisedWeightHalfLifeSteps, priorRows, combined, weights,
                                 priorWeight, m_options.realisedWeightByAbsoluteError);
            for (std::size_t i = 0; i < count; ++i) {
                if (std::isfinite(combined[i]) && std::isfinite(forecast[i])) {
                    forecast[i] = combined[i];
                }
            }
        };
        // The weight on the PBM's change per row (1: the last measurement held).
        std::vector<double> blendWeights(count, trainedBlend(j));
        if (m_options.realisedReferenceBlend) {
            // 1. s: the held error, less s of the PBM's change (s = 1: the last measurement held).
            std::vector<double> minusChange(count);
            for (std::size_t i = 0; i < count; ++i) {
                minusChange[i] = -change[i];
                if (std::isfinite(held[i])) {
                    reference[i] = held[i];
                }
            }
            weighOnTop(reference, minusChange, trainedBlend(j), &blendWeights);
        }
        if (correctionChange) {
            // 1b. How much of the correction's own change to take back (all of it: the PBM's own
            // change with its last error held, the second reference, exactly).
            std::vector<double> takeBack(count);
            for (std::size_t i = 0; i < count; ++i) {
                // What is left of the correction's change after the blend towards holding the
                // last measurement (which holds no change at all).
                const double left =
                    1.0 - (std::isfinite(blendWeights[i]) ? blendWeights[i] : trainedBlend(j));
                takeBack[i] = -correctionChangeOf[j][i] * left;
                if (!std::isfinite(takeBack[i])) {
                    takeBack[i] = 0;
                }
            }
            // Prior: the share of the change the correction's cross-validation did not trust.
            const double trusted =
                m_inputDriven ? m_inputDriven->changeWeight(static_cast<int>(horizon))(j) : 1.0;
            weighOnTop(reference, takeBack, 1.0 - trusted);
        }
        // 2. The learnt correction on top.
        std::vector<double> combined = reference;
        weighOnTop(combined, learned, 1.0);
        if (m_options.realisedHeldErrorDecay) {
            // 3. How much of the held error to let go: all of it is the free-run hybrid's own
            // forecast (with the learnt correction), right where the error decorrelates within
            // the horizon or the last measurement is mostly transmitter noise.
            std::vector<double> minusHeld(count);
            for (std::size_t i = 0; i < count; ++i) {
                minusHeld[i] = -held[i];
            }
            weighOnTop(combined, minusHeld, trainedDecay(j));
        }
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t k = v.rows.begin + i;
            if (!std::isfinite(combined[i])) {
                continue;
            }
            residual[i] = combined[i];
            if (j == 0) {
                p.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[k]) + combined[i]; // Eq. (21)
            } else {
                p.tOutC[i] = units::kelvinToCelsius(v.pbm->tOutK[k]) + combined[i];
            }
        }
    }
}

} // namespace drytwin::residual
