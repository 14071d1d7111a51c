#include "monitoring/ChangePoint.h"
#include "monitoring/DynamicPca.h"
#include "monitoring/Monitor.h"
#include "monitoring/StreamingMonitor.h"

#include <QtTest>
#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <chrono>
#include <cmath>
#include <random>

using namespace drytwin;
using namespace drytwin::monitoring;

namespace {

template <class T> std::string why(const Expected<T>& e) {
    return e.ok() ? std::string() : e.error().message();
}

/// The error of a call that should have failed; one that says so when it did not.
template <class T> Error errorOf(const Expected<T>& e) {
    return e.ok() ? Error{ErrorKind::BadInput, "<none>", "unexpectedly succeeded"} : e.error();
}

/// What to do to a simulated run, from which row on.
struct Fault {
    int fromRow = -1;     ///< −1: healthy
    int shiftColumn = -1; ///< add shiftSd marginal SDs to this column
    double shiftSd = 0;
    bool breakColumn1 = false; ///< column 1 follows an independent copy of factor 0 instead
};

Fault meanShift(int fromRow, int column, double sd) {
    return Fault{fromRow, column, sd, false};
}

/// 3 AR(1) latent factors (unit variance, φ = 0.99 per second) seen through fixed loadings, plus
/// AR(1) sensor noise (φ = 0.7, SD 0.5): correlated columns that wander like a process.
struct Process {
    int columns = 6;
    double loading(int j, int k) const {
        // Distinct columns (no two with near-equal loadings, which no contribution can tell
        // apart); c0 and c1 share factor 0, which the correlation break takes from c1.
        static const double first[6][3] = {{1.0, 0.0, 0.2},  {0.9, 0.3, 0.0},  {0.0, 1.0, 0.3},
                                           {-0.5, 0.6, 0.0}, {0.3, -0.2, 1.0}, {0.0, 0.5, -0.8}};
        return j < 6 ? first[j][k] : std::cos(0.9 * (j + 1) * (k + 1));
    }
    double marginalSd(int j) const {
        return std::sqrt(0.25 + loading(j, 0) * loading(j, 0) + loading(j, 1) * loading(j, 1) +
                         loading(j, 2) * loading(j, 2));
    }
    MonitorRun run(std::mt19937& rng, const std::string& id, int rows, const Fault& fault = {}) const {
        std::normal_distribution<double> n01(0, 1);
        const double phiF = 0.99, phiE = 0.7, noiseSd = 0.5;
        double f[4] = {n01(rng), n01(rng), n01(rng), n01(rng)}; // braces: drawn in this order
        std::vector<double> e(static_cast<std::size_t>(columns));
        std::generate(e.begin(), e.end(), [&] { return noiseSd * n01(rng); });
        MonitorRun r{id, {}, Eigen::MatrixXd(rows, columns)};
        for (int t = 0; t < rows; ++t) {
            r.timeS.push_back(t);
            for (double& v : f) {
                v = phiF * v + std::sqrt(1 - phiF * phiF) * n01(rng);
            }
            const bool faulty = fault.fromRow >= 0 && t >= fault.fromRow;
            for (int j = 0; j < columns; ++j) {
                auto& ej = e[static_cast<std::size_t>(j)];
                ej = phiE * ej + noiseSd * std::sqrt(1 - phiE * phiE) * n01(rng);
                const double f0 = (faulty && fault.breakColumn1 && j == 1) ? f[3] : f[0];
                double x = 10.0 * j + loading(j, 0) * f0 + loading(j, 1) * f[1] + loading(j, 2) * f[2] + ej;
                if (faulty && j == fault.shiftColumn) {
                    x += fault.shiftSd * marginalSd(j);
                }
                r.values(t, j) = x;
            }
        }
        return r;
    }
    std::vector<MonitorRun> runs(unsigned seed, int count, int rows, const std::string& prefix,
                                 int faultRun = -1, const Fault& fault = {}) const {
        std::mt19937 rng(seed);
        std::vector<MonitorRun> out;
        for (int i = 0; i < count; ++i) {
            out.push_back(run(rng, prefix + std::to_string(i + 1), rows, i == faultRun ? fault : Fault{}));
        }
        return out;
    }
    std::vector<std::string> names() const {
        std::vector<std::string> n(static_cast<std::size_t>(columns));
        std::generate(n.begin(), n.end(), [j = 0]() mutable { return "c" + std::to_string(j++); });
        return n;
    }
};

} // namespace

class TestMonitoring : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // 2 columns, lags 1, blocks of one sample: the correlation matrix [[1, r], [r, 1]] has
    // eigenvalues 1 ± r with vectors (1, ±1)/√2, so everything has a closed form.
    void handComputationOnTwoColumns() {
        const double x1[6] = {1, 2, 3, 4, 5, 6}, x2[6] = {1.2, 1.9, 3.3, 3.8, 5.1, 6.4}, n = 6;
        double m1 = 0, m2 = 0, s11 = 0, s22 = 0, s12 = 0;
        for (int i = 0; i < 6; ++i) {
            m1 += x1[i] / n;
            m2 += x2[i] / n;
        }
        for (int i = 0; i < 6; ++i) {
            s11 += (x1[i] - m1) * (x1[i] - m1) / (n - 1);
            s22 += (x2[i] - m2) * (x2[i] - m2) / (n - 1);
            s12 += (x1[i] - m1) * (x2[i] - m2) / (n - 1);
        }
        const double r = s12 / std::sqrt(s11 * s22), lambda1 = 1 + r, lambda2 = 1 - r;
        QVERIFY(lambda1 / 2 >= 0.9); // one component explains ≥ 90 %

        const std::vector<double> time{0, 1, 2, 3, 4, 5};
        Eigen::MatrixXd values(6, 2);
        values << 1, 1.2, 2, 1.9, 3, 3.3, 4, 3.8, 5, 5.1, 6, 6.4;
        DynamicPcaOptions o;
        o.blockS = 1;
        o.lags = 1;
        const Eigen::MatrixXd lagged = lagBlocks(time, values, o.blockS, o.lags);
        QVERIFY((lagged - values).cwiseAbs().maxCoeff() < 1e-15); // no averaging, no lag
        auto pca = DynamicPca::fit(std::vector<Eigen::MatrixXd>{lagged}, 2, o);
        QVERIFY2(pca.ok(), why(pca).c_str());
        QCOMPARE(pca->components(), 1);
        QVERIFY(std::abs(pca->eigenvalues()[0] - lambda1) < 1e-12);
        QVERIFY(std::abs(pca->eigenvalues()[1] - lambda2) < 1e-12);

        const double z1 = (3.5 - m1) / std::sqrt(s11), z2 = (2.0 - m2) / std::sqrt(s22);
        const double t1 = (z1 + z2) / std::sqrt(2.0), t2 = t1 * t1 / lambda1, spe = (z1 - z2) * (z1 - z2) / 2;
        Eigen::MatrixXd point(1, 2);
        point << 3.5, 2.0;
        const PcaScores s = pca->score(point);
        QVERIFY2(std::abs(s.t2[0] - t2) < 1e-9, qPrintable(QString("T2 %1 vs %2").arg(s.t2[0]).arg(t2)));
        QVERIFY2(std::abs(s.spe[0] - spe) < 1e-9, qPrintable(QString("SPE %1 vs %2").arg(s.spe[0]).arg(spe)));
        // residual = ±(z1 − z2)/2 on each column; T² part of column j: z_j t1 / (√2 λ1)
        for (int j = 0; j < 2; ++j) {
            QVERIFY(std::abs(s.speContributions(0, j) - spe / 2) < 1e-9);
            const double zj = j == 0 ? z1 : z2;
            QVERIFY(std::abs(s.t2Contributions(0, j) - zj * t1 / (std::sqrt(2.0) * lambda1)) < 1e-9);
        }
        // Reconstruction along one of two columns removes the whole residual (and the whole
        // T²): with C̃ = p₂p₂ᵀ, r_j² / C̃_jj = 2 (z1 − z2)²/4 = SPE; with D = p₁p₁ᵀ/λ1 likewise T².
        for (int j = 0; j < 2; ++j) {
            QVERIFY(std::abs(s.speReconstruction(0, j) - spe) < 1e-9);
            QVERIFY(std::abs(s.t2Reconstruction(0, j) - t2) < 1e-9);
        }
        // Limits through other distributions: F(1, ν) = t²_ν, and χ²_1 = z² (Box with h = 1, g = λ2).
        const double t995 = boost::math::quantile(boost::math::students_t(n - 1), 0.995);
        const double z995 = boost::math::quantile(boost::math::normal(), 0.995);
        const double t2Limit = 1 * (n - 1) * (n + 1) / (n * (n - 1)) * t995 * t995;
        QVERIFY2(std::abs(pca->t2Limit() - t2Limit) < 1e-9 * t2Limit,
                 qPrintable(QString("%1 vs %2").arg(pca->t2Limit()).arg(t2Limit)));
        QVERIFY2(std::abs(pca->speLimit() - lambda2 * z995 * z995) < 1e-9,
                 qPrintable(QString("%1 vs %2").arg(pca->speLimit()).arg(lambda2 * z995 * z995)));
    }

    void glrAndCusumByHand() {
        const std::vector<double> z{0, 0, 1, 2, 3};
        const GlrScan s = scanGlr(z, 2);
        // τ = 0..3 (segments ≥ 2): sums 6, 6, 6, 5 over 5, 4, 3, 2 values.
        const std::vector<double> expected{36.0 / 5, 36.0 / 4, 36.0 / 3, 25.0 / 2, 0};
        for (std::size_t t = 0; t < z.size(); ++t) {
            QVERIFY2(std::abs(s.glr[t] - expected[t]) < 1e-12, qPrintable(QString::number(t)));
        }
        QCOMPARE(s.onset, 3);
        QCOMPARE(s.low, 1); // 9 ≥ 12.5 − 3.84 but 7.2 is not
        QCOMPARE(s.high, 3);
        const auto c = cusumPath({1, -2, 3, 0.5}, 0.5);
        QCOMPARE(c, (std::vector<double>{0.5, 0, 2.5, 2.5}));
        ChangePointOptions o;
        o.falseAlarmRate = 0.05;
        o.simulations = 999;
        const auto d1 = nullDistribution(NullModel::iid(50), o), d2 = nullDistribution(NullModel::iid(50), o);
        QCOMPARE(d1.get(), d2.get()); // cached
        // 0.05 × 1000 = 50 tail values allowed: threshold is the 50th largest of 999
        QCOMPARE(d1->glrThreshold, d1->glrMaxima[999 - 50]);
        QVERIFY(d1->pValue(d1->glrThreshold + 1e-12) <= 0.05);
        QVERIFY(d1->pValue(d1->glrMaxima[999 - 51]) > 0.05);
        // Run and shared offsets make long stretches wander: both thresholds must rise.
        NullModel wander;
        wander.runLengths = {25, 25};
        wander.runEffectVariance = 0.05;
        wander.offsetVariance = 0.02;
        const auto d3 = nullDistribution(wander, o);
        QVERIFY(d3->glrThreshold > d1->glrThreshold && d3->cusumThreshold > d1->cusumThreshold);
        QVERIFY(!detectChangePoint(std::vector<double>(49, 0.0), wander, o).ok()); // 49 ≠ 50 values
        // Runs whose own mean is taken off wander less than any run with its level: the run and
        // shared offsets are gone, and what is left sums to zero within each run.
        NullModel levelFree = wander;
        levelFree.levelFree = {1, 1};
        const auto d4 = nullDistribution(levelFree, o);
        QVERIFY(d4.get() != d3.get()); // a model of its own in the cache
        QVERIFY2(d4->glrThreshold < d1->glrThreshold && d4->cusumThreshold < d1->cusumThreshold,
                 qPrintable(QString("%1 vs %2").arg(d4->glrThreshold).arg(d1->glrThreshold)));
    }

    void contributionsSumToTheStatistics() {
        const Process proc;
        std::mt19937 rng(7);
        const MonitorRun a = proc.run(rng, "a", 300), b = proc.run(rng, "b", 80, meanShift(40, 1, 2.0));
        DynamicPcaOptions o;
        o.blockS = 1;
        auto pca = DynamicPca::fit(std::vector<Eigen::MatrixXd>{lagBlocks(a.timeS, a.values, 1, 3)}, 6, o);
        QVERIFY2(pca.ok(), why(pca).c_str());
        // Box's SPE limit over several discarded eigenvalues, from its moments: g χ²_h has mean θ1
        // and variance 2 θ2, so g = θ2/θ1, h = θ1²/θ2 (here 18 lagged columns, a < 17).
        const Eigen::VectorXd rest = pca->eigenvalues().tail(18 - pca->components());
        const double g = rest.squaredNorm() / rest.sum(), h = rest.sum() / g;
        const double box = g * boost::math::quantile(boost::math::chi_squared(h), 0.99);
        QVERIFY2(std::abs(pca->speLimit() - box) < 1e-9 * box, qPrintable(QString::number(pca->speLimit())));
        const PcaScores s = pca->score(lagBlocks(b.timeS, b.values, 1, 3));
        QVERIFY(std::isnan(s.t2[0]) && std::isnan(s.spe[1])); // lags before the run's start
        for (Eigen::Index r = 2; r < s.t2.size(); ++r) {
            QVERIFY(std::abs(s.t2Contributions.row(r).sum() - s.t2[r]) < 1e-9 * (1 + s.t2[r]));
            QVERIFY(std::abs(s.speContributions.row(r).sum() - s.spe[r]) < 1e-9 * (1 + s.spe[r]));
            QVERIFY(s.speContributions.row(r).minCoeff() >= 0);
            // a reconstruction removes at most the whole statistic
            QVERIFY(s.speReconstruction.row(r).minCoeff() >= -1e-12);
            QVERIFY(s.speReconstruction.row(r).maxCoeff() <= s.spe[r] * (1 + 1e-9));
            QVERIFY(s.t2Reconstruction.row(r).minCoeff() >= -1e-12);
            QVERIFY(s.t2Reconstruction.row(r).maxCoeff() <= s.t2[r] * (1 + 1e-9));
        }
        // The monitor's mean shares then sum to 1.
        auto m = Monitor::fit(proc.runs(3, 2, 2500, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto d = m->judge(proc.runs(4, 1, 2500, "new"));
        QVERIFY2(d.ok(), why(d).c_str());
        double sums[4] = {0, 0, 0, 0};
        for (const auto& c : d->contributions) {
            sums[0] += c.speShare;
            sums[1] += c.t2Share;
            sums[2] += c.speReconstructionShare;
            sums[3] += c.t2ReconstructionShare;
        }
        for (double sum : sums) {
            QVERIFY2(std::abs(sum - 1) < 1e-9, qPrintable(QString::number(sum)));
        }
    }

    // Target: falseAlarmRate = 1 % for `changed`, and 1 % for any CUSUM alarm. 20 null judgements
    // against 4 reference runs: at most 3 changed (P(≥ 4) < 0.1 % at 1 %). The same seeds against
    // 2 reference runs, where run-to-run wander is hardest to tell from a change, add power to
    // the check: at most 4 of all 40 judgements with any alarm (expected 0.8 at 2 %; a null
    // without run and offset terms gives about 6).
    void nullGivesFewFalseAlarms() {
        const Process proc;
        int changed = 0, anyAlarm = 0;
        for (unsigned seed = 0; seed < 20; ++seed) {
            for (int referenceRuns : {4, 2}) {
                auto m = Monitor::fit(proc.runs(1000 + seed, referenceRuns, 3000, "ref"), proc.names());
                QVERIFY2(m.ok(), why(m).c_str());
                auto d = m->judge(proc.runs(5000 + seed, 4, 3000, "new"));
                QVERIFY2(d.ok(), why(d).c_str());
                QVERIFY(d->pValue > 0 && d->pValue <= 1);
                changed += referenceRuns == 4 && d->changed ? 1 : 0;
                anyAlarm += d->changed || d->hasFirstAlarm ? 1 : 0;
            }
        }
        qInfo("null: %d of 20 judgements changed (target 1 %%); %d of 40 with any alarm", changed, anyAlarm);
        QVERIFY2(changed <= 3, qPrintable(QString("%1 false alarms in 20").arg(changed)));
        QVERIFY2(anyAlarm <= 4, qPrintable(QString("%1 of 40 with an alarm").arg(anyAlarm)));
    }

    // A transmitter's one-sample spike is not a change of the line: the block mean leaves it out
    // (and only it), so new runs with a spike every few minutes in one column judge as normal.
    void aSpikeIsNotAChange() {
        std::vector<double> block{1.0, 1.1, 0.9, 1.0, 50.0, 1.0, 1.05, 0.95, 1.0, 1.0};
        QCOMPARE(robustBlockMean(block), 9.0 / 9.0 + (0.1 - 0.1 + 0.05 - 0.05) / 9.0);
        std::vector<double> honest{1.0, 1.3, 0.7, 1.0, 1.6, 1.0, 1.05, 0.95, 1.0, std::nan("")};
        QCOMPARE(robustBlockMean(honest), (1.0 + 1.3 + 0.7 + 1.0 + 1.6 + 1.0 + 1.05 + 0.95 + 1.0) / 9.0);
        std::vector<double> none{std::nan(""), std::nan("")};
        QVERIFY(std::isnan(robustBlockMean(none)));

        const Process proc;
        auto m = Monitor::fit(proc.runs(11, 4, 3000, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto newRuns = proc.runs(5003, 4, 3000, "new");
        const auto clean = m->judge(newRuns);
        QVERIFY2(clean.ok(), why(clean).c_str());
        QVERIFY(!clean->changed);
        for (auto& run : newRuns) {
            for (Eigen::Index t = 97; t < run.values.rows(); t += 211) { // 14 spikes a run
                run.values(t, 2) += 30 * proc.marginalSd(2);
            }
        }
        const auto spiky = m->judge(newRuns);
        QVERIFY2(spiky.ok(), why(spiky).c_str());
        QVERIFY(!spiky->changed);
        QCOMPARE(spiky->pValue, clean->pValue); // the spikes changed no block at all
    }

    void meanShiftIsFoundWithItsOnsetAndColumn() {
        const Process proc;
        const int rows = 3000, shiftRow = 1800; // 60 % into the third run
        auto newRuns = proc.runs(77, 4, rows, "new", 2, meanShift(shiftRow, 2, 1.5));
        for (Eigen::Index t = 0; t < rows; ++t) { // the fault persists into the fourth run
            newRuns[3].values(t, 2) += 1.5 * proc.marginalSd(2);
        }
        auto m = Monitor::fit(proc.runs(11, 4, rows, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto d = m->judge(newRuns);
        QVERIFY2(d.ok(), why(d).c_str());
        qInfo("shift: %s; onset %s %.0f s [%.0f, %.0f]; first alarm %s %.0f s", d->ending.message.c_str(),
              d->onsetRun.c_str(), d->onsetS, d->onsetLowS, d->onsetHighS, d->firstAlarmRun.c_str(),
              d->firstAlarmTimeS);
        QVERIFY(d->changed);
        QVERIFY(d->pValue <= 0.01);
        QVERIFY(d->hasOnset);
        QCOMPARE(d->onsetRun, std::string("new3"));
        QVERIFY(d->onsetLowS <= shiftRow && shiftRow <= d->onsetHighS);
        QVERIFY(d->onsetLowS <= d->onsetS && d->onsetS <= d->onsetHighS);
        QVERIFY2(std::abs(d->onsetS - shiftRow) <= 300, qPrintable(QString::number(d->onsetS)));
        QCOMPARE(d->contributions.front().column, std::string("c2"));
        QVERIFY(d->hasFirstAlarm);
        QCOMPARE(d->firstAlarmRun, std::string("new3"));
        // Within a quarter of an hour: the run effects' upper 75 % bound in the null (ChangePoint.cpp)
        // makes the CUSUM wait longer than the point estimate did (7 min) for its stated rate.
        QVERIFY2(d->firstAlarmTimeS > shiftRow && d->firstAlarmTimeS < shiftRow + 900,
                 qPrintable(QString::number(d->firstAlarmTimeS)));
        QVERIFY(d->series[static_cast<std::size_t>(d->firstAlarmWindow)].alarm);
        QCOMPARE(static_cast<int>(d->series.size()), 4 * rows / 60);
        QCOMPARE(d->runStarts, (std::vector<int>{0, 50, 100, 150}));
    }

    // A run in conditions the reference never saw has no normal level: with its level not
    // judged, a whole-run offset (a new operating point) is no change, while a fault that starts
    // within the run and persists is still found, from its onset there.
    void aRunWhoseLevelIsNotJudgedShowsOnlyChangesWithinIt() {
        const Process proc;
        const int rows = 3000;
        auto m = Monitor::fit(proc.runs(11, 4, rows, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto newRuns = proc.runs(5003, 4, rows, "new", 1, meanShift(0, 2, 2.5));
        const auto judged = m->judge(newRuns);
        QVERIFY2(judged.ok(), why(judged).c_str());
        QVERIFY(judged->changed); // its level, judged, is a change
        QVERIFY(judged->levelNotJudged.empty());
        newRuns[1].levelJudged = false;
        const auto free = m->judge(newRuns);
        QVERIFY2(free.ok(), why(free).c_str());
        qInfo("whole-run offset: judged p %.3g; level not judged p %.3g", judged->pValue, free->pValue);
        QVERIFY(!free->changed);
        QCOMPARE(free->levelNotJudged, (std::vector<std::string>{"new2"}));
        double sumT2 = 0, sumSpe = 0; // the run's standardised statistics lost their own mean
        for (int w = free->runStarts[1]; w < free->runStarts[2]; ++w) {
            sumT2 += free->series[static_cast<std::size_t>(w)].zT2;
            sumSpe += free->series[static_cast<std::size_t>(w)].zSpe;
        }
        QVERIFY2(std::abs(sumT2) < 1e-9 && std::abs(sumSpe) < 1e-9, qPrintable(QString::number(sumT2)));

        // A fault from mid-run on, persisting into the runs after it (judged as usual).
        const int shiftRow = 1500;
        auto within = proc.runs(5003, 4, rows, "new", 1, meanShift(shiftRow, 2, 1.5));
        for (int r : {2, 3}) {
            within[static_cast<std::size_t>(r)].values.col(2).array() += 1.5 * proc.marginalSd(2);
        }
        within[1].levelJudged = false;
        const auto d = m->judge(within);
        QVERIFY2(d.ok(), why(d).c_str());
        qInfo("shift within: %s; onset %s %.0f s [%.0f, %.0f]", d->ending.message.c_str(),
              d->onsetRun.c_str(), d->onsetS, d->onsetLowS, d->onsetHighS);
        QVERIFY(d->changed);
        QCOMPARE(d->onsetRun, std::string("new2"));
        QVERIFY2(std::abs(d->onsetS - shiftRow) <= 300, qPrintable(QString::number(d->onsetS)));
    }

    void correlationBreakIsSeenBySpe() {
        const Process proc;
        const Fault fault{0, -1, 0, true};
        std::mt19937 rng(99);
        std::vector<MonitorRun> newRuns;
        newRuns.push_back(proc.run(rng, "new1", 3000));
        for (int i = 2; i <= 4; ++i) {
            newRuns.push_back(proc.run(rng, "new" + std::to_string(i), 3000, fault));
        }
        auto m = Monitor::fit(proc.runs(21, 4, 3000, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto d = m->judge(newRuns);
        QVERIFY2(d.ok(), why(d).c_str());
        qInfo("break: %s (T2 p %.3g, SPE p %.3g)", d->ending.message.c_str(), d->t2.pValue, d->spe.pValue);
        QVERIFY(d->changed);
        QVERIFY(d->spe.changed);
        QCOMPARE(d->statistic, std::string("SPE"));
        QCOMPARE(d->onsetRun, std::string("new2"));
    }

    void missingValuesAndConstantColumnsAreHarmless() {
        const Process proc;
        auto ref = proc.runs(31, 4, 3000, "ref");
        auto newRuns = proc.runs(32, 4, 3000, "new");
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(0, 1);
        for (auto& run : newRuns) {
            for (Eigen::Index t = 0; t < 3000; ++t) {
                run.values(t, 3) = 7.0 + 1e-7 * std::sin(0.1 * t); // stuck, with a little round-off
            }
            run.values = run.values.unaryExpr([&](double v) { return u(rng) < 0.02 ? std::nan("") : v; });
        }
        newRuns[1].values.block(1000, 4, 120, 1).setConstant(std::nan("")); // one sensor away 2 min
        newRuns[2].values.middleRows(500, 60).setConstant(std::nan(""));    // the logger away 1 min
        for (auto& run : ref) {
            run.values.col(3).setConstant(7.0); // stuck in the reference
        }
        auto m = Monitor::fit(ref, proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        QCOMPARE(static_cast<int>(m->pca().constantColumns().size()), 3); // its three lags
        QVERIFY(std::isfinite(m->limits().t2Empirical) && std::isfinite(m->limits().speEmpirical));
        QVERIFY(std::isfinite(m->limits().t2Theoretical) && std::isfinite(m->limits().speTheoretical));
        auto d = m->judge(newRuns);
        QVERIFY2(d.ok(), why(d).c_str());
        qInfo("missing: %s", d->ending.message.c_str());
        QVERIFY(!d->changed);
        QVERIFY(!d->hasFirstAlarm);
        int missingWindows = 0;
        for (const auto& pt : d->series) {
            missingWindows += std::isnan(pt.t2) ? 1 : 0;
            QVERIFY(std::isnan(pt.t2) || (std::isfinite(pt.zT2) && std::isfinite(pt.zSpe)));
        }
        QVERIFY(missingWindows >= 2); // the sensor gap invalidates whole windows
    }

    void streamingAgreesWithBatch() {
        const Process proc;
        auto newRuns = proc.runs(41, 3, 3000, "new", 1, meanShift(1200, 4, 1.0));
        newRuns[0].values.block(700, 0, 30, 2).setConstant(std::nan(""));
        auto m = Monitor::fit(proc.runs(42, 3, 3000, "ref"), proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto d = m->judge(newRuns);
        QVERIFY2(d.ok(), why(d).c_str());
        QVERIFY(d->hasFirstAlarm);
        // The planned durations: the valid windows' length, as judge() counts them.
        std::vector<double> plannedS(newRuns.size(), 0.0);
        for (const auto& pt : d->series) {
            plannedS[static_cast<std::size_t>(pt.runIndex)] +=
                std::isfinite(pt.t2) ? m->windowLengthS() : 0.0;
        }
        auto s = StreamingMonitor::create(*m, plannedS);
        QVERIFY2(s.ok(), why(s).c_str());
        QCOMPARE(s->t2Threshold(), d->t2.cusumThreshold);
        QCOMPARE(s->speThreshold(), d->spe.cusumThreshold);
        std::vector<StreamingWindow> seen;
        for (const auto& run : newRuns) {
            s->startRun(run.id);
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowsFirst =
                run.values;
            for (Eigen::Index t = 0; t < rowsFirst.rows(); ++t) {
                auto w = s->push(run.timeS[static_cast<std::size_t>(t)], rowsFirst.row(t).data());
                QVERIFY2(w.ok(), why(w).c_str());
                seen.insert(seen.end(), w->begin(), w->end());
            }
            const auto last = s->endRun();
            seen.insert(seen.end(), last.begin(), last.end());
        }
        QCOMPARE(seen.size(), d->series.size());
        int firstAlarm = -1;
        for (std::size_t i = 0; i < seen.size(); ++i) {
            const WindowPoint& b = d->series[i];
            QCOMPARE(seen[i].run, b.run);
            QCOMPARE(seen[i].timeS, b.timeS);
            QVERIFY(std::isnan(b.zSpe) ? std::isnan(seen[i].zSpe) : std::abs(seen[i].zSpe - b.zSpe) < 1e-12);
            QCOMPARE(seen[i].alarm, b.alarm);
            if (firstAlarm < 0 && seen[i].alarm) {
                firstAlarm = static_cast<int>(i);
                QVERIFY(seen[i].hasOnset);
                QCOMPARE(seen[i].onsetRun, std::string("new2"));
            }
        }
        QCOMPARE(firstAlarm, d->firstAlarmWindow);
        QCOMPARE(seen[static_cast<std::size_t>(firstAlarm)].run, d->firstAlarmRun);
        QCOMPARE(seen[static_cast<std::size_t>(firstAlarm)].timeS, d->firstAlarmTimeS);
    }

    void badInputIsAnErrorWithPlaceAndReason() {
        const Process proc;
        auto none = Monitor::fit({}, proc.names());
        QCOMPARE(errorOf(none).code, ErrorCode::NotEnoughData);
        QCOMPARE(errorOf(none).place, std::string("monitor.fit"));

        auto ref = proc.runs(51, 2, 2000, "ref");
        auto fewer = ref;
        fewer[1].values.conservativeResize(Eigen::NoChange, 5);
        auto mismatch = Monitor::fit(fewer, proc.names());
        QCOMPARE(errorOf(mismatch).place, std::string("monitor.fit: run 'ref2'"));
        QVERIFY(errorOf(mismatch).reason.find("5 columns") != std::string::npos);

        MonitorOptions bad;
        bad.lags = 0;
        auto badOptions = Monitor::fit(ref, proc.names(), bad);
        QCOMPARE(errorOf(badOptions).code, ErrorCode::InvalidOption);
        QCOMPARE(errorOf(badOptions).place, std::string("lags"));
        bad = MonitorOptions{};
        bad.windowS = 5;
        QCOMPARE(bad.validate().error().place, std::string("windowS"));
        bad = MonitorOptions{};
        bad.simulations = 150; // cannot resolve 0.5 % per statistic
        QCOMPARE(bad.validate().error().place, std::string("simulations"));

        auto backwards = ref;
        backwards[0].timeS[10] = backwards[0].timeS[9];
        QCOMPARE(errorOf(Monitor::fit(backwards, proc.names())).code, ErrorCode::TimeNotIncreasing);

        auto tooShort = Monitor::fit(proc.runs(52, 1, 400, "short"), proc.names());
        QCOMPARE(errorOf(tooShort).code, ErrorCode::NotEnoughData);
        QVERIFY(errorOf(tooShort).reason.find("three parts") != std::string::npos);
        auto oneRun = Monitor::fit(proc.runs(53, 1, 3000, "long"), proc.names());
        QVERIFY2(oneRun.ok(), why(oneRun).c_str()); // thirds stand in for runs

        auto m = Monitor::fit(ref, proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        QCOMPARE(errorOf(m->judge(fewer)).place, std::string("monitor.judge: run 'ref2'"));
        QCOMPARE(errorOf(m->judge({})).code, ErrorCode::NotEnoughData);
        auto s = StreamingMonitor::create(*m, {3600.0});
        QVERIFY(s.ok());
        const double row[6] = {0, 0, 0, 0, 0, 0};
        QCOMPARE(errorOf(s->push(0, row)).kind, ErrorKind::Usage); // no run started
        s->startRun("live");
        QVERIFY(s->push(1, row).ok());
        QCOMPARE(errorOf(s->push(1, row)).code, ErrorCode::TimeNotIncreasing);
        QCOMPARE(errorOf(StreamingMonitor::create(*m, {0.0})).code, ErrorCode::InvalidOption);
        QCOMPARE(errorOf(StreamingMonitor::create(*m, {})).place, std::string("runDurationsS"));
    }

    void tenLongRunsAreFast() {
        Process proc;
        proc.columns = 13;
        const auto ref = proc.runs(61, 10, 6300, "ref");
        const auto newRuns = proc.runs(62, 10, 6300, "new");
        const auto start = std::chrono::steady_clock::now();
        auto m = Monitor::fit(ref, proc.names());
        QVERIFY2(m.ok(), why(m).c_str());
        auto d = m->judge(newRuns);
        QVERIFY2(d.ok(), why(d).c_str());
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        qInfo("10 x 6300 x 13: fit + judge %.3f s (judge %.3f s), %d components, %s", seconds,
              d->ending.elapsedSeconds, d->components, d->ending.message.c_str());
        QVERIFY(!d->changed);
#if defined(__OPTIMIZE__) && !defined(__SANITIZE_ADDRESS__)
        QVERIFY2(seconds < 1.0, qPrintable(QString::number(seconds)));
#endif
    }
};

QTEST_APPLESS_MAIN(TestMonitoring)
#include "TestMonitoring.moc"
