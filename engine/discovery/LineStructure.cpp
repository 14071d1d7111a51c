// The line's own structure, learnt on the reference period: the commissioned model's error on
// each measured output as a ridge regression on the inputs and the model's own outputs, each
// raw and through two causal first-order filters (60 s, 300 s: the line's dynamics beyond the
// model's). A distributed tube, a gas phase, a layered belt leave an error that the inputs
// drive the same way in every period; it is taken off the measurements before a change is
// looked for, so that what is left on new data is what changed, not what the model always lacked.
//
// Why a ridge and not the candidates' own parameters: a fitted fouling or wall loss compensates
// the structure on one channel and worsens another (issue #23), while a linear map of the inputs
// fits every channel's structural error at once, is cheap, and cannot take up a change it never
// saw. Hand-written (Eigen's LDLT on the normal equations) because it is twenty lines; a library
// would add a dependency for no gain.
#include "discovery/DiscoveryInternal.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>

namespace drytwin::discovery::detail {

namespace {

constexpr double kFilterS[] = {60, 300};
constexpr double kLambdas[] = {1e-4, 1e-3, 1e-2, 1e-1, 1};
constexpr int kRawInputs = 7;  ///< T_hot, air speed, feed, X_in, T_in, T_amb, RH
constexpr int kRawOutputs = 4; ///< the model's X_out, T_out, X_hdt, T_hdt
constexpr int kRaw = kRawInputs + kRawOutputs;
constexpr int kFeatures = kRaw * 3;

/// The raw signals at row k, file units (the model's tube-outlet ones are 0 where it has none).
void rawSignals(const data::SiBatch& b, const physics::SimulationResult& s, std::size_t k, double* out) {
    out[0] = units::kelvinToCelsius(b.tHotK[k]);
    out[1] = b.airSpeedMPerS[k];
    out[2] = 3600 * b.feedKgPerS[k];
    out[3] = units::dryToWetPct(b.xInDb[k]);
    out[4] = units::kelvinToCelsius(b.tInK[k]);
    out[5] = units::kelvinToCelsius(b.tAmbK[k]);
    out[6] = 100 * b.rhAmb[k];
    out[7] = units::dryToWetPct(s.xOutDb[k]);
    out[8] = units::kelvinToCelsius(s.tOutK[k]);
    out[9] = s.xHdtDb.size() > k ? units::dryToWetPct(s.xHdtDb[k]) : 0.0;
    out[10] = s.tHdtK.size() > k ? units::kelvinToCelsius(s.tHdtK[k]) : 0.0;
}

/// Every row's features (raw, and through the causal filters from the batch's start).
Eigen::MatrixXd featuresOf(const data::SiBatch& b, const physics::SimulationResult& s) {
    Eigen::MatrixXd f(static_cast<Eigen::Index>(b.rows()), kFeatures);
    double raw[kRaw];
    double filtered[2][kRaw];
    for (std::size_t k = 0; k < b.rows(); ++k) {
        rawSignals(b, s, k, raw);
        const double dt = k == 0 ? 0.0 : b.timeS[k] - b.timeS[k - 1];
        for (int i = 0; i < kRaw; ++i) {
            const double v = std::isfinite(raw[i]) ? raw[i] : (k ? filtered[0][i] : 0.0);
            for (int j = 0; j < 2; ++j) {
                filtered[j][i] =
                    k == 0 ? v : filtered[j][i] + (1 - std::exp(-dt / kFilterS[j])) * (v - filtered[j][i]);
            }
            const auto row = static_cast<Eigen::Index>(k);
            f(row, i) = v;
            f(row, kRaw + i) = filtered[0][i];
            f(row, 2 * kRaw + i) = filtered[1][i];
        }
    }
    return f;
}

/// Each feature's range over some feature matrices (their finite values).
struct FeatureRange {
    Eigen::VectorXd low, high;
};

FeatureRange rangeOf(const std::vector<const Eigen::MatrixXd*>& features) {
    FeatureRange r;
    r.low = Eigen::VectorXd::Constant(kFeatures, INFINITY);
    r.high = Eigen::VectorXd::Constant(kFeatures, -INFINITY);
    for (const auto* f : features) {
        if (f->rows() == 0) {
            continue;
        }
        r.low = r.low.cwiseMin(f->colwise().minCoeff().transpose());
        r.high = r.high.cwiseMax(f->colwise().maxCoeff().transpose());
    }
    return r;
}

/// The features held within @p range, column by column (a column never seen is left alone).
Eigen::MatrixXd heldWithin(Eigen::MatrixXd f, const FeatureRange& range) {
    for (Eigen::Index j = 0; j < f.cols(); ++j) {
        if (range.low(j) <= range.high(j)) {
            f.col(j) = f.col(j).cwiseMax(range.low(j)).cwiseMin(range.high(j));
        }
    }
    return f;
}

/// Rows (features, target) of one channel over some batches, kept and measured rows only.
struct Rows {
    Eigen::MatrixXd x;
    Eigen::VectorXd y;
};

Rows rowsOf(const std::vector<const data::SiBatch*>& batches,
            const std::vector<const physics::SimulationResult*>& sims,
            const std::vector<Eigen::MatrixXd>& features, int channel) {
    std::size_t n = 0;
    std::vector<std::pair<std::size_t, std::size_t>> which;
    std::vector<double> target;
    for (std::size_t i = 0; i < batches.size(); ++i) {
        for (std::size_t k = 0; k < batches[i]->rows(); ++k) {
            double obs = 0, pred = 0, toFile = 1;
            if (channelAt(*batches[i], *sims[i], k, k, channel, obs, pred, toFile)) {
                which.emplace_back(i, k);
                target.push_back(obs - pred);
                ++n;
            }
        }
    }
    Rows r;
    r.x.resize(static_cast<Eigen::Index>(n), kFeatures);
    r.y.resize(static_cast<Eigen::Index>(n));
    for (std::size_t j = 0; j < n; ++j) {
        r.x.row(static_cast<Eigen::Index>(j)) =
            features[which[j].first].row(static_cast<Eigen::Index>(which[j].second));
        r.y(static_cast<Eigen::Index>(j)) = target[j];
    }
    return r;
}

struct ChannelFit {
    bool ok = false;
    Eigen::VectorXd mean, sd, beta;
    double intercept = 0;
};

ChannelFit fitRidge(const Rows& r, double lambda) {
    ChannelFit fit;
    if (r.y.size() < 10 * kFeatures) {
        return fit;
    }
    fit.mean = r.x.colwise().mean();
    Eigen::MatrixXd z = r.x.rowwise() - fit.mean.transpose();
    fit.sd = (z.array().square().colwise().sum() / static_cast<double>(z.rows())).sqrt();
    for (Eigen::Index j = 0; j < fit.sd.size(); ++j) {
        if (!(fit.sd(j) > 1e-9)) {
            fit.sd(j) = 1; // a constant column (an input the files do not measure): no information
        }
    }
    z = z.array().rowwise() / fit.sd.transpose().array();
    fit.intercept = r.y.mean();
    const Eigen::VectorXd yc = r.y.array() - fit.intercept;
    Eigen::MatrixXd a = z.transpose() * z;
    a.diagonal().array() += lambda * static_cast<double>(z.rows());
    fit.beta = a.ldlt().solve(z.transpose() * yc);
    fit.ok = fit.beta.allFinite();
    return fit;
}

double predictRow(const ChannelFit& fit, const Eigen::MatrixXd& features, Eigen::Index row) {
    return fit.intercept +
           ((features.row(row).transpose() - fit.mean).array() / fit.sd.array()).matrix().dot(fit.beta);
}

/// Copies of @p batches with each channel's structural error predicted by @p fits taken off.
data::SiBatch corrected(const data::SiBatch& b, const Eigen::MatrixXd& features,
                        const std::array<ChannelFit, 4>& fits) {
    data::SiBatch out = b;
    for (std::size_t k = 0; k < b.rows(); ++k) {
        const auto row = static_cast<Eigen::Index>(k);
        for (int c = 0; c < 4; ++c) {
            if (!fits[static_cast<std::size_t>(c)].ok) {
                continue;
            }
            const double e = predictRow(fits[static_cast<std::size_t>(c)], features, row);
            switch (c) {
            case kXOut:
                out.xOutDb[k] = units::wetPctToDry(units::dryToWetPct(b.xOutDb[k]) - e);
                break;
            case kTOut:
                out.tOutK[k] = b.tOutK[k] - e;
                break;
            case kXHdt:
                if (b.hasXHdt) {
                    out.xHdtDb[k] = units::wetPctToDry(units::dryToWetPct(b.xHdtDb[k]) - e);
                }
                break;
            default:
                if (b.hasTHdt) {
                    out.tHdtK[k] = b.tHdtK[k] - e;
                }
                break;
            }
        }
    }
    return out;
}

/// The parts a reference is split into for cross-fitting: its batches (three or more), else
/// thirds of each (a single recording still gets an honest, out-of-part correction).
std::vector<std::vector<std::pair<std::size_t, std::pair<std::size_t, std::size_t>>>>
partsOf(const std::vector<data::SiBatch>& ref) {
    std::vector<std::vector<std::pair<std::size_t, std::pair<std::size_t, std::size_t>>>> parts;
    if (ref.size() >= 3) {
        for (std::size_t b = 0; b < ref.size(); ++b) {
            parts.push_back({{b, {0, ref[b].rows()}}});
        }
        return parts;
    }
    for (int third = 0; third < 3; ++third) {
        parts.emplace_back();
        for (std::size_t b = 0; b < ref.size(); ++b) {
            const std::size_t n = ref[b].rows();
            parts.back().push_back(
                {b, {n * static_cast<std::size_t>(third) / 3, n * static_cast<std::size_t>(third + 1) / 3}});
        }
    }
    return parts;
}

/// A batch restricted to rows [lo, hi) for fitting (rows outside masked out).
data::SiBatch masked(const data::SiBatch& b, std::size_t lo, std::size_t hi, bool inside) {
    data::SiBatch out = b;
    for (std::size_t k = 0; k < b.rows(); ++k) {
        const bool in = k >= lo && k < hi;
        if (in != inside) {
            out.keep[k] = 0;
        }
    }
    return out;
}

} // namespace

LineStructure learnLineStructure(const std::vector<data::SiBatch>& reference,
                                 const std::vector<physics::SimulationResult>& refSims, bool withinRange) {
    LineStructure out;
    std::vector<Eigen::MatrixXd> features;
    std::vector<const physics::SimulationResult*> sims;
    for (std::size_t b = 0; b < reference.size(); ++b) {
        features.push_back(featuresOf(reference[b], refSims[b]));
        sims.push_back(&refSims[b]);
    }
    // One fold per part: the rows of every other part train, the part's own rows test. Their
    // rows per channel are gathered once; only the ridge fit changes with the penalty.
    const auto parts = partsOf(reference);
    struct Fold {
        std::array<Rows, 4> train, test;
    };
    std::vector<Fold> folds(parts.size());
    for (std::size_t p = 0; p < parts.size(); ++p) {
        std::vector<data::SiBatch> train, test;
        for (std::size_t b = 0; b < reference.size(); ++b) {
            std::size_t lo = 0, hi = 0;
            for (const auto& [pb, range] : parts[p]) {
                if (pb == b) {
                    lo = range.first;
                    hi = range.second;
                }
            }
            train.push_back(masked(reference[b], lo, hi, false));
            test.push_back(masked(reference[b], lo, hi, true));
        }
        std::vector<const data::SiBatch*> trainPtr, testPtr;
        for (std::size_t b = 0; b < reference.size(); ++b) {
            trainPtr.push_back(&train[b]);
            testPtr.push_back(&test[b]);
        }
        for (int c = 0; c < 4; ++c) {
            folds[p].train[static_cast<std::size_t>(c)] = rowsOf(trainPtr, sims, features, c);
            folds[p].test[static_cast<std::size_t>(c)] = rowsOf(testPtr, sims, features, c);
        }
    }
    // The penalty by cross-validation over the folds, the channels' squared errors weighted
    // alike (each relative to its own variance about the training mean).
    double bestScore = INFINITY;
    double bestLambda = kLambdas[2];
    for (double lambda : kLambdas) {
        double score = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            double sse = 0, sst = 0;
            for (const auto& fold : folds) {
                const Rows& tr = fold.train[c];
                const Rows& te = fold.test[c];
                const ChannelFit fit = fitRidge(tr, lambda);
                if (!fit.ok || te.y.size() == 0) {
                    continue;
                }
                const double trainMean = tr.y.mean();
                for (Eigen::Index i = 0; i < te.y.size(); ++i) {
                    const double e = te.y(i) - predictRow(fit, te.x, i);
                    sse += e * e;
                    sst += (te.y(i) - trainMean) * (te.y(i) - trainMean);
                }
            }
            score += sst > 0 ? sse / sst : 0;
        }
        if (score < bestScore) {
            bestScore = score;
            bestLambda = lambda;
        }
    }
    out.lambda = bestLambda;
    std::vector<const data::SiBatch*> all;
    for (const auto& b : reference) {
        all.push_back(&b);
    }
    std::array<ChannelFit, 4> fits;
    for (int c = 0; c < 4; ++c) {
        fits[static_cast<std::size_t>(c)] = fitRidge(rowsOf(all, sims, features, c), bestLambda);
        out.fitted[static_cast<std::size_t>(c)] = fits[static_cast<std::size_t>(c)].ok;
    }
    std::vector<const Eigen::MatrixXd*> allFeatures;
    for (const auto& f : features) {
        allFeatures.push_back(&f);
    }
    const FeatureRange seen = rangeOf(allFeatures);
    out.apply = [fits, seen, withinRange](const data::SiBatch& b, const physics::SimulationResult& s) {
        return corrected(b, withinRange ? heldWithin(featuresOf(b, s), seen) : featuresOf(b, s), fits);
    };
    // The reference itself, each part corrected by its fold's fit on the other parts: its normal
    // values and its monitor's null then carry the structure model's own error, as new data will.
    out.referenceCorrected = reference;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        std::array<ChannelFit, 4> partFits;
        for (std::size_t c = 0; c < 4; ++c) {
            partFits[c] = fitRidge(folds[p].train[c], bestLambda);
        }
        // The part's rows held within what the other parts saw, as new data are within the whole.
        std::vector<const Eigen::MatrixXd*> othersFeatures;
        for (std::size_t q = 0; q < parts.size(); ++q) {
            if (q != p) {
                for (const auto& [b, range] : parts[q]) {
                    othersFeatures.push_back(&features[b]); // whole batches: thirds share their batch
                }
            }
        }
        const FeatureRange othersSeen = rangeOf(othersFeatures);
        for (const auto& [b, range] : parts[p]) {
            const data::SiBatch fixed = corrected(
                reference[b], withinRange ? heldWithin(features[b], othersSeen) : features[b], partFits);
            for (std::size_t k = range.first; k < range.second; ++k) {
                auto& o = out.referenceCorrected[b];
                o.xOutDb[k] = fixed.xOutDb[k];
                o.tOutK[k] = fixed.tOutK[k];
                o.xHdtDb[k] = fixed.xHdtDb[k];
                o.tHdtK[k] = fixed.tHdtK[k];
            }
        }
    }
    return out;
}

} // namespace drytwin::discovery::detail
