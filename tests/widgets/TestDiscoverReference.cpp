// The Discover tab against a reference period (issue #41): the reference chosen, discovery run
// against it, both detectors' verdicts, the monitor's chart with its limits and the columns'
// contributions shown, and the reference kept by a saved project.
#include "MainWindow.h"
#include "common/PlotStack.h"
#include "common/Workbench.h"
#include "discovery/DiscoverPanel.h"
#include "workflow/Session.h"

#include "WaitIdle.h"
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>

#include <QtTest>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

using namespace drytwin;
using drytwin::widgets::MainWindow;

namespace {

bool waitIdle(MainWindow& w, int ms = 240000) {
    return widgets::test::waitUntilIdle(w, ms);
}

/// Virtual-plant batches (distributed plant, realistic sensors) written to @p folder.
void generate(const QString& folder, unsigned seed, double meterOffsetPct) {
    workflow::GenerateOptions o;
    o.plant.plant = plant::PlantKind::Distributed;
    o.plant.sensors = plant::SensorMode::Realistic;
    o.plant.seed = seed;
    o.plant.batches = 3;
    o.plant.samples = 2400;
    if (meterOffsetPct != 0) {
        o.plant.effects[plant::Mechanism::MoistureMeterOffset] = meterOffsetPct;
    }
    o.outFolder = folder.toStdString();
    workflow::Session s;
    auto r = s.generate(o);
    if (!r) {
        qFatal("%s", r.error().message().c_str());
    }
}

int curvesWithData(QwtPlot* plot) {
    int n = 0;
    for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
        n += static_cast<QwtPlotCurve*>(item)->dataSize() > 0;
    }
    return n;
}

} // namespace

class TestDiscoverReference : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void referencePeriodIsComparedShownAndKept() {
        QTemporaryDir dir;
        const QString reference = dir.filePath("healthy");
        const QString changed = dir.filePath("after");
        generate(reference, 61, 0);
        generate(changed, 62, 0.6);

        MainWindow w;
        auto* disc = w.discoverPanel();
        QVERIFY(disc->referenceLabel()->text().contains("No reference"));
        w.workbench().setReferencePath(reference);
        QVERIFY2(disc->referenceLabel()->text().contains("healthy"),
                 qPrintable(disc->referenceLabel()->text()));
        w.openDataSet(changed);
        QVERIFY(waitIdle(w));
        w.workbench().discover();
        QVERIFY(waitIdle(w));
        const auto& latest = w.workbench().latest().discover;
        QVERIFY(latest.has_value());
        QVERIFY(latest->discovery.hasReference);
        // Both detectors' verdicts in words, the monitor drawn with its limits, the contributions.
        const QString detection = disc->detection()->text();
        QVERIFY2(detection.contains("DryTwin") && detection.contains("PCA"), qPrintable(detection));
        QVERIFY2(latest->discovery.detection.drytwinChanged, qPrintable(detection));
        QVERIFY2(detection.contains("has changed"), qPrintable(detection));
        QCOMPARE(curvesWithData(disc->monitorPlots()->plot(0)), 2); // T² and its 99 % limit
        QCOMPARE(curvesWithData(disc->monitorPlots()->plot(1)), 2); // SPE and its limit
        QVERIFY(disc->contributions()->rowCount() >= 1);
        // The meter's offset moves the outlet moisture's error first.
        QVERIFY2(disc->contributions()->item(0, 0)->text().contains("outlet moisture"),
                 qPrintable(disc->contributions()->item(0, 0)->text()));

        // The project keeps the reference.
        const QString project = dir.filePath("p.drytwin");
        QString error;
        QVERIFY2(w.saveProject(project, &error, false), qPrintable(error));
        QVERIFY(waitIdle(w));
        MainWindow reopened;
        QVERIFY2(reopened.openProject(project, &error, false), qPrintable(error));
        QVERIFY(waitIdle(reopened));
        QCOMPARE(reopened.workbench().referencePath(), QFileInfo(reference).absoluteFilePath());
        QVERIFY(reopened.discoverPanel()->referenceLabel()->text().contains("healthy"));
        // Cleared: the data are judged alone again.
        reopened.workbench().setReferencePath({});
        QVERIFY(reopened.discoverPanel()->referenceLabel()->text().contains("No reference"));
    }
};

QTEST_MAIN(TestDiscoverReference)
#include "TestDiscoverReference.moc"
