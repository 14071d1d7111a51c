#include "common/Units.h"
#include "data/BatchReader.h"
#include "data/BatchWriter.h"
#include "data/Cleaning.h"
#include "data/DataSetSummary.h"
#include "data/SiBatch.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>

using namespace drytwin;
using namespace drytwin::data;

namespace {

const char* kHeader = "time_s,T_hot_sp_C,T_hot_C,air_speed_m_s,feed_kg_h,X_in_pct,T_in_C,T_amb_C,RH_amb_pct,"
                      "X_hdt_pct,T_hdt_C,X_out_pct,T_out_C";

std::string row(double t, double xOut = 12.8, double feed = 6200, double xHdt = 14.0, double tHdt = 58.0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%g,170,169.5,16,%g,22,25,24,55,%g,%g,%g,55.2", t, feed, xHdt, tHdt, xOut);
    return buf;
}

std::string goodFile(int rows = 5) {
    std::string s = "# batch: B07\n# line: 2\n";
    s += kHeader;
    s += "\n";
    for (int i = 0; i < rows; ++i) {
        s += row(i) + "\n";
    }
    return s;
}

void writeText(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

/// A folder holding one batch file B07.csv with @p text, loaded as a user's folder is.
LoadResult loadOneFile(const std::string& text) {
    QTemporaryDir dir;
    writeText(dir.filePath("B07.csv"), text);
    return loadDataSet(dir.path().toStdString());
}

} // namespace

class TestBatchReader : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void readsGoodFileWithMetadata() {
        auto b = parseBatchText(goodFile(), "dir/B07_file.csv");
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE(b->id, std::string("B07")); // metadata overrides the file stem
        QCOMPARE(b->metadata("line"), std::string("2"));
        QCOMPARE(b->rows(), std::size_t(5));
        QCOMPARE(b->metadataLines.size(), std::size_t(2));
        QCOMPARE((*b->values(Column::XOut))[3], 12.8);
        QCOMPARE((*b->values(Column::Time))[4], 4.0);
    }

    void columnsInAnyOrderAndExtraTextColumnsKept() {
        std::string s = "operator,X_out_pct,T_out_C,time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct\n"
                        "anna,12.5,55,0,170,6000,22,20,50\n"
                        "\"li, wei\",12.6,55.1,1,171,6000,22,20,50\n";
        auto b = parseBatchText(s, "x.csv");
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE(b->text.size(), std::size_t(1));
        QCOMPARE(b->text[0].cells[1], std::string("li, wei"));
        QVERIFY(!b->has(Column::XHdt));
        QCOMPARE((*b->values(Column::XOut))[1], 12.6);
    }

    // A contract column spelt another way is not read under a name it does not have, but the user
    // is told: an optional one in a note naming the header and the contract name, a required one
    // in the error. Headers that only share a letter are not taken for one.
    void aMisspeltContractColumnIsNamed() {
        QVERIFY(headerLooksLike("T_inlet_C", Column::TIn));
        QVERIFY(headerLooksLike("T_hot_setpoint_C", Column::THotSp));
        QVERIFY(headerLooksLike("air_speed", Column::AirSpeed));
        QVERIFY(headerLooksLike("X_hdt", Column::XHdt));
        QVERIFY(headerLooksLike("x_out_pct", Column::XOut));
        QVERIFY(headerLooksLike("Tamb degC", Column::TAmb));
        QVERIFY(!headerLooksLike("T_hot_C", Column::THotSp));
        QVERIFY(!headerLooksLike("T_hot_C", Column::THdt));
        QVERIFY(!headerLooksLike("operator", Column::TIn));
        QVERIFY(!headerLooksLike("X_out_pct", Column::XHdt));

        std::string text = goodFile(3);
        text.replace(text.find(",T_in_C,"), 8, ",T_inlet_C,");
        const auto loaded = loadOneFile(text);
        QVERIFY(loaded.ok());
        const auto summary = summarize(loaded.dataSet);
        QVERIFY(!summary.columns[static_cast<std::size_t>(Column::TIn)].present);
        const auto note = std::find_if(summary.notes.begin(), summary.notes.end(), [](const std::string& n) {
            return n.find("column 'T_inlet_C' is not a contract column") != std::string::npos &&
                   n.find("looks like 'T_in_C'") != std::string::npos;
        });
        QVERIFY2(note != summary.notes.end() && note->find("B07.csv") != std::string::npos,
                 summary.notes.empty() ? "no note" : summary.notes.front().c_str());

        std::string required = goodFile(3);
        required.replace(required.find(",X_out_pct,"), 11, ",x_out_pct,");
        const auto refused = parseBatchText(required, "B08.csv");
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message().find("missing required column 'X_out_pct'") != std::string::npos &&
                     refused.error().message().find("the file has 'x_out_pct'") != std::string::npos,
                 refused.error().message().c_str());
    }

    // Columns each possible alone but impossible together (a wrong unit, swapped headers) are
    // noted; time_s in Excel serial days is refused, naming the remedy.
    void aWrongUnitOrSwappedColumnsAreNoted() {
        const auto notesOf = [](const std::string& text) {
            const auto loaded = loadOneFile(text);
            return loaded.ok() ? summarize(loaded.dataSet).notes : std::vector<std::string>{"load failed"};
        };
        const auto has = [](const std::vector<std::string>& notes, const std::string& part) {
            return std::any_of(notes.begin(), notes.end(),
                               [&](const std::string& n) { return n.find(part) != std::string::npos; });
        };
        QVERIFY(notesOf(goodFile(3)).empty());
        // X_out 0.128 (a fraction) against X_in 22 % wb.
        std::string fraction = "# batch: B07\n" + std::string(kHeader) + "\n";
        for (int i = 0; i < 3; ++i) {
            fraction += row(i, 0.128) + "\n";
        }
        QVERIFY(has(notesOf(fraction), "X_out_pct (mean 0.128 % wb) is below a hundredth of X_in_pct"));
        // The outlet temperature in °F (131 for 55.2 °C) against the tube outlet's 58 °C.
        std::string fahrenheit = goodFile(3);
        for (std::size_t at = fahrenheit.find(",55.2\n"); at != std::string::npos;
             at = fahrenheit.find(",55.2\n")) {
            fahrenheit.replace(at, 6, ",131.4\n");
        }
        QVERIFY(has(notesOf(fahrenheit), "T_out_C (mean 131.4 °C) is 73 K above the tube outlet's T_hdt_C"));

        std::string excel = "# batch: B07\n" + std::string(kHeader) + "\n";
        for (int i = 0; i < 3; ++i) {
            std::string r = row(i);
            char stamp[32];
            std::snprintf(stamp, sizeof stamp, "%.10f", 45811.25 + i / 86400.0);
            excel += stamp + r.substr(r.find(',')) + "\n";
        }
        const auto refused = parseBatchText(excel, "B07.csv");
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message().find("Excel serial days") != std::string::npos &&
                     refused.error().message().find("B07.csv:4:1") != std::string::npos,
                 refused.error().message().c_str());
    }

    // A UTF-8 byte-order mark (Excel's "CSV UTF-8") before the "# batch:" line: the batch keeps
    // its name and nothing is taken for a title line.
    void aByteOrderMarkKeepsTheBatchMetadata() {
        const auto loaded = loadOneFile("\xEF\xBB\xBF" + goodFile(3));
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.dataSet.batches.size(), std::size_t(1));
        QCOMPARE(loaded.dataSet.batches[0].id, std::string("B07"));
        QCOMPARE(loaded.dataSet.batches[0].metadata("line"), std::string("2"));
        const auto notes = summarize(loaded.dataSet).notes;
        QVERIFY2(
            std::none_of(notes.begin(), notes.end(),
                         [](const std::string& n) { return n.find("title lines") != std::string::npos; }),
            notes.empty() ? "" : notes.front().c_str());
    }

    // One batch of a folder in another unit (a folder of files from two exports: X_out as a
    // fraction, the hot air in °F) is named, not averaged away with the rest (a newcomer's folder
    // loaded with exit 0 and a calibration on garbage); a data set wholly in °F is noted too.
    void aBatchInAnotherUnitThanTheOthersIsNamed() {
        const auto batchText = [](const std::string& id, double xOut, double hotAirC, double ambientC) {
            std::string s = "# batch: " + id + "\n" + std::string(kHeader) + "\n";
            for (int i = 0; i < 3; ++i) {
                char buf[256];
                std::snprintf(buf, sizeof buf, "%d,%g,%g,16,6200,22,25,%g,55,14,58,%g,55.2", i, hotAirC + 0.5,
                              hotAirC, ambientC, xOut);
                s += std::string(buf) + "\n";
            }
            return s;
        };
        // The notes of a folder holding these files (name without ".csv", text).
        const auto notesOfFolder = [](const std::vector<std::pair<std::string, std::string>>& files) {
            QTemporaryDir dir;
            for (const auto& [name, text] : files) {
                writeText(dir.filePath(QString::fromStdString(name) + ".csv"), text);
            }
            const auto loaded = loadDataSet(dir.path().toStdString());
            return loaded.ok() ? summarize(loaded.dataSet).notes : std::vector<std::string>{"load failed"};
        };
        const auto has = [](const std::vector<std::string>& notes, const std::string& a,
                            const std::string& b) {
            return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) {
                return n.find(a) != std::string::npos && n.find(b) != std::string::npos;
            });
        };
        const auto joined = [](const std::vector<std::string>& notes) {
            std::string all;
            for (const auto& n : notes) {
                all += n + "\n";
            }
            return all;
        };
        const auto notes = notesOfFolder({{"B01", batchText("B01", 12.8, 169.5, 24)},
                                          {"B02", batchText("B02", 12.9, 170.0, 25)},
                                          {"B03", batchText("B03", 13.0, 168.0, 23)},
                                          {"B04", batchText("B04", 12.8, 337.1, 24)},    // hot air in °F
                                          {"B05", batchText("B05", 0.128, 169.0, 24)}}); // X_out a fraction
        QVERIFY2(has(notes, "B04.csv", "T_hot_C reads 337.1 °C on average, the other batches about 169.2"),
                 joined(notes).c_str());
        QVERIFY2(has(notes, "B04.csv", "T_hot_C (mean 337.1 °C) is hotter than the hot air"),
                 joined(notes).c_str());
        QVERIFY2(has(notes, "B05.csv", "X_out_pct reads 0.128 % wb on average"), joined(notes).c_str());
        QVERIFY2(has(notes, "B05.csv", "below a hundredth of X_in_pct"), joined(notes).c_str());
        // Only the odd batches are named.
        for (const char* fine : {"B01.csv", "B02.csv", "B03.csv"}) {
            QVERIFY2(!has(notes, fine, ""), joined(notes).c_str());
        }
        // Every batch in °F, ambient too: said once, for the data set.
        const auto allNotes = notesOfFolder({{"B01", batchText("B01", 12.8, 337.1, 75.2)},
                                             {"B02", batchText("B02", 12.8, 337.1, 75.2)},
                                             {"B03", batchText("B03", 12.8, 337.1, 75.2)}});
        QVERIFY2(has(allNotes, "every batch: ", "T_hot_C (mean 337.1 °C) is hotter than the hot air"),
                 joined(allNotes).c_str());
        QVERIFY2(has(allNotes, "every batch: ", "T_amb_C (mean 75.2 °C) is hotter than any air"),
                 joined(allNotes).c_str());
        QCOMPARE(
            std::count_if(allNotes.begin(), allNotes.end(),
                          [](const std::string& n) { return n.find("T_hot_C (mean") != std::string::npos; }),
            std::ptrdiff_t(1));
        // Feed in t/h under a kg/h header.
        std::string tonnes = "# batch: B07\n" + std::string(kHeader) + "\n";
        for (int i = 0; i < 3; ++i) {
            tonnes += row(i, 12.8, 6.2) + "\n";
        }
        const auto tonnesNotes = notesOfFolder({{"B07", tonnes}});
        QVERIFY2(has(tonnesNotes, "B07.csv", "6.2 t/h is 6200 kg/h"), joined(tonnesNotes).c_str());

        // Two batches failing two different checks of one column are each named with their own
        // check, not one "every batch" note with the first's words.
        const auto twoNotes =
            notesOfFolder({{"B01", batchText("B01", 30.0, 169.5, 24)},    // X_out above X_in
                           {"B02", batchText("B02", 0.128, 169.5, 24)}}); // X_out a fraction
        QVERIFY2(has(twoNotes, "B01.csv", "is above X_in_pct"), joined(twoNotes).c_str());
        QVERIFY2(has(twoNotes, "B02.csv", "below a hundredth of X_in_pct"), joined(twoNotes).c_str());
        QVERIFY2(!has(twoNotes, "every batch", ""), joined(twoNotes).c_str());

        // What a real line does between batches is no unit: a winter batch among summer ones
        // (ambient -25 against 27 and 28 °C), two products' hot air 55 K apart.
        const auto seasonNotes = notesOfFolder({{"B01", batchText("B01", 12.8, 130.0, -25)},
                                                {"B02", batchText("B02", 12.8, 185.0, 27)},
                                                {"B03", batchText("B03", 12.8, 130.0, 28)}});
        QVERIFY2(!has(seasonNotes, "reads", "on average"), joined(seasonNotes).c_str());
        // ... while the same ambient in °F in one batch is named (68 °F is 20 °C).
        const auto ambientNotes = notesOfFolder({{"B01", batchText("B01", 12.8, 169.5, 20)},
                                                 {"B02", batchText("B02", 12.8, 169.5, 21)},
                                                 {"B03", batchText("B03", 12.8, 169.5, 68)}});
        QVERIFY2(has(ambientNotes, "B03.csv", "T_amb_C reads 68 °C on average, the other batches about 20.5"),
                 joined(ambientNotes).c_str());
    }

    // An outlet transmitter that never moves over ten minutes or more is frozen, even where the
    // column has too few changes to say what is usual for it; five minutes of it are not.
    void anOutletThatNeverMovesIsFrozen() {
        for (const int rows : {700, 300}) {
            const auto loaded = loadOneFile(goodFile(rows)); // every column constant
            QVERIFY(loaded.ok());
            const auto report = clean(loaded.dataSet, CleaningOptions{});
            const bool outletFrozen =
                std::any_of(report.stuck.begin(), report.stuck.end(), [](const CleaningReport::StuckSpan& s) {
                    return s.column == Column::XOut && s.seconds >= 600;
                });
            QCOMPARE(outletFrozen, rows == 700);
            // Inputs and ambient columns may hold a coarse value: never flagged by this rule.
            QVERIFY(std::none_of(report.stuck.begin(), report.stuck.end(),
                                 [](const CleaningReport::StuckSpan& s) {
                                     return spec(s.column).role != ColumnRole::Output;
                                 }));
        }
    }

    // What a spreadsheet writes is read as the plant-file reader reads it: a separator after the
    // last header is no column, "#N/A" and a historian's "Bad" are missing cells.
    void aSpreadsheetsTrailingSeparatorAndNoValueCellsAreRead() {
        std::string text = std::string(kHeader) + ",\n";
        for (int i = 0; i < 3; ++i) {
            text += row(i) + ",\n";
        }
        text += row(3).substr(0, row(3).rfind(',')) + ",#N/A,\n";
        text += row(4).substr(0, row(4).rfind(',')) + ",Bad,\n";
        const auto b = parseBatchText(text, "f.csv");
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE(b->rows(), std::size_t(5));
        QVERIFY(b->text.empty()); // no column made of the trailing separator
        QVERIFY(std::isnan((*b->values(Column::TOut))[3]) && std::isnan((*b->values(Column::TOut))[4]));
        QCOMPARE(b->missing.size(), std::size_t(2));
        QCOMPARE(b->missing[0].line, 5);
    }

    void missingCellsReportedNotZeroFilled() {
        std::string s = std::string(kHeader) + "\n" + row(0) + "\n" +
                        "1,170,169.5,16,6200,22,25,24,55,14,58,,55.2\n" +
                        "2,170,NaN,16,6200,22,25,24,55,14,58,12.9,55\n";
        auto b = parseBatchText(s, "m.csv");
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE(b->missing.size(), std::size_t(2));
        QCOMPARE(b->missing[0].line, 3);
        QCOMPARE(b->missing[0].column, 12);
        QCOMPARE(b->missing[0].columnName, std::string("X_out_pct"));
        QCOMPARE(b->missing[1].line, 4);
        QCOMPARE(b->missing[1].columnName, std::string("T_hot_C"));
        QVERIFY(std::isnan((*b->values(Column::XOut))[1]));
        QVERIFY(std::isnan((*b->values(Column::THot))[2]));
        // inspect lists where they are (CONTRACT.md §1: with file and line), the first few a column.
        DataSet ds;
        ds.batches.push_back(*b);
        for (int i = 0; i < 8; ++i) { // more than are listed in one column
            Batch more = *b;
            more.id = more.sourcePath = "more" + std::to_string(i) + ".csv";
            ds.batches.push_back(more);
        }
        const auto summary = summarize(ds);
        QCOMPARE(summary.missingCells.size(), 2 * DataSetSummary::kMaxListedMissing);
        QCOMPARE(summary.missingCells[0].file, b->sourcePath.empty() ? b->id : b->sourcePath);
        QCOMPARE(summary.missingCells[0].line, 3);
        QCOMPARE(summary.missingCells[0].fileColumn, 12);
        QCOMPARE(summary.missingCells[0].contractColumn, std::string("X_out_pct"));
        QCOMPARE(summary.missingCells[1].line, 4);
        QCOMPARE(summary.missingCells[1].contractColumn, std::string("T_hot_C"));
        // Several rows from one line of the file (a historian's 5 s samples put on a 1 s grid):
        // the place is listed once.
        Batch grid = *b;
        grid.lineOfRow = {2, 3, 3};
        auto& xOut = grid.numeric[static_cast<std::size_t>(
            std::find_if(grid.numeric.begin(), grid.numeric.end(),
                         [](const Batch::NumericColumn& c) { return c.id == Column::XOut; }) -
            grid.numeric.begin())];
        xOut.values[2] = std::numeric_limits<double>::quiet_NaN(); // rows 1 and 2 both line 3
        DataSet gridded;
        gridded.batches.push_back(grid);
        const auto once = summarize(gridded);
        QCOMPARE(std::count_if(once.missingCells.begin(), once.missingCells.end(),
                               [](const MissingCellPlace& m) { return m.contractColumn == "X_out_pct"; }),
                 std::ptrdiff_t(1));
    }

    /// A contract header over no rows (a spreadsheet saved empty): said as such, not as a time
    /// column the plant-file reader could not read.
    void headerWithoutRowsIsSaidToHaveNoRows() {
        QTemporaryDir dir;
        writeText(dir.filePath("B01.csv"), "# batch: B01\n" + std::string(kHeader) + "\n\n");
        const auto loaded = loadDataSet(dir.filePath("B01.csv").toStdString());
        QCOMPARE(loaded.errors.size(), std::size_t(1));
        QVERIFY2(loaded.errors.front().reason.find("header but no data rows") != std::string::npos,
                 loaded.errors.front().message().c_str());
        QVERIFY(loaded.errors.front().place.find("B01.csv:2") != std::string::npos);
    }

    void malformed_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expectedPlace");
        QTest::addColumn<QString>("expectedReason");
        const std::string h = std::string(kHeader) + "\n";
        QTest::newRow("empty file") << QString() << "f.csv:1:1"
                                    << "empty file";
        QTest::newRow("only blank lines") << QString("\n\n  \n") << "f.csv:3:1"
                                          << "empty file";
        QTest::newRow("only metadata") << QString("# batch: x\n") << "f.csv:1:1"
                                       << "no header row";
        QTest::newRow("numeric first row")
            << QString::fromStdString(row(0) + "\n" + row(1) + "\n") << "f.csv:1:1"
            << "no header row";
        QTest::newRow("semicolon delimiter") << QString("time_s;T_hot_C;feed_kg_h\n0;1;2\n") << "f.csv:1:1"
                                             << "wrong delimiter";
        QTest::newRow("tab delimiter") << QString("time_s\tT_hot_C\n0\t1\n") << "f.csv:1:1"
                                       << "wrong delimiter";
        QTest::newRow("missing required column")
            << QString("time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,X_out_pct\n0,1,2,3,4,5,6\n")
            << "f.csv:1:1"
            << "missing required column 'T_out_C'";
        QTest::newRow("duplicate column")
            << QString::fromStdString(std::string(kHeader) + ",X_out_pct\n") << "f.csv:1:14"
            << "duplicate column 'X_out_pct'";
        // Empty inside the header: refused. A trailing separator is no column (a spreadsheet's),
        // unless a row puts a value under it.
        QTest::newRow("empty column name")
            << QString::fromStdString("time_s,," + std::string(kHeader).substr(7) + "\n") << "f.csv:1:2"
            << "empty column name";
        QTest::newRow("value under no header")
            << QString::fromStdString(std::string(kHeader) + ",\n" + row(0) + ",7\n") << "f.csv:2:14"
            << "value '7' under no header";
        QTest::newRow("header only") << QString::fromStdString(h) << "f.csv:1:1"
                                     << "no data rows";
        QTest::newRow("text in number")
            << QString::fromStdString(h + row(0) + "\n" + "1,170,169.5,16,6200,22,25,24,55,14,58,wet,55\n")
            << "f.csv:3:12"
            << "text 'wet' in numeric column 'X_out_pct'";
        QTest::newRow("decimal comma")
            << QString::fromStdString(h + "0,170,169.5,16,6200,22,25,24,55,14,58,\"12,8\",55\n")
            << "f.csv:2:12"
            << "text '12,8'";
        QTest::newRow("too few fields") << QString::fromStdString(h + row(0) + "\n1,2,3\n") << "f.csv:3:4"
                                        << "expected 13 fields";
        QTest::newRow("too many fields") << QString::fromStdString(h + row(0) + ",7\n") << "f.csv:2:14"
                                         << "expected 13 fields";
        QTest::newRow("time goes backwards")
            << QString::fromStdString(h + row(0) + "\n" + row(5) + "\n" + row(3) + "\n") << "f.csv:4:1"
            << "time does not increase";
        QTest::newRow("time repeats")
            << QString::fromStdString(h + row(0) + "\n" + row(0) + "\n") << "f.csv:3:1"
            << "time does not increase";
        QTest::newRow("missing time")
            << QString::fromStdString(h + ",170,169.5,16,6200,22,25,24,55,14,58,12,55\n") << "f.csv:2:1"
            << "missing time";
        QTest::newRow("infinite value")
            << QString::fromStdString(h + "0,170,inf,16,6200,22,25,24,55,14,58,12,55\n") << "f.csv:2:3"
            << "infinite value";
        QTest::newRow("unterminated quote")
            << QString::fromStdString(h + row(0) + "\n1,\"170,169\n") << "f.csv:3:1"
            << "malformed CSV";
        QTest::newRow("stray quote") << QString::fromStdString(
                                            h + "0,17\"0,169.5,16,6200,22,25,24,55,14,58,12,55\n")
                                     << "f.csv:2:2"
                                     << "malformed CSV";
    }
    void malformed() {
        QFETCH(QString, text);
        QFETCH(QString, expectedPlace);
        QFETCH(QString, expectedReason);
        auto b = parseBatchText(text.toStdString(), "f.csv");
        QVERIFY(!b.ok());
        QCOMPARE(QString::fromStdString(b.error().place), expectedPlace);
        QVERIFY2(QString::fromStdString(b.error().reason).contains(expectedReason),
                 b.error().message().c_str());
        QCOMPARE(exitCodeFor(b.error().kind), 3);
    }

    void wrongEncoding() {
        std::string latin1 = goodFile();
        latin1.insert(latin1.find("# line"), "# operator: J\xFCrgen\n"); // Latin-1 ü
        auto b = parseBatchText(latin1, "f.csv");
        QVERIFY(!b.ok());
        QCOMPARE(QString::fromStdString(b.error().place), QString("f.csv:2:14"));
        QVERIFY(QString::fromStdString(b.error().reason).contains("UTF-8"));

        const std::string utf16("\xFF\xFEt\0i\0", 6);
        auto c = parseBatchText(utf16, "g.csv");
        QVERIFY(!c.ok());
        QVERIFY(QString::fromStdString(c.error().reason).contains("UTF-16"));
    }

    void utf8BomAndCrlfAccepted() {
        std::string s = "\xEF\xBB\xBF" + std::string(kHeader) + "\r\n" + row(0) + "\r\n" + row(1) + "\r\n";
        auto b = parseBatchText(s, "crlf.csv");
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE(b->rows(), std::size_t(2));
        QCOMPARE((*b->values(Column::TOut))[1], 55.2);
    }

    void columnMapping() {
        ColumnMapping m;
        m.contractToFile["X_out_pct"] = "Moisture_Out";
        ReadOptions ro;
        ro.mapping = m;
        std::string s =
            "time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,Moisture_Out,T_out_C\n0,1,2,3,4,5,6,7\n";
        auto b = parseBatchText(s, "m.csv", ro);
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QCOMPARE((*b->values(Column::XOut))[0], 6.0);
        // Written back with the file's own names, with contract names on request.
        QVERIFY(formatBatch(*b).find("Moisture_Out") != std::string::npos);
        QVERIFY(formatBatch(*b, HeaderNames::Contract).find("X_out_pct") != std::string::npos);
        // The mapping names the column but the file lacks it: the message says so.
        auto c = parseBatchText(
            "time_s,T_hot_C,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,T_out_C\n0,1,2,3,4,5,7\n", "n.csv", ro);
        QVERIFY(!c.ok());
        QVERIFY(QString::fromStdString(c.error().reason).contains("Moisture_Out"));
        ColumnMapping bad;
        bad.contractToFile["X_wet"] = "a";
        QVERIFY(!bad.validate().ok());
    }

    void columnMappingConvertsUnits() {
        // A plant logging °F, moisture on dry basis, feed in t/h and RH as a fraction.
        ColumnMapping m;
        m.contractToFile["T_hot_C"] = "HotAir_F";
        m.contractToUnit["T_hot_C"] = "degF";
        m.contractToFile["X_out_pct"] = "Moist_db";
        m.contractToUnit["X_out_pct"] = "% db";
        m.contractToUnit["feed_kg_h"] = "t/h";
        m.contractToUnit["RH_amb_pct"] = "fraction";
        QVERIFY(m.validate().ok());
        ReadOptions ro;
        ro.mapping = m;
        auto b = parseBatchText("time_s,HotAir_F,feed_kg_h,X_in_pct,T_amb_C,RH_amb_pct,Moist_db,T_out_C\n"
                                "0,338,6.2,22,20,0.5,15,55\n",
                                "u.csv", ro);
        QVERIFY2(b.ok(), b.ok() ? "" : b.error().message().c_str());
        QVERIFY(std::abs((*b->values(Column::THot))[0] - 170.0) < 1e-12);          // (338 − 32)·5/9
        QVERIFY(std::abs((*b->values(Column::XOut))[0] - 1500.0 / 115.0) < 1e-12); // 15 % db → 13.04 % wb
        QVERIFY(std::abs((*b->values(Column::Feed))[0] - 6200.0) < 1e-9);
        QVERIFY(std::abs((*b->values(Column::RHAmb))[0] - 50.0) < 1e-12);
        QCOMPARE((*b->values(Column::XIn))[0], 22.0); // unmapped columns as they are
        // A unit the column's quantity does not have is refused, naming the choices.
        ColumnMapping wrong;
        wrong.contractToUnit["feed_kg_h"] = "degF";
        QVERIFY(!wrong.validate().ok());
        QVERIFY(wrong.validate().error().reason.find("kg/h") != std::string::npos);
        // A mapping file takes a unit as a units row would say it ("°F", "[t/h]"), as its name.
        const auto written = readColumnMappingText(
            R"({"T_hot_C": {"header": "HotAir", "unit": "°F"}, "feed_kg_h": {"header": "Feed", "unit": "[t/h]"}})",
            "tags.json");
        QVERIFY2(written.ok(), written.ok() ? "" : written.error().message().c_str());
        QCOMPARE(written->contractToUnit.at("T_hot_C"), std::string("degF"));
        QCOMPARE(written->contractToUnit.at("feed_kg_h"), std::string("t/h"));
        QVERIFY(
            !readColumnMappingText(R"({"T_hot_C": {"header": "HotAir", "unit": "°R"}})", "tags.json").ok());
    }

    void roundTripIsLossless() {
        std::string s = goodFile(3);
        s += "3,170,169.5,16,6200,22,25,24,55,14,58,0.1000000000000000055511151231257827,55.2\n";
        s += "4,170,169.5,16,6200,22,25,24,55,,58,12.345678901234567,55.2\n";
        auto a = parseBatchText(s, "r.csv");
        QVERIFY(a.ok());
        const std::string written = formatBatch(*a);
        auto b = parseBatchText(written, "r.csv");
        QVERIFY(b.ok());
        QCOMPARE(b->metadataLines, a->metadataLines);
        QCOMPARE(b->rows(), a->rows());
        QCOMPARE(b->missing.size(), a->missing.size());
        for (std::size_t c = 0; c < a->numeric.size(); ++c) {
            for (std::size_t r = 0; r < a->rows(); ++r) {
                const double x = a->numeric[c].values[r];
                const double y = b->numeric[c].values[r];
                QVERIFY((std::isnan(x) && std::isnan(y)) || x == y); // bit-exact
            }
        }
        QCOMPARE(formatBatch(*b), written);
    }

    void folderLoadReportsEveryBadFileAndKeepsNothingHalfLoaded() {
        QTemporaryDir dir;
        writeText(dir.filePath("a.csv"), goodFile());
        writeText(dir.filePath("b.csv"), std::string(kHeader) + "\n" + row(0) + "\n1,2\n");
        writeText(dir.filePath("c.csv"), "");
        writeText(dir.filePath("notes.txt"), "ignored");
        auto r = loadDataSet(dir.path().toStdString());
        QVERIFY(!r.ok());
        QCOMPARE(r.errors.size(), std::size_t(2));
        QVERIFY(QString::fromStdString(r.errors[0].place).endsWith("b.csv:3:3"));
        QVERIFY(QString::fromStdString(r.errors[1].place).endsWith("c.csv:1:1"));

        QTemporaryDir good;
        writeText(good.filePath("b2.csv"), goodFile(4).replace(goodFile(4).find("B07"), 3, "B08"));
        writeText(good.filePath("b1.csv"), goodFile(3));
        auto ok = loadDataSet(good.path().toStdString());
        QVERIFY(ok.ok());
        QCOMPARE(ok.dataSet.batches.size(), std::size_t(2));
        QCOMPARE(ok.dataSet.batches[0].id, std::string("B07")); // b1.csv sorts first
        QCOMPARE(ok.dataSet.totalRows(), std::size_t(7));

        QTemporaryDir dup;
        writeText(dup.filePath("x.csv"), goodFile());
        writeText(dup.filePath("y.csv"), goodFile());
        auto d = loadDataSet(dup.path().toStdString());
        QCOMPARE(d.errors.size(), std::size_t(1));
        QVERIFY(QString::fromStdString(d.errors[0].reason).contains("B07"));

        auto none = loadDataSet(dir.filePath("nope").toStdString());
        QVERIFY(!none.ok());
    }

    void cancelStopsLoading() {
        QTemporaryDir dir;
        writeText(dir.filePath("a.csv"), goodFile());
        auto r = loadDataSet(dir.path().toStdString(), {},
                             [](const ProgressInfo&) { return ProgressAction::Stop; });
        QVERIFY(r.cancelled);
        QVERIFY(r.dataSet.batches.empty());
    }

    void atomicWriteReplacesAndFailsCleanly() {
        QTemporaryDir dir;
        auto b = parseBatchText(goodFile(), "w.csv");
        const std::string path = dir.filePath("out.csv").toStdString();
        QVERIFY(writeBatchFile(*b, path).ok());
        auto back = readBatchFile(path);
        QVERIFY(back.ok());
        QCOMPARE(back->rows(), b->rows());
        auto bad = writeBatchFile(*b, dir.filePath("no/such/dir/out.csv").toStdString());
        QVERIFY(!bad.ok());
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size() == 1); // no temp left
    }

    void cleaningRulesOfThePaper() {
        std::string s = std::string(kHeader) + "\n" + row(0) + "\n" + row(1, 12.8, 5000) + "\n" +
                        row(2, 12.8, 6200, 10.5) + "\n" + row(3, 12.8, 6200, 14, 45) + "\n" +
                        "4,170,169.5,16,6200,22,25,24,55,14,58,,55\n";
        DataSet ds;
        ds.batches.push_back(*parseBatchText(s, "c.csv"));
        auto rep = clean(ds);
        QCOMPARE(rep.kept, std::size_t(1));
        QCOMPARE(rep.droppedFeed, std::size_t(1));
        QCOMPARE(rep.droppedXhdt, std::size_t(1));
        QCOMPARE(rep.droppedThdt, std::size_t(1));
        QCOMPARE(rep.droppedMissing, std::size_t(1));
        CleaningOptions loose;
        loose.minFeedKgPerHour = 0;
        loose.minXhdtPct = 0;
        loose.minThdtC = 0;
        QCOMPARE(clean(ds, loose).kept, std::size_t(4));
        CleaningOptions invalid;
        invalid.minXhdtPct = 120;
        QVERIFY(!invalid.validate().ok());
    }

    void impossibleValuesAreListedDroppedAndNeverSimulated() {
        // Line 3 is the header; data rows are lines 4 … 9. RH 130 % on line 5, feed −50 kg/h on
        // line 7, an outlet moisture of 104 % wb on line 8.
        std::string text = "# batch: B09\n# line: 2\n" + std::string(kHeader) + "\n";
        for (int i = 0; i < 6; ++i) {
            std::string r = row(i, i == 4 ? 104.0 : 12.8, i == 3 ? -50.0 : 6200);
            if (i == 1) {
                r.replace(r.find(",24,55,"), 7, ",24,130,");
            }
            text += r + "\n";
        }
        QTemporaryDir dir;
        writeText(dir.filePath("B09.csv"), text);
        const auto loaded = loadDataSet(dir.path().toStdString());
        QVERIFY(loaded.ok());
        const DataSet* ds = &loaded.dataSet;
        const auto summary = summarize(*ds);
        QCOMPARE(summary.impossibleTotal, std::size_t(3));
        QCOMPARE(summary.impossible.size(), std::size_t(3));
        bool rh = false, feed = false, xOut = false;
        for (const auto& w : summary.impossible) {
            QVERIFY(QString::fromStdString(w.file).endsWith("B09.csv"));
            rh = rh || (w.column == "RH_amb_pct" && w.line == 5 && w.value == 130);
            feed = feed || (w.column == "feed_kg_h" && w.line == 7 && w.value == -50);
            xOut = xOut || (w.column == "X_out_pct" && w.line == 8 && w.value == 104);
        }
        QVERIFY(rh && feed && xOut);
        const auto c = clean(*ds);
        QCOMPARE(c.droppedImpossible, std::size_t(3));
        QCOMPARE(c.keep[0][1], std::uint8_t(0));
        QCOMPARE(c.keep[0][0], std::uint8_t(1));
        // The simulation never sees them: inputs bridged from the neighbours, the output missing.
        const auto si = toSi(*ds, c);
        QCOMPARE(si[0].rhAmb[1], 0.55);
        QVERIFY(si[0].feedKgPerS[3] > 0);
        QVERIFY(std::isnan(si[0].xOutDb[4]));
    }

    // A transmitter that hangs (the same reading for minutes) is no reading: its rows are dropped
    // from fits and an input is bridged like a dropout. A column that is often held by its
    // coarse resolution (a hall thermometer) is not taken for frozen.
    void frozenReadingsAreMaskedAndBridged() {
        std::string s = std::string(kHeader) + "\n";
        const auto feedAt = [](int i) { return 6200 + 40 * std::sin(0.05 * i) + (i % 2); };
        for (int i = 0; i < 600; ++i) {
            const double feed = i >= 200 && i < 300 ? feedAt(200) : feedAt(i);       // frozen 100 s
            const double xOut = i >= 400 && i < 480 ? 12.8 : 12.81 + 0.01 * (i % 7); // frozen 80 s
            const double tAmb = 24 + 0.1 * (i / 30);                                 // held 30 s at a time
            char line[256];
            std::snprintf(line, sizeof line, "%d,170,%.1f,16,%.4f,22,25,%.1f,55,14,58,%.2f,55.2\n", i,
                          169.5 + 0.1 * (i % 3), feed, tAmb, xOut);
            s += line;
        }
        DataSet ds;
        ds.batches.push_back(*parseBatchText(s, "frozen.csv"));
        const auto rep = clean(ds);
        QCOMPARE(rep.stuck.size(), std::size_t(2));
        QCOMPARE(rep.droppedStuck, std::size_t(180));
        bool feedSpan = false, xOutSpan = false;
        for (const auto& span : rep.stuck) {
            feedSpan = feedSpan || (span.column == Column::Feed && span.begin == 200 && span.end == 300 &&
                                    span.seconds == 99);
            xOutSpan = xOutSpan || (span.column == Column::XOut && span.begin == 400 && span.end == 480);
        }
        QVERIFY(feedSpan && xOutSpan);
        QCOMPARE(int(rep.keep[0][250]), 0);
        QCOMPARE(int(rep.keep[0][199]), 1);
        const auto si = toSi(ds, rep);
        // The frozen feed is bridged from its last reading before to its first after.
        const double before = feedAt(199) / 3600, after = feedAt(300) / 3600;
        QVERIFY(std::abs(si[0].feedKgPerS[250] - (before + (after - before) * 51.0 / 101.0)) <
                1e-7); // file: 4 decimals
        QVERIFY(std::isnan(si[0].xOutDb[450]));
        QVERIFY(!std::isnan(si[0].xOutDb[480]));
        // Switched off, nothing is masked; an impossible setting is refused.
        CleaningOptions off;
        off.maskStuck = false;
        QCOMPARE(clean(ds, off).droppedStuck, std::size_t(0));
        CleaningOptions bad;
        bad.stuckRunFactor = 0.5;
        QVERIFY(!bad.validate().ok());
    }

    void siConversionAndSplits() {
        std::string s = std::string(kHeader) + "\n";
        for (int i = 0; i < 100; ++i) {
            s += row(i) + "\n";
        }
        DataSet ds;
        ds.batches.push_back(*parseBatchText(s, "s.csv"));
        (*ds.batches[0].values(Column::THot))[10] = std::nan("");
        ds.batches[0].missing.push_back({12, 3, "T_hot_C"});
        const auto si = toSi(ds, clean(ds));
        QCOMPARE(si.size(), std::size_t(1));
        QCOMPARE(si[0].xOutDb[0], 0.128 / (1 - 0.128));
        QCOMPARE(si[0].tOutK[0], 55.2 + 273.15);
        QCOMPARE(si[0].feedKgPerS[0], 6200.0 / 3600.0);
        QCOMPARE(si[0].rhAmb[0], 0.55);
        QCOMPARE(si[0].tHotK[10], 169.5 + 273.15); // bridged ...
        QCOMPARE(int(si[0].keep[10]), 0);          // ... and masked out of fitting
        QCOMPARE(units::dryToWetPct(units::wetPctToDry(13.7)), 13.7);

        auto split = chronologicalSplit({6300, 6300, 6300, 6300, 6300, 6300, 6300, 6300, 6300, 6300});
        QCOMPARE(split.name, std::string("chronological_70_30"));
        QCOMPARE(split.train[6].size(), std::size_t(6300));
        QCOMPARE(split.train[7].size(), std::size_t(0));
        QCOMPARE(split.test[7].size(), std::size_t(6300));
        auto uneven = chronologicalSplit({10, 10, 5});
        QCOMPARE(uneven.train[1].end, std::size_t(7)); // floor(0.7*25) = 17 = 10 + 7
        QCOMPARE(uneven.test[1].begin, std::size_t(7));

        auto subset = calibrationSubset(si, 10, 5);
        QCOMPARE(subset.size(), std::size_t(5));
        QCOMPARE(subset[0].row, std::size_t(0));
        QCOMPARE(subset[1].row, std::size_t(11)); // row 10 masked, so the 10th kept row is row 11
    }
};

QTEST_APPLESS_MAIN(TestBatchReader)
#include "TestBatchReader.moc"
