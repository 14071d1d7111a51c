// Issue #72, items 4, 5, 10 and 11: what the workbench says where a process engineer reads it.
// The verdict against a reference does not advise comparing with one; the line's commissioning
// runs are offered as the reference; statistics in plain words with their names in tooltips; and
// the small things: the engine's notes in Chinese, "1 batch", the Extend question naming what it
// adds, the calibration's MAEs said for their rows, names that wrap instead of being cut.
#include "calibration/CalibrationPanel.h"
#include "common/DisplayNames.h"
#include "common/EngineText.h"
#include "common/Translations.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "discovery/DiscoverPanel.h"
#include "discovery/DiscoveryNotes.h"
#include "discovery/RankingWords.h"

#include "WaitIdle.h"
#include <QAction>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>

#include <QtTest>
#include <fstream>

using namespace drytwin;
using namespace drytwin::widgets;

namespace {

/// English words of three letters or more left in a Chinese text, less symbols and names that stay.
QStringList englishWords(const QString& text) {
    static const QStringList kept{"PGRL",  "LSTM", "MPC", "PCA",       "MAE",   "NTU",    "PI",
                                  "Ipopt", "HDT",  "CSV", "STATUS",    "shift", "narrow", "csv",
                                  "PV",    "NIR",  "XIN", "Timestamp", "Tag",   "Value"};
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

const char* kBatch =
    "time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,X_out_pct,T_out_C\n"
    "0,170,6000,22,20,50,12.5,55\n1,171,6000,22,20,50,12.6,55.1\n2,171,6000,22,20,50,12.7,55.3\n";

bool waitIdle(Workbench& wb, int ms = 60000) {
    return widgets::test::waitUntilIdle(wb, ms);
}

} // namespace

class TestPlainWords : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
    }
    void cleanup() { setLanguage("en"); }

    // Item 4: compared with a reference already, the next step is not "compare with a reference";
    // in both languages, and not the words of the data judged alone.
    void aVerdictAgainstAReferenceDoesNotAdviseOne() {
        for (const char* language : {"en", "zh_CN"}) {
            QVERIFY(setLanguage(language));
            for (const std::string verdict : {"no_structural_cause", "unexplained_structure"}) {
                const QString against = verdictNextStep(verdict, false, true);
                const QString alone = verdictNextStep(verdict, false, false);
                QVERIFY(!against.isEmpty());
                QVERIFY2(against != alone, qPrintable(against));
                QVERIFY2(!against.contains("ran well") &&
                             !against.contains("Compare with a reference period"),
                         qPrintable(against));
                if (QLatin1String(language) == QLatin1String("zh_CN")) {
                    QVERIFY2(!against.contains(QString::fromUtf8("与参考期比较")) &&
                                 !against.contains(QString::fromUtf8("运行良好时的数据")),
                             qPrintable(against));
                    QVERIFY2(englishWords(against).isEmpty(), qPrintable(against));
                }
            }
        }
    }

    // Item 5: a data set with commissioning runs offered (a training recording's) has them first in
    // Discover's reference menu; choosing them makes them the reference. Without, no such entry.
    void theCommissioningRunsAreOfferedAsTheReference() {
        const QString recording = m_dir.filePath("recording.csv");
        std::ofstream(recording.toStdString()) << kBatch;
        const QString commissioning = m_dir.filePath("commissioning");
        QDir().mkpath(commissioning);
        for (const char* run : {"R01.csv", "R02.csv", "R03.csv"}) {
            std::ofstream((commissioning + "/" + run).toStdString()) << kBatch;
        }
        Workbench wb;
        DiscoverPanel panel(wb);
        wb.openData(recording);
        QVERIFY(waitIdle(wb));
        QMenu* menu = panel.referenceButton()->menu();
        Q_EMIT menu->aboutToShow();
        QVERIFY(!menu->actions().isEmpty());
        QVERIFY(!menu->actions().front()->text().contains("commissioning"));
        wb.suggestReference(recording, commissioning);
        Q_EMIT menu->aboutToShow();
        QAction* offered = menu->actions().front();
        QVERIFY2(offered->text().startsWith("The line's commissioning runs (3 runs"),
                 qPrintable(offered->text()));
        offered->trigger();
        QCOMPARE(wb.referencePath(), commissioning);
        QVERIFY(panel.referenceLabel()->text().contains("commissioning"));
    }

    // Item 10: the ranking's and the calibration's headers in plain words; the statistics' names
    // in their tooltips and in the evidence's details.
    void technicalNamesAreInTooltipsAndDetails() {
        Workbench wb;
        DiscoverPanel discover(wb);
        QStringList headers;
        for (int c = 0; c < discover.ranking()->columnCount(); ++c) {
            headers << discover.ranking()->horizontalHeaderItem(c)->text();
        }
        const QString onScreen = headers.join(" | ");
        QVERIFY2(!onScreen.contains("Score z") && !onScreen.contains("Holm"), qPrintable(onScreen));
        QVERIFY(onScreen.contains("How strong\nthe evidence is") && onScreen.contains("Chance it\nis noise"));
        QVERIFY(discover.ranking()->horizontalHeaderItem(2)->toolTip().startsWith("Score z:"));
        QVERIFY(discover.ranking()->horizontalHeaderItem(3)->toolTip().startsWith("p (Holm):"));
        // A p from the cause's own screen: the number alone, why in its tooltip (it read "1 *").
        QTableWidgetItem cell;
        setRankingPValue(&cell, 1.0, true);
        QCOMPARE(cell.text(), QStringLiteral("1"));
        QVERIFY(cell.toolTip().contains("own score test"));
        CalibrationPanel calibration(wb);
        const QString seHeader = calibration.estimates()->horizontalHeaderItem(4)->text();
        QVERIFY2(!seHeader.contains("Fisher"), qPrintable(seHeader));
        QVERIFY(calibration.estimates()->horizontalHeaderItem(4)->toolTip().contains("Fisher"));
        QVERIFY(!intervalMethodText("sandwich (Newey-West)").contains("Newey"));
        QVERIFY(intervalMethodDetails("sandwich (Newey-West)").contains("Newey-West"));
        discovery::Finding f;
        f.cause = "heat_transfer_fouling";
        f.parameter = properties::Param::theta_foul;
        f.output = "X_out";
        const QString evidence = DiscoverPanel::evidenceText(f);
        QVERIFY2(!evidence.contains("Diebold") &&
                     evidence.contains("the chance that a gain this large is luck"),
                 qPrintable(evidence));
    }

    // Item 11: the engine's notes a historian export gives, and the MPC's reasons, in Chinese.
    void engineNotesAreWordedInChinese() {
        const std::vector<std::string> notes{
            "shift.csv: column 'STATUS' holds text; it is not kept in the runs",
            "shift.csv:1002:1-1301: a run of 42 s is shorter than the minimum of 60 s; left out",
            "B03.csv:812: a gap of 300 s in time (rows typically 1 s apart): the model runs across it as if "
            "the "
            "line had run on; a stop is better cut into two batches",
            "B04.csv: T_hot_C reads 338.1 °C on average, the other batches about 170 (their median): this "
            "batch in another unit (°F, K, a fraction, t/h) or another column? Check it",
            "narrow.csv: a tag/value export (one row per tag and time stamp: columns 'Timestamp', 'Tag', "
            "'Value'), read as one column per tag: 7 tags over 400 time stamps; 200 cells where a tag has no "
            "sample at a stamp hold its last sample (at most 10 s back), 0 are left empty; places in later "
            "messages count rows of that table"};
        QVERIFY(setLanguage("zh_CN"));
        for (const auto& note : notes) {
            const QString worded = dataNoteText(note);
            QVERIFY2(worded != QString::fromStdString(note) && englishWords(worded).isEmpty(),
                     qPrintable(worded));
        }
        QVERIFY(dataNoteText(notes[3]).contains("338.1"));
        for (const std::string reason : {"the model shows no effect of the hot air on the outlet moisture",
                                         "Ipopt: Maximum_Iterations"}) {
            QVERIFY2(englishWords(fallbackReasonText(reason).remove("Maximum_Iterations")).isEmpty(),
                     qPrintable(fallbackReasonText(reason)));
        }
        // An engine detail the window has no words for: in Chinese the worded point, not the English.
        QCOMPARE(engineDetailText("a long English reason", QStringLiteral("原因")), QStringLiteral("原因"));
        setLanguage("en");
        QCOMPARE(engineDetailText("a long English reason", QStringLiteral("x")),
                 QStringLiteral("a long English reason"));
        QCOMPARE(dataNoteText(notes[0]), QString::fromStdString(notes[0]));
    }

    // Item 11: "Simulated 1 batch" (not "1 batches"), and its MAE over the kept rows as the
    // Calibrate tab's summary says it for those rows; the calibration's own MAEs named for its rows.
    void oneBatchAndTheMaesSaidForTheirRows() {
        const QString file = m_dir.filePath("one.csv");
        std::ofstream(file.toStdString()) << kBatch;
        Workbench wb;
        CalibrationPanel panel(wb);
        QStringList said;
        QObject::connect(&wb, &Workbench::status, [&](const QString& s) { said << s; });
        wb.openData(file);
        QVERIFY(waitIdle(wb));
        wb.simulate();
        QVERIFY(waitIdle(wb));
        const QString simulated = said.filter("Simulated").value(0);
        QVERIFY2(simulated.startsWith("Simulated 1 batch;") && simulated.contains("over all 3 kept rows"),
                 qPrintable(said.join("\n")));
        workflow::LatestResults results;
        workflow::CalibrateResult c;
        c.calibration.rowsUsed = 3;
        c.calibration.before = {0.2, 0.3, 1.0};
        c.calibration.after = {0.1, 0.15, 0.8};
        c.calibration.intervalMethod = "sandwich (Newey-West)";
        c.startParameters = wb.model().parameters;
        results.calibrate = c;
        wb.restoreResults(results);
        QVERIFY(waitIdle(wb));
        wb.simulate();
        QVERIFY(waitIdle(wb));
        const QString summary = panel.summary()->text();
        QVERIFY2(summary.contains("on its 3 calibration rows") && summary.contains("On all 3 kept rows"),
                 qPrintable(summary));
        const QString mae = QString::number(wb.latest().simulate->maeXOutPctAllKeptRows(), 'f', 3);
        QVERIFY2(summary.contains(mae) && said.last().contains(mae),
                 qPrintable(summary + "\n" + said.last()));
    }

    // Item 11: Extend's question names what the extended model adds, not only what goes stale.
    void theExtendQuestionNamesWhatItAdds() {
        Workbench wb;
        hybrid::HybridModel extended = wb.model();
        extended.mechanisms["heat_transfer_fouling"] = {};
        extended.parameters[properties::Param::h_HDT] = wb.model().parameters[properties::Param::h_HDT] + 5;
        const QString question = wb.invalidationQuestion("Extend the model", &extended);
        QVERIFY2(question.startsWith("Extend the model adds to the physics model: heat-transfer fouling."),
                 qPrintable(question));
        QVERIFY2(question.contains("Refitted with it: h_HDT."), qPrintable(question));
    }

    // Item 11: a name narrower than its text wraps onto two lines instead of being cut.
    void aNarrowNameWrapsInsteadOfBeingCut() {
        QWidget host;
        auto* table = makeResultTable({"Cause", "Outcome", "z", "p", "Fitted", "Loss"});
        table->setParent(&host);
        table->setRowCount(2);
        setTableRow(table, 0,
                    {"drying air cooling along the tube", "fitted, not the best", "1.98", "0.0946", "yes",
                     "0.1767 → 0.1679"});
        setTableRow(table, 1, {"fouling", "named", "4.66", "1.4e-05", "yes", "0.1767 → 0.08083"});
        fitTableWidth(table);
        host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&host));
        const QHeaderView* header = table->horizontalHeader();
        table->resize(1600, 200); // every column whole first
        QCoreApplication::processEvents();
        const int wide = header->length() + table->width() - table->viewport()->width();
        table->resize(wide - 100, 200); // 100 px short of that: the names give way
        QCoreApplication::processEvents();
        const int column = header->sectionSize(0);
        const int text = table->fontMetrics().horizontalAdvance(table->item(0, 0)->text());
        QVERIFY2(column < text, qPrintable(QStringLiteral("%1 < %2").arg(column).arg(text)));
        QVERIFY(table->wordWrap());
        QCOMPARE(table->textElideMode(), Qt::ElideNone);
        QVERIFY2(table->rowHeight(0) >= 2 * table->fontMetrics().lineSpacing(),
                 qPrintable(QString::number(table->rowHeight(0))));
    }
};

QTEST_MAIN(TestPlainWords)
#include "TestPlainWords.moc"
