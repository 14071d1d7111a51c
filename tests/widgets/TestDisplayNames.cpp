// What the workbench calls things (issue #43, items 13, 14 and 16): one name per cause on every
// tab; a plain line beside every statistic or method named on screen; no English left in the
// Chinese window where the engine's English texts, keys or a cached list used to show through.
#include "MainWindow.h"
#include "calibration/CalibrationPanel.h"
#include "common/DisplayNames.h"
#include "common/ErrorText.h"
#include "common/PlotStack.h"
#include "common/Series.h"
#include "common/Translations.h"
#include "common/Workbench.h"
#include "data/ColumnMappingDialog.h"
#include "data/DataPanel.h"
#include "discovery/DiscoverPanel.h"
#include "model/ParameterTexts.h"
#include "mpc/MpcPanel.h"
#include "mpc/ScenarioForm.h"
#include "plant/Mechanisms.h"
#include "residual/ResidualPanel.h"
#include "training/TrainingPanel.h"
#include "view3d/LineView3D.h"

#include <QComboBox>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

using namespace drytwin;
using namespace drytwin::widgets;

namespace {

QString headerTip(const QTableWidget* t, int c) {
    return t->horizontalHeaderItem(c) ? t->horizontalHeaderItem(c)->toolTip() : QString();
}

/// English words left in a text of the Chinese window: words of three or more letters, less the
/// symbols, units and proper names that stay as they are in Chinese too.
QStringList englishWords(const QString& text) {
    static const QStringList kept{"PGRL",  "LSTM", "MPC",     "PCA",     "SPE",     "ACF",    "CCF",   "PSD",
                                  "MAE",   "IAE",  "NLopt",   "BOBYQA",  "Holm",    "Fisher", "Ljung", "Box",
                                  "Newey", "West", "Diebold", "Mariano", "DryTwin", "JSON",   "CSV",   "PNG",
                                  "SVG",   "PDF",  "ISO",     "Unix",    "min",     "max",    "HDT",   "Conv",
                                  "wb",    "RH",   "ms",      "kg",      "Hz",      "CRS2",   "LM",    "CI"};
    static const QRegularExpression word(QStringLiteral("(?<![A-Za-z0-9_])[A-Za-z]{3,}(?![A-Za-z0-9_])"));
    QStringList found;
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const QString w = it.next().captured(0);
        if (!kept.contains(w)) {
            found << w;
        }
    }
    return found;
}

void writeText(const QString& path, const std::string& text) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text.c_str());
}

} // namespace

class TestDisplayNames : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void cleanup() { setLanguage("en"); }

    // Item 15: every verdict ends in what to do next, in plant words, in both languages.
    void everyVerdictSaysWhatToDoNext() {
        const std::vector<std::string> verdicts{"cause_found", "no_structural_cause",
                                                "unexplained_structure"};
        QStringList english;
        for (const auto& v : verdicts) {
            const QString next = verdictNextStep(v);
            QVERIFY2(next.startsWith(QStringLiteral("Next: ")), qPrintable(QString::fromStdString(v)));
            QVERIFY2(!next.contains(QLatin1Char('_')), qPrintable(next)); // no internal keys
            QVERIFY(!english.contains(next));
            english << next;
        }
        QVERIFY(verdictNextStep("no_such_verdict").isEmpty());
        // A cause that fits but failed a check: the reference period is the way on, not "nothing".
        const QString failedACheck = verdictNextStep("no_structural_cause", true);
        QVERIFY2(failedACheck.startsWith(QStringLiteral("Next: ")) &&
                     failedACheck.contains("reference period") && !english.contains(failedACheck),
                 qPrintable(failedACheck));
        setLanguage("zh_CN");
        QVERIFY(verdictNextStep("no_structural_cause", true) != failedACheck);
        QVERIFY2(englishWords(verdictNextStep("no_structural_cause", true)).isEmpty(),
                 qPrintable(verdictNextStep("no_structural_cause", true)));
        for (std::size_t i = 0; i < verdicts.size(); ++i) {
            const QString next = verdictNextStep(verdicts[i]);
            QVERIFY(next != english[static_cast<int>(i)]);
            QVERIFY2(englishWords(next).isEmpty(), qPrintable(englishWords(next).join(' ')));
        }
        // Discovery's channel names read as plant words too.
        setLanguage("en");
        QCOMPARE(columnDisplayName("X_out"), QStringLiteral("outlet moisture"));
        QCOMPARE(columnDisplayName("T_hdt"), QStringLiteral("tube-outlet temperature"));
    }

    // Item 14: a cause has one name, on Discover, Training, the scenario form and the model table.
    void oneNamePerCauseOnEveryTab() {
        Workbench wb;
        TrainingPanel training(wb);
        MpcPanel mpc(wb);
        mpc.form()->addMechanism("moisture_meter_lag", 10, 0);
        auto* scenarioCombo = qobject_cast<QComboBox*>(
            mpc.form()->mechanisms()->cellWidget(mpc.form()->mechanisms()->rowCount() - 1, 0));
        QVERIFY(scenarioCombo);
        for (const auto& mi : plant::mechanisms()) {
            const std::string key(mi.name);
            const QString name = causeDisplayName(key);
            QVERIFY2(name != QString::fromStdString(key), key.c_str()); // a name, not the key
            // Discover words its findings with it ...
            discovery::Finding f;
            f.cause = key;
            f.parameter = properties::Param::tau_meter;
            f.output = "X_out";
            QVERIFY2(DiscoverPanel::evidenceText(f).contains(name), key.c_str());
            // ... Training's fault list and the trainee's answer list use the same ...
            const int fault = training.faultKind()->findData(int(mi.id));
            QVERIFY(fault >= 0);
            QCOMPARE(training.faultKind()->itemText(fault), name);
            const int answer = training.cause()->findData(QString::fromStdString(key));
            QVERIFY(answer >= 0);
            QCOMPARE(training.cause()->itemText(answer), name);
            // ... and so does the what-if scenario's list of hidden causes.
            QCOMPARE(scenarioCombo->itemText(scenarioCombo->findData(QString::fromStdString(key))), name);
        }
        QCOMPARE(causeDisplayName("moisture_meter_lag"), QString("slow outlet moisture meter"));
        // A parameter discovery added names its cause the same way.
        for (const auto& info : properties::parameterTable()) {
            const std::string source(info.source);
            if (source.rfind("extension ", 0) == 0) {
                QVERIFY2(parameterSource(info).contains(causeDisplayName(source.substr(10))), source.c_str());
            }
        }
    }

    // Item 16: every statistic and method named on screen has a plain line beside it or a tooltip.
    void jargonHasPlainWords() {
        Workbench wb;
        DiscoverPanel discover(wb);
        for (int c : {1, 2}) { // Score z, p (Holm)
            QVERIFY2(headerTip(discover.ranking(), c).size() > 40, qPrintable(QString::number(c)));
        }
        QVERIFY(headerTip(discover.ranking(), 2).contains("chance"));
        MpcPanel mpc(wb);
        QVERIFY(headerTip(mpc.table(), 1).contains("setpoint")); // IAE [%·s]
        QVERIFY(headerTip(mpc.table(), 2).contains("hot-air"));  // Effort [K²]
        CalibrationPanel calibration(wb);
        QVERIFY(headerTip(calibration.estimates(), 4).contains("standard error")); // Fisher SE
        QVERIFY(headerTip(calibration.estimates(), 5).contains("edge"));           // At bound
        // The method in plain words on screen, its name in the tooltip (issue #72 item 10).
        bool bobyqaExplained = false;
        for (auto* label : calibration.findChildren<QLabel*>()) {
            bobyqaExplained =
                bobyqaExplained || (label->text().contains("no derivatives") &&
                                    !label->text().contains("BOBYQA") && label->toolTip().contains("BOBYQA"));
        }
        QVERIFY(bobyqaExplained);
        ResidualPanel residual(wb);
        for (int c = 1; c < residual.metrics()->columnCount(); ++c) {
            QVERIFY2(!headerTip(residual.metrics(), c).isEmpty(), qPrintable(QString::number(c)));
        }
        discovery::Finding f;
        f.cause = "heat_transfer_fouling";
        f.parameter = properties::Param::theta_foul;
        f.output = "X_out";
        QVERIFY(DiscoverPanel::evidenceText(f).contains("the chance that a gain this large is luck"));
        QVERIFY(intervalMethodText("sandwich (Newey-West)").contains("not independent"));
        // A what-if run's progress names the model, not its key.
        const QString progress = progressDetailText("mpc", "pgrl_cc, step 600/1300");
        QCOMPARE(progress, QString("Physics + learnt correction (PGRL-CC): second 600 of 1300"));
        QCOMPARE(progressDetailText("load", "B01.csv"), QString("B01.csv"));
    }

    // Item 13: the texts that came from the engine's English, a key or a list cached in the
    // language the program started in, in the Chinese window.
    void noEnglishLeftInTheChineseWindow() {
        // A list built before the language changes must not keep its English.
        QCOMPARE(batchSeriesTitleFeed(), QString("feed [kg/h]"));
        QVERIFY(setLanguage("zh_CN"));
        QCOMPARE(batchSeriesTitleFeed(), QString::fromUtf8("进料 [kg/h]"));
        Workbench wb;
        DataPanel data(wb);
        QCOMPARE(data.plots()->yTitle(4), QString::fromUtf8("进料 [kg/h]"));

        // An engine reason with no code of its own, as a data file's shape or an empty folder gives
        // it, in Chinese with its numbers (the review's window showed them in English).
        const QString fields =
            errorText(Error{ErrorKind::BadInput,
                            "B02.csv:7:9",
                            "expected 13 fields as in the header, found 8",
                            ErrorCode::DataFileFormat,
                            {"B02.csv", "7", "9", "expected 13 fields as in the header, found 8"}});
        QVERIFY2(!fields.contains(QLatin1String("expected")) && fields.contains(QLatin1String("13")) &&
                     fields.contains(QLatin1String("8")),
                 qPrintable(fields));
        const QString empty =
            errorText(Error{ErrorKind::BadInput, "/data/empty", "the folder holds no *.csv batch files"});
        QVERIFY2(!empty.contains(QLatin1String("holds no")) &&
                     empty.startsWith(QLatin1String("/data/empty: ")),
                 qPrintable(empty));

        // The stale-model reason: a key, worded when shown (a project saved in English reads back).
        LearntPart part;
        part.kind = control::ControllerKind::PgrlCc;
        part.state = PartState::Stale;
        part.staleBecause = QString::fromLatin1(staleReason::kExtended);
        wb.restoreLearntParts({part, LearntPart::absent(control::ControllerKind::ExtInputResidual),
                               LearntPart::absent(control::ControllerKind::Lstm)});
        const QString state = wb.modelStateText();
        QVERIFY2(!state.contains("extended by discovery") && state.contains(QString::fromUtf8("发现功能")),
                 qPrintable(state));

        // What a part was learnt on, saved in English ("demo (4 batches)"), reads back in Chinese.
        LearntPart learnt;
        learnt.learntOn = QStringLiteral("demo (4 batches)");
        learnt.learntOnName = QStringLiteral("demo");
        learnt.learntOnBatches = 4;
        QCOMPARE(learnt.learntOnText(), QString::fromUtf8("demo（4 个批次）"));

        // The column-mapping dialog: why each header was proposed, what each column means, the
        // time stamps' format, why each run ended.
        QTemporaryDir dir;
        std::string text = "Timestamp;HDT_TT101.PV;FEED_WT201.PV;NIR_XIN.PV;HALL_TT301.PV;HALL_MT302.PV;"
                           "NIR_XOUT.PV;WIN_TT401.PV\n";
        for (int i = 0; i < 1500; ++i) {
            const bool stopped = i >= 600 && i < 900;
            char line[256];
            std::snprintf(line, sizeof line, "2025-06-03T%02d:%02d:%02d;%.1f;%.0f;%.1f;24.1;55.3;%.2f;55.2\n",
                          8 + i / 3600, (i / 60) % 60, i % 60, 170 + 5 * std::sin(i / 300.0),
                          stopped ? 0.0 : 6200.0, 22 + 0.4 * std::sin(i / 500.0),
                          13 + 0.2 * std::sin(i / 400.0));
            text += line;
        }
        writeText(dir.filePath("shift.csv"), text);
        ColumnMappingDialog dialog(dir.filePath("shift.csv"));
        QTableWidget* table = dialog.mappingTable();
        int reasons = 0;
        for (int r = 0; r < table->rowCount(); ++r) {
            for (int c : {4, 5}) {
                const QString cell = table->item(r, c) ? table->item(r, c)->text() : QString();
                reasons += c == 4 && !cell.isEmpty() ? 1 : 0;
                QVERIFY2(englishWords(cell).isEmpty(),
                         qPrintable(QStringLiteral("row %1 column %2: %3").arg(r).arg(c).arg(cell)));
            }
        }
        QVERIFY(reasons >= 7);
        QVERIFY(dialog.previewTable()->rowCount() >= 2);
        for (int r = 0; r < dialog.previewTable()->rowCount(); ++r) {
            const QString ended = dialog.previewTable()->item(r, 5)->text();
            QVERIFY2(englishWords(ended).isEmpty(), qPrintable(ended));
        }
        for (auto* label : dialog.findChildren<QLabel*>()) {
            QVERIFY2(!label->text().contains("iso8601"), qPrintable(label->text()));
        }
        QVERIFY(englishWords(mappingReasonText("time stamps: iso8601")).isEmpty());
        QVERIFY(englishWords(runEndText("end of file")).isEmpty());

        // The 3D view's colour bar and the correlates' legends.
        LineView3D view(wb);
        QVERIFY2(view.colourBarTitle().contains(QString::fromUtf8("含水率")),
                 qPrintable(view.colourBarTitle()));
        for (const char* proxy : {"proxy_X_HDT", "proxy_T_HDT", "proxy_X_Conv", "proxy_T_Conv"}) {
            QVERIFY2(!columnDisplayName(proxy).contains("proxy"), proxy);
            QVERIFY2(englishWords(columnDisplayName(proxy)).isEmpty(), qPrintable(columnDisplayName(proxy)));
        }
    }

    // Item 13: the whole Chinese window, with data: no table header, axis title or legend in English.
    void chineseWindowHeadersTitlesAndLegends() {
        QTemporaryDir dir;
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(5, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 900;
        g.outFolder = dir.filePath("plant").toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        QVERIFY(setLanguage("zh_CN"));
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        w.openDataSet(dir.filePath("plant"));
        QVERIFY(loaded.wait(30000));
        QTRY_VERIFY_WITH_TIMEOUT(!w.jobs().busy(), 60000);
        QStringList english;
        for (auto* table : w.findChildren<QTableWidget*>()) {
            for (int c = 0; c < table->columnCount(); ++c) {
                if (const auto* item = table->horizontalHeaderItem(c);
                    item && !englishWords(item->text()).isEmpty()) {
                    english << QStringLiteral("header '%1'").arg(item->text());
                }
            }
        }
        for (auto* plot : w.findChildren<QwtPlot*>()) {
            for (int axis : {int(QwtPlot::yLeft), int(QwtPlot::xBottom)}) {
                const QString title = plot->axisTitle(axis).text();
                if (!englishWords(title).isEmpty()) {
                    english << QStringLiteral("axis '%1'").arg(title);
                }
            }
            for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
                const QString name = item->title().text();
                if (item->testItemAttribute(QwtPlotItem::Legend) && !englishWords(name).isEmpty()) {
                    english << QStringLiteral("legend '%1'").arg(name);
                }
            }
        }
        english.removeDuplicates();
        QVERIFY2(english.isEmpty(), qPrintable(english.join("; ")));
    }

private:
    static QString batchSeriesTitleFeed() { return batchSeries().at(1).title; }
};

QTEST_MAIN(TestDisplayNames)
#include "TestDisplayNames.moc"
