#include "common/Units.h"
#include "data/SiBatch.h"
#include "diagnostics/Metrics.h"
#include "physics/LineSimulator.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace drytwin;
using plant::Mechanism;
using properties::Param;

namespace {

plant::PlantOptions small(unsigned seed = 3) {
    plant::PlantOptions o;
    o.seed = seed;
    o.batches = 2;
    o.samples = 1500;
    return o;
}

/// Residual of the outlet moisture [% wb] of the model with the plant's true parameters.
struct Residual {
    double mean = 0;
    double mae = 0;
    double lateMinusEarly = 0; ///< mean residual of the last third minus the first third
};

Residual residualWithTruth(const plant::PlantResult& r) {
    std::vector<double> all;
    double early = 0;
    double late = 0;
    int ne = 0;
    int nl = 0;
    for (const auto& b : r.batches) {
        auto sim = physics::simulateLine(plant::toLineInputs(b), r.truth);
        if (!sim) {
            qFatal("%s", sim.error().message().c_str());
        }
        const std::size_t n = b.timeS.size();
        for (std::size_t k = 100; k < n; ++k) { // skip the start-up of the loop
            const double e = units::dryToWetPct(b.xOutDb[k]) - units::dryToWetPct(sim->xOutDb[k]);
            all.push_back(e);
            if (k < n / 3) {
                early += e;
                ++ne;
            } else if (k > 2 * n / 3) {
                late += e;
                ++nl;
            }
        }
    }
    Residual res;
    res.mean = diagnostics::mean(all);
    res.mae = diagnostics::meanAbsoluteError(all, std::vector<double>(all.size(), 0.0));
    res.lateMinusEarly = late / nl - early / ne;
    return res;
}

} // namespace

class TestVirtualPlant : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void deterministicForASeed() {
        auto a = plant::runPlant(small(5));
        auto b = plant::runPlant(small(5));
        auto c = plant::runPlant(small(6));
        QVERIFY(a.ok() && b.ok() && c.ok());
        QCOMPARE(a->batches[1].xOutDb, b->batches[1].xOutDb);
        QCOMPARE(a->batches[0].feedKgPerS, b->batches[0].feedKgPerS);
        QVERIFY(a->batches[1].xOutDb != c->batches[1].xOutDb);
    }

    void withoutMechanismsTheModelLeavesOnlyNoise() {
        auto r = plant::runPlant(small());
        QVERIFY(r.ok());
        const auto res = residualWithTruth(*r);
        // Meter noise is 0.02 % wb (MAE of white noise ≈ 0.016 %); input noise adds a little.
        QVERIFY2(res.mae < 0.03, qPrintable(QString::number(res.mae)));
        QVERIFY2(std::abs(res.mean) < 0.005, qPrintable(QString::number(res.mean)));
        // The plant's h_HDT and k_HDT differ from the model defaults: default PBM is visibly off.
        const auto& b = r->batches[0];
        auto def = physics::simulateLine(plant::toLineInputs(b), properties::ParameterSet{});
        std::vector<double> o, p;
        for (std::size_t k = 100; k < b.timeS.size(); ++k) {
            o.push_back(units::dryToWetPct(b.xOutDb[k]));
            p.push_back(units::dryToWetPct(def->xOutDb[k]));
        }
        QVERIFY(diagnostics::meanAbsoluteError(o, p) > 0.2);
    }

    void everyMechanismLeavesItsSignature_data() {
        QTest::addColumn<int>("mechanism");
        QTest::addColumn<double>("strength");
        QTest::newRow("tube_wall_heat_loss") << int(Mechanism::TubeWallHeatLoss) << 0.05;
        QTest::newRow("gas_phase_coupling") << int(Mechanism::GasPhaseCoupling) << 0.5;
        QTest::newRow("falling_rate_drying") << int(Mechanism::FallingRateDrying) << 0.5;
        QTest::newRow("ambient_reabsorption") << int(Mechanism::AmbientReabsorption) << 5.0;
        QTest::newRow("moisture_meter_offset") << int(Mechanism::MoistureMeterOffset) << 0.3;
    }
    void everyMechanismLeavesItsSignature() {
        QFETCH(int, mechanism);
        QFETCH(double, strength);
        auto o = small();
        o.effects[static_cast<Mechanism>(mechanism)] = strength;
        auto r = plant::runPlant(o);
        QVERIFY(r.ok());
        // Each leaves the product wetter than the base model predicts from the recorded inputs.
        const auto res = residualWithTruth(*r);
        QVERIFY2(res.mean > 0.05, qPrintable(QString::number(res.mean)));
    }

    void foulingGrowsDuringTheBatch() {
        auto o = small();
        o.effects[Mechanism::HeatTransferFouling] = 0.3;
        auto r = plant::runPlant(o);
        const auto res = residualWithTruth(*r);
        QVERIFY2(res.lateMinusEarly > 0.05, qPrintable(QString::number(res.lateMinusEarly)));
    }

    void transportDelayAndMeterLagShiftAndSmooth() {
        auto quiet = small();
        quiet.noiseScale = 0; // ideal instruments, so that roughness is the process's own
        auto base = plant::runPlant(quiet);
        auto o = quiet;
        o.effects[Mechanism::MoistureMeterLag] = 60;
        auto lag = plant::runPlant(o);
        // Same disturbances (same seed): the lagged meter reads a smoother signal.
        auto roughness = [](const std::vector<double>& x) {
            double s = 0;
            for (std::size_t i = 1; i < x.size(); ++i) {
                s += std::abs(x[i] - x[i - 1]);
            }
            return s;
        };
        QVERIFY(roughness(lag->batches[0].xOutDb) < 0.7 * roughness(base->batches[0].xOutDb));
        auto d = small();
        d.effects[Mechanism::TransportDelayError] = 20;
        auto delayed = plant::runPlant(d);
        QVERIFY(delayed.ok());
        QVERIFY(delayed->batches[0].xOutDb != base->batches[0].xOutDb);
    }

    void realisticRanges() {
        auto r = plant::runPlant(plant::PlantOptions::demo(11));
        QVERIFY(r.ok());
        QCOMPARE(r->batches.size(), std::size_t(10));
        QCOMPARE(r->batches[0].timeS.size(), std::size_t(6300));
        double fMin = 1e9, fMax = 0, xoMin = 100, xoMax = 0, xhMin = 100, xhMax = 0, toMin = 1e9, toMax = 0,
               thMin = 1e9, thMax = 0;
        for (const auto& b : r->batches) {
            for (std::size_t k = 150; k < b.timeS.size(); ++k) {
                fMin = std::min(fMin, b.feedKgPerS[k] * 3600);
                fMax = std::max(fMax, b.feedKgPerS[k] * 3600);
                xoMin = std::min(xoMin, units::dryToWetPct(b.xOutDb[k]));
                xoMax = std::max(xoMax, units::dryToWetPct(b.xOutDb[k]));
                xhMin = std::min(xhMin, units::dryToWetPct(b.xHdtDb[k]));
                xhMax = std::max(xhMax, units::dryToWetPct(b.xHdtDb[k]));
                toMin = std::min(toMin, b.tOutK[k] - 273.15);
                toMax = std::max(toMax, b.tOutK[k] - 273.15);
                thMin = std::min(thMin, b.tHotK[k] - 273.15);
                thMax = std::max(thMax, b.tHotK[k] - 273.15);
            }
        }
        const QString ranges = QString("feed %1-%2 Xout %3-%4 Xhdt %5-%6 Tout %7-%8 Thot %9-%10")
                                   .arg(fMin)
                                   .arg(fMax)
                                   .arg(xoMin)
                                   .arg(xoMax)
                                   .arg(xhMin)
                                   .arg(xhMax)
                                   .arg(toMin)
                                   .arg(toMax)
                                   .arg(thMin)
                                   .arg(thMax);
        QVERIFY2(fMin >= 5780 && fMax <= 6620, qPrintable(ranges));
        QVERIFY2(xoMin > 11.5 && xoMax < 14.0, qPrintable(ranges));
        QVERIFY2(xhMin > 12.0 && xhMax < 16.5, qPrintable(ranges));
        QVERIFY2(toMin > 40 && toMax < 66, qPrintable(ranges));
        QVERIFY2(thMin >= 139.5 && thMax <= 200.5, qPrintable(ranges));
    }

    void exportKeepsTheContract() {
        auto r = plant::runPlant(small());
        const auto batch = plant::toBatch(r->batches[0], 3);
        for (const auto& s : data::columnSpecs()) {
            QVERIFY2(batch.has(s.id), s.name.data());
        }
        QCOMPARE(batch.metadata("batch"), std::string("B01"));
        QCOMPARE(batch.rows(), std::size_t(1500));
    }

    void rejectsBadOptions() {
        auto o = small();
        o.effects[Mechanism::MoistureMeterOffset] = -1;
        QVERIFY(!plant::runPlant(o).ok());
        o = small();
        o.samples = 10;
        QVERIFY(!plant::runPlant(o).ok());
        o = small();
        o.truth[Param::tau_HDT] = 6.5;
        QVERIFY(!plant::runPlant(o).ok());
        auto c = plant::runPlant(small(), [](const ProgressInfo&) { return ProgressAction::Stop; });
        QVERIFY(!c.ok());
        QCOMPARE(exitCodeFor(c.error().kind), 130);
    }
};

QTEST_APPLESS_MAIN(TestVirtualPlant)
#include "TestVirtualPlant.moc"
