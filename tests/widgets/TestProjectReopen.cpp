// Issue #72 item 3: a reopened project shows what was saved. Every tab's results and plots come
// back, for each data set the window had open (a historian export looked at after the plant's
// data left the plant's results empty on reopening), with the edited what-if scenario; a data set
// saved beside the project keeps its name; and closing with unsaved results asks first.
#include "MainWindow.h"
#include "calibration/CalibrationPanel.h"
#include "common/PlotStack.h"
#include "discovery/DiscoverPanel.h"
#include "mpc/MpcPanel.h"
#include "mpc/ScenarioForm.h"
#include "residual/ResidualPanel.h"
#include "workflow/Session.h"

#include "WaitIdle.h"
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTimer>

#include <QtTest>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

using namespace drytwin;
using drytwin::widgets::MainWindow;

namespace {

bool waitIdle(MainWindow& w, int ms = 600000) {
    return widgets::test::waitUntilIdle(w, ms);
}

int curvesWithData(QwtPlot* plot) {
    int n = 0;
    for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
        n += static_cast<QwtPlotCurve*>(item)->dataSize() > 0 ? 1 : 0;
    }
    return n;
}

/// What a user sees of the results on the Calibrate, Residual model, Discover and What-if tabs:
/// table rows and curves drawn, and the texts that name the results.
struct Shown {
    int estimates = 0, lossCurves = 0, fitCurves = 0;
    int metrics = 0, skillCurves = 0;
    int ranking = 0, gains = 0, residualCurves = 0;
    QString evidence;
    int mpcRows = 0, mpcCurves = 0;

    static Shown of(MainWindow& w) {
        Shown s;
        s.estimates = w.calibrationPanel()->estimates()->rowCount();
        s.lossCurves = curvesWithData(w.calibrationPanel()->lossPlot()->plot(0));
        s.fitCurves = curvesWithData(w.calibrationPanel()->fitPlot()->plot(0));
        s.metrics = w.residualPanel()->metrics()->rowCount();
        s.skillCurves = curvesWithData(w.residualPanel()->skill()->plot(0));
        s.ranking = w.discoverPanel()->ranking()->rowCount();
        s.gains = w.discoverPanel()->gains()->rowCount();
        s.residualCurves = curvesWithData(w.discoverPanel()->plots()->plot(0));
        s.evidence = w.discoverPanel()->evidence()->toPlainText();
        s.mpcRows = w.mpcPanel()->table()->rowCount();
        s.mpcCurves = curvesWithData(w.mpcPanel()->plots()->plot(0));
        return s;
    }
    QString describe() const {
        return QStringLiteral("estimates %1, loss curves %2, fit curves %3, metrics %4, skill curves %5, "
                              "ranking %6, gains %7, residual curves %8, what-if rows %9, what-if curves %10")
            .arg(estimates)
            .arg(lossCurves)
            .arg(fitCurves)
            .arg(metrics)
            .arg(skillCurves)
            .arg(ranking)
            .arg(gains)
            .arg(residualCurves)
            .arg(mpcRows)
            .arg(mpcCurves);
    }
};

/// A historian export with tag names and decimal commas, one line stop (two runs).
void writeHistorianExport(const QString& path) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << "Timestamp;HDT_TT101.PV;FEED_WT201.PV;NIR_XIN.PV;HALL_TT301.PV;HALL_MT302.PV;NIR_XOUT.PV;"
           "WIN_TT401.PV\n";
    for (int i = 0; i < 2400; ++i) {
        const bool stopped = i >= 1000 && i < 1300;
        char line[256];
        std::snprintf(line, sizeof line, "2025-06-03 %02d:%02d:%02d;%.2f;%.1f;%.2f;24.1;55.3;%.2f;55.2\n",
                      8 + i / 3600, (i / 60) % 60, i % 60, 170 + 5 * std::sin(i / 300.0),
                      stopped ? 0.0 : 6200.0, 22 + 0.4 * std::sin(i / 500.0), 13 + 0.2 * std::sin(i / 400.0));
        out << line;
    }
}

const char* kHistorianMapping = R"({"time_s": {"header": "Timestamp"}, "T_hot_C": "HDT_TT101.PV",
  "feed_kg_h": "FEED_WT201.PV", "X_in_pct": "NIR_XIN.PV", "T_amb_C": "HALL_TT301.PV",
  "RH_amb_pct": "HALL_MT302.PV", "X_out_pct": "NIR_XOUT.PV", "T_out_C": "WIN_TT401.PV"})";

/// Answers the next modal message box with @p button (and a save dialog, should one come, with
/// @p saveAs); counts what it answered.
class ModalAnswerer : public QObject {
public:
    ModalAnswerer(QMessageBox::StandardButton button, QString saveAs = {})
        : m_button(button), m_saveAs(std::move(saveAs)) {
        connect(&m_timer, &QTimer::timeout, this, [this] {
            QWidget* modal = QApplication::activeModalWidget();
            if (auto* box = qobject_cast<QMessageBox*>(modal)) {
                ++asked;
                text = box->text();
                box->button(m_button)->click();
            } else if (auto* files = qobject_cast<QFileDialog*>(modal)) {
                // Typed into the name field, as a user does (selectFile() lost to the dialog's
                // default name, set once it has opened).
                if (auto* name = files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) {
                    name->setText(m_saveAs);
                }
                static_cast<QDialog*>(files)->accept(); // QFileDialog::accept() is protected
            }
        });
        m_timer.start(100);
    }
    int asked = 0;
    QString text;

private:
    QTimer m_timer;
    QMessageBox::StandardButton m_button;
    QString m_saveAs;
};

} // namespace

class TestProjectReopen : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_plant, m_export, m_mapping;

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        m_plant = m_dir.filePath("plant");
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(7, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 1500;
        g.outFolder = m_plant.toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        QDir().mkpath(m_dir.filePath("historian"));
        m_export = m_dir.filePath("historian/shift.csv");
        writeHistorianExport(m_export);
        m_mapping = m_dir.filePath("historian/mapping.json");
        std::ofstream(m_mapping.toStdString()) << kHistorianMapping;
    }

    // A full run on the plant's data with an edited scenario, then a historian export opened
    // beside it, the project saved in the plant's data folder and reopened in a new window: both
    // data sets keep their names, and switching back to the plant's data shows every tab as it was.
    void everyTabsResultsComeBackForEveryDataSet() {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        w.workbench().setInvalidationPolicy(widgets::AfterInvalidation::KeepStale);
        w.openDataSet(m_plant);
        QVERIFY(waitIdle(w));
        w.calibrationPanel()->setBudget(150);
        w.calibrationPanel()->run();
        w.residualPanel()->setQuick(true);
        w.residualPanel()->train();
        w.workbench().discover();
        QVERIFY(waitIdle(w));
        // The scenario edited in the form, run, then edited again: the project keeps the text as
        // it stands (it reverted to the bundled one on reopening).
        auto* mpc = w.mpcPanel();
        mpc->editor()->setPlainText(R"({"name": "reopen", "length_s": 60, "warmup_s": 150, "seed": 4,
                                        "setpoint_steps": [{"at_s": 10, "to_pct": 12.6}]})");
        mpc->run();
        QVERIFY(waitIdle(w));
        mpc->form()->band()->setValue(0.7);
        const QString scenario = mpc->scenarioText();
        QVERIFY(scenario.contains("0.7"));
        const Shown before = Shown::of(w);
        QVERIFY2(before.estimates > 0 && before.lossCurves > 0 && before.fitCurves == 3 &&
                     before.metrics > 0 && before.skillCurves > 0 && before.ranking > 0 && before.gains > 0 &&
                     before.residualCurves > 0 && before.mpcRows > 0 && before.mpcCurves > 0,
                 qPrintable(before.describe()));

        // The historian export beside it: the tabs show that data set's (none yet).
        w.openDataSet(m_export, m_mapping);
        QVERIFY(waitIdle(w));
        QCOMPARE(w.workbench().dataSets().size(), std::size_t(2));
        QCOMPARE(w.calibrationPanel()->estimates()->rowCount(), 0);
        QVERIFY(!w.unsavedWork().isEmpty());
        // In the plant's data folder: the project names that folder "." (it read back as "plant/",
        // whose name was lost: "(2 batches)").
        const QString project = m_dir.filePath("plant/line.drytwin");
        QString error;
        QVERIFY2(w.saveProject(project, &error), qPrintable(error));
        QVERIFY(waitIdle(w));
        QVERIFY(w.unsavedWork().isEmpty());

        MainWindow reopened;
        reopened.resize(1280, 800);
        reopened.show();
        QVERIFY2(reopened.openProject(project, &error), qPrintable(error));
        QVERIFY(waitIdle(reopened));
        QVERIFY(reopened.unsavedWork().isEmpty()); // nothing new to lose by closing it
        // The export keeps its name in the data-set list (it came back as "(1 batch)").
        QCOMPARE(reopened.workbench().dataSets().size(), std::size_t(2));
        for (int i = 0; i < reopened.dataSetChooser()->count(); ++i) {
            const QString label = reopened.dataSetChooser()->itemText(i);
            QVERIFY2(label.startsWith("plant (2 batches)") || label.startsWith("shift.csv ("),
                     qPrintable(label));
        }
        QCOMPARE(reopened.dataSetChooser()->currentText(), w.dataSetChooser()->currentText());
        QCOMPARE(reopened.mpcPanel()->scenarioText(), scenario);
        QCOMPARE(reopened.mpcPanel()->form()->band()->value(), 0.7);

        // Back to the plant's data: every tab as it was before the export was opened.
        reopened.workbench().switchDataSet(0);
        QVERIFY(waitIdle(reopened));
        w.workbench().switchDataSet(0);
        QVERIFY(waitIdle(w));
        const Shown back = Shown::of(reopened);
        const Shown original = Shown::of(w);
        QVERIFY2(back.estimates == before.estimates && back.lossCurves == before.lossCurves &&
                     back.fitCurves == before.fitCurves && back.metrics == before.metrics &&
                     back.skillCurves == before.skillCurves && back.ranking == before.ranking &&
                     back.gains == before.gains && back.residualCurves == before.residualCurves &&
                     back.mpcRows == before.mpcRows && back.mpcCurves == before.mpcCurves,
                 qPrintable("reopened: " + back.describe() + "\nbefore:   " + before.describe()));
        QCOMPARE(back.evidence, original.evidence);
        QCOMPARE(reopened.calibrationPanel()->estimates()->item(0, 1)->text(),
                 w.calibrationPanel()->estimates()->item(0, 1)->text());
        QCOMPARE(reopened.mpcPanel()->table()->item(0, 1)->text(), w.mpcPanel()->table()->item(0, 1)->text());
        // The scenario is the edited one still, not the bundled one the results' switch could load.
        QCOMPARE(reopened.mpcPanel()->scenarioText(), scenario);
    }

    // Ctrl+Q (File ▸ Quit) and the window's close button ask before unsaved results go: Cancel
    // keeps the window, Save writes the project first, Discard closes; nothing to lose, no question.
    void quittingWithUnsavedResultsAsks() {
        MainWindow fresh;
        fresh.show();
        {
            ModalAnswerer answer(QMessageBox::Cancel);
            QVERIFY(fresh.close()); // nothing done: closes without a question
            QCOMPARE(answer.asked, 0);
        }

        MainWindow w;
        w.show();
        w.openDataSet(m_plant);
        QVERIFY(waitIdle(w));
        w.mpcPanel()->editor()->setPlainText(
            R"({"name": "quit", "length_s": 30, "warmup_s": 150, "seed": 5})");
        w.mpcPanel()->run();
        QVERIFY(waitIdle(w));
        QVERIFY2(w.unsavedWork().contains("the what-if run"), qPrintable(w.unsavedWork().join(", ")));
        {
            ModalAnswerer answer(QMessageBox::Cancel);
            QVERIFY(!w.close()); // the close event is ignored
            QCOMPARE(answer.asked, 1);
            QVERIFY2(answer.text.contains("the what-if run"), qPrintable(answer.text));
            QVERIFY(w.isVisible());
        }
        // Save, with no project yet: the save dialog names the file, then the window closes.
        const QString project = m_dir.filePath("quit/q.drytwin");
        QDir().mkpath(m_dir.filePath("quit"));
        {
            ModalAnswerer answer(QMessageBox::Save, project);
            QVERIFY(w.close());
            QCOMPARE(answer.asked, 1);
        }
        QVERIFY2(QFileInfo::exists(project), qPrintable(QDir(m_dir.filePath("quit")).entryList().join(", ")));
        QVERIFY(QFileInfo::exists(project + ".results.json"));
        QFile saved(project);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        QVERIFY(QJsonDocument::fromJson(saved.readAll())
                    .object()
                    .value("scenario")
                    .toObject()
                    .value("text")
                    .toString()
                    .contains("\"quit\""));

        // Discard: closes without writing anything.
        MainWindow other;
        other.show();
        other.openDataSet(m_plant);
        QVERIFY(waitIdle(other));
        other.mpcPanel()->form()->band()->setValue(0.9); // an edited scenario is work too
        QVERIFY(other.unsavedWork().contains("the edited scenario"));
        {
            ModalAnswerer answer(QMessageBox::Discard);
            QVERIFY(other.close());
            QCOMPARE(answer.asked, 1);
        }
    }
};

QTEST_MAIN(TestProjectReopen)
#include "TestProjectReopen.moc"
