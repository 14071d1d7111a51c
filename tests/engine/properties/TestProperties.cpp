#include "properties/Parameters.h"
#include "properties/Properties.h"

#include <QtTest>
#include <cmath>

using namespace drytwin::properties;

class TestProperties : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void magnusMatchesSteamTables_data() {
        QTest::addColumn<double>("celsius");
        QTest::addColumn<double>("pascal"); // IAPWS saturation pressure
        QTest::newRow("20 °C") << 20.0 << 2339.2;
        QTest::newRow("60 °C") << 60.0 << 19946.0;
        QTest::newRow("100 °C") << 100.0 << 101418.0;
    }
    void magnusMatchesSteamTables() {
        QFETCH(double, celsius);
        QFETCH(double, pascal);
        const double p = saturationPressure(celsius + kKelvin);
        QVERIFY2(std::abs(p - pascal) / pascal < 0.01, qPrintable(QString::number(p)));
    }

    void sorptionIsothermAgreesWithOswinAt25C() {
        const ParameterSet p;
        for (double rh : {0.2, 0.4, 0.6, 0.8, 0.95}) {
            const double xe = equilibriumMoisture(298.15, rh, p);
            QVERIFY(std::abs(sorptionIsotherm(xe, p) - rh) < 1e-12);
            // Eq. 2 at 25 °C has no temperature correction, so a_w(X_e) = RH exactly.
            QVERIFY(std::abs(waterActivity(298.15, xe, p, true) - rh) < 1e-12);
        }
    }

    void waterActivityClampedToUnitInterval() {
        const ParameterSet p;
        bool exceedsWithoutClamp = false;
        for (double t = 280; t <= 420; t += 5) {
            for (double x = 0; x <= 0.6; x += 0.01) {
                const double aw = waterActivity(t, x, p, true);
                QVERIFY(aw >= 0.0 && aw <= 1.0);
                exceedsWithoutClamp = exceedsWithoutClamp || waterActivity(t, x, p, false) > 1.0;
            }
        }
        QVERIFY(exceedsWithoutClamp); // the clamp matters in the tube (θ_aw1 < 0 raises a_w with T)
        QCOMPARE(waterActivity(330, 0.0, p, true), 0.0);
    }

    void specificHeatAndSwitches() {
        const ParameterSet p;
        ModelSwitches s;
        QCOMPARE(specificHeat(0.0, p, s), 1300.0);
        QVERIFY(std::abs(specificHeat(1e6, p, s) - 4186.0) < 1.0);
        QCOMPARE(heatCapacityPerDryKg(0.25, p, s), 1300.0 + 0.25 * 4186.0);
        s.moistureDependentCp = false;
        QCOMPARE(specificHeat(0.05, p, s), specificHeat(0.4, p, s));
    }

    void latentHeat() {
        const ParameterSet p;
        ModelSwitches s;
        QCOMPARE(drytwin::properties::latentHeat(kKelvin, 1.0, p, s), 2501e3);
        QCOMPARE(drytwin::properties::latentHeat(kKelvin + 100, 1.0, p, s), (2501 - 236.1) * 1e3);
        // Bound water (a_w < 1) costs more; without the correction it does not.
        QVERIFY(drytwin::properties::latentHeat(330, 0.5, p, s) >
                drytwin::properties::latentHeat(330, 1.0, p, s));
        s.latentHeatCorrection = false;
        QCOMPARE(drytwin::properties::latentHeat(330, 0.5, p, s),
                 drytwin::properties::latentHeat(330, 1.0, p, s));
    }

    void equilibriumAndDiffusivityMonotonic() {
        const ParameterSet p;
        QVERIFY(equilibriumMoisture(298, 0.7, p) > equilibriumMoisture(298, 0.5, p));
        QVERIFY(equilibriumMoisture(320, 0.5, p) < equilibriumMoisture(290, 0.5, p));
        QVERIFY(std::isfinite(equilibriumMoisture(298, 1.0, p))); // RH clamped below 1
        QVERIFY(effectiveDiffusivity(340, 0.5, 0.2, p) > effectiveDiffusivity(310, 0.5, 0.2, p));
        QVERIFY(effectiveDiffusivity(330, 0.8, 0.2, p) < effectiveDiffusivity(330, 0.2, 0.2, p));
    }

    void parameterTableIsComplete() {
        ParameterSet p;
        QVERIFY(p.validate().ok());
        for (const auto& i : parameterTable()) {
            QVERIFY(i.lower <= i.defaultValue && i.defaultValue <= i.upper);
            QVERIFY(!i.unit.empty() && !i.meaning.empty() && !i.source.empty());
            QCOMPARE(paramBySymbol(i.symbol).value(), i.id);
        }
        QCOMPARE(info(Param::h_HDT).defaultValue, 66.6);
        QCOMPARE(info(Param::theta_aw1).lower, -6000.0);
        p[Param::k_HDT] = -1;
        QVERIFY(!p.validate().ok());
        QCOMPARE(p.validate().error().place, std::string("k_HDT"));
        QVERIFY(!paramBySymbol("h_hdt"));
    }

    /// A value in a sentence carries its unit, and a dimensionless one none ("0.164", not "0.164 -").
    void spacedUnitLeavesDimensionlessOut() {
        QCOMPARE(spacedUnit(Param::theta_xe1), std::string());
        QCOMPARE(spacedUnit(Param::X_meter_offset), std::string(" % wb"));
        QCOMPARE(spacedUnit(Param::tau_meter), std::string(" s"));
    }
};

QTEST_APPLESS_MAIN(TestProperties)
#include "TestProperties.moc"
