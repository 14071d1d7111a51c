// The input-driven correction of the PBM's free run (issue #42): the fit and its cross-validation,
// the correction of a batch (its inputs and basis: InputDrivenBasis.cpp).
#include "residual/InputDrivenCorrection.h"

#include "common/Units.h"
#include "residual/InputDrivenInternal.h"
#include "residual/ResidualModel.h"
#include "residual/TrailingHampel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>

namespace drytwin::residual {

using namespace input_driven;

namespace {

/// Median sample step of a batch [s]; 1 s when it cannot be told.
double medianStep(const data::SiBatch& b) {
    std::vector<double> d;
    for (std::size_t k = 1; k < b.timeS.size(); ++k) {
        const double s = b.timeS[k] - b.timeS[k - 1];
        if (std::isfinite(s) && s > 0) {
            d.push_back(s);
        }
    }
    if (d.empty()) {
        return 1.0;
    }
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    return d[d.size() / 2];
}

/// The measured minus the PBM's outlet outputs at row k (% wb, °C).
bool pbmError(const data::SiBatch& b, const physics::SimulationResult& pbm, std::size_t k,
              Eigen::Vector2d& e) {
    e(0) = units::dryToWetPct(b.xOutDb[k]) - units::dryToWetPct(pbm.xOutDb[k]);
    e(1) = b.tOutK[k] - pbm.tOutK[k];
    return e.allFinite() && (b.keep.empty() || b.keep[k] != 0);
}

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/// Ridge coefficients of one output from Gram G and right-hand side r; the constant (column 0)
/// is not penalised.
Eigen::VectorXd ridgeSolve(Eigen::MatrixXd gram, const Eigen::VectorXd& rhs, double penalty) {
    gram.diagonal().tail(gram.rows() - 1).array() += penalty;
    gram(0, 0) += 1e-9 * std::max(1.0, gram(0, 0));
    return gram.ldlt().solve(rhs);
}

} // namespace

Status InputDrivenOptions::validate() const {
    if (basis != InputBasis::LaggedInputs) {
        if (timeConstantsS.empty() || cascadeOrder < 1 || cascadeOrder > 4) {
            return Error{ErrorKind::Usage, "input-driven correction",
                         "needs at least one time constant and a cascade order of 1 to 4"};
        }
        for (double t : timeConstantsS) {
            if (!(t > 0 && std::isfinite(t))) {
                return Error{ErrorKind::Usage, "input-driven correction",
                             "time constants must be positive seconds"};
            }
        }
    }
    if (basis != InputBasis::FilterBank && !(lagStrideS > 0 && maxLagS >= 0 && maxLagS / lagStrideS <= 200)) {
        return Error{ErrorKind::Usage, "input-driven correction",
                     "lags need a positive stride and at most 200 of them"};
    }
    if (!(agreementZ >= 0 && agreementZ <= 10)) {
        return Error{ErrorKind::Usage, "input-driven correction", "the agreement's z must lie in [0, 10]"};
    }
    if (!(supportQuantile > 0 && supportQuantile <= 1)) {
        return Error{ErrorKind::Usage, "input-driven correction", "the support quantile must lie in (0, 1]"};
    }
    if (ridgeGrid.empty() || !(rangeMargin >= 0) || !(outlierCutoff > 1)) {
        return Error{ErrorKind::Usage, "input-driven correction",
                     "needs ridge penalties, a range margin ≥ 0 and an outlier cut-off > 1"};
    }
    for (double r : ridgeGrid) {
        if (!(r > 0)) {
            return Error{ErrorKind::Usage, "input-driven correction", "ridge penalties must be positive"};
        }
    }
    return {};
}

Expected<InputDrivenCorrection> InputDrivenCorrection::train(const std::vector<BatchView>& views,
                                                             const InputDrivenOptions& options) {
    if (auto s = options.validate(); !s) {
        return s.error();
    }
    if (options.basis == InputBasis::ChosenByValidation) {
        return trainChoosingBasis(views, options);
    }
    InputDrivenCorrection m;
    m.m_options = options;
    const int n = m.inputCount();
    // Raw inputs of every batch up to the end of its view, and the training rows' statistics.
    std::vector<Eigen::MatrixXd> raw;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(n), sumSq = Eigen::VectorXd::Zero(n);
    double count = 0;
    for (const auto& v : views) {
        raw.push_back(m.inputSeries(*v.batch, *v.pbm));
        const auto& z = raw.back();
        for (std::size_t k = v.rows.begin; k < std::min<std::size_t>(v.rows.end, z.rows()); ++k) {
            const Eigen::VectorXd r = z.row(static_cast<Eigen::Index>(k)).transpose();
            if (!r.allFinite()) {
                continue;
            }
            sum += r;
            sumSq += r.cwiseProduct(r);
            count += 1;
        }
    }
    if (count < 50) {
        return Error{ErrorKind::BadInput, "input-driven correction",
                     "fewer than 50 training rows with every input present"};
    }
    m.m_stepS = medianStep(*views.front().batch);
    m.m_inputMean = sum / count;
    const Eigen::VectorXd var = (sumSq / count - m.m_inputMean.cwiseProduct(m.m_inputMean)).cwiseMax(0.0);
    m.m_inputScale = var.cwiseSqrt().unaryExpr([](double s) { return s > 1e-12 ? s : 1.0; });
    // The training range of the standardised inputs, after the spikes are taken out as basisOf
    // takes them out: a spike in the training data must not widen what counts as seen.
    Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
    Eigen::VectorXd hi = -lo;
    for (std::size_t i = 0; i < views.size(); ++i) {
        Eigen::MatrixXd z = (raw[i].rowwise() - m.m_inputMean.transpose()).array().rowwise() /
                            m.m_inputScale.transpose().array();
        despikeTrailing(z, kMeasuredInputs, kDespikeWindow, kDespikeCutoff, kDespikeFloor);
        for (std::size_t k = views[i].rows.begin; k < std::min<std::size_t>(views[i].rows.end, z.rows());
             ++k) {
            const Eigen::VectorXd r = z.row(static_cast<Eigen::Index>(k)).transpose();
            if (r.allFinite()) {
                lo = lo.cwiseMin(r);
                hi = hi.cwiseMax(r);
            }
        }
    }
    m.m_inputLow = lo - options.rangeMargin * (hi - lo);
    m.m_inputHigh = hi + options.rangeMargin * (hi - lo);

    // Stack the training rows' basis and targets, remembering each row's fold.
    std::vector<Eigen::RowVectorXd> phiRows;
    std::vector<Eigen::Vector2d> targets;
    std::vector<std::size_t> rowTime; // each stacked row's row in its batch
    std::vector<Segment> segments;
    const bool batchFolds = views.size() >= 3;
    for (std::size_t i = 0; i < views.size(); ++i) {
        const auto& v = views[i];
        const Eigen::MatrixXd phi = m.basisOf(raw[i], medianStep(*v.batch));
        const std::size_t end = std::min<std::size_t>(v.rows.end, static_cast<std::size_t>(phi.rows()));
        const std::size_t span = end > v.rows.begin ? end - v.rows.begin : 0;
        for (int block = 0; block < (batchFolds ? 1 : 3); ++block) {
            Segment seg;
            seg.begin = static_cast<Eigen::Index>(phiRows.size());
            seg.fold = batchFolds ? static_cast<int>(i) : block;
            seg.view = i;
            const std::size_t from = v.rows.begin + (batchFolds ? 0 : span * block / 3);
            const std::size_t to = batchFolds ? end : v.rows.begin + span * (block + 1) / 3;
            for (std::size_t k = from; k < to; ++k) {
                Eigen::Vector2d e;
                const auto row = phi.row(static_cast<Eigen::Index>(k));
                if (pbmError(*v.batch, *v.pbm, k, e) && row.allFinite()) {
                    phiRows.push_back(row);
                    targets.push_back(e);
                    rowTime.push_back(k);
                }
            }
            seg.end = static_cast<Eigen::Index>(phiRows.size());
            if (seg.end > seg.begin) {
                segments.push_back(seg);
            }
        }
    }
    const auto rows = static_cast<Eigen::Index>(phiRows.size());
    if (rows < 50) {
        return Error{ErrorKind::BadInput, "input-driven correction",
                     "fewer than 50 training rows with the outlet outputs measured"};
    }
    const Eigen::Index features = phiRows.front().size();
    Eigen::MatrixXd phi(rows, features);
    Eigen::MatrixXd y(rows, kCorrectedOutputs);
    for (Eigen::Index r = 0; r < rows; ++r) {
        phi.row(r) = phiRows[static_cast<std::size_t>(r)];
        y.row(r) = targets[static_cast<std::size_t>(r)].transpose();
    }
    phiRows.clear();
    // Standardised basis columns (the constant stays 1), so that one penalty suits every column.
    m.m_featureMean = phi.colwise().mean().transpose();
    m.m_featureMean(0) = 0;
    m.m_featureScale =
        ((phi.rowwise() - m.m_featureMean.transpose()).colwise().squaredNorm().transpose() / double(rows))
            .cwiseSqrt()
            .unaryExpr([](double s) { return s > 1e-9 ? s : 1.0; });
    m.m_featureScale(0) = 1;
    phi = (phi.rowwise() - m.m_featureMean.transpose()).array().rowwise() /
          m.m_featureScale.transpose().array();

    // Transmitter spikes in the outputs: one fit, rows far outside the robust spread dropped.
    std::vector<char> inlier(static_cast<std::size_t>(rows), 1);
    {
        const double middle = options.ridgeGrid[options.ridgeGrid.size() / 2] * double(rows);
        const Eigen::MatrixXd gram = phi.transpose() * phi;
        const Eigen::MatrixXd rhs = phi.transpose() * y;
        for (int o = 0; o < kCorrectedOutputs; ++o) {
            const Eigen::VectorXd res = y.col(o) - phi * ridgeSolve(gram, rhs.col(o), middle);
            std::vector<double> abs(res.data(), res.data() + res.size());
            for (double& a : abs) {
                a = std::abs(a);
            }
            const double spread = 1.4826 * median(abs);
            for (Eigen::Index r = 0; r < rows; ++r) {
                if (spread > 0 && std::abs(res(r)) > options.outlierCutoff * spread) {
                    inlier[static_cast<std::size_t>(r)] = 0;
                }
            }
        }
    }
    int folds = 0;
    for (const auto& s : segments) {
        folds = std::max(folds, s.fold + 1);
    }
    std::vector<Eigen::MatrixXd> foldGram(static_cast<std::size_t>(folds),
                                          Eigen::MatrixXd::Zero(features, features));
    std::vector<Eigen::MatrixXd> foldRhs(static_cast<std::size_t>(folds),
                                         Eigen::MatrixXd::Zero(features, kCorrectedOutputs));
    for (const auto& s : segments) {
        Eigen::MatrixXd p = phi.middleRows(s.begin, s.end - s.begin);
        Eigen::MatrixXd t = y.middleRows(s.begin, s.end - s.begin);
        for (Eigen::Index r = 0; r < p.rows(); ++r) {
            if (!inlier[static_cast<std::size_t>(s.begin + r)]) {
                p.row(r).setZero();
                t.row(r).setZero();
            }
        }
        foldGram[static_cast<std::size_t>(s.fold)] += p.transpose() * p;
        foldRhs[static_cast<std::size_t>(s.fold)] += p.transpose() * t;
    }
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(features, features);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(features, kCorrectedOutputs);
    for (int f = 0; f < folds; ++f) {
        gram += foldGram[static_cast<std::size_t>(f)];
        rhs += foldRhs[static_cast<std::size_t>(f)];
    }
    // Per segment, the sums the batches' own levels need (within-batch fit): Σφ, Σy and the rows.
    std::vector<Eigen::VectorXd> segmentPhi;
    std::vector<Eigen::Vector2d> segmentY;
    std::vector<double> segmentRows;
    for (const auto& sg : segments) {
        Eigen::VectorXd sumPhi = Eigen::VectorXd::Zero(features);
        Eigen::Vector2d sumY = Eigen::Vector2d::Zero();
        double count = 0;
        for (Eigen::Index r = sg.begin; r < sg.end; ++r) {
            if (inlier[static_cast<std::size_t>(r)]) {
                sumPhi += phi.row(r).transpose();
                sumY += y.row(r).transpose();
                count += 1;
            }
        }
        segmentPhi.push_back(std::move(sumPhi));
        segmentY.push_back(sumY);
        segmentRows.push_back(count);
    }
    // The ridge fit of output o on every fold but @p without (−1: all), at an absolute penalty.
    // Within-batch (options.withinBatch): each batch's level is a parameter of its own (fixed
    // effects, profiled out), so that the coefficients learn only what varies within batches, and
    // the constant is the mean of the batches' levels: the level of a batch not seen.
    // The ridge fit from the normal equations @p g, @p r of the rows it uses and, for the
    // within-batch fit, those rows' per-batch sums of φ and y and their counts.
    const auto solveFrom = [&](Eigen::MatrixXd g, Eigen::VectorXd r,
                               const std::vector<Eigen::VectorXd>& viewPhi, const std::vector<double>& viewY,
                               const std::vector<double>& viewRows, double penalty) -> Eigen::VectorXd {
        if (!options.withinBatch) {
            return ridgeSolve(std::move(g), r, penalty);
        }
        for (std::size_t i = 0; i < views.size(); ++i) {
            if (viewRows[i] > 0) {
                g.noalias() -= viewPhi[i] * viewPhi[i].transpose() / viewRows[i];
                r -= viewPhi[i] * (viewY[i] / viewRows[i]);
            }
        }
        const Eigen::Index n = features - 1;
        Eigen::MatrixXd tail = g.bottomRightCorner(n, n);
        tail.diagonal().array() += penalty;
        Eigen::VectorXd beta = Eigen::VectorXd::Zero(features);
        beta.tail(n) = tail.ldlt().solve(r.tail(n));
        double levels = 0, batches = 0;
        for (std::size_t i = 0; i < views.size(); ++i) {
            if (viewRows[i] > 0) {
                levels += (viewY[i] - viewPhi[i].dot(beta)) / viewRows[i];
                batches += 1;
            }
        }
        beta(0) = batches > 0 ? levels / batches : 0.0;
        return beta;
    };
    const auto solve = [&](int without, int o, double penalty) -> Eigen::VectorXd {
        Eigen::MatrixXd g = gram;
        Eigen::VectorXd r = rhs.col(o);
        if (without >= 0) {
            g -= foldGram[static_cast<std::size_t>(without)];
            r -= foldRhs[static_cast<std::size_t>(without)].col(o);
        }
        std::vector<Eigen::VectorXd> viewPhi(views.size(), Eigen::VectorXd::Zero(features));
        std::vector<double> viewY(views.size(), 0.0), viewRows(views.size(), 0.0);
        if (options.withinBatch) {
            for (std::size_t q = 0; q < segments.size(); ++q) {
                if (segments[q].fold == without) {
                    continue;
                }
                viewPhi[segments[q].view] += segmentPhi[q];
                viewY[segments[q].view] += segmentY[q](o);
                viewRows[segments[q].view] += segmentRows[q];
            }
        }
        return solveFrom(std::move(g), std::move(r), viewPhi, viewY, viewRows, penalty);
    };
    // Forward in time (options.laterInTime): the fit on the first two thirds of the training rows
    // in time (the batches in their order), judged on the last third: how the correction is used
    // (the evaluation's held-out part is the data set's last 30 %, a what-if run goes on from
    // now), and what the batch folds cannot see: a correction that holds across the batches seen
    // so far but not on the ones that came after. The stacked rows are in time order already.
    std::vector<char> later(static_cast<std::size_t>(rows), 0);
    for (Eigen::Index r = rows - rows / 3; r < rows; ++r) {
        later[static_cast<std::size_t>(r)] = 1;
    }
    // The earlier rows' normal equations and per-batch sums, once for both outputs: one product of
    // the (inlier) earlier rows, not a rank-one update per row.
    const Eigen::Index earlierRows = options.laterInTime ? rows - rows / 3 : 0;
    Eigen::MatrixXd earlierGram, earlierRhs;
    std::vector<Eigen::VectorXd> earlierViewPhi(views.size(), Eigen::VectorXd::Zero(features));
    std::vector<Eigen::Vector2d> earlierViewY(views.size(), Eigen::Vector2d::Zero());
    std::vector<double> earlierViewRows(views.size(), 0.0);
    if (options.laterInTime) {
        Eigen::MatrixXd p = phi.topRows(earlierRows);
        Eigen::MatrixXd t = y.topRows(earlierRows);
        for (Eigen::Index k = 0; k < earlierRows; ++k) {
            if (!inlier[static_cast<std::size_t>(k)]) {
                p.row(k).setZero();
                t.row(k).setZero();
            }
        }
        earlierGram = p.transpose() * p;
        earlierRhs = p.transpose() * t;
        for (const auto& sg : segments) {
            for (Eigen::Index k = sg.begin; k < std::min(sg.end, earlierRows); ++k) {
                if (inlier[static_cast<std::size_t>(k)]) {
                    earlierViewPhi[sg.view] += phi.row(k).transpose();
                    earlierViewY[sg.view] += y.row(k).transpose();
                    earlierViewRows[sg.view] += 1;
                }
            }
        }
    }
    const auto solveEarlier = [&](int o, double penalty) -> Eigen::VectorXd {
        std::vector<double> viewY(views.size(), 0.0);
        for (std::size_t i = 0; i < views.size(); ++i) {
            viewY[i] = earlierViewY[i](o);
        }
        return solveFrom(earlierGram, earlierRhs.col(o), earlierViewPhi, viewY, earlierViewRows, penalty);
    };
    // Cross-validated absolute error per penalty and output, judged on every row of the held-out
    // fold (spikes included: that is what a user's data holds).
    m.m_coefficients = Eigen::MatrixXd::Zero(features, kCorrectedOutputs);
    auto& val = m.m_validation;
    val.folds = folds;
    double pbmAbs[kCorrectedOutputs] = {0, 0};
    double chosenPenalty[kCorrectedOutputs] = {0, 0};
    // Each row's correction from the fit without its fold, κ applied (0 where an output is not
    // corrected): what the weights on the correction's change are judged on.
    Eigen::MatrixXd heldOutCorrection = Eigen::MatrixXd::Zero(rows, kCorrectedOutputs);
    for (const auto& s : segments) {
        pbmAbs[0] += y.col(0).segment(s.begin, s.end - s.begin).cwiseAbs().sum();
        pbmAbs[1] += y.col(1).segment(s.begin, s.end - s.begin).cwiseAbs().sum();
    }
    for (int o = 0; o < kCorrectedOutputs; ++o) {
        double best = std::numeric_limits<double>::infinity();
        double bestPenalty = options.ridgeGrid.front();
        Eigen::VectorXd bestHeldOut;           // each row's forecast by the fit without its fold
        std::vector<Eigen::VectorXd> bestBeta; // the fits without each fold, at the best penalty
        for (double ridge : options.ridgeGrid) {
            const double penalty = ridge * double(rows);
            std::vector<Eigen::VectorXd> beta(static_cast<std::size_t>(folds));
            for (int f = 0; f < folds; ++f) {
                beta[static_cast<std::size_t>(f)] = solve(f, o, penalty);
            }
            Eigen::VectorXd heldOut(rows);
            for (const auto& s : segments) {
                heldOut.segment(s.begin, s.end - s.begin) =
                    phi.middleRows(s.begin, s.end - s.begin) * beta[static_cast<std::size_t>(s.fold)];
            }
            const double abs = (y.col(o) - heldOut).cwiseAbs().sum();
            if (abs < best) {
                best = abs;
                bestPenalty = ridge;
                bestHeldOut = std::move(heldOut);
                bestBeta = beta;
            }
        }
        // How much of the correction to keep: the share κ ∈ [0, 1] (steps of 0.05) with the
        // smallest held-out absolute error. A correction that partly does not carry over from one
        // batch to the next (an unmeasured drift the closed loop's inputs echo) is shrunk, not
        // taken whole; κ = 0 is the PBM itself.
        // With everyFoldNoWorse, only a κ under which no held-out fold (a batch it had not seen)
        // comes out worse than the PBM counts.
        std::vector<double> pbmFold(static_cast<std::size_t>(folds), 0.0);
        for (const auto& sg : segments) {
            pbmFold[static_cast<std::size_t>(sg.fold)] +=
                y.col(o).segment(sg.begin, sg.end - sg.begin).cwiseAbs().sum();
        }
        double shrink = 0;
        best = pbmAbs[o];              // κ = 0
        Eigen::VectorXd laterForecast; // the later rows' correction by the fit on the earlier ones
        double laterPbm = 0;
        if (options.laterInTime) {
            laterForecast = phi * solveEarlier(o, bestPenalty * double(rows));
            for (Eigen::Index k = 0; k < rows; ++k) {
                laterPbm += later[static_cast<std::size_t>(k)] ? std::abs(y(k, o)) : 0.0;
            }
        }
        for (int step = 1; step <= 20; ++step) {
            const double kappa = 0.05 * step;
            if (options.laterInTime) {
                double laterAbs = 0;
                for (Eigen::Index k = 0; k < rows; ++k) {
                    laterAbs += later[static_cast<std::size_t>(k)]
                                    ? std::abs(y(k, o) - kappa * laterForecast(k))
                                    : 0.0;
                }
                if (laterAbs > laterPbm) {
                    continue; // worse than the physics later in the batches than it was fitted on
                }
            }
            std::vector<double> fold(static_cast<std::size_t>(folds), 0.0);
            for (const auto& sg : segments) {
                fold[static_cast<std::size_t>(sg.fold)] +=
                    (y.col(o).segment(sg.begin, sg.end - sg.begin) -
                     kappa * bestHeldOut.segment(sg.begin, sg.end - sg.begin))
                        .cwiseAbs()
                        .sum();
            }
            bool noFoldWorse = true;
            for (int f = 0; f < folds; ++f) {
                noFoldWorse =
                    noFoldWorse && fold[static_cast<std::size_t>(f)] <= pbmFold[static_cast<std::size_t>(f)];
            }
            double abs = 0;
            for (double a : fold) {
                abs += a;
            }
            if (abs < best && (noFoldWorse || !options.everyFoldNoWorse)) {
                best = abs;
                shrink = kappa;
            }
        }
        const bool better = shrink > 0;
        (o == 0 ? val.maeMoisturePbm : val.maeTemperaturePbm) = pbmAbs[o] / double(rows);
        (o == 0 ? val.maeMoistureCorrected : val.maeTemperatureCorrected) = best / double(rows);
        (o == 0 ? val.moistureUsed : val.temperatureUsed) = better;
        if (o == 0) {
            val.ridge = bestPenalty;
        }
        chosenPenalty[o] = bestPenalty * double(rows);
        if (better) {
            heldOutCorrection.col(o) = shrink * bestHeldOut;
            m.m_coefficients.col(o) = shrink * solve(-1, o, bestPenalty * double(rows));
            if (options.agreementAcrossFolds && folds >= 2) {
                if (m.m_foldCoefficients.cols() != kCorrectedOutputs * folds) {
                    m.m_foldCoefficients = Eigen::MatrixXd::Zero(features, kCorrectedOutputs * folds);
                }
                for (int f = 0; f < folds; ++f) {
                    m.m_foldCoefficients.col(kCorrectedOutputs * f + o) =
                        shrink * bestBeta[static_cast<std::size_t>(f)];
                }
            }
        } else {
            val.note +=
                std::string(val.note.empty() ? "" : " ") +
                (o == 0 ? "Outlet moisture" : "Outlet temperature") +
                ": the input-driven correction did not beat the physics model on held-out parts of the "
                "training data, so the physics model's free run is used as it is.";
        }
    }
    if (m.used()) {
        m.m_changeWeights = fitChangeWeights(y, heldOutCorrection, rowTime, segments);
    }
    if (options.supportGuard && m.used()) {
        // The guard at the smaller penalty of the outputs corrected: the one whose fit leans most
        // on directions the training rows hardly span.
        double penalty = std::numeric_limits<double>::infinity();
        for (int o = 0; o < kCorrectedOutputs; ++o) {
            if (m.m_coefficients.col(o).squaredNorm() > 0) {
                penalty = std::min(penalty, chosenPenalty[o]);
            }
        }
        m.fitSupport(phi, inlier, gram, penalty);
    }
    return m;
}

void InputDrivenCorrection::correct(const data::SiBatch& batch, const physics::SimulationResult& pbm,
                                    std::vector<double>& moisturePct, std::vector<double>& temperatureC,
                                    std::vector<double>* support) const {
    moisturePct.assign(batch.rows(), kNaN);
    temperatureC.assign(batch.rows(), kNaN);
    if (support) {
        support->assign(batch.rows(), 1.0);
    }
    if (m_coefficients.size() == 0) {
        return;
    }
    const Eigen::MatrixXd raw = inputSeries(batch, pbm);
    if (raw.rows() == 0) {
        return;
    }
    Eigen::VectorXd inRange;
    Eigen::MatrixXd phi = basisOf(raw, medianStep(batch), m_options.rangeGuard ? &inRange : nullptr);
    phi = (phi.rowwise() - m_featureMean.transpose()).array().rowwise() / m_featureScale.transpose().array();
    const Eigen::MatrixXd fitted = phi * m_coefficients;
    Eigen::MatrixXd out = fitted;
    if (inRange.size() == out.rows()) {
        out.array().colwise() *= inRange.array();
    }
    applyGuards(phi, out);
    for (Eigen::Index k = 0; support && k < out.rows(); ++k) {
        if (std::isfinite(out(k, 0)) && fitted(k, 0) != 0) {
            (*support)[static_cast<std::size_t>(k)] = out(k, 0) / fitted(k, 0);
        }
    }
    for (Eigen::Index k = 0; k < out.rows(); ++k) {
        if (out.row(k).allFinite()) {
            moisturePct[static_cast<std::size_t>(k)] = out(k, 0);
            temperatureC[static_cast<std::size_t>(k)] = out(k, 1);
        }
    }
}

physics::SimulationResult InputDrivenCorrection::corrected(const data::SiBatch& batch,
                                                           const physics::SimulationResult& pbm) const {
    return correctedFrom(pbm, batch, pbm);
}

physics::SimulationResult
InputDrivenCorrection::correctedFrom(const physics::SimulationResult& pbm, const data::SiBatch& sourceBatch,
                                     const physics::SimulationResult& sourcePbm) const {
    physics::SimulationResult out = pbm;
    if (!used()) {
        return out;
    }
    std::vector<double> cx, ct;
    correct(sourceBatch, sourcePbm, cx, ct);
    for (std::size_t k = 0; k < std::min(cx.size(), out.xOutDb.size()); ++k) {
        if (std::isfinite(cx[k]) && std::isfinite(ct[k])) {
            out.xOutDb[k] = units::wetPctToDry(units::dryToWetPct(out.xOutDb[k]) + cx[k]);
            out.tOutK[k] += ct[k];
        }
    }
    return out;
}

} // namespace drytwin::residual
