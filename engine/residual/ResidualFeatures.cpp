// What the lifted model sees at a row: its inputs z, lifted features, learnt residual and state.
#include "residual/ResidualModelInternal.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>

namespace drytwin::residual {

using namespace detail;

namespace {

const std::vector<std::string> kProxyNames{"X_HDT", "T_HDT", "X_Conv", "T_Conv", "X_mix", "T_mix"};
const std::vector<std::string> kDisturbanceNames{"feed", "X_in", "T_in", "T_amb", "RH"};

} // namespace

namespace detail {

std::vector<std::string> inputNames(bool proxies) {
    std::vector<std::string> n;
    if (proxies) {
        n = kProxyNames;
    }
    n.push_back("T_hot");
    n.insert(n.end(), kDisturbanceNames.begin(), kDisturbanceNames.end());
    return n;
}

} // namespace detail

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
    if (static_cast<std::size_t>(m_inputLow.size()) == z.size()) {
        // Issue #42: inside the training range widened by the margin (a missing value stays missing).
        for (std::size_t i = 0; i < z.size(); ++i) {
            const auto j = static_cast<Eigen::Index>(i);
            z[i] = std::isfinite(z[i]) ? std::clamp(z[i], m_inputLow(j), m_inputHigh(j)) : z[i];
        }
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
    const Eigen::Vector2d sH = referenceChangeAt(static_cast<int>(target - origin));
    const Eigen::Vector2d change = pbmChange(v, origin, target);
    e(0) -= sH(0) * change(0);
    e(1) -= sH(1) * change(1);
    return e;
}

Eigen::Vector2d ResidualModel::pbmChange(const BatchView& v, std::size_t origin, std::size_t target) {
    const auto& pbm = *v.pbm;
    return {units::dryToWetPct(pbm.xOutDb[target]) - units::dryToWetPct(pbm.xOutDb[origin]),
            pbm.tOutK[target] - pbm.tOutK[origin]};
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

} // namespace drytwin::residual
