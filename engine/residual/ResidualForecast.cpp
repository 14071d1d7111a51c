// What the model predicts: one step, H steps, several horizons, from one origin, free run, rollout.
#include "residual/ResidualModelInternal.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>

namespace drytwin::residual {

using namespace detail;

HybridPrediction ResidualModel::predictOneStep(const BatchView& v) const {
    return predictAhead(v, 1);
}

HybridPrediction ResidualModel::predictAhead(const BatchView& v, int horizon) const {
    // One horizon of predictHorizons: the same numbers, and the realised-weight guard in one place.
    return predictHorizons(v, {std::max(1, horizon)}).front();
}

std::vector<HybridPrediction> ResidualModel::predictHorizons(const BatchView& v,
                                                             const std::vector<int>& horizons) const {
    if (m_inputDriven && m_inputDriven->used() && !v.baseCorrected) {
        std::vector<physics::SimulationResult> runs;
        auto out = predictHorizonsOn(correctedViews({v}, runs).front(), horizons, v.pbm);
        for (auto& p : out) {
            residualAgainstPbm(v, p);
        }
        return out;
    }
    return predictHorizonsOn(v, horizons, nullptr);
}

std::vector<HybridPrediction>
ResidualModel::predictHorizonsOn(const BatchView& v, const std::vector<int>& horizons,
                                 const physics::SimulationResult* rawPbm) const {
    const std::size_t count = v.rows.size();
    std::vector<HybridPrediction> out(horizons.size(), HybridPrediction::unknown(count));
    // The learnt part of each slot's forecasts (% wb, °C), for the realised-weight guard.
    std::vector<std::vector<double>> learnedX(horizons.size(), std::vector<double>(count, kNaN));
    auto learnedT = learnedX;
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
                e = boundedLearnt(static_cast<int>(h), e.cwiseProduct(correctionWeight(static_cast<int>(h))));
            }
            const Eigen::Vector2d base = velocity() ? levelOf(v, origin, target) : targetBase;
            for (std::size_t slot : slotsOf[h]) {
                auto& p = out[slot];
                learnedX[slot][i] = e(0) * m_eScale(0);
                learnedT[slot][i] = e(1) * m_eScale(1);
                p.residualXPct[i] = e(0) * m_eScale(0) + base(0);
                p.residualTC[i] = e(1) * m_eScale(1) + base(1);
                p.xOutPct[i] = units::dryToWetPct(v.pbm->xOutDb[target]) + p.residualXPct[i]; // Eq. (21)
                p.tOutC[i] = v.pbm->tOutK[target] - units::kKelvinOffset + p.residualTC[i];
            }
        }
    }
    for (std::size_t slot = 0; slot < horizons.size(); ++slot) {
        if (horizons[slot] >= 1) {
            weighByRealisedSkill(v, static_cast<std::size_t>(horizons[slot]), learnedX[slot], learnedT[slot],
                                 out[slot], rawPbm);
        }
    }
    return out;
}

HybridPrediction ResidualModel::forecastFrom(const BatchView& v, std::size_t origin, int horizon) const {
    return forecastFrom(std::vector<BatchView>{v}, origin, horizon).front();
}

std::vector<HybridPrediction> ResidualModel::forecastFrom(const std::vector<BatchView>& views,
                                                          std::size_t origin, int horizon) const {
    if (m_inputDriven && m_inputDriven->used() && !views.empty() && !views.front().baseCorrected) {
        // The realised-weight guard needs the forecasts' history, which one origin does not have:
        // the MPC's forecasts use the trained κ_H alone.
        std::vector<physics::SimulationResult> runs;
        const auto corrected = correctedViews(views, runs);
        auto out = forecastFrom(corrected, origin, horizon);
        for (std::size_t c = 0; c < out.size(); ++c) {
            BatchView ahead = views[c];
            ahead.rows = {origin + 1, origin + 1 + out[c].xOutPct.size()};
            if (ahead.rows.end > ahead.pbm->xOutDb.size()) {
                continue;
            }
            // The share of the correction's own change its cross-validation did not trust is taken
            // back (issue #75), as the realised weights start from for the recorded forecasts.
            const auto& raw = *views[c].pbm;
            const auto& base = *corrected[c].pbm;
            const auto correctionAt = [&](std::size_t k) -> Eigen::Vector2d {
                return {units::dryToWetPct(base.xOutDb[k]) - units::dryToWetPct(raw.xOutDb[k]),
                        base.tOutK[k] - raw.tOutK[k]};
            };
            const Eigen::Vector2d atOrigin = correctionAt(origin);
            for (std::size_t i = 0; i < out[c].xOutPct.size() && atOrigin.allFinite(); ++i) {
                const int h = static_cast<int>(i) + 1;
                const Eigen::Vector2d untrusted =
                    (Eigen::Vector2d::Ones() - m_inputDriven->changeWeight(h))
                        .cwiseProduct(Eigen::Vector2d::Ones() - referenceChangeAt(h))
                        .cwiseProduct(correctionAt(origin + 1 + i) - atOrigin);
                if (untrusted.allFinite()) {
                    out[c].xOutPct[i] -= untrusted(0);
                    out[c].tOutC[i] -= untrusted(1);
                }
            }
            residualAgainstPbm(ahead, out[c]);
        }
        return out;
    }
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
            for (Eigen::Index c = 0; c < e.cols(); ++c) {
                e.col(c) = boundedLearnt(static_cast<int>(i) + 1, e.col(c));
            }
        }
        for (Eigen::Index c = 0; c < nv; ++c) {
            const BatchView& v = views[static_cast<std::size_t>(c)];
            auto& o = out[static_cast<std::size_t>(c)];
            Eigen::Vector2d base = levelOf(v, origin, target);
            if (velocity()) {
                // The trained share of the held error let go (issue #75).
                Eigen::Vector2d held;
                if (observedResidual(*v.batch, *v.pbm, origin, held(0), held(1))) {
                    base -= decayAt(static_cast<int>(i) + 1).cwiseProduct(held);
                }
            }
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
    if (m_inputDriven && m_inputDriven->used() && !v.baseCorrected) {
        std::vector<physics::SimulationResult> runs;
        const BatchView corrected = correctedViews({v}, runs).front();
        HybridPrediction out;
        if (velocity()) {
            // The free-run hybrid is the PBM plus the input-driven correction. The velocity
            // form's lifted model is the measured error's feedback: without a measured output
            // it has no error to start from, and summing its learnt changes from an error taken
            // as zero made the free run worse on two of six fresh data sets (issue #42,
            // docs/hybrid-study.md), so it adds nothing here.
            out = HybridPrediction::unknown(v.rows.size());
            for (std::size_t i = 0; i < v.rows.size(); ++i) {
                const std::size_t k = v.rows.begin + i;
                out.xOutPct[i] = units::dryToWetPct(corrected.pbm->xOutDb[k]);
                out.tOutC[i] = units::kelvinToCelsius(corrected.pbm->tOutK[k]);
            }
        } else {
            // The paper's level form: below the correction, whatever the lifted model adds
            // without a measured output.
            out = predictFreeRun(corrected);
        }
        residualAgainstPbm(v, out);
        return out;
    }
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
                velocity() ? (fitted ? boundedLearnt(ahead, correctionWeight(ahead).cwiseProduct(sum))
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

} // namespace drytwin::residual
