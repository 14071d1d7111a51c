// The workbench driven through its widgets, offscreen: open data, edit a parameter (validated,
// undoable), simulate, calibrate with stop-and-keep-best, train, discover and extend, run a
// scenario, save and reopen a project; and what the plots and tables show after each.
#include "MainWindow.h"
#include "calibration/CalibrationPanel.h"
#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "data/ColumnMappingDialog.h"
#include "data/DataPanel.h"
#include "diagnostics/DiagnosticsPanel.h"
#include "discovery/DiscoverPanel.h"
#include "model/ModelPanel.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "view3d/LineView3D.h"
#include "workflow/Session.h"

#include <QLabel>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTranslator>
#include <QUndoStack>
#include <QtTest>
#include <fstream>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

using namespace drytwin;
using drytwin::widgets::MainWindow;

namespace {

void writeText(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

const char* kGood =
    "time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,X_out_pct,T_out_C\n"
    "0,170,6000,22,20,50,12.5,55\n1,171,6000,22,20,50,12.6,55.1\n2,171,6000,22,20,50,12.7,55.3\n";

/// Waits until the window's engine queue is empty (every queued action and its follow-ups done).
bool waitIdle(MainWindow& w, int ms = 120000) {
    QElapsedTimer t;
    t.start();
    int idle = 0;
    while (t.elapsed() < ms) {
        QTest::qWait(50);
        idle = w.jobs().busy() ? 0 : idle + 1;
        if (idle >= 4) {
            return true;
        }
    }
    return false;
}

int curvesWithData(QwtPlot* plot) {
    int n = 0;
    for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
        n += static_cast<QwtPlotCurve*>(item)->dataSize() > 0 ? 1 : 0;
    }
    return n;
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_data;

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_data = m_dir.filePath("plant");
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(7, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 1500;
        g.outFolder = m_data.toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
    }

    void findingsWordGroupsOnsetsAndPartsInBothLanguages() {
        // A finding of a look-alike group with an onset and per-batch estimates, as discovery
        // reports it: the Discover tab words all of it, in English and in Chinese.
        discovery::Finding f;
        f.cause = "moisture_meter_offset";
        f.parameter = properties::Param::X_meter_offset;
        f.value = 0.5;
        f.output = "X_out";
        f.perPart = {{"B01", 0.48, 0.03}, {"B02", 0.52, 0.04}, {"B03", 0.50, 0.03}};
        f.transferChecked = true;
        f.transferReduction = 0.4;
        f.hasOnset = true;
        f.onsetS = 1200;
        f.onsetLowS = 1080;
        f.onsetHighS = 1320;
        f.group = "moisture_offset";
        f.lookAlikes.push_back(
            {"inlet_moisture_sensor_offset", properties::Param::X_in_offset, 0.9, 1.01, 0.4, false});
        const QString english = widgets::DiscoverPanel::specificityText(f);
        for (const char* part : {"between 0.48 and 0.52", "consistent", "starts 20 min into the batch",
                                 "inlet moisture gauge offset fits these data about as well",
                                 "To tell them apart", "oven-dry"}) {
            QVERIFY2(english.contains(QLatin1String(part)), qPrintable(english));
        }
        QTranslator chinese;
        QVERIFY(chinese.load(QStringLiteral("drytwin_zh_CN"), QStringLiteral(DRYTWIN_QM_DIR)));
        QCoreApplication::installTranslator(&chinese);
        const QString translated = widgets::DiscoverPanel::specificityText(f);
        QCoreApplication::removeTranslator(&chinese);
        for (const char* part : {"逐段拟合", "一致", "min 出现", "数据无法区分二者", "区分方法", "烘箱法"}) {
            QVERIFY2(translated.contains(QString::fromUtf8(part)), qPrintable(translated));
        }
        // No English sentence left beside the cause names and units.
        QVERIFY2(!translated.contains(QLatin1String("tell them apart")) &&
                     !translated.contains(QLatin1String("Fitted")),
                 qPrintable(translated));
    }

    void hasMenusTabsAndAbout() {
        MainWindow w;
        QStringList menus;
        for (auto* a : w.menuBar()->actions()) {
            menus << a->text();
        }
        QVERIFY(menus.contains("&File") && menus.contains("&View") && menus.contains("&Help"));
        QCOMPARE(w.tabs()->count(), 9);
        QCOMPARE(w.tabs()->tabText(8), QStringLiteral("Training"));
        const QString about = MainWindow::aboutText();
        for (const char* lib : {"Qt", "Qwt", "VTK", "SUNDIALS", "NLopt", "Ipopt", "Eigen"}) {
            QVERIFY2(about.contains(lib), lib);
        }
    }

    void rejectedFileKeepsWhatWasLoaded() {
        QTemporaryDir dir;
        writeText(dir.filePath("good.csv"), kGood);
        writeText(dir.filePath("bad.csv"), "time_s;T_hot_C\n0;1\n");
        MainWindow w;
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        w.openDataSet(dir.filePath("good.csv"));
        QVERIFY(loaded.wait(10000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), true);
        QVERIFY(waitIdle(w));
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1));
        QCOMPARE(w.dataPanel()->batchTable()->rowCount(), 1);
        // The physics model's predictions are drawn on the Model tab (three rows of one batch).
        bool modelDrawn = false;
        for (auto* item : w.modelPanel()->plots()->plot(0)->itemList(QwtPlotItem::Rtti_PlotCurve)) {
            auto* c = static_cast<QwtPlotCurve*>(item);
            modelDrawn = modelDrawn || (c->title().text().contains("model") && c->dataSize() == 3);
        }
        QVERIFY(modelDrawn);
        w.openDataSet(dir.filePath("bad.csv"));
        QVERIFY(loaded.wait(10000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), false);
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1)); // nothing lost
        QCOMPARE(w.dataPanel()->batchTable()->rowCount(), 1);
        QVERIFY(w.statusBar()->findChild<QLabel*>()->text().contains("bad.csv"));
    }

    void foreignColumnNamesAreMappedAndLoaded() {
        QTemporaryDir dir;
        writeText(dir.filePath("plant.csv"),
                  "Zeit,Heissluft,Durchsatz,Feuchte_ein,Umgebung,RF,Feuchte_aus,Temp_aus\n"
                  "0,338,6000,22,20,50,12.5,55\n1,339.8,6000,22,20,50,12.6,55.1\n2,339.8,6000,22,20,50,12.7,"
                  "55.3\n");
        widgets::ColumnMappingDialog dialog(dir.filePath("plant.csv"));
        QCOMPARE(dialog.headers().size(), 8);
        const QStringList contract{"time_s",  "T_hot_C",    "feed_kg_h", "X_in_pct",
                                   "T_amb_C", "RH_amb_pct", "X_out_pct", "T_out_C"};
        for (int i = 0; i < contract.size(); ++i) {
            QVERIFY2(dialog.choose(contract[i], dialog.headers()[i]), qPrintable(contract[i]));
        }
        QVERIFY(!dialog.choose("no_such_column", "Zeit"));
        QVERIFY(dialog.chooseUnit("T_hot_C", "degF")); // this plant logs the hot air in °F
        QVERIFY(!dialog.chooseUnit("T_hot_C", "kg/h"));
        const QString mapping = dir.filePath("mapping.json");
        QVERIFY(dialog.save(mapping));
        MainWindow w;
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        w.workbench().openData(dir.filePath("plant.csv"), mapping);
        QVERIFY(loaded.wait(10000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), true);
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1));
        QVERIFY(w.dataPanel()->cleaningSummary()->text().contains("3 of 3 rows kept"));
        // 338 °F is 170 °C.
        QVERIFY(std::abs((*w.dataSet().batches[0].values(data::Column::THot))[0] - 170.0) < 1e-9);
        // Without the mapping the same file is rejected, naming a missing column.
        w.workbench().openData(dir.filePath("plant.csv"));
        QVERIFY(loaded.wait(10000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), false);
        QCOMPARE(w.dataSet().batches.size(), std::size_t(1));
    }

    // A historian export with tag names: the dialog proposes the mapping from the tags and the
    // values' ranges, previews the runs the file gives, and the saved mapping loads them.
    void historianExportIsGuessedPreviewedAndLoaded() {
        QTemporaryDir dir;
        std::string text = "Timestamp;HDT_TT101.PV;FEED_WT201.PV;NIR_XIN.PV;HALL_TT301.PV;HALL_MT302.PV;"
                           "NIR_XOUT.PV;WIN_TT401.PV;STATUS\n";
        for (int i = 0; i < 2400; ++i) {
            const bool stopped = i >= 1000 && i < 1300;
            char line[256];
            std::snprintf(
                line, sizeof line, "2025-06-03 %02d:%02d:%02d;%.2f;%.1f;%.2f;24,1;55,3;%.2f;55,2;%s\n",
                8 + i / 3600, (i / 60) % 60, i % 60, 170 + 5 * std::sin(i / 300.0), stopped ? 0.0 : 6200.0,
                22 + 0.4 * std::sin(i / 500.0), 13 + 0.2 * std::sin(i / 400.0), stopped ? "STOP" : "RUN");
            std::string l(line);
            // Decimal commas everywhere, as a German or Chinese Excel writes them.
            for (std::size_t k = l.find('.'); k != std::string::npos; k = l.find('.', k)) {
                if (l.compare(k, 3, ".PV") != 0) {
                    l[k] = ',';
                }
                ++k;
            }
            text += l;
        }
        writeText(dir.filePath("shift.csv"), text);
        widgets::ColumnMappingDialog dialog(dir.filePath("shift.csv"));
        QCOMPARE(dialog.headers().size(), 9);
        QCOMPARE(dialog.chosen("T_hot_C"), QString("HDT_TT101.PV"));
        QCOMPARE(dialog.chosen("feed_kg_h"), QString("FEED_WT201.PV"));
        QCOMPARE(dialog.chosen("X_in_pct"), QString("NIR_XIN.PV"));
        QCOMPARE(dialog.chosen("T_amb_C"), QString("HALL_TT301.PV"));
        QCOMPARE(dialog.chosen("RH_amb_pct"), QString("HALL_MT302.PV"));
        QCOMPARE(dialog.chosen("X_out_pct"), QString("NIR_XOUT.PV"));
        QCOMPARE(dialog.chosen("T_out_C"), QString("WIN_TT401.PV"));
        QCOMPARE(dialog.chosen("time_s"), QString("Timestamp"));
        QCOMPARE(dialog.chosen("T_hot_sp_C"), QString()); // nothing in the file looks like it
        // The preview: the line stop cuts the shift into two runs.
        QCOMPARE(dialog.previewTable()->rowCount(), 2);
        QCOMPARE(dialog.previewTable()->item(0, 3)->text(), QString("1000"));
        QCOMPARE(dialog.previewTable()->item(0, 5)->text(), QString("line stop"));
        QCOMPARE(dialog.previewTable()->item(1, 1)->text(), QString("2025-06-03T08:21:40"));
        if (qEnvironmentVariableIsSet("DRYTWIN_SCREENSHOT_DIR")) { // scripts/screenshots.sh, under Xvfb
            dialog.show();
            QTest::qWait(200);
            dialog.grab().save(qEnvironmentVariable("DRYTWIN_SCREENSHOT_DIR") + "/column-mapping.png");
        }
        const QString mapping = dir.filePath("mapping.json");
        QVERIFY(dialog.save(mapping));
        MainWindow w;
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        w.workbench().openData(dir.filePath("shift.csv"), mapping);
        QVERIFY(loaded.wait(10000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), true);
        QCOMPARE(w.dataSet().batches.size(), std::size_t(2));
        QCOMPARE(w.dataSet().batches[1].rows(), std::size_t(1100));
        // Where each run came from shows on the Data tab.
        QCOMPARE(w.dataPanel()->batchTable()->rowCount(), 2);
        bool shown = false;
        for (int c = 0; c < w.dataPanel()->batchTable()->columnCount(); ++c) {
            const auto* item = w.dataPanel()->batchTable()->item(1, c);
            shown = shown || (item && item->text().contains("1302"));
        }
        QVERIFY2(shown, "the run's first file line is not on the Data tab");
        if (qEnvironmentVariableIsSet("DRYTWIN_SCREENSHOT_DIR")) {
            w.resize(1280, 800);
            w.show();
            QTest::qWait(300);
            w.grab().save(qEnvironmentVariable("DRYTWIN_SCREENSHOT_DIR") + "/data-runs.png");
        }
    }

    void mainFlowsThroughTheWidgets() {
        MainWindow w;
        w.show();
        w.openDataSet(m_data);
        QVERIFY(waitIdle(w));
        // Data: both batches listed, every column plotted for the selected one.
        QCOMPARE(w.dataPanel()->batchTable()->rowCount(), 2);
        auto* dataPlots = w.dataPanel()->plots();
        QCOMPARE(dataPlots->plotCount(), 8);
        for (int i = 0; i < dataPlots->plotCount(); ++i) {
            QCOMPARE(dataPlots->curveCount(i), 1);
        }
        w.dataPanel()->selectBatches({0, 1});
        QCOMPARE(dataPlots->curveCount(6), 2); // overlaid
        // Measuring cursors: the readout gives the difference between them.
        dataPlots->setMeasuringCursor(0, 100);
        dataPlots->setMeasuringCursor(1, 400);
        QVERIFY(dataPlots->readout().contains(QStringLiteral("Δx 300")));
        // Export of the whole stack in the three formats.
        for (const char* ext : {"png", "svg", "pdf"}) {
            const QString file = m_dir.filePath(QStringLiteral("plots.%1").arg(ext));
            QVERIFY2(dataPlots->exportTo(file), ext);
            QVERIFY(QFileInfo(file).size() > 1000);
        }

        // Model: an out-of-bounds value is refused, a valid one is set and can be undone.
        auto* model = w.modelPanel();
        int hRow = -1;
        for (int r = 0; r < model->parameterTable()->rowCount(); ++r) {
            if (model->parameterTable()->item(r, 0)->text() == "h_HDT") {
                hRow = r;
            }
        }
        QVERIFY(hRow >= 0);
        const double hBefore = w.workbench().model().parameters[properties::Param::h_HDT];
        QVERIFY(!model->editParameter(hRow, 1e6));
        QVERIFY(model->editParameter(hRow, 80.0));
        QVERIFY(waitIdle(w));
        QCOMPARE(w.workbench().model().parameters[properties::Param::h_HDT], 80.0);
        QCOMPARE(model->parameterTable()->item(hRow, 1)->text(), QString("80"));
        model->undoStack()->undo();
        QVERIFY(waitIdle(w));
        QCOMPARE(w.workbench().model().parameters[properties::Param::h_HDT], hBefore);
        // Simulate: measured and model curves in the four output plots.
        QSignalSpy simulated(&w.workbench(), &widgets::Workbench::simulated);
        w.workbench().simulate();
        QVERIFY(simulated.count() > 0 || simulated.wait(30000));
        QVERIFY(curvesWithData(model->plots()->plot(0)) >= 2);
        // The physics model's error against an operating variable, on the Diagnostics tab.
        QVERIFY(curvesWithData(w.diagnosticsPanel()->scatter()->plot(0)) == 1);

        // Calibrate, stopped early with the best so far.
        auto* cal = w.calibrationPanel();
        cal->setBudget(400);
        QSignalSpy calibrated(&w.workbench(), &widgets::Workbench::calibrated);
        QTest::mouseClick(cal->runButton(), Qt::LeftButton);
        QVERIFY(cal->stopButton()->isEnabled());
        QTest::qWait(1500);
        QTest::mouseClick(cal->stopButton(), Qt::LeftButton);
        QVERIFY(calibrated.count() > 0 || calibrated.wait(60000));
        QVERIFY(waitIdle(w));
        QCOMPARE(cal->estimates()->rowCount(), 3); // h_HDT, k_HDT, phi_X_in_scatter with intervals
        QVERIFY(cal->estimates()->item(0, 2)->text().startsWith("["));
        QVERIFY(w.workbench().model().calibration.has_value());
        QVERIFY(curvesWithData(cal->lossPlot()->plot(0)) >= 1);
        QVERIFY(curvesWithData(cal->fitPlot()->plot(0)) == 3); // measured, before, after

        // Train (a quick setting), then the metrics, eigenvalues and skill curve are shown.
        w.residualPanel()->setQuick(true);
        w.residualPanel()->train();
        QVERIFY(waitIdle(w, 180000));
        QVERIFY(w.workbench().model().pgrlCc != nullptr);
        QVERIFY(w.residualPanel()->metrics()->rowCount() >= 4);
        QVERIFY(curvesWithData(w.residualPanel()->eigenvalues()->plot(0)) >= 2);
        QVERIFY(curvesWithData(w.residualPanel()->skill()->plot(0)) >= 4);

        // Discover, then extend the model in one click.
        auto* disc = w.discoverPanel();
        w.workbench().discover();
        QVERIFY(waitIdle(w, 240000));
        QVERIFY(w.workbench().latest().discover.has_value());
        QVERIFY(disc->ranking()->rowCount() == 10); // the inlet scatter share is fitted with h_HDT, k_HDT
        // The verdict in an engineer's words, with the data set it belongs to; the key in the tooltip.
        const QString verdict = disc->verdict()->text();
        QVERIFY2((verdict.startsWith("Cause found") || verdict.startsWith("No cause found") ||
                  verdict.startsWith("Something is left")) &&
                     verdict.contains("plant (2 batches)"),
                 qPrintable(verdict));
        QVERIFY(disc->verdict()->toolTip().contains(
            QString::fromStdString(w.workbench().latest().discover->discovery.verdict)));
        // Each finding's evidence is worded by the panel from the finding's numbers (translatable).
        for (const auto& f : w.workbench().latest().discover->discovery.findings) {
            const QString sentence = widgets::DiscoverPanel::evidenceText(f);
            QVERIFY2(sentence.contains(widgets::causeDisplayName(f.cause)) &&
                         sentence.contains("held-out MAE") &&
                         !sentence.contains(QRegularExpression("%[0-9]")),
                     qPrintable(sentence));
            QVERIFY(disc->evidence()->toPlainText().contains(sentence.left(40)));
        }
        // Every round's decision is shown, so the engineer sees why the selection stopped there.
        const QString evidence = disc->evidence()->toPlainText();
        for (std::size_t i = 0; i < w.workbench().latest().discover->discovery.rounds.size(); ++i) {
            QVERIFY2(evidence.contains(QStringLiteral("Round %1:").arg(i + 1)), qPrintable(evidence));
        }
        QVERIFY(curvesWithData(w.diagnosticsPanel()->crossCorrelation()->plot(0)) >= 1);
        if (disc->extendButton()->isEnabled()) {
            const auto k =
                w.workbench().latest().discover->extendedModel.parameters[properties::Param::k_HDT];
            QTest::mouseClick(disc->extendButton(), Qt::LeftButton);
            QVERIFY(waitIdle(w));
            QCOMPARE(w.workbench().model().parameters[properties::Param::k_HDT], k);
        }

        // A short what-if scenario typed into the editor, two controllers.
        auto* mpc = w.mpcPanel();
        mpc->editor()->setPlainText(R"({"name": "gui", "length_s": 60, "warmup_s": 150, "seed": 4,
                                        "setpoint_steps": [{"at_s": 10, "to_pct": 12.6}]})");
        mpc->run();
        QVERIFY(waitIdle(w, 120000));
        QVERIFY(w.workbench().latest().mpc.has_value());
        QCOMPARE(mpc->table()->rowCount(), 5);
        QVERIFY(curvesWithData(mpc->plots()->plot(0)) >= 3);
        // A wrong scenario names its line and changes nothing.
        mpc->editor()->setPlainText("{\n \"name\": \"x\",\n \"band_pct\": -4\n}");
        mpc->run();
        QVERIFY(waitIdle(w));
        QVERIFY(w.statusBar()->findChild<QLabel*>()->text().contains(":3:"));
        QVERIFY(w.workbench().latest().mpc.has_value());

        // The 3D line: parcels drawn, the slider moves the shared time cursor.
        w.tabs()->setCurrentWidget(w.lineView());
        QTest::qWait(200);
        w.lineView()->slider()->setValue(300);
        QVERIFY(w.lineView()->parcelCount() > 50);
        QCOMPARE(w.dataPanel()->plots()->timeCursor(), 300.0);
        const auto range = w.lineView()->colourRange();
        QVERIFY(range.first < range.second);

        // Save the project and open it in a new window: data, model and tab come back.
        const QString project = m_dir.filePath("p.drytwin");
        w.tabs()->setCurrentIndex(6);
        QString error;
        QVERIFY2(w.saveProject(project, &error), qPrintable(error));
        QVERIFY(waitIdle(w));
        const double kSaved = w.workbench().model().parameters[properties::Param::k_HDT];
        MainWindow reopened;
        QSignalSpy ready(&reopened, &MainWindow::projectReady);
        QVERIFY(reopened.openProject(project, &error));
        QVERIFY(waitIdle(reopened));
        QCOMPARE(reopened.dataPanel()->batchTable()->rowCount(), 2);
        QCOMPARE(reopened.workbench().model().parameters[properties::Param::k_HDT], kSaved);
        QVERIFY(reopened.workbench().model().pgrlCc != nullptr);
        QCOMPARE(reopened.tabs()->currentIndex(), 6);
        QVERIFY(!reopened.openProject(m_dir.filePath("plant/B01.csv"), &error)); // not a project
        QVERIFY(error.contains("not a DryTwin project"));
    }

    void generatedPlantDataIsOpened() {
        QTemporaryDir dir;
        MainWindow w;
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(3, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 1200;
        g.outFolder = dir.filePath("gen").toStdString();
        w.workbench().generate(g);
        QVERIFY(loaded.wait(30000));
        QCOMPARE(loaded.takeFirst().at(0).toBool(), true);
        QCOMPARE(w.dataPanel()->batchTable()->rowCount(), 2);
        QCOMPARE(w.workbench().dataPath(), dir.filePath("gen"));
    }

    void closingMidRunCancelsCleanly() {
        auto* w = new MainWindow;
        w->openDataSet(m_data);
        QVERIFY(waitIdle(*w));
        w->residualPanel()->train(); // long: the full setting
        QTest::qWait(300);
        QVERIFY(w->jobs().busy());
        QElapsedTimer t;
        t.start();
        w->close();
        delete w; // cancels and joins the engine thread
        QVERIFY(t.elapsed() < 30000);
    }
};

QTEST_MAIN(TestMainWindow)
#include "TestMainWindow.moc"
