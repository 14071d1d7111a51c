// The What-if tab's scenario form checks itself (issue #43, item 10): a form that contradicts
// itself says so beside the field and Run stays off; a run that fails leaves the tab saying why,
// not "Running…", and never names the temporary file the editor's text ran from.
#include "common/Workbench.h"
#include "mpc/MpcPanel.h"
#include "mpc/ScenarioForm.h"

#include "WaitIdle.h"
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QWheelEvent>

#include <QtTest>

using namespace drytwin;
using namespace drytwin::widgets;

namespace {

bool waitIdle(Workbench& wb, int ms = 60000) {
    return widgets::test::waitUntilIdle(wb, ms);
}

// A run the engine refuses: the note says why, without the temporary file's name.
void aFailedRunSaysWhy(Workbench& wb, MpcPanel& panel) {
    panel.editor()->setPlainText(R"({"name": "short warm-up", "length_s": 30, "warmup_s": 0, "seed": 2})");
    QVERIFY(panel.runButton()->isEnabled());
    for (int i = 1; i < 5; ++i) {
        panel.controllerBox(i)->setChecked(false);
    }
    panel.run();
    QVERIFY(panel.note()->text().contains("Running"));
    QVERIFY(!panel.runButton()->isEnabled()); // queued
    QVERIFY(waitIdle(wb));
    QVERIFY2(!panel.note()->text().contains("Running"), qPrintable(panel.note()->text()));
    QVERIFY2(panel.note()->text().contains("warmup_s"), qPrintable(panel.note()->text()));
    QVERIFY(!panel.note()->text().contains("drytwin-scenario"));
    QVERIFY(panel.runButton()->isEnabled());
    QVERIFY(!wb.latest().mpc.has_value());
}

} // namespace

class TestMpcPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // At 1280 x 800 the tab is about 1270 x 700: the results table keeps the room for a row per
    // controller (five) and the scenario form above it scrolls; it showed 3½ rows before.
    void theResultsTableShowsEveryControllerAt1280x800() {
        Workbench wb;
        MpcPanel panel(wb);
        panel.resize(1270, 700);
        static_cast<QWidget&>(panel).show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTableWidget* table = panel.table();
        // The viewport is what shows rows; it already leaves out the header and the scroll bar.
        const int rowsShown = table->viewport()->height() / table->verticalHeader()->defaultSectionSize();
        QVERIFY2(rowsShown >= 5, qPrintable(QString("%1 rows in %2 px").arg(rowsShown).arg(table->height())));
    }

    // Under the table, a controller whose model believes a third of the plant's gain is said to
    // over-act, one with three times to act too little, one of the other sign to steer wrong.
    // Issue #72 item 7: the wheel turned over the form scrolls it; a value under the pointer does
    // not change unless its box has the focus (the band went 0.50 → 0.01 % wb unnoticed).
    void theWheelChangesNoValueItsBoxHasNotTheFocusOf() {
        Workbench wb;
        MpcPanel panel(wb);
        panel.resize(700, 500);
        static_cast<QWidget&>(panel).show(); // MpcPanel::show() redraws its results
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* band = panel.form()->band();
        const double before = band->value();
        const auto turn = [](QWidget* target) {
            const QPoint at = target->rect().center();
            QWheelEvent wheel(at, target->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(target, &wheel);
        };
        band->clearFocus();
        turn(band);
        QCOMPARE(band->value(), before);
        QCOMPARE(band->focusPolicy(), Qt::StrongFocus);
        // A combo box in a table cell alike (an input change's input).
        panel.form()->addInputChange("feed_kg_h", 10, 0, 6400);
        auto* input = qobject_cast<QComboBox*>(panel.form()->inputChanges()->cellWidget(0, 0));
        QVERIFY(input);
        const int chosen = input->currentIndex();
        turn(input);
        QCOMPARE(input->currentIndex(), chosen);
        // With the focus (clicked into, or tabbed to), the wheel steps the value as usual.
        panel.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&panel));
        band->setFocus();
        QTRY_VERIFY(band->hasFocus());
        turn(band);
        QVERIFY2(band->value() != before, qPrintable(QString::number(band->value())));
    }

    // Issue #72 item 7: Add appends a setpoint step after the last one, so Run stays on.
    void addAppendsAStepAfterTheLast() {
        Workbench wb;
        MpcPanel panel(wb);
        panel.editor()->setPlainText(R"({"name": "steps", "length_s": 1000, "warmup_s": 150, "seed": 2,
            "setpoint_steps": [{"at_s": 300, "to_pct": 12.5}, {"at_s": 600, "to_pct": 13.2}]})");
        QVERIFY(panel.runButton()->isEnabled());
        QPushButton* add = nullptr;
        for (auto* b : panel.form()->findChildren<QPushButton*>()) {
            if (b->text() == QStringLiteral("Add") && !add) {
                add = b; // the first Add: the setpoint steps'
            }
        }
        QVERIFY(add);
        add->click();
        QCOMPARE(panel.form()->setpointSteps()->rowCount(), 3);
        const double added = panel.form()->setpointSteps()->item(2, 0)->text().toDouble();
        QVERIFY2(added > 600 && added <= 1000, qPrintable(QString::number(added)));
        QCOMPARE(panel.form()->setpointSteps()->item(2, 1)->text().toDouble(),
                 13.2); // holds the last setpoint
        QVERIFY2(panel.runButton()->isEnabled(), qPrintable(panel.scenarioProblem()));
        add->click(); // and again, still after the last and within the run
        QVERIFY(panel.form()->setpointSteps()->item(3, 0)->text().toDouble() > added);
        QVERIFY(panel.form()->isValid());
    }

    void aMismatchedGainIsExplained() {
        const QString under = MpcPanel::gainMismatchText(QStringLiteral("LSTM"), 0.32);
        const QString over = MpcPanel::gainMismatchText(QStringLiteral("LSTM"), 3.0);
        const QString sign = MpcPanel::gainMismatchText(QStringLiteral("LSTM"), -0.5);
        QVERIFY2(under.startsWith(QLatin1String("LSTM")) && under.contains(QLatin1String("0.32")) &&
                     under.contains(QLatin1String("over-acts")),
                 qPrintable(under));
        QVERIFY2(over.contains(QLatin1String("3.00")) && over.contains(QLatin1String("too little")),
                 qPrintable(over));
        QVERIFY2(sign.contains(QLatin1String("wrong way")), qPrintable(sign));
    }

    // Scored length 600 s, a setpoint step at 780 s: the form says so under the steps and under
    // the length, the cell is marked, Run is off and run() starts nothing.
    void stepAfterTheScoredLengthIsRefusedInTheForm() {
        Workbench wb;
        MpcPanel panel(wb);
        static_cast<QWidget&>(panel).show(); // MpcPanel::show() redraws its results
        ScenarioForm* form = panel.form();
        panel.editor()->setPlainText(
            R"({"name": "t", "length_s": 1000, "setpoint_steps": [{"at_s": 100, "to_pct": 12.5}]})");
        QVERIFY(form->isValid());
        QVERIFY(panel.runButton()->isEnabled());
        QVERIFY(!panel.runBlockedMessage()->isVisible());

        form->setpointSteps()->item(0, 0)->setText("780");
        QVERIFY(form->isValid()); // 780 s lies inside 1000 s
        form->scoredLength()->setValue(600);
        QVERIFY(!form->isValid());
        QVERIFY(form->setpointStepsMessage()->isVisible());
        QVERIFY2(form->setpointStepsMessage()->text().contains("780 s") &&
                     form->setpointStepsMessage()->text().contains("600 s"),
                 qPrintable(form->setpointStepsMessage()->text()));
        QVERIFY(form->lengthMessage()->isVisible());
        QVERIFY(form->setpointSteps()->item(0, 0)->toolTip().contains("after the scored length"));
        QVERIFY(!panel.runButton()->isEnabled());
        QVERIFY(panel.runBlockedMessage()->isVisible());
        QVERIFY(panel.runBlockedMessage()->text().contains("780 s"));
        if (const QString shots = qEnvironmentVariable("DRYTWIN_TEST_SHOTS"); !shots.isEmpty()) {
            panel.resize(1000, 760); // a picture of the refused form, to look at
            QTest::qWait(50);
            panel.grab().save(shots + "/mpc-form-refused.png");
        }

        QSignalSpy started(&wb, &Workbench::runningChanged);
        panel.run();
        QCOMPARE(started.count(), 0); // nothing queued
        QVERIFY(panel.note()->text().contains("780 s"));
        QVERIFY(!panel.note()->text().contains("Running"));

        // Lengthening the run puts it right: the message goes, Run comes back.
        form->scoredLength()->setValue(900);
        QVERIFY(form->isValid());
        QVERIFY(!form->setpointStepsMessage()->isVisible());
        QVERIFY(!form->lengthMessage()->isVisible());
        QVERIFY(panel.runButton()->isEnabled());
    }

    // Values outside what the scenario parser accepts are named in the form too.
    void outOfRangeValuesAreNamedBesideTheTable() {
        Workbench wb;
        MpcPanel panel(wb);
        ScenarioForm* form = panel.form();
        panel.editor()->setPlainText(R"({"name": "t", "length_s": 600,
            "setpoint_steps": [{"at_s": 100, "to_pct": 12.5}, {"at_s": 50, "to_pct": 12}],
            "input_changes": [{"input": "feed_kg_h", "at_s": 10, "to": 6400}]})");
        QVERIFY(!form->isValid()); // steps out of order
        QVERIFY(form->setpointStepsMessage()->text().contains("time order"));
        form->setpointSteps()->item(1, 0)->setText("150");
        QVERIFY(form->isValid());
        form->inputChanges()->item(0, 3)->setText("12000");
        QVERIFY(!form->isValid());
        QVERIFY2(form->inputChangesMessage()->text().contains("3000") &&
                     form->inputChangesMessage()->text().contains("9000"),
                 qPrintable(form->inputChangesMessage()->text()));
        QVERIFY(!panel.runButton()->isEnabled());
    }

    // JSON typed by hand that the form cannot check is checked by the scenario parser: the line is
    // named beside Run, and the temporary file is not.
    void typedJsonIsCheckedBeforeARun() {
        Workbench wb;
        MpcPanel panel(wb);
        panel.scenarioTabs()->setCurrentIndex(1);
        panel.editor()->setPlainText("{\n \"name\": \"x\",\n \"band_pct\": -4\n}");
        QVERIFY(!panel.runButton()->isEnabled());
        QVERIFY2(panel.runBlockedMessage()->text().contains("line 3"),
                 qPrintable(panel.runBlockedMessage()->text()));
        QVERIFY(!panel.runBlockedMessage()->text().contains("drytwin-scenario"));
    }

    // A run the engine refuses (warm-up shorter than the controller's history) leaves the tab
    // saying why, in the note under Run, and Run usable again.
    void aFailedRunLeavesTheTabSayingWhy() {
        Workbench wb;
        QString scenarioFile;
        {
            MpcPanel panel(wb);
            aFailedRunSaysWhy(wb, panel);
            if (QTest::currentTestFailed()) {
                return;
            }
            scenarioFile = panel.temporaryScenarioPath();
            QVERIFY(QFile::exists(scenarioFile));
        }
        // The scenario's temporary file goes with the panel.
        QVERIFY2(!QFile::exists(scenarioFile), qPrintable(scenarioFile));
    }

    // A cancelled run says so too.
    void aCancelledRunSaysSo() {
        Workbench wb;
        MpcPanel panel(wb);
        panel.editor()->setPlainText(R"({"name": "long", "length_s": 5000, "warmup_s": 300, "seed": 2})");
        panel.run();
        QTest::qWait(100);
        wb.cancelAll();
        QVERIFY(waitIdle(wb));
        // Cancelled while queued or running: it says so, or that the runs so far are kept.
        const QString note = panel.note()->text();
        QVERIFY2(!note.contains("Running") && (note.contains("cancelled") || note.contains("Stopped by you")),
                 qPrintable(note));
        QVERIFY(panel.runButton()->isEnabled());
    }
};

QTEST_MAIN(TestMpcPanel)
#include "TestMpcPanel.moc"
