#include "baselines/LstmBaseline.h"
#include "common/Units.h"
#include "hybrid/HybridTraining.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <QtTest>
#include <cmath>

using namespace drytwin;

class TestLstmBaseline : public QObject {
    Q_OBJECT
    std::vector<data::SiBatch> m_batches;
    std::vector<physics::SimulationResult> m_pbm;

private Q_SLOTS:
    void initTestCase() {
        auto o = plant::PlantOptions::demo(3, plant::PlantKind::Lumped);
        o.batches = 3;
        o.samples = 1500;
        auto r = plant::runPlant(o);
        m_batches = plant::toSiBatches(*r, o.seed);
        m_pbm = std::move(*hybrid::simulatePbm(m_batches, hybrid::HybridModel{}, {}));
    }

    void trainsPredictsAndRoundTrips() {
        baselines::LstmOptions o;
        o.hidden = 8;
        o.epochs = 6;
        o.seed = 11;
        const auto train = hybrid::splitViews(m_batches, m_pbm, false);
        const auto test = hybrid::splitViews(m_batches, m_pbm, true);
        auto m = baselines::LstmBaseline::train(train, o);
        QVERIFY2(m.ok(), m.ok() ? "" : m.error().message().c_str());
        QCOMPARE(m->lossHistory().size(), std::size_t(6));
        QVERIFY(m->lossHistory().back() < m->lossHistory().front()); // it learns
        const auto p1 = m->predictAhead(test[0], 1);
        const auto p5 = m->predictAhead(test[0], 5);
        double maeLstm = 0;
        double maePbm = 0;
        int n = 0;
        for (std::size_t i = 0; i < p1.xOutPct.size(); ++i) {
            const std::size_t k = test[0].rows.begin + i;
            QVERIFY(std::isfinite(p1.xOutPct[i]) && std::isfinite(p5.tOutC[i]));
            maeLstm += std::abs(units::dryToWetPct(test[0].batch->xOutDb[k]) - p1.xOutPct[i]);
            maePbm += std::abs(units::dryToWetPct(test[0].batch->xOutDb[k]) -
                               units::dryToWetPct(test[0].pbm->xOutDb[k]));
            ++n;
        }
        QVERIFY(maeLstm < maePbm); // with the measured outputs it beats the uncalibrated PBM one step ahead
        auto back = baselines::LstmBaseline::fromJson(m->toJson());
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().message().c_str());
        const auto q1 = back->predictAhead(test[0], 1);
        for (std::size_t i = 0; i < q1.xOutPct.size(); i += 53) {
            QVERIFY(std::abs(q1.xOutPct[i] - p1.xOutPct[i]) < 1e-4);
        }
        // Several horizons at once give what one horizon at a time gives.
        const auto many = m->predictHorizons(test[0], {5, 1, 12});
        const auto p12 = m->predictAhead(test[0], 12);
        int compared = 0;
        for (std::size_t i = 0; i < p1.xOutPct.size(); ++i) {
            for (const auto& [got, want] :
                 {std::pair{&many[0], &p5}, std::pair{&many[1], &p1}, std::pair{&many[2], &p12}}) {
                QCOMPARE(std::isnan(got->xOutPct[i]), std::isnan(want->xOutPct[i]));
                if (std::isfinite(want->xOutPct[i])) {
                    QVERIFY(std::abs(got->xOutPct[i] - want->xOutPct[i]) < 1e-4);
                    QVERIFY(std::abs(got->tOutC[i] - want->tOutC[i]) < 1e-4);
                    ++compared;
                }
            }
        }
        QVERIFY(compared > 1000);
        // Seeded: the same seed gives the same network.
        auto again = baselines::LstmBaseline::train(train, o);
        QCOMPARE(again->lossHistory(), m->lossHistory());
    }

    void badOptions() {
        baselines::LstmOptions o;
        o.hidden = 0;
        QVERIFY(!o.validate().ok());
        QVERIFY(!baselines::LstmBaseline::fromJson("{}").ok());
    }
};

QTEST_APPLESS_MAIN(TestLstmBaseline)
#include "TestLstmBaseline.moc"
