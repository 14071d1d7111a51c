// Discovery on virtual-plant data with an effect hidden in it: the test must find it from the
// data alone. The plant writes every mechanism in its own, richer form (docs/mechanisms.md), and
// the seed (21) is not one the settings were chosen on (12-14).
#include "DiscoveryTestSupport.h"
#include "discovery/Discovery.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace drytwin;
using plant::Mechanism;

namespace {

std::vector<data::SiBatch> plantData(plant::PlantOptions o) {
    o.seed = 21;
    return test::fourBatchesOf(o);
}

discovery::DiscoveryResult discoverIn(const plant::PlantOptions& o) {
    auto r = discovery::discover(plantData(o), hybrid::HybridModel{});
    if (!r) {
        qFatal("%s", r.error().message().c_str());
    }
    // A round that names its cause carries no reason to stop (a newcomer found a named round
    // with the first-tried candidate's rejection as its reason in discover.json).
    for (const auto& rd : r->rounds) {
        if (rd.named && !rd.reason.empty()) {
            qFatal("round naming %s carries a reason: %s", rd.best.c_str(), rd.reason.c_str());
        }
    }
    return *r;
}

QString names(const discovery::DiscoveryResult& r) {
    QStringList n;
    for (const auto& f : r.findings) {
        n << QString::fromStdString(f.cause);
    }
    // The rounds' decisions, so that a failure says why.
    QStringList rounds;
    for (const auto& rd : r.rounds) {
        QString line = QString::fromStdString(rd.best) + ": " +
                       (rd.named ? QStringLiteral("named") : QString::fromStdString(rd.reason));
        for (const auto& x : rd.rejected) {
            line += QStringLiteral("; not %1 (%2: %3)")
                        .arg(QString::fromStdString(x.cause), QString::fromStdString(x.code),
                             QString::fromStdString(x.reason));
        }
        rounds << line;
    }
    for (const auto& c : r.ranking) {
        rounds << QStringLiteral("%1 z=%2 fitted=%3")
                      .arg(QString::fromStdString(c.cause))
                      .arg(c.score)
                      .arg(c.fitted);
    }
    for (const auto& u : r.unexplained) {
        rounds << QStringLiteral("unexplained %1 %2 lag %3 strength %4")
                      .arg(QString::fromStdString(u.type), QString::fromStdString(u.output))
                      .arg(u.lagS)
                      .arg(u.strength);
    }
    return n.join(',') + " / " + QString::fromStdString(r.verdict) + "\n  " + rounds.join("\n  ");
}

/// Discovery on data with mechanism @p m at @p strength from @p onsetS into each batch.
discovery::DiscoveryResult discoverFromOnset(Mechanism m, double strength, double onsetS) {
    plant::PlantOptions o;
    o.effects[m] = strength;
    o.effectOnsetS[m] = onsetS;
    return discoverIn(o);
}

/// Empty when the first finding of @p r acts from an onset within ±10 min of @p onsetS, inside
/// its own interval; else what is wrong.
QString onsetMismatch(const discovery::DiscoveryResult& r, double onsetS) {
    if (r.findings.empty()) {
        return "nothing named: " + names(r);
    }
    const auto& f = r.findings.front();
    if (!f.hasOnset) {
        return "no onset: " + names(r);
    }
    if (std::abs(f.onsetS - onsetS) > 600) {
        return QStringLiteral("onset at %1 s").arg(f.onsetS);
    }
    if (!(f.onsetLowS <= f.onsetS && f.onsetS <= f.onsetHighS)) {
        return QStringLiteral("onset %1 s outside [%2, %3] s")
            .arg(f.onsetS)
            .arg(f.onsetLowS)
            .arg(f.onsetHighS);
    }
    return {};
}

} // namespace

class TestDiscovery : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyMechanismIsNamedFirst_data() {
        QTest::addColumn<int>("mechanism");
        QTest::addColumn<double>("strength");
        // Realistic strengths: each moves the outlet by a few tenths of % wb or °C.
        QTest::newRow("tube_wall_heat_loss") << int(Mechanism::TubeWallHeatLoss) << 0.3;
        QTest::newRow("gas_phase_coupling") << int(Mechanism::GasPhaseCoupling) << 0.5;
        QTest::newRow("heat_transfer_fouling") << int(Mechanism::HeatTransferFouling) << 0.2;
        QTest::newRow("moisture_meter_lag") << int(Mechanism::MoistureMeterLag) << 30.0;
        QTest::newRow("moisture_meter_offset") << int(Mechanism::MoistureMeterOffset) << 0.2;
        QTest::newRow("transport_delay_error") << int(Mechanism::TransportDelayError) << 15.0;
        QTest::newRow("falling_rate_drying") << int(Mechanism::FallingRateDrying) << 0.5;
        QTest::newRow("ambient_reabsorption") << int(Mechanism::AmbientReabsorption) << 3.0;
        // The sensor causes (issue #23): the measured inputs are not the truth.
        QTest::newRow("inlet_moisture_sensor_offset") << int(Mechanism::InletMoistureSensorOffset) << 1.0;
        QTest::newRow("hot_air_sensor_lag") << int(Mechanism::HotAirSensorLag) << 60.0;
        QTest::newRow("inlet_moisture_sensor_noise") << int(Mechanism::InletMoistureSensorNoise) << 0.8;
    }
    void everyMechanismIsNamedFirst() {
        QFETCH(int, mechanism);
        QFETCH(double, strength);
        plant::PlantOptions o;
        o.effects[static_cast<Mechanism>(mechanism)] = strength;
        const auto r = discoverIn(o);
        const std::string hidden(plant::info(static_cast<Mechanism>(mechanism)).name);
        QVERIFY2(!r.findings.empty(), qPrintable(names(r)));
        QCOMPARE(r.verdict, std::string("cause_found"));
        QCOMPARE(r.findings.front().cause, hidden);
        QVERIFY2(test::roundsDisagreeWithFindings(r).isEmpty(),
                 qPrintable(test::roundsDisagreeWithFindings(r)));
        // The held-out MAE of the output it affects falls by at least 30 % with the extended PBM.
        const auto& g = r.findings.front().gain;
        const double dropX = 1 - g.maeMoistureAfter / g.maeMoistureBefore;
        const double dropT = 1 - g.maeTemperatureAfter / g.maeTemperatureBefore;
        QVERIFY2(std::max(dropX, dropT) >= 0.30,
                 qPrintable(QStringLiteral("X %1 %, T %2 %").arg(100 * dropX).arg(100 * dropT)));
        QVERIFY(g.pValue < 0.05);
        // The parameter carries an interval around its value, and the evidence names numbers.
        const auto& f = r.findings.front();
        QVERIFY(f.ci95Low <= f.value && f.value <= f.ci95High);
        QVERIFY(f.evidence.find("held-out MAE") != std::string::npos);
        QVERIFY(f.explainedFraction > 0.15 && f.explainedFraction <= 1);
    }

    void noMechanismNamesNothing() {
        const auto r = discoverIn({});
        QVERIFY2(r.findings.empty(), qPrintable(names(r)));
        QCOMPARE(r.verdict, std::string("no_structural_cause"));
        QVERIFY(r.unexplained.empty());
        // Not named, but bounded: every mechanism gets the interval the data allow, inside its range.
        QCOMPARE(r.bounds.size(), std::size_t{10}); // the scatter share is freed with h_HDT, k_HDT
        for (const auto& b : r.bounds) {
            const auto& info = properties::info(b.parameter);
            QVERIFY2(b.ci95Low < b.ci95High, b.cause.c_str());
            QVERIFY(b.ci95Low >= info.lower && b.ci95High <= info.upper);
        }
    }

    void unmeasuredDriftAloneNamesNothing() {
        plant::PlantOptions o;
        o.unmeasuredDrift = true;
        const auto r = discoverIn(o);
        QVERIFY2(r.findings.empty(), qPrintable(names(r)));
    }

    void meterLagBehindDriftIsNamed() {
        // The demo's case: a 20 s meter lag under unmeasured slow drift, which dominates the whole
        // held-out error. The lag is judged on the error's fast part too (fastBandWindowS).
        plant::PlantOptions o;
        o.unmeasuredDrift = true;
        o.effects[Mechanism::MoistureMeterLag] = 20;
        const auto data = plantData(o);
        auto r = discovery::discover(data, hybrid::HybridModel{});
        QVERIFY(r.ok());
        QVERIFY2(!r->findings.empty(), qPrintable(names(*r)));
        QCOMPARE(r->findings.front().cause, std::string("moisture_meter_lag"));
        // The bounds are for what was left unnamed, at the model with the lag.
        for (const auto& b : r->bounds) {
            QVERIFY(b.cause != "moisture_meter_lag");
        }
        const auto& named = r->rounds.front();
        qInfo("explained: %.3f of the whole held-out error, %.3f of its fast part", named.explainedFraction,
              named.explainedFractionFast);
        QVERIFY(named.explainedFractionFast >= 0.15);
        QVERIFY(named.explainedFractionFast > named.explainedFraction);
        // 10-40 s: the plant's is two first-order stages of 10 s each.
        QVERIFY2(r->findings.front().value > 10 && r->findings.front().value < 40,
                 qPrintable(QString::number(r->findings.front().value)));
    }

    void twoMechanismsAreBothNamed() {
        plant::PlantOptions o;
        o.effects[Mechanism::HeatTransferFouling] = 0.2;
        o.effects[Mechanism::MoistureMeterOffset] = 0.3;
        const auto r = discoverIn(o);
        QStringList found;
        for (const auto& f : r.findings) {
            found << QString::fromStdString(f.cause);
        }
        QVERIFY2(found.contains("heat_transfer_fouling") && found.contains("moisture_meter_offset"),
                 qPrintable(names(r)));
        QVERIFY2(test::roundsDisagreeWithFindings(r).isEmpty(),
                 qPrintable(test::roundsDisagreeWithFindings(r)));
        QCOMPARE(found.size(), 2);
    }

    void periodicDisturbanceIsUnexplainedNotNamed() {
        plant::PlantOptions o;
        o.hiddenPeriodS = 600;
        o.hiddenAmplitudeK = 3;
        const auto r = discoverIn(o);
        QVERIFY2(r.findings.empty(), qPrintable(names(r)));
        QCOMPARE(r.verdict, std::string("unexplained_structure"));
        bool periodic = false;
        for (const auto& s : r.unexplained) {
            if (s.type == "periodic") {
                periodic = true;
                QVERIFY2(std::abs(s.periodS - 600) <= 0.05 * 600, qPrintable(QString::number(s.periodS)));
            }
        }
        QVERIFY(periodic);
    }

    void missingOptionalColumnsAreNotedNotFatal() {
        plant::PlantOptions o;
        o.effects[Mechanism::MoistureMeterOffset] = 0.3;
        auto data = plantData(o);
        for (auto& b : data) { // as if the file had no tube-outlet or air-speed columns
            b.hasXHdt = b.hasTHdt = false;
            std::fill(b.xHdtDb.begin(), b.xHdtDb.end(), std::nan(""));
            std::fill(b.tHdtK.begin(), b.tHdtK.end(), std::nan(""));
            std::fill(b.airSpeedMPerS.begin(), b.airSpeedMPerS.end(), 16.0);
        }
        auto r = discovery::discover(data, hybrid::HybridModel{});
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        // The three channels the files lack (beside the note on the inlet gauge's normal scatter).
        const auto lacking = std::count_if(r->notes.begin(), r->notes.end(), [](const std::string& n) {
            return n.find("not measured") != std::string::npos || n.find("is constant") != std::string::npos;
        });
        QCOMPARE(lacking, 3);
        QVERIFY(!r->findings.empty());
        QCOMPARE(r->findings.front().cause, std::string("moisture_meter_offset"));
    }

    void midBatchOnsetIsFoundWithItsTime() {
        // A meter offset that appears 20 min into each 50 min batch (a knocked sensor head):
        // named, with the onset within ±10 min and an interval around it.
        const auto r = discoverFromOnset(Mechanism::MoistureMeterOffset, 0.5, 1200);
        const QString onset = onsetMismatch(r, 1200);
        QVERIFY2(onset.isEmpty(), qPrintable(onset));
        const auto& f = r.findings.front();
        QCOMPARE(f.cause, std::string("moisture_meter_offset"));
        // Fitted where it acts, the offset is near the plant's (0.5 % wb at 55 °C).
        QVERIFY2(f.value > 0.3 && f.value < 0.8, qPrintable(QString::number(f.value)));
    }

    void midBatchMeterLagIsFoundOnItsEffect() {
        // A 60 s meter lag from 20 min into each 50 min batch (a fouled sample window). Its
        // tangent at 0 (the outlet's rate of change) shows no onset, and fitted from the start
        // the lag is diluted by the 20 min without it, which the held-out part does not confirm.
        // Its onset is found on its own effect on the training part: named, from its onset.
        const auto r = discoverFromOnset(Mechanism::MoistureMeterLag, 60, 1200);
        const QString onset = onsetMismatch(r, 1200);
        QVERIFY2(onset.isEmpty(), qPrintable(onset));
        // Alone, or in the outlet response time's group with a transport time.
        const auto& f = r.findings.front();
        const bool asLookAlike = std::any_of(f.lookAlikes.begin(), f.lookAlikes.end(), [](const auto& l) {
            return l.cause == "moisture_meter_lag" && !l.ruledOut;
        });
        QVERIFY2(f.cause == "moisture_meter_lag" || (f.group == "outlet_response_time" && asLookAlike),
                 qPrintable(names(r)));
    }

    void midBatchInletOffsetIsScreenedFromItsOnset() {
        // An inlet-gauge offset of 1 % wb from 20 min into each 50 min batch (a knocked gauge
        // head). Screened from each batch's start its tangent is diluted by the time before, and
        // the score test does not pass the screen, so it was never fitted. Screened from the onset
        // its tangent shows, it is fitted, named, and its onset reported.
        const auto r = discoverFromOnset(Mechanism::InletMoistureSensorOffset, 1.0, 1200);
        const QString onset = onsetMismatch(r, 1200);
        QVERIFY2(onset.isEmpty(), qPrintable(onset));
        QCOMPARE(r.findings.front().cause, std::string("inlet_moisture_sensor_offset"));
    }

    void distributedNullNamesNothing() {
        // The distributed plant with realistic sensors and no hidden effect: the model is wrong
        // everywhere a little, and nothing may be named for it.
        plant::PlantOptions o;
        o.plant = plant::PlantKind::Distributed;
        const auto r = discoverIn(o);
        QVERIFY2(r.findings.empty(), qPrintable(names(r)));
        QVERIFY(r.verdict != "cause_found");
    }

    void lookAlikesAreReportedAsAGroup() {
        // An outlet-meter offset in data with neither tube-outlet channel nor a usable outlet
        // temperature: an inlet-gauge offset leaves much the same steady outlet bias. The finding
        // names the group, the evidence for each member and what would tell them apart.
        plant::PlantOptions o;
        o.effects[Mechanism::MoistureMeterOffset] = 0.5;
        auto data = plantData(o);
        for (auto& b : data) {
            b.hasXHdt = b.hasTHdt = false;
            std::fill(b.xHdtDb.begin(), b.xHdtDb.end(), std::nan(""));
            std::fill(b.tHdtK.begin(), b.tHdtK.end(), std::nan(""));
        }
        auto r = discovery::discover(data, hybrid::HybridModel{});
        QVERIFY(r.ok());
        QVERIFY2(!r->findings.empty(), qPrintable(names(*r)));
        const auto& f = r->findings.front();
        QVERIFY2(f.cause == "moisture_meter_offset" || f.cause == "inlet_moisture_sensor_offset",
                 qPrintable(names(*r)));
        QCOMPARE(f.lookAlikes.size(), std::size_t{1});
        const auto& other = f.lookAlikes.front();
        qInfo("%s vs %s: held-out loss ratio %.3f, p %.3g", f.cause.c_str(), other.cause.c_str(),
              other.heldOutLossRatio, other.pValue);
        if (!other.ruledOut) {
            QCOMPARE(f.group, std::string("moisture_offset"));
            QVERIFY(f.evidence.find("To tell them apart") != std::string::npos);
            QVERIFY(!f.tellApart.empty());
        } else {
            QVERIFY(f.group.empty());
            QVERIFY(f.evidence.find("Not " + other.cause) != std::string::npos);
        }
        // Either way the hidden cause is the one named or in the group with it.
        QVERIFY(f.cause == "moisture_meter_offset" || !other.ruledOut);
    }

    void outletChannelsTellMeterLagFromTransportTime_data() {
        QTest::addColumn<int>("mechanism");
        QTest::addColumn<double>("strength");
        QTest::newRow("moisture_meter_lag") << int(Mechanism::MoistureMeterLag) << 30.0;
        QTest::newRow("transport_delay_error") << int(Mechanism::TransportDelayError) << 15.0;
    }
    void outletChannelsTellMeterLagFromTransportTime() {
        // The distributed line answers later than the model in the outlet temperature even with
        // nothing hidden (its product's heat capacity, the pyrometer), so a transport time fitted
        // in a meter lag's place also fixes that and wins any comparison in its place. The delay
        // each outlet channel asks for alone decides: the moisture later than the temperature is
        // a meter's; otherwise the finding names the group, never the wrong cause alone.
        QFETCH(int, mechanism);
        QFETCH(double, strength);
        plant::PlantOptions o;
        o.plant = plant::PlantKind::Distributed;
        o.effects[static_cast<Mechanism>(mechanism)] = strength;
        const auto r = discoverIn(o);
        const std::string hidden(plant::info(static_cast<Mechanism>(mechanism)).name);
        QVERIFY2(!r.findings.empty(), qPrintable(names(r)));
        const auto& f = r.findings.front();
        const auto other = std::find_if(f.lookAlikes.begin(), f.lookAlikes.end(), [](const auto& l) {
            return l.cause == "moisture_meter_lag" || l.cause == "transport_delay_error";
        });
        QVERIFY2(other != f.lookAlikes.end(), qPrintable(names(r)));
        qInfo("%s first; %s: channels %d, moisture %.1f s, temperature %.1f s, p %.2g, ruled out %d",
              f.cause.c_str(), other->cause.c_str(), other->byChannels, other->moistureDelayS,
              other->temperatureDelayS, other->pValue, other->ruledOut);
        // The hidden cause is named, alone or in the group with its look-alike.
        QVERIFY2(f.cause == hidden || (!other->ruledOut && other->cause == hidden), qPrintable(names(r)));
        if (!other->ruledOut) {
            QCOMPARE(f.group, std::string("outlet_response_time"));
            QVERIFY(f.evidence.find("To tell them apart") != std::string::npos);
        }
        if (other->byChannels) {
            // The channels' delays are the ones that decided, and the evidence gives them: the
            // transport time is ruled out only where the moisture answers later and the held-out
            // part confirms it (p < 0.05); apart without that confirmation, the group stands.
            QVERIFY(other->moistureDelayS > 0 && other->temperatureDelayS > 0);
            QCOMPARE(other->ruledOut, f.cause == "moisture_meter_lag" &&
                                          other->moistureDelayS > other->temperatureDelayS &&
                                          other->pValue < 0.05);
            QVERIFY2(f.evidence.find("fitted alone") != std::string::npos, f.evidence.c_str());
        }
    }

    void temperatureLagAloneIsTheLinesDynamics() {
        // Seed 301 of the distributed plant, nothing hidden: fitted to the outlet temperature
        // alone the conveyor delay comes out ~17 s (the product's heat capacity, the pyrometer),
        // to the moisture alone ~1 s. That is neither a transport time (it would delay both) nor a
        // meter lag (the moisture alone); before this rule the pair was named as a group once the
        // explained-share rule was relaxed to 5 % (it removes 10-12 % of the held-out error), so
        // the share is relaxed here: the timing alone must turn it down.
        plant::PlantOptions o;
        o.plant = plant::PlantKind::Distributed;
        o.seed = 301;
        o.batches = 4;
        o.samples = 3000;
        o.sensorFaults = plant::SensorFaultRates{0, 0, 0};
        auto p = plant::runPlant(o);
        QVERIFY(p.ok());
        discovery::DiscoveryOptions options;
        options.minExplainedFraction = 0.05;
        auto r = discovery::discover(plant::toSiBatches(*p, o.seed), hybrid::HybridModel{}, options);
        QVERIFY(r.ok());
        QVERIFY2(r->findings.empty(), qPrintable(names(*r)));
        bool saidWhy = false;
        for (const auto& rd : r->rounds) {
            for (const auto& x : rd.rejected) {
                if (x.code == "line_dynamics" &&
                    (x.cause == "transport_delay_error" || x.cause == "moisture_meter_lag")) {
                    qInfo("%s: %s", x.cause.c_str(), x.reason.c_str());
                    saidWhy = x.reason.find("thermal dynamics") != std::string::npos;
                }
            }
        }
        QVERIFY2(saidWhy, qPrintable(names(*r)));
    }

    void distributedDriftNamesNothingAndSaysWhy() {
        // The distributed plant under unmeasured drift: the candidates that fit the training part
        // are tried, and each is turned down with its reason; none is named.
        plant::PlantOptions o;
        o.plant = plant::PlantKind::Distributed;
        o.unmeasuredDrift = true;
        const auto r = discoverIn(o);
        QVERIFY2(r.findings.empty(), qPrintable(names(r)));
        int tried = 0;
        for (const auto& rd : r.rounds) {
            QVERIFY(!rd.named && !rd.reason.empty());
            for (const auto& x : rd.rejected) {
                qInfo("not named: %s (%s): %s", x.cause.c_str(), x.code.c_str(), x.reason.c_str());
                QVERIFY(!x.reason.empty() && !x.code.empty());
                ++tried;
            }
        }
        QVERIFY2(tried >= 1, qPrintable(names(r)));
    }

    void onlyTheCausesAskedAreTried() {
        // An engineer asks about two suspects: only they are scored, and the hidden one is named;
        // asked about another alone, discovery does not reach for the hidden one.
        plant::PlantOptions o;
        o.effects[Mechanism::MoistureMeterOffset] = 0.4;
        const auto data = plantData(o);
        discovery::DiscoveryOptions asked;
        asked.causes = {"tube_wall_heat_loss", "moisture_meter_offset"};
        auto both = discovery::discover(data, hybrid::HybridModel{}, asked);
        QVERIFY(both.ok());
        QCOMPARE(both->ranking.size(), std::size_t{2});
        for (const auto& c : both->ranking) {
            QVERIFY2(c.cause == "tube_wall_heat_loss" || c.cause == "moisture_meter_offset", c.cause.c_str());
        }
        QVERIFY2(!both->findings.empty() && both->findings.front().cause == "moisture_meter_offset",
                 qPrintable(names(*both)));
        asked.causes = {"tube_wall_heat_loss"};
        auto other = discovery::discover(data, hybrid::HybridModel{}, asked);
        QVERIFY(other.ok());
        QCOMPARE(other->ranking.size(), std::size_t{1});
        QVERIFY(std::any_of(other->notes.begin(), other->notes.end(), [](const std::string& n) {
            return n.find("only the causes asked") != std::string::npos;
        }));
        for (const auto& f : other->findings) {
            QVERIFY2(f.cause == "tube_wall_heat_loss", qPrintable(names(*other)));
        }
        asked.causes = {"moisture_meter_ofset"};
        QCOMPARE(discovery::discover(data, hybrid::HybridModel{}, asked).error().code,
                 ErrorCode::InvalidOption);
    }

    void badInputAndCancelAreErrors() {
        // Too few rows: a short batch leaves too little to test and to judge.
        plant::PlantOptions o;
        o.seed = 3;
        o.batches = 1;
        o.samples = 300;
        auto small = plant::runPlant(o);
        QVERIFY(small.ok());
        auto r = discovery::discover(plant::toSiBatches(*small, 3), hybrid::HybridModel{});
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::NotEnoughData);
        QCOMPARE(exitCodeFor(r.error().kind), 3);
        QVERIFY(discovery::discover({}, hybrid::HybridModel{}).error().code == ErrorCode::NotEnoughData);
        // Options are checked first.
        discovery::DiscoveryOptions bad;
        bad.screenAlpha = 0;
        QCOMPARE(discovery::discover(plantData({}), {}, bad).error().code, ErrorCode::InvalidOption);
        // Cancel at the first report stops with the Cancelled error.
        int calls = 0;
        auto c = discovery::discover(plantData({}), hybrid::HybridModel{}, {}, [&](const ProgressInfo&) {
            ++calls;
            return ProgressAction::Stop;
        });
        QVERIFY(!c.ok());
        QCOMPARE(c.error().code, ErrorCode::Cancelled);
        QCOMPARE(calls, 1);
    }
};

QTEST_APPLESS_MAIN(TestDiscovery)
#include "TestDiscovery.moc"
