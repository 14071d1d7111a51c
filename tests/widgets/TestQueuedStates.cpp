// Issue #72 item 8: work that waits says what it waits for, and no tab says what is not true while
// it waits: a queued Discover showed only a greyed button; the Residual tab said "Learnt.
// Scoring…" while its plots asked to learn; the What-if tab said "stale … retrain it" while a
// retraining ran.
#include "MainWindow.h"
#include "calibration/CalibrationPanel.h"
#include "common/ModelStateBar.h"
#include "common/PlotStack.h"
#include "common/QueuedNote.h"
#include "discovery/DiscoverPanel.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "workflow/Session.h"

#include "WaitIdle.h"
#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <QtTest>

using namespace drytwin;
using drytwin::widgets::MainWindow;

namespace {

bool waitIdle(MainWindow& w, int ms = 600000) {
    return widgets::test::waitUntilIdle(w, ms);
}

/// Waits until @p holds() is true, for at most @p ms.
bool waitFor(const std::function<bool()>& holds, int ms = 300000) {
    QElapsedTimer t;
    t.start();
    while (!holds() && t.elapsed() < ms) {
        QTest::qWait(20);
    }
    return holds();
}

/// The queued-work line on @p tab (a visible QueuedNote), or empty.
QString queuedNoteOn(QWidget* tab) {
    for (auto* note : tab->findChildren<widgets::QueuedNote*>()) {
        if (note->isVisibleTo(tab) && !note->text().isEmpty()) {
            return note->text();
        }
    }
    return {};
}

} // namespace

class TestQueuedStates : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_data;

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        m_data = m_dir.filePath("plant");
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(7, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 1500;
        g.outFolder = m_data.toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
    }

    // Discover clicked while a calibration runs: its tab says what it waits for, until it runs.
    void aQueuedDiscoverSaysWhatItWaitsFor() {
        MainWindow w;
        w.show();
        w.openDataSet(m_data);
        QVERIFY(waitIdle(w));
        QCOMPARE(queuedNoteOn(w.discoverPanel()), QString());
        w.calibrationPanel()->setBudget(600);
        w.calibrationPanel()->run();
        w.workbench().discover();
        const QString queued = queuedNoteOn(w.discoverPanel());
        QVERIFY2(queued == QStringLiteral("Queued — waits for “Calibrate”"), qPrintable(queued));
        QCOMPARE(queuedNoteOn(w.calibrationPanel()), QString()); // the running one is not "queued"
        // Once it runs (the calibration done), the note goes.
        QVERIFY(waitFor(
            [&] { return w.workbench().isRunningNow(widgets::Action::Discover) || !w.jobs().busy(); }));
        QCOMPARE(queuedNoteOn(w.discoverPanel()), QString());
        w.jobs().cancelAll();
        QVERIFY(waitIdle(w));
    }

    // Learnt, with the scoring queued behind a Discover: the note says so and the plots do not
    // ask to learn; once scored, the plots are drawn.
    void learntModelsWaitingForTheirScoresSaySo() {
        MainWindow w;
        w.show();
        w.openDataSet(m_data);
        QVERIFY(waitIdle(w));
        QSignalSpy trained(&w.workbench(), &widgets::Workbench::trained);
        w.residualPanel()->setQuick(true);
        w.residualPanel()->train();
        w.workbench().discover(); // queued behind the learning; the scoring comes after it
        QVERIFY(trained.count() > 0 || trained.wait(300000));
        QTest::qWait(50);
        const QString note = w.residualPanel()->note()->text();
        QVERIFY2(note.startsWith("Learnt.") && note.contains("Queued — waits for “Discover”"),
                 qPrintable(note));
        QVERIFY2(w.residualPanel()->eigenvalues()->emptyText().startsWith("Learnt:"),
                 qPrintable(w.residualPanel()->eigenvalues()->emptyText()));
        QVERIFY(!w.residualPanel()->skill()->emptyText().contains("Learn the correction models to see"));
        QVERIFY(waitIdle(w));
        QVERIFY(w.workbench().latest().evaluate.has_value());
        QVERIFY(!w.residualPanel()->note()->text().startsWith("Learnt."));
        QVERIFY(w.residualPanel()->eigenvalues()->emptyText().startsWith("Learn the correction models"));
    }

    // Stale learnt models being learnt again: no tab tells the user to retrain them meanwhile.
    void aRetrainingUnderWayIsNotAdvisedAgain() {
        MainWindow w;
        w.show();
        w.workbench().setInvalidationPolicy(widgets::AfterInvalidation::KeepStale);
        w.openDataSet(m_data);
        QVERIFY(waitIdle(w));
        w.residualPanel()->setQuick(true);
        w.residualPanel()->train();
        QVERIFY(waitIdle(w));
        w.calibrationPanel()->setBudget(60);
        w.calibrationPanel()->run();
        QVERIFY(waitIdle(w));
        QVERIFY(w.workbench().hasStaleParts());
        const QString stale = w.mpcPanel()->modelState()->text()->text();
        QVERIFY2(stale.contains("retrain it to use it"), qPrintable(stale));
        w.workbench().retrain();
        QVERIFY(waitFor([&] { return w.workbench().isRunningNow(widgets::Action::Train); }));
        QTest::qWait(50);
        const QString during = w.mpcPanel()->modelState()->text()->text();
        QVERIFY2(!during.contains("retrain it") && during.contains("being learnt again now"),
                 qPrintable(during));
        QVERIFY(!w.mpcPanel()->modelState()->findChild<QPushButton*>()->isVisibleTo(w.mpcPanel()));
        const QString box = w.mpcPanel()->controllerBox(3)->text(); // PGRL-CC
        QVERIFY2(box.contains("being learnt again"), qPrintable(box));
        QVERIFY(waitIdle(w));
        QVERIFY(!w.workbench().hasStaleParts());
    }
};

QTEST_MAIN(TestQueuedStates)
#include "TestQueuedStates.moc"
