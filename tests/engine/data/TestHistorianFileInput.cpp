// What a plant file and its column mapping say before a time stamp is read (issue #72, items 14,
// 15 and 16): a line without end refused as it is read, with memory bounded whatever the file's
// size; a pipe-delimited export read; a mapping's wrong value named at its line and column.
#include "data/BatchReader.h"
#include "data/ColumnMapping.h"
#include "data/PlantFileReader.h"
#include "data/historian/CsvLines.h"
#include "data/historian/JsonPlaces.h"
#include "data/historian/LineLengthGuard.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <istream>
#include <streambuf>
#include <sys/resource.h>

using namespace drytwin;
using namespace drytwin::data;

namespace {

/// A stream of @p head followed by @p character for ever (a file without line breaks of any size),
/// counting what the reader took.
class EndlessLine : public std::streambuf {
public:
    EndlessLine(std::string head, const std::string& character) : m_head(std::move(head)) {
        while (m_block.size() < (std::size_t(1) << 16)) {
            m_block += character;
        }
    }
    std::size_t bytesGiven() const { return m_given; }

protected:
    int_type underflow() override {
        std::string& next = m_headGiven ? m_block : m_head;
        m_headGiven = true;
        setg(next.data(), next.data(), next.data() + next.size());
        m_given += next.size();
        return traits_type::to_int_type(next.front());
    }

private:
    std::string m_head, m_block;
    bool m_headGiven = false;
    std::size_t m_given = 0;
};

std::string utf16(const std::string& ascii, bool littleEndian) {
    std::string out;
    for (char c : ascii) {
        out += littleEndian ? std::string{c, '\0'} : std::string{'\0', c};
    }
    return out;
}

/// The peak resident memory of this process so far, in MiB.
double peakResidentMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

const char* const kTags[] = {"HDT_TT101.PV",  "FEED_WT201.PV", "NIR_XIN.PV",  "HALL_TT301.PV",
                             "HALL_MT302.PV", "NIR_XOUT.PV",   "WIN_TT401.PV"};

/// A shift of the seven tags, ISO stamps one second apart, with @p delimiter.
std::string shiftText(int rows, char delimiter) {
    const std::string d(1, delimiter);
    std::string s = "Timestamp";
    for (const char* tag : kTags) {
        s += d + tag;
    }
    s += "\n";
    for (int i = 0; i < rows; ++i) {
        char line[200];
        std::snprintf(line, sizeof line, "2025-06-03 08:%02d:%02d%s%.3f%s%.3f%s22.000%s24%s55%s13.000%s55",
                      i / 60, i % 60, d.c_str(), 170 + 5 * std::sin(i / 300.0), d.c_str(),
                      6200 + 100 * std::sin(i / 700.0), d.c_str(), d.c_str(), d.c_str(), d.c_str(),
                      d.c_str());
        s += std::string(line) + "\n";
    }
    return s;
}

ReadOptions sevenTags() {
    auto m = readColumnMappingText(R"({"time_s": {"header": "Timestamp"}, "T_hot_C": "HDT_TT101.PV",
        "feed_kg_h": "FEED_WT201.PV", "X_in_pct": "NIR_XIN.PV", "T_amb_C": "HALL_TT301.PV",
        "RH_amb_pct": "HALL_MT302.PV", "X_out_pct": "NIR_XOUT.PV", "T_out_C": "WIN_TT401.PV"})",
                                   "tags.json");
    if (!m) {
        qFatal("%s", m.error().message().c_str());
    }
    ReadOptions o;
    o.mapping = *m;
    return o;
}

#define VERIFY_OK(r) QVERIFY2((r).ok(), (r) ? "" : (r).error().message().c_str())

} // namespace

class TestHistorianFileInput : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // 15. A line longer than the limit stops the reading there: from a stream without end, the
    // reader takes the limit and one chunk, and names the line, in every encoding and line end.
    void aLineWithoutEndStopsTheReading_data() {
        QTest::addColumn<QByteArray>("head"); // two short lines before the endless third
        QTest::addColumn<QByteArray>("character");
        QTest::addColumn<int>("bytesPerCharacter");
        QTest::newRow("UTF-8, \\n") << QByteArray("Timestamp;A\n2025-06-03 08:00:00;1\n") << QByteArray("7")
                                    << 1;
        QTest::newRow("UTF-8 BOM, \\r\\n")
            << QByteArray("\xEF\xBB\xBFTimestamp;A\r\n1;2\r\n") << QByteArray("7") << 1;
        QTest::newRow("classic Mac OS, \\r") << QByteArray("Timestamp;A\r1;2\r") << QByteArray("7") << 1;
        QTest::newRow("zeros after the header") << QByteArray("Timestamp;A\n\n") << QByteArray(1, '\0') << 1;
        // UTF-16 is counted in characters: the limit in characters is twice as many bytes.
        const std::string lines = "Timestamp\tA\r\n1\t2\r\n";
        const std::string le = "\xFF\xFE" + utf16(lines, true), be = utf16(lines, false);
        QTest::newRow("UTF-16 LE with BOM")
            << QByteArray(le.data(), int(le.size())) << QByteArray("7\0", 2) << 2;
        QTest::newRow("UTF-16 BE without BOM") << QByteArray(be.data(), int(be.size()))
                                               << QByteArray("\0"
                                                             "7",
                                                             2)
                                               << 2;
    }
    void aLineWithoutEndStopsTheReading() {
        QFETCH(QByteArray, head);
        QFETCH(QByteArray, character);
        QFETCH(int, bytesPerCharacter);
        const std::size_t limit = 100000;
        EndlessLine source(std::string(head.constData(), std::size_t(head.size())),
                           std::string(character.constData(), std::size_t(character.size())));
        std::istream in(&source);
        auto text = historian::readWithLineLimit(in, "endless.csv", limit);
        QVERIFY(!text.ok());
        QCOMPARE(
            text.error().message(),
            std::string("endless.csv:3:1: line 3 is longer than 97.7 KiB, the most a line of a plant file "
                        "may hold; reading stopped there. The line breaks are missing, or this is not a "
                        "CSV export (export the data again as CSV or text, one sample per line)"));
        // The limit (in characters) and at most one chunk of 64 KiB more: not the file.
        QVERIFY2(source.bytesGiven() <= head.size() + limit * std::size_t(bytesPerCharacter) + (2u << 16),
                 std::to_string(source.bytesGiven()).c_str());
    }

    // Chunk borders change nothing: a line end split across two chunks ends one line; a line of
    // exactly the limit passes, one byte more does not.
    void theGuardCountsLinesAcrossChunks_data() {
        QTest::addColumn<int>("chunk");
        for (int chunk : {1, 2, 3, 7, 4096}) {
            QTest::newRow(qPrintable(QString("%1 byte(s)").arg(chunk))) << chunk;
        }
    }
    void theGuardCountsLinesAcrossChunks() {
        QFETCH(int, chunk);
        const std::string atLimit(16, 'x');
        const std::string text = "a\r\nb\rc\n\n" + atLimit + "\r\n" + atLimit + "y\n";
        historian::LineLengthGuard guard("g.csv", 16);
        Status st;
        for (std::size_t p = 0; p < text.size() && st.ok(); p += std::size_t(chunk)) {
            st = guard.feed(std::string_view(text).substr(p, std::size_t(chunk)));
        }
        QVERIFY(!st.ok());
        QCOMPARE(st.error().place, std::string("g.csv:6:1"));
    }

    // A file on disk: the same refusal from readPlantFile and readBatchFile, with the file's size,
    // and a 600 MiB file of one line (sparse: no disk space) is refused without 600 MiB of memory.
    void aFileWithoutLineBreaksIsRefusedAsItIsRead() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = (std::filesystem::path(dir.path().toStdString()) / "long.csv").string();
        {
            std::ofstream out(path, std::ios::binary);
            out << "Timestamp;HDT_TT101.PV\n" << std::string(3u << 20, '1') << "\n";
        }
        const std::string expected = path + ":2:1: line 2 is longer than 1.0 MiB, the most a line of a plant "
                                            "file may hold; reading stopped there (the file is 3.0 MiB)";
        auto plant = readPlantFile(path);
        QVERIFY(!plant.ok());
        QCOMPARE(plant.error().message().substr(0, expected.size()), expected);
        auto batch = readBatchFile(path);
        QVERIFY(!batch.ok());
        QCOMPARE(batch.error().message().substr(0, expected.size()), expected);
        QCOMPARE(exitCodeFor(plant.error().kind), 3);

        const std::string huge = (std::filesystem::path(dir.path().toStdString()) / "huge.csv").string();
        {
            std::ofstream out(huge, std::ios::binary);
            out << "Timestamp;HDT_TT101.PV\n";
        }
        std::filesystem::resize_file(huge, std::uintmax_t(600) << 20);
        const double peakBefore = peakResidentMiB();
        auto refused = readPlantFile(huge);
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message().find(huge + ":2:1: line 2 is longer than 1.0 MiB") == 0 &&
                     refused.error().message().find("(the file is 600.0 MiB)") != std::string::npos,
                 refused.error().message().c_str());
        // Read whole, the file alone would raise the peak past 600 MiB.
        QVERIFY2(peakResidentMiB() < std::max(peakBefore, 100.0) + 50.0,
                 qPrintable(QString("peak %1 MiB, %2 MiB before").arg(peakResidentMiB()).arg(peakBefore)));
    }

    // A preview reads the file's head only, cut after its last whole line.
    void aPreviewReadsTheHeadOnly() {
        QTemporaryDir dir;
        const std::string path = (std::filesystem::path(dir.path().toStdString()) / "shift.csv").string();
        const std::string text = shiftText(400, ';');
        {
            std::ofstream out(path, std::ios::binary);
            out << text;
        }
        auto head = readPlantFileHead(path, 1000);
        VERIFY_OK(head);
        QVERIFY(head->size() <= 1000 && head->size() > 800);
        QCOMPARE(head->back(), '\n');
        QCOMPARE(*head, text.substr(0, head->size()));
        auto all = readPlantFileHead(path, 0);
        VERIFY_OK(all);
        QCOMPARE(*all, text);
        auto exact = readPlantFileHead(path, text.size());
        VERIFY_OK(exact);
        QCOMPARE(*exact, text);
    }

    // 16. A pipe-delimited export is read as the same export with semicolons is; a pipe inside
    // the tag names of a comma file leaves it a comma file.
    void aPipeDelimitedExportIsRead() {
        auto pipe = parsePlantText(shiftText(400, '|'), "pipe.csv", sevenTags());
        VERIFY_OK(pipe);
        auto semicolon = parsePlantText(shiftText(400, ';'), "semicolon.csv", sevenTags());
        VERIFY_OK(semicolon);
        QCOMPARE(pipe->shape.delimiter, '|');
        QCOMPARE(pipe->runs.size(), std::size_t(1));
        QCOMPARE(pipe->runs[0].rows(), std::size_t(400));
        QCOMPARE(*pipe->runs[0].values(Column::THot), *semicolon->runs[0].values(Column::THot));
        QCOMPARE(*pipe->runs[0].values(Column::Feed), *semicolon->runs[0].values(Column::Feed));
        std::string shortRow = shiftText(400, '|');
        shortRow.replace(shortRow.find("\n2025-06-03 08:01:40|"), 21, "\n2025-06-03 08:01:40;");
        auto bad = parsePlantText(shortRow, "pipe.csv", sevenTags());
        QVERIFY(!bad.ok());
        QCOMPARE(bad.error().message(),
                 std::string("pipe.csv:102:8: expected 8 fields as in the header, found 7 (pipe-separated)"));
        const std::string commaWithPipes = "Timestamp,L1|TT101,L1|FT201\n2025-06-03 08:00:00,1,2\n";
        QCOMPARE(historian::detectDelimiter(commaWithPipes.substr(0, commaWithPipes.find('\n'))), ',');
    }

    // 14. What a valid JSON mapping says wrong is named at the line and column of the value (or
    // of the key, when the key is what is wrong).
    void mappingErrorsNameTheirPlace_data() {
        QTest::addColumn<QString>("json");
        QTest::addColumn<QString>("expected");
        QTest::newRow("unknown contract column")
            << "{\n  \"time_s\": \"Timestamp\",\n  \"T_hot\": \"HDT_TT101.PV\"\n}"
            << "m.json:3:3: 'T_hot' is neither a column of the batch format (CONTRACT.md §1) nor a key of "
               "the "
               "column mapping (batch_id, runs, decimal_mark); did you mean 'T_hot_C'?";
        QTest::newRow("unknown time format")
            << "{\n  \"time_s\": {\"header\": \"Timestamp\", \"format\": \"excel\"}\n}"
            << "m.json:2:47: the time format 'excel' is not one of seconds, iso8601, Y/m/d, d.m.Y, d/m/Y, "
               "m/d/Y, "
               "d-Mon-Y, excel_days, epoch_s, epoch_ms";
        QTest::newRow("unknown unit")
            << "{\"T_hot_C\": \"A\",\n \"T_out_C\": {\"header\": \"B\",\n              \"unit\": "
               "\"Celsius\"}}"
            << "m.json:3:23: unit 'Celsius' of 'T_out_C' is not one of degC, degF, K";
        QTest::newRow("unit of an escaped key")
            << "{\"T_hot\\u005fC\": {\"header\": \"A\", \"unit\": \"kg/h\"}}"
            << "m.json:1:42: unit 'kg/h' of 'T_hot_C' is not one of degC, degF, K";
        QTest::newRow("an array instead of an object")
            << "\n  [\"T_hot_C\", \"HDT_TT101.PV\"]\n"
            << "m.json:2:3: a column mapping must be a JSON object ({\"<contract column>\": \"<header>\", "
               "…}), "
               "not an array";
        QTest::newRow("a header that is a number") << "{\n  \"X_out_pct\": 12\n}"
                                                   << "m.json:2:16: the value for 'X_out_pct' must be a "
                                                      "header or {\"header\": …, \"unit\": …}, not a "
                                                      "number";
        QTest::newRow("an object without a header") << "{\n  \"X_out_pct\": {\"unit\": \"% wb\"}\n}"
                                                    << "m.json:2:16: the value for 'X_out_pct' must be a "
                                                       "header or {\"header\": …, \"unit\": …}; this "
                                                       "object has no \"header\"";
        QTest::newRow("the same header twice")
            << "{\n  \"T_out_C\": \"WIN_TT401.PV\",\n  \"T_hdt_C\": \"WIN_TT401.PV\"\n}"
            << "m.json:3:14: file header 'WIN_TT401.PV' is mapped to two contract columns ('T_hdt_C' and "
               "'T_out_C')";
        QTest::newRow("runs: a step of 0 s")
            << "{\"T_hot_C\": \"A\", \"runs\": {\n  \"min_run_s\": 300,\n  \"step_s\": 0}}"
            << "m.json:3:13: runs.step_s: must lie in (0, 60] s";
        QTest::newRow("runs: a negative threshold") << "{\"runs\": {\"min_stop_s\": -5}}"
                                                    << "m.json:1:25: runs.min_stop_s: must not be negative";
        QTest::newRow("runs: an unknown key")
            << "{\"runs\": {\"step\": 2}}"
            << "m.json:1:11: runs.step is not one of step_s, line_stop_feed_kg_h, min_stop_s, "
               "max_interpolated_gap_s, min_run_s";
        QTest::newRow("runs: text for a number") << "{\"runs\": {\"step_s\": \"1\"}}"
                                                 << "m.json:1:21: runs.step_s must be a number, not a string";
        QTest::newRow("decimal mark") << "{\n\"decimal_mark\": \";\"}"
                                      << "m.json:2:17: \"decimal_mark\" must be \".\" or \",\"";
        QTest::newRow("batch column as a string")
            << "{\"batch_id\": \"Charge\"}"
            << "m.json:1:14: \"batch_id\" must be {\"header\": \"<column>\"}";
    }
    void mappingErrorsNameTheirPlace() {
        QFETCH(QString, json);
        QFETCH(QString, expected);
        auto m = readColumnMappingText(json.toStdString(), "m.json");
        QVERIFY(!m.ok());
        QCOMPARE(QString::fromStdString(m.error().message()), expected);
        QCOMPARE(exitCodeFor(m.error().kind), 3);
    }

    // An empty format leaves the time column to detection, as it did before the checks had places.
    void anEmptyTimeFormatIsLeftToDetection() {
        auto m = readColumnMappingText(R"({"time_s": {"header": "Timestamp", "format": ""}})", "m.json");
        VERIFY_OK(m);
        QCOMPARE(m->timeFormat, std::string());
    }

    // The index the places come from: values, keys and the fallback to the enclosing value.
    void jsonPlacesFindValuesAndKeys() {
        const std::string text = "{\"a\": {\"b/c\": [1, {\"d\": true}]}, \"e~\": \"x\"}";
        const historian::JsonPlaces places(text);
        QCOMPARE(places.valueAt("/a/b~1c/1/d"), text.find("true"));
        QCOMPARE(places.keyAt("/a/b~1c"), text.find("\"b/c\""));
        QCOMPARE(places.valueAt("/e~0"), text.find("\"x\""));
        QCOMPARE(places.valueAt("/a/missing"), text.find("{\"b/c\""));
        QCOMPARE(places.valueAt(""), std::size_t(0));
    }
};

QTEST_APPLESS_MAIN(TestHistorianFileInput)
#include "TestHistorianFileInput.moc"
