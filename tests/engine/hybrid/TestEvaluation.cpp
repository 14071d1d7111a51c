// The reference predictors every forecast is compared with, against a hand computation.
#include "common/Units.h"
#include "hybrid/Evaluation.h"

#include <QtTest>
#include <cmath>

using namespace drytwin;

class TestEvaluation : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void referencePredictorsByHand() {
        // Measured outlet 12, 13, 14, 15 % wb and 50, 51, 52, 53 °C; the PBM says 11, 11.5, 12, 12.5
        // % wb and 49 °C throughout.
        data::SiBatch b;
        physics::SimulationResult m;
        for (int k = 0; k < 4; ++k) {
            b.timeS.push_back(k);
            b.xOutDb.push_back(units::wetPctToDry(12.0 + k));
            b.tOutK.push_back(units::celsiusToKelvin(50.0 + k));
            b.keep.push_back(1);
            m.xOutDb.push_back(units::wetPctToDry(11.0 + 0.5 * k));
            m.tOutK.push_back(units::celsiusToKelvin(49.0));
        }
        const residual::BatchView view{&b, &m, {1, 4}};
        // Persistence one step ahead: row k gets y_{k-1}.
        const auto p1 = evaluation::referencePrediction(view, 1, false);
        QCOMPARE(p1.xOutPct.size(), std::size_t(3));
        QVERIFY(std::abs(p1.xOutPct[0] - 12.0) < 1e-12);
        QVERIFY(std::abs(p1.xOutPct[2] - 14.0) < 1e-12);
        QVERIFY(std::abs(p1.tOutC[1] - 51.0) < 1e-12);
        // Two steps ahead: row 1 has no measurement two steps before.
        const auto p2 = evaluation::referencePrediction(view, 2, false);
        QVERIFY(std::isnan(p2.xOutPct[0]));
        QVERIFY(std::abs(p2.xOutPct[1] - 12.0) < 1e-12);
        // PBM with its last error held: ŷ_k = ŷmech_k + (y_{k-1} − ŷmech_{k-1}).
        // Row 3: 12.5 + (14 − 12) = 14.5 % wb; 49 + (52 − 49) = 52 °C.
        const auto h1 = evaluation::referencePrediction(view, 1, true);
        QVERIFY(std::abs(h1.xOutPct[2] - 14.5) < 1e-12);
        QVERIFY(std::abs(h1.tOutC[2] - 52.0) < 1e-12);
        // Scored over the rows: persistence errs by exactly 1 % wb and 1 °C at every row.
        const auto scored = evaluation::scorePredictions(
            {view}, [](const residual::BatchView& v) { return evaluation::referencePrediction(v, 1, false); },
            1);
        QVERIFY(std::abs(scored.moisture.mae - 1.0) < 1e-12);
        QVERIFY(std::abs(scored.temperature.mae - 1.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestEvaluation)
#include "TestEvaluation.moc"
