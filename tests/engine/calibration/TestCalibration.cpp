#include "calibration/Calibration.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <QtTest>
#include <cmath>

using namespace drytwin;
using properties::Param;

namespace {

/// Plant batches as a data set would give them after loading, cleaning and SI conversion.
std::vector<data::SiBatch> plantData(const plant::PlantOptions& o) {
    auto r = plant::runPlant(o);
    if (!r) {
        qFatal("%s", r.error().message().c_str());
    }
    return plant::toSiBatches(*r, o.seed);
}

plant::PlantOptions noMechanisms() {
    plant::PlantOptions o;
    o.seed = 17;
    o.batches = 2;
    o.samples = 3200;
    return o;
}

} // namespace

class TestCalibration : public QObject {
    Q_OBJECT
    std::vector<data::SiBatch> m_data;

private Q_SLOTS:
    void initTestCase() { m_data = plantData(noMechanisms()); }

    void recoversThePlantsCoefficients() {
        calibration::CalibrationOptions o;
        auto r = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message().c_str());
        const auto truth = plant::PlantOptions::defaultTruth();
        QCOMPARE(r->rowsUsed, std::size_t(300));
        for (const auto& e : r->estimates) {
            const double t = truth[e.param];
            QVERIFY2(std::abs(e.value - t) < 0.05 * t,
                     qPrintable(QString("%1: %2 vs %3")
                                    .arg(properties::info(e.param).symbol.data())
                                    .arg(e.value)
                                    .arg(t)));
            QVERIFY(e.ci95Low < e.value && e.value < e.ci95High);
            QVERIFY(std::isfinite(e.standardErrorFisher) && e.standardErrorFisher > 0);
            QVERIFY(!e.atBound);
        }
        QVERIFY(QString::fromStdString(r->intervalMethod).startsWith("sandwich"));
        QVERIFY(r->after.loss < 0.05 * r->before.loss);
        QVERIFY(r->after.maeXOutPct < 0.03); // noise level: meter noise 0.02 % wb
        QVERIFY(!r->history.empty());
        QCOMPARE(int(r->history.size()), r->evaluations);
        QVERIFY(r->history.back().bestLoss <= r->history.front().loss);
        QVERIFY(r->evaluations <= o.maxEvaluations);
    }

    void sandwichIntervalsWidenWithAutocorrelatedResiduals() {
        // Unmeasured drift makes the residuals slow: independent-row (Fisher) intervals are then
        // far too narrow, and the sandwich with a HAC meat must be several times wider.
        auto o = noMechanisms();
        o.unmeasuredDrift = true;
        const auto drifting = plantData(o);
        calibration::CalibrationOptions co;
        co.globalSearch = false;
        co.maxEvaluations = 80;
        auto r = calibration::calibrate(drifting, plant::PlantOptions::defaultTruth(), co);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message().c_str());
        for (const auto& e : r->estimates) {
            qInfo("%s: sandwich SE %.4g, Fisher SE %.4g", properties::info(e.param).symbol.data(),
                  e.standardError, e.standardErrorFisher);
            QVERIFY(e.standardError > 2 * e.standardErrorFisher);
            QCOMPARE(e.ci95High - e.ci95Low, 2 * 1.96 * e.standardError);
        }
    }

    void anIntervalAtABoundStaysWithinTheRange() {
        // h_HDT held below its true value ends at its upper bound; its interval may not reach past
        // it (the inlet gauge's scatter share at 1 had [0.88, 1.12] in the workbench).
        const double truth = plant::PlantOptions::defaultTruth()[properties::Param::h_HDT];
        calibration::CalibrationOptions o;
        o.globalSearch = false;
        o.maxEvaluations = 60;
        o.bounds[properties::Param::h_HDT] = {0.5 * truth, 0.8 * truth};
        auto r = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message().c_str());
        bool sawBound = false;
        for (const auto& e : r->estimates) {
            if (e.param != properties::Param::h_HDT) {
                continue;
            }
            sawBound = e.atBound;
            QVERIFY2(e.value > 0.79 * truth, qPrintable(QString::number(e.value)));
            QVERIFY(std::isfinite(e.standardError) && e.standardError > 0);
            QVERIFY2(e.ci95High <= 0.8 * truth + 1e-12 && e.ci95Low < e.ci95High,
                     qPrintable(QStringLiteral("[%1, %2]").arg(e.ci95Low).arg(e.ci95High)));
        }
        QVERIFY(sawBound);
    }

    void sameSeedSameResult() {
        calibration::CalibrationOptions o;
        o.maxEvaluations = 60;
        o.seed = 4;
        auto a = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        auto b = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY(a.ok() && b.ok());
        QCOMPARE(a->parameters[Param::h_HDT], b->parameters[Param::h_HDT]);
        QCOMPARE(a->parameters[Param::k_HDT], b->parameters[Param::k_HDT]);
        QCOMPARE(a->evaluations, b->evaluations);
    }

    void failedEvaluationsDoNotAbort() {
        // With a tight cap on solver steps, fast-drying parameter sets make the tube run out of
        // steps: those evaluations fail, the search carries on.
        calibration::CalibrationOptions o;
        o.maxEvaluations = 80;
        o.simulation.maxStepsPerSection = 60;
        o.bounds[Param::k_HDT] = {0.01, 0.2};
        auto r = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().message().c_str());
        QVERIFY2(r->failedEvaluations > 0, qPrintable(QString::number(r->failedEvaluations)));
        QVERIFY(r->failedEvaluations < r->evaluations);
        QVERIFY(std::isfinite(r->after.loss));
    }

    void parameterAtABoundIsFlagged() {
        calibration::CalibrationOptions o;
        o.maxEvaluations = 80;
        o.bounds[Param::h_HDT] = {10, 50}; // the plant's 72 lies outside
        auto r = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY(r.ok());
        QVERIFY(r->estimates[0].atBound);
        QVERIFY(std::abs(r->estimates[0].value - 50) < 0.1);
    }

    void badOptionsAreErrors() {
        calibration::CalibrationOptions o;
        o.bounds[Param::h_HDT] = {100, 50};
        QVERIFY(!calibration::calibrate(m_data, properties::ParameterSet{}, o).ok());
        o = {};
        o.bounds[Param::h_HDT] = {1, 50}; // below the table's lower bound of 10
        QVERIFY(!o.validate().ok());
        o = {};
        o.freeParameters = {Param::R_gas};
        QVERIFY(!o.validate().ok());
        o = {};
        o.freeParameters = {Param::h_HDT, Param::h_HDT};
        QVERIFY(!o.validate().ok());
        o = {};
        o.freeParameters.clear();
        QVERIFY(!o.validate().ok());
        o = {};
        o.rows = {{0, 1}, {0, 2}};
        auto few = calibration::calibrate(m_data, properties::ParameterSet{}, o);
        QVERIFY(!few.ok());
        QCOMPARE(exitCodeFor(few.error().kind), 3);
        QVERIFY(!calibration::calibrate({}, properties::ParameterSet{}, {}).ok());
    }

    void cancelStops() {
        calibration::CalibrationOptions o;
        int calls = 0;
        auto r = calibration::calibrate(m_data, properties::ParameterSet{}, o, [&](const ProgressInfo&) {
            return ++calls > 5 ? ProgressAction::Stop : ProgressAction::Continue;
        });
        QVERIFY(!r.ok());
        QCOMPARE(exitCodeFor(r.error().kind), 130);
        QVERIFY(calls < 10);
    }
};

QTEST_APPLESS_MAIN(TestCalibration)
#include "TestCalibration.moc"
