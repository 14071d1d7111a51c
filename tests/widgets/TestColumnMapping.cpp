// Issue #72 item 6, the column-mapping dialog as a user meets it with a historian export: an NIR
// analyser is proposed as a moisture, a mapping the user corrected is proposed again for a file
// with the same headers, the file mapped is the data set (not its folder), the help names the
// button by its name, and the units are in the window's language.
#include "MainWindow.h"
#include "common/Translations.h"
#include "data/ColumnMappingDialog.h"
#include "data/DataPanel.h"

#include "WaitIdle.h"
#include <QApplication>
#include <QComboBox>
#include <QFileDialog>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>

#include <QtTest>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace drytwin;
using namespace drytwin::widgets;

namespace {

/// A shift exported by a historian: tag names, an NIR analyser at the inlet ("NIR_IN.PV", 22 % wb,
/// a value an inlet temperature could have too) and one at the outlet, a line stop.
void writeShift(const QString& path) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << "Timestamp;HDT_TT101.PV;FEED_WT201.PV;NIR_IN.PV;HALL_TT301.PV;HALL_MT302.PV;NIR_XOUT.PV;WIN_TT401."
           "PV\n";
    for (int i = 0; i < 2400; ++i) {
        const bool stopped = i >= 1000 && i < 1300;
        char line[256];
        std::snprintf(line, sizeof line, "2025-06-03 %02d:%02d:%02d;%.2f;%.1f;%.2f;24.1;55.3;%.2f;55.2\n",
                      8 + i / 3600, (i / 60) % 60, i % 60, 170 + 5 * std::sin(i / 300.0),
                      stopped ? 0.0 : 6200.0, 22 + 0.4 * std::sin(i / 500.0), 13 + 0.2 * std::sin(i / 400.0));
        out << line;
    }
}

/// The cell widget of @p column in the row of @p contractName of the dialog's table.
QComboBox* comboOf(ColumnMappingDialog& d, const QString& contractName, int column) {
    for (int r = 0; r < d.mappingTable()->rowCount(); ++r) {
        if (d.mappingTable()->item(r, 0)->data(Qt::UserRole).toString() == contractName) {
            return qobject_cast<QComboBox*>(d.mappingTable()->cellWidget(r, column));
        }
    }
    return nullptr;
}

bool waitIdle(MainWindow& w, int ms = 120000) {
    return widgets::test::waitUntilIdle(w, ms);
}

} // namespace

class TestColumnMapping : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // remembered mappings go to a test settings file
        QVERIFY(m_dir.isValid());
    }
    void init() {
        QSettings().remove(QStringLiteral("columnMappings"));
        setLanguage(QStringLiteral("en"));
    }

    void anNirAnalyserIsProposedAsAMoisture() {
        writeShift(m_dir.filePath("nir.csv"));
        ColumnMappingDialog dialog(m_dir.filePath("nir.csv"));
        QCOMPARE(dialog.chosen("X_in_pct"), QString("NIR_IN.PV")); // it was taken for T_in_C
        QVERIFY(dialog.chosen("T_in_C") != QString("NIR_IN.PV"));
        QCOMPARE(dialog.chosen("X_out_pct"), QString("NIR_XOUT.PV"));
        QVERIFY(!dialog.proposedFromMemory());
    }

    // The tags of scripts/lib/historian_export.py (the screenshots' historian export, every
    // contract column): the dialog proposes each for its column, NIR_IN.PV as the inlet moisture.
    void aWholeLinesTagsAreEachProposedForTheirColumn() {
        const QStringList tags{"HDT_TIC101.SP", "HDT_TT101.PV",  "HDT_ST102.PV",  "FEED_WT201.PV",
                               "NIR_IN.PV",     "FEED_TT202.PV", "HALL_TT301.PV", "HALL_MT302.PV",
                               "HDT_MT103.PV",  "HDT_TT104.PV",  "NIR_OUT.PV",    "WIN_TT401.PV"};
        const QStringList columns{"T_hot_sp_C", "T_hot_C", "air_speed_m_s", "feed_kg_h",
                                  "X_in_pct",   "T_in_C",  "T_amb_C",       "RH_amb_pct",
                                  "X_hdt_pct",  "T_hdt_C", "X_out_pct",     "T_out_C"};
        {
            std::ofstream out(m_dir.filePath("line.csv").toStdString());
            out << "Timestamp;" << tags.join(';').toStdString() << "\n";
            for (int i = 0; i < 600; ++i) {
                char line[320];
                std::snprintf(
                    line, sizeof line,
                    "2025-06-03 06:%02d:%02d;181,2;%.1f;16,0;%.0f;%.2f;25,0;18,2;54,3;13,45;67,6;%.2f;53,8\n",
                    i / 60, i % 60, 170 + 3 * std::sin(i / 90.0), 6169 + 40 * std::sin(i / 70.0),
                    23.4 + 0.5 * std::sin(i / 50.0), 13 + 0.2 * std::sin(i / 40.0));
                std::string l(line);
                out << l;
            }
        }
        ColumnMappingDialog dialog(m_dir.filePath("line.csv"));
        for (int i = 0; i < tags.size(); ++i) {
            QVERIFY2(dialog.chosen(columns[i]) == tags[i],
                     qPrintable(columns[i] + ": " + dialog.chosen(columns[i]) + " instead of " + tags[i]));
        }
    }

    // The user's corrections, a column taken away and a unit changed included, are proposed for
    // the next file with the same header row; a file with other headers gets the guess.
    void aCorrectedMappingIsProposedAgain() {
        QDir().mkpath(m_dir.filePath("monday"));
        QDir().mkpath(m_dir.filePath("tuesday"));
        writeShift(m_dir.filePath("monday/shift.csv"));
        writeShift(m_dir.filePath("tuesday/shift.csv"));
        {
            ColumnMappingDialog first(m_dir.filePath("monday/shift.csv"));
            QCOMPARE(first.chosen("T_amb_C"), QString("HALL_TT301.PV"));
            // This line's hall thermometer stands at the feed: the user maps it to the inlet material.
            QVERIFY(first.choose("T_in_C", "HALL_TT301.PV"));
            QCOMPARE(first.chosen("T_amb_C"), QString()); // a header feeds one column
            QVERIFY(first.chooseUnit("T_hot_C", "degF"));
            first.rememberForTheseHeaders();
        }
        ColumnMappingDialog again(m_dir.filePath("tuesday/shift.csv"));
        QVERIFY(again.proposedFromMemory());
        QCOMPARE(again.chosen("T_in_C"), QString("HALL_TT301.PV"));
        QCOMPARE(again.chosen("T_amb_C"), QString());
        QCOMPARE(comboOf(again, "T_hot_C", 3)->currentData().toString(), QString("degF"));
        QVERIFY(again.mappingJson().contains("degF"));
        // Its reason says where the proposal came from.
        bool said = false;
        for (int r = 0; r < again.mappingTable()->rowCount(); ++r) {
            said = said ||
                   again.mappingTable()->item(r, 4)->text().contains("as you mapped these headers before");
        }
        QVERIFY(said);

        std::ofstream other(m_dir.filePath("other.csv").toStdString());
        other << "Zeit,Heissluft,Feuchte_aus\n0,170,13\n1,170,13\n";
        other.close();
        ColumnMappingDialog unrelated(m_dir.filePath("other.csv"));
        QVERIFY(!unrelated.proposedFromMemory());
    }

    // "Column mapping…" on the Data tab: the file chosen is the data set; another CSV in its
    // folder (here a contract batch file that would load) is not pulled in.
    void theMappedFileIsTheDataSetNotItsFolder() {
        const QString folder = m_dir.filePath("export");
        QDir().mkpath(folder);
        writeShift(folder + "/shift.csv");
        std::ofstream neighbour((folder + "/plots.csv").toStdString());
        neighbour << "plot,curve,x,y\nX_out,measured,0,13\n";
        neighbour.close();
        MainWindow w;
        QSignalSpy loaded(&w, &MainWindow::loadFinished);
        int handled = 0;
        QTimer driver;
        QObject::connect(&driver, &QTimer::timeout, [&handled] {
            QWidget* modal = QApplication::activeModalWidget();
            if (auto* d = qobject_cast<ColumnMappingDialog*>(modal)) {
                d->accept();
                ++handled;
            } else if (auto* f = qobject_cast<QFileDialog*>(modal)) {
                f->reject(); // not saved to a file of one's own: kept in DryTwin's folder
                ++handled;
            }
        });
        driver.start(100);
        w.dataPanel()->mapAndOpen(folder + "/shift.csv");
        driver.stop();
        QCOMPARE(handled, 2);
        QVERIFY(loaded.count() > 0 || loaded.wait(20000));
        QVERIFY(loaded.takeFirst().at(0).toBool());
        QVERIFY(waitIdle(w));
        QCOMPARE(w.workbench().dataPath(), QFileInfo(folder + "/shift.csv").absoluteFilePath());
        QCOMPARE(w.dataSet().batches.size(), std::size_t(2)); // the two runs of the shift, nothing else
        QVERIFY2(w.dataSetChooser()->currentText().startsWith("shift.csv ("),
                 qPrintable(w.dataSetChooser()->currentText()));
        // The accepted mapping is remembered for the next export with these headers.
        ColumnMappingDialog next(folder + "/shift.csv");
        QVERIFY(next.proposedFromMemory());

        // The help names the button as the Data tab and the status bar call it.
        const QString help = w.dataPanel()->cleaningSummary()->text();
        QVERIFY2(help.contains("“Column mapping…”"), qPrintable(help));
        QVERIFY(!help.contains("Map its columns"));
        bool onDataTab = false;
        for (auto* b : w.dataPanel()->findChildren<QPushButton*>()) {
            onDataTab = onDataTab || b->text() == QStringLiteral("Column mapping…");
        }
        QVERIFY(onDataTab);
        QCOMPARE(w.mapColumnsButton()->text(), QStringLiteral("Column mapping…"));
    }

    // The Chinese window: the units of the contract and of the file in Chinese, not "degC", "% wb".
    void theDialogsUnitsAreInTheWindowsLanguage() {
        writeShift(m_dir.filePath("units.csv"));
        QVERIFY(setLanguage(QStringLiteral("zh_CN")));
        ColumnMappingDialog dialog(m_dir.filePath("units.csv"));
        QStringList shown;
        for (int r = 0; r < dialog.mappingTable()->rowCount(); ++r) {
            shown << dialog.mappingTable()->item(r, 1)->text();
            auto* units = qobject_cast<QComboBox*>(dialog.mappingTable()->cellWidget(r, 3));
            for (int i = 0; i < units->count(); ++i) {
                shown << units->itemText(i);
            }
        }
        const QString all = shown.join(" | ");
        QVERIFY2(!all.contains("degC") && !all.contains("degF") && !all.contains("% wb") &&
                     !all.contains("% db"),
                 qPrintable(all));
        QVERIFY2(all.contains(QString::fromUtf8("°C")) && all.contains(QString::fromUtf8("°F")) &&
                     all.contains(QString::fromUtf8("% 湿基")) && all.contains(QString::fromUtf8("% 干基")),
                 qPrintable(all));
        if (qEnvironmentVariableIsSet("DRYTWIN_SCREENSHOT_DIR")) { // scripts/screenshots.sh, under Xvfb
            dialog.show();
            QTest::qWait(200);
            dialog.grab().save(qEnvironmentVariable("DRYTWIN_SCREENSHOT_DIR") + "/column-mapping.png");
        }
        // The file's unit chosen in Chinese is still the mapping file's name for it.
        QVERIFY(dialog.chooseUnit("X_out_pct", "% db"));
        QVERIFY(dialog.mappingJson().contains("% db"));
    }
};

QTEST_MAIN(TestColumnMapping)
#include "TestColumnMapping.moc"
