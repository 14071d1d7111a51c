#include "diagnostics/Correlation.h"
#include "diagnostics/DieboldMariano.h"
#include "diagnostics/LjungBox.h"
#include "diagnostics/LongRunVariance.h"
#include "diagnostics/Metrics.h"
#include "diagnostics/Stability.h"
#include "diagnostics/WelchPsd.h"

#include <QtTest>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

using namespace drytwin::diagnostics;

namespace {

/// The fixture series, read once (a copy of ../shared/fixtures lives in tests/data).
std::map<std::string, std::vector<double>> loadSeries() {
    std::ifstream in(std::string(DRYTWIN_TEST_DATA) + "/diagnostics_series.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    std::stringstream hs(line);
    for (std::string n; std::getline(hs, n, ',');) {
        names.push_back(n);
    }
    std::map<std::string, std::vector<double>> cols;
    while (std::getline(in, line)) {
        std::stringstream ls(line);
        std::size_t i = 0;
        for (std::string cell; std::getline(ls, cell, ','); ++i) {
            cols[names[i]].push_back(std::stod(cell));
        }
    }
    return cols;
}

nlohmann::json loadReference() {
    std::ifstream in(std::string(DRYTWIN_TEST_DATA) + "/diagnostics_reference.json");
    return nlohmann::json::parse(in);
}

} // namespace

class TestDiagnostics : public QObject {
    Q_OBJECT
    std::map<std::string, std::vector<double>> m_series;
    nlohmann::json m_ref;

private Q_SLOTS:
    void initTestCase() {
        m_series = loadSeries();
        m_ref = loadReference();
        QCOMPARE(m_series["white"].size(), std::size_t(3000));
    }

    void acfMatchesStatsmodels_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("white") << "white";
        QTest::newRow("coloured") << "coloured";
    }
    void acfMatchesStatsmodels() {
        QFETCH(QString, name);
        const auto& ref = m_ref["cases"][name.toStdString()]["acf_lags_0_to_40"];
        const auto acf = autocorrelation(m_series[name.toStdString()], 40);
        QCOMPARE(acf.size(), ref.size());
        for (std::size_t k = 0; k < acf.size(); ++k) {
            QVERIFY2(std::abs(acf[k] - ref[k].get<double>()) < 1e-9, qPrintable(QString("lag %1").arg(k)));
        }
    }

    void ljungBoxMatchesStatsmodels_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("lags");
        for (const char* n : {"white", "coloured"}) {
            for (int l : {10, 20, 40}) {
                QTest::newRow(qPrintable(QString("%1 %2").arg(n).arg(l))) << n << l;
            }
        }
    }
    void ljungBoxMatchesStatsmodels() {
        QFETCH(QString, name);
        QFETCH(int, lags);
        const auto& ref = m_ref["cases"][name.toStdString()]["ljung_box"][std::to_string(lags)];
        const auto lb = ljungBox(m_series[name.toStdString()], lags);
        const double q = ref["Q"].get<double>();
        QVERIFY2(std::abs(lb.q - q) <= 1e-6 * q, qPrintable(QString("Q %1 vs %2").arg(lb.q).arg(q)));
        QVERIFY2(std::abs(lb.pValue - ref["p"].get<double>()) <= 1e-6,
                 qPrintable(QString::number(lb.pValue)));
    }

    void welchMatchesScipy_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("white") << "white";
        QTest::newRow("coloured") << "coloured";
    }
    void welchMatchesScipy() {
        QFETCH(QString, name);
        const auto& ref = m_ref["cases"][name.toStdString()]["welch_psd"];
        WelchOptions o;
        o.sampleRateHz = ref["fs"];
        o.segmentLength = ref["nperseg"];
        o.overlap = ref["noverlap"];
        auto psd = welchPsd(m_series[name.toStdString()], o);
        QVERIFY(psd.ok());
        QCOMPARE(psd->density.size(), ref["psd"].size());
        for (std::size_t k = 0; k < psd->density.size(); ++k) {
            const double r = ref["psd"][k];
            QVERIFY2(std::abs(psd->density[k] - r) <= 1e-9 * std::abs(r),
                     qPrintable(QString("bin %1").arg(k)));
            QCOMPARE(psd->frequencyHz[k], ref["freq"][k].get<double>());
        }
    }

    void ccfMatchesStatsmodelsAndFindsTheLag() {
        const auto& ref = m_ref["cases"]["cross_correlation"];
        const auto ccf = crossCorrelation(m_series[ref["x"]], m_series[ref["y"]], 20);
        QCOMPARE(ccf.size(), ref["ccf_lags_0_to_20"].size());
        for (std::size_t k = 0; k < ccf.size(); ++k) {
            QVERIFY2(std::abs(ccf[k] - ref["ccf_lags_0_to_20"][k].get<double>()) < 1e-9,
                     qPrintable(QString("lag %1").arg(k)));
        }
        const auto peak = std::max_element(ccf.begin(), ccf.end()) - ccf.begin();
        QCOMPARE(int(peak), 7);
    }

    void welchRejectsBadInput() {
        QVERIFY(!welchPsd(std::vector<double>(100, 1.0)).ok()); // shorter than a segment
        std::vector<double> x(1000, 0.0);
        x[5] = std::nan("");
        QVERIFY(!welchPsd(x).ok());
        WelchOptions o;
        o.overlap = 256;
        QVERIFY(!o.validate().ok());
    }

    void lowFrequencyShareSeparatesWhiteFromColoured() {
        const double white = lowFrequencyShare(*welchPsd(m_series["white"]), 0.02);
        const double coloured = lowFrequencyShare(*welchPsd(m_series["coloured"]), 0.02);
        // White noise spreads power evenly: about 0.02/0.5 of it below 0.02 Hz.
        QVERIFY(white > 0.01 && white < 0.1);
        QVERIFY(coloured > 3 * white);
    }

    void longRunVarianceAndBandwidthMatchDirectSums_data() {
        QTest::addColumn<double>("phi");
        QTest::addColumn<int>("n");
        QTest::addColumn<int>("lag");
        QTest::addColumn<bool>("demean");
        QTest::newRow("white, short window (direct)") << 0.0 << 500 << 5 << true;
        QTest::newRow("AR(1) 0.995, 6300 rows, 700 lags (FFT)") << 0.995 << 6300 << 700 << true;
        QTest::newRow("AR(1) 0.99 about 0, 5000 rows, 2000 lags (FFT)") << 0.99 << 5000 << 2000 << false;
        QTest::newRow("window longer than the series") << 0.9 << 300 << 1000 << true;
    }
    void longRunVarianceAndBandwidthMatchDirectSums() {
        // Long series with long windows go through FFTW; the result must be the textbook sum.
        QFETCH(double, phi);
        QFETCH(int, n);
        QFETCH(int, lag);
        QFETCH(bool, demean);
        std::mt19937 rng(7);
        std::normal_distribution<double> e(0, 1);
        std::vector<double> x(static_cast<std::size_t>(n));
        double state = 0;
        for (auto& v : x) {
            state = phi * state + e(rng);
            v = 0.3 + state;
        }
        double m = 0;
        for (double v : x) {
            m += demean ? v / n : 0.0;
        }
        const auto gamma = [&](int k) {
            double s = 0;
            for (int t = k; t < n; ++t) {
                s += (x[t] - m) * (x[t - k] - m);
            }
            return s / n;
        };
        double expected = gamma(0);
        for (int l = 1; l <= lag && l < n; ++l) {
            expected += 2.0 * (1.0 - static_cast<double>(l) / (lag + 1)) * gamma(l);
        }
        const double got = longRunVariance(x, lag, demean);
        QVERIFY2(std::abs(got - expected) <= 1e-10 * std::abs(expected),
                 qPrintable(QString("%1 vs %2").arg(got, 0, 'g', 17).arg(expected, 0, 'g', 17)));
        // The bandwidth: the first lag whose autocorrelation (about the mean) falls below 0.1.
        double mean = 0;
        for (double v : x) {
            mean += v / n;
        }
        double denom = 0;
        for (double v : x) {
            denom += (v - mean) * (v - mean);
        }
        const int maxLag = n / 3; // the window asked for, within the function's own cap of n/2
        int first = maxLag;
        for (int k = 1; k <= maxLag; ++k) {
            double s = 0;
            for (int t = k; t < n; ++t) {
                s += (x[t] - mean) * (x[t - k] - mean);
            }
            if (!(std::abs(s / denom) >= 0.1)) {
                first = k;
                break;
            }
        }
        QCOMPARE(bandwidthFromAutocorrelation(x, 0.1, n / 3), first);
        if (phi > 0.98) {
            QVERIFY(first > 100); // long memory: the FFT part of the search decided
        }
    }

    void maeAndR2() {
        const std::vector<double> obs{1, 2, 3, 4, std::nan("")};
        const std::vector<double> pred{1.5, 2, 2, 4, 7};
        QCOMPARE(meanAbsoluteError(obs, pred), 1.5 / 4);
        QCOMPARE(rootMeanSquaredError(obs, pred), std::sqrt(1.25 / 4));
        QCOMPARE(rSquared(obs, pred), 1.0 - 1.25 / 5.0);
        QCOMPARE(rSquared(obs, obs), 1.0);
        QVERIFY(std::isnan(meanAbsoluteError({}, {})));
    }

    void eigenvaluesAndCertificate() {
        Eigen::MatrixXd a(2, 2);
        a << 0.5, 1.0, 0.0, 0.9;
        QVERIFY(std::abs(spectralRadius(a) - 0.9) < 1e-12);
        const auto ev = eigenvalues(a);
        QVERIFY(std::abs(std::abs(ev[1]) - 0.5) < 1e-12);
        const auto rates = contractionRates(a);
        QVERIFY(std::abs(rates[0] + std::log(0.9)) < 1e-12);
        // P from the Lyapunov equation of A/α, (A/α)ᵀP(A/α) − P = −I, certifies α = 0.95 ...
        const Eigen::MatrixXd as = a / 0.95;
        Eigen::MatrixXd p = Eigen::MatrixXd::Identity(2, 2);
        for (int i = 0; i < 2000; ++i) {
            p = as.transpose() * p * as + Eigen::MatrixXd::Identity(2, 2);
        }
        QVERIFY(certificateMaxEigenvalue(a, p, 0.95) <= 0);
        // ... and no P can certify α below the spectral radius.
        QVERIFY(certificateMaxEigenvalue(a, p, 0.85) > 0);
    }

    void dieboldMarianoDetectsTheBetterModel() {
        std::mt19937 rng(7);
        std::normal_distribution<double> n(0, 1);
        std::vector<double> good;
        std::vector<double> bad;
        std::vector<double> same;
        for (int i = 0; i < 2000; ++i) {
            const double e = n(rng);
            good.push_back(0.5 * e);
            bad.push_back(e + 0.3 * n(rng));
            same.push_back(0.5 * n(rng));
        }
        auto r = dieboldMariano(good, bad);
        QVERIFY(r.ok());
        QVERIFY(r->statistic < 0);
        QVERIFY(r->pValue < 1e-6);
        auto s = dieboldMariano(good, same);
        QVERIFY(s->pValue > 0.01);
        QVERIFY(!dieboldMariano(good, std::vector<double>(5, 0.0)).ok());
    }
};

QTEST_APPLESS_MAIN(TestDiagnostics)
#include "TestDiagnostics.moc"
