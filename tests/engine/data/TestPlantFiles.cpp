// Plant files as historians export them (issue #25): each kind generated here, read, and checked
// for the right runs and rows; bad stamps, duplicates and clock jumps named with file:line.
#include "data/BatchReader.h"
#include "data/ColumnMapping.h"
#include "data/PlantFileReader.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <ctime>
#include <fstream>
#include <functional>

using namespace drytwin;
using namespace drytwin::data;

namespace {

/// The tags of a plant's historian, mapped to the contract's columns.
const char* kTagMapping = R"({
  "T_hot_C": "HDT_TT101.PV",
  "feed_kg_h": "FEED_WT201.PV",
  "X_in_pct": "NIR_XIN.PV",
  "T_amb_C": "HALL_TT301.PV",
  "RH_amb_pct": "HALL_MT302.PV",
  "X_out_pct": "NIR_XOUT.PV",
  "T_out_C": "WIN_TT401.PV"
})";
const char* kTags[] = {"HDT_TT101.PV",  "FEED_WT201.PV", "NIR_XIN.PV",  "HALL_TT301.PV",
                       "HALL_MT302.PV", "NIR_XOUT.PV",   "WIN_TT401.PV"};

/// Values of the seven tags at time t [s]; feed 0 during a line stop.
std::vector<double> tagValues(double t, bool stopped) {
    return {170 + 5 * std::sin(t / 300),
            stopped ? 0.0 : 6200 + 100 * std::sin(t / 700),
            22 + 0.5 * std::sin(t / 900),
            24,
            55,
            13 + 0.2 * std::sin(t / 400),
            55};
}

/// "2025-06-03 08:00:00" style stamps from epoch seconds, in the given strftime pattern.
std::string stamp(double epoch, const char* pattern) {
    const auto t = static_cast<time_t>(epoch);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[64];
    std::strftime(buf, sizeof buf, pattern, &tm);
    return buf;
}

std::string number(double v, bool decimalComma) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s(buf);
    if (decimalComma) {
        std::replace(s.begin(), s.end(), '.', ',');
    }
    return s;
}

struct FileSpec {
    char delimiter = ',';
    bool decimalComma = false;
    std::string timeHeader = "Timestamp";
    std::function<std::string(double)> timeCell;
    std::string unitsRow; ///< without the time column's cell
    std::string batchHeader;
    std::function<std::string(double)> batchOf;
};

/// A historian export from t0 (epoch s), @p n samples @p periodS apart; @p stopped marks line stops.
std::string historianFile(const FileSpec& f, double t0, int n, double periodS,
                          const std::function<bool(double)>& stopped = {}) {
    const std::string d(1, f.delimiter);
    std::string s = f.timeHeader;
    if (!f.batchHeader.empty()) {
        s += d + f.batchHeader;
    }
    for (const char* tag : kTags) {
        s += d + tag;
    }
    s += "\n";
    if (!f.unitsRow.empty()) {
        s += f.unitsRow + "\n";
    }
    for (int i = 0; i < n; ++i) {
        const double t = t0 + i * periodS;
        s += f.timeCell(t);
        if (!f.batchHeader.empty()) {
            s += d + f.batchOf(t);
        }
        for (double v : tagValues(t - t0, stopped && stopped(t - t0))) {
            s += d + number(v, f.decimalComma);
        }
        s += "\n";
    }
    return s;
}

ReadOptions tagOptions(const std::string& extra = {}) {
    QTemporaryDir dir;
    const std::string path = dir.filePath("m.json").toStdString();
    std::string json = kTagMapping;
    if (!extra.empty()) {
        json.insert(json.size() - 1, "," + extra);
    }
    std::ofstream(path) << json;
    auto m = readColumnMapping(path);
    if (!m) {
        qFatal("%s", m.error().message().c_str());
    }
    ReadOptions o;
    o.mapping = *m;
    return o;
}

constexpr double kJune3 = 1748937600; // 2025-06-03T08:00:00Z

} // namespace

class TestPlantFiles : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // ISO stamps, ';' and decimal commas, no batch column: one shift with a 10-min line stop is two runs.
    void isoSemicolonDecimalCommaSplitAtLineStop() {
        FileSpec f;
        f.delimiter = ';';
        f.decimalComma = true;
        f.timeCell = [](double t) { return stamp(t, "%Y-%m-%d %H:%M:%S"); };
        const std::string text =
            historianFile(f, kJune3, 4000, 1.0, [](double t) { return t >= 1500 && t < 2100; });
        auto r = parsePlantText(text, "shift.csv", tagOptions());
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QVERIFY(r->shape.historian);
        QCOMPARE(r->shape.delimiter, ';');
        QVERIFY(r->shape.decimalComma);
        QCOMPARE(r->shape.timeFormat, TimeFormat::Iso8601);
        QCOMPARE(r->runs.size(), std::size_t(2));
        QCOMPARE(r->runs[0].rows(), std::size_t(1500));
        QCOMPARE(r->runs[1].rows(), std::size_t(1900));
        QCOMPARE(r->runs[0].id, std::string("shift_R01"));
        QCOMPARE(r->runs[0].run->firstLine, 2);
        QCOMPARE(r->runs[0].run->lastLine, 1501);
        QCOMPARE(r->runs[0].run->splitReason, std::string("line stop"));
        QCOMPARE(r->runs[1].run->firstLine, 2102);
        QCOMPARE(r->runs[1].run->startTimestamp, std::string("2025-06-03T08:35:00"));
        QCOMPARE(r->runs[1].metadata("start"), std::string("2025-06-03T08:35:00"));
        // Values arrive in contract units, decimal commas read.
        const auto* xIn = r->runs[1].values(Column::XIn);
        QVERIFY(xIn);
        QVERIFY(std::abs((*xIn)[0] - tagValues(2100, false)[2]) < 1e-3);
        QCOMPARE(r->runs[1].values(Column::Time)->back(), 1899.0);
        QCOMPARE(r->runs[0].run->interpolatedCells, std::size_t(0));
    }

    // Excel serial days with a batch column: each batch its own run, named by it.
    void excelDatesWithBatchColumn() {
        FileSpec f;
        f.timeCell = [](double t) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.8f", t / 86400.0 + 25569.0);
            return std::string(buf);
        };
        f.timeHeader = "Date";
        f.batchHeader = "Batch";
        f.batchOf = [](double t) { return t < kJune3 + 1200 ? std::string("L0612") : std::string("L0613"); };
        const std::string text = historianFile(f, kJune3, 3000, 1.0);
        auto r = parsePlantText(text, "excel.csv", tagOptions(R"("batch_id": {"header": "Batch"})"));
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->shape.timeFormat, TimeFormat::ExcelDays);
        QCOMPARE(r->runs.size(), std::size_t(2));
        QCOMPARE(r->runs[0].id, std::string("L0612"));
        QCOMPARE(r->runs[1].id, std::string("L0613"));
        QCOMPARE(r->runs[0].rows(), std::size_t(1200));
        QCOMPARE(r->runs[1].rows(), std::size_t(1800));
        QCOMPARE(r->runs[0].run->splitReason, std::string("batch id"));
        QCOMPARE(r->runs[1].run->startTimestamp, std::string("2025-06-03T08:20:00"));
    }

    // Unix seconds every 5 s: resampled to the model's 1 s with the interpolated cells counted.
    void epochSecondsAtFiveSecondsAreResampled() {
        FileSpec f;
        f.delimiter = '\t';
        f.timeHeader = "time";
        f.timeCell = [](double t) { return number(t, false); };
        const std::string text = historianFile(f, kJune3, 400, 5.0);
        auto r = parsePlantText(text, "epoch.tsv", tagOptions());
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->shape.timeFormat, TimeFormat::EpochSeconds);
        QCOMPARE(r->runs.size(), std::size_t(1));
        const auto& b = r->runs[0];
        QCOMPARE(b.rows(), std::size_t(1996)); // 399 intervals of 5 s, and the last sample
        QCOMPARE(b.run->samples, std::size_t(400));
        QCOMPARE(b.run->interpolatedCells, std::size_t(399 * 4 * 7)); // 4 of every 5 grid rows, 7 columns
        const auto* tHot = b.values(Column::THot);
        // Linear between samples: halfway between the samples at 0 and 5 s.
        QVERIFY(std::abs((*tHot)[2] - (0.6 * tagValues(0, false)[0] + 0.4 * tagValues(5, false)[0])) < 1e-3);
        QCOMPARE(b.lineOfRow[7], 3); // the sample at 5 s is on line 3
    }

    // A units row under the header: °F and t/h converted to the contract's units.
    void unitsRowIsHonoured() {
        FileSpec f;
        f.timeCell = [](double t) { return stamp(t, "%d.%m.%Y %H:%M:%S"); };
        f.unitsRow = ",degF,t/h,%,°C,%,%,°C";
        const std::string text = historianFile(f, kJune3, 600, 1.0);
        auto r = parsePlantText(text, "units.csv", tagOptions());
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QVERIFY(r->shape.unitsRow);
        QCOMPARE(r->shape.timeFormat, TimeFormat::DmyDot);
        const auto& b = r->runs[0];
        QVERIFY(std::abs((*b.values(Column::THot))[0] - (tagValues(0, false)[0] - 32) * 5 / 9) < 1e-3);
        QVERIFY(std::abs((*b.values(Column::Feed))[0] - tagValues(0, false)[1] * 1000) < 1e-3);
        QCOMPARE(b.run->firstLine, 3); // header, units row, then data
        // A unit the column cannot have is named with its place.
        f.unitsRow = ",degF,t/h,%,m/s,%,%,°C";
        auto bad = parsePlantText(historianFile(f, kJune3, 600, 1.0), "units.csv", tagOptions());
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error().message().find("units.csv:2:5") != std::string::npos,
                 bad.error().message().c_str());
    }

    void badStampDuplicateAndClockJumpNamedWithTheirLine() {
        FileSpec f;
        f.delimiter = ';';
        f.timeCell = [](double t) { return stamp(t, "%Y-%m-%dT%H:%M:%S"); };
        std::string text = historianFile(f, kJune3, 1200, 1.0);
        // Line 11 gets a stamp of another form, then one of a day that does not exist.
        std::size_t line11 = 0;
        for (int line = 1; line < 11; ++line) {
            line11 = text.find('\n', line11) + 1;
        }
        std::string bad = text;
        bad.replace(line11, 19, "2025-06-03 at 08:09");
        auto r = parsePlantText(bad, "stamps.csv", tagOptions());
        QVERIFY(!r.ok());
        QVERIFY2(r.error().message().find("stamps.csv:11:1: bad time stamp '2025-06-03 at 08:09'") == 0,
                 r.error().message().c_str());
        bad = text;
        bad.replace(line11, 19, "2025-06-31T08:00:09");
        auto impossible = parsePlantText(bad, "stamps.csv", tagOptions());
        QVERIFY(!impossible.ok());
        QCOMPARE(
            impossible.error().message(),
            std::string("stamps.csv:11:1: impossible date or time '2025-06-31T08:00:09': June has 30 days. "
                        "The cell is damaged; correct or remove the row"));
        // A duplicate stamp: reported with its line, the row left out, nothing reordered.
        std::string dup;
        {
            const std::string plain = historianFile(f, kJune3, 1200, 1.0);
            std::size_t pos = 0;
            for (int line = 1; pos < plain.size(); ++line) {
                const auto nl = plain.find('\n', pos);
                const std::string l = plain.substr(pos, nl - pos + 1);
                dup += l;
                if (line == 20) {
                    dup += l; // line 21 repeats line 20's stamp and values
                }
                pos = nl + 1;
            }
        }
        auto d = parsePlantText(dup, "dup.csv", tagOptions());
        QVERIFY2(d.ok(), d ? "" : d.error().message().c_str());
        QCOMPARE(d->runs.size(), std::size_t(1));
        QCOMPARE(d->runs[0].rows(), std::size_t(1200));
        QCOMPARE(d->notes.size(), std::size_t(1));
        QVERIFY2(d->notes[0].find("dup.csv:21:1") != std::string::npos, d->notes[0].c_str());
        // The clock goes back an hour in the night daylight saving ends (26 October 2025, 03:00 to
        // 02:00 in central Europe): a new run from that line, reported.
        constexpr double kFallBackNight = 1761436800 + 3 * 3600 - 700; // 2025-10-26 02:48:20 local
        FileSpec g = f;
        g.timeCell = [](double t) {
            return stamp(t >= kFallBackNight + 700 ? t - 3600 : t, "%Y-%m-%dT%H:%M:%S");
        };
        auto j = parsePlantText(historianFile(g, kFallBackNight, 1200, 1.0), "dst.csv", tagOptions());
        QVERIFY2(j.ok(), j ? "" : j.error().message().c_str());
        QCOMPARE(j->runs.size(), std::size_t(2));
        QCOMPARE(j->runs[0].run->splitReason, std::string("clock jump"));
        QCOMPARE(j->runs[0].rows(), std::size_t(700));
        QCOMPARE(j->runs[1].rows(), std::size_t(500));
        QCOMPARE(j->runs[1].run->firstLine, 702);
        bool named = false;
        for (const auto& n : j->notes) {
            named = named || (n.find("dst.csv:702:1") != std::string::npos &&
                              n.find("clock goes back 3599 s") != std::string::npos);
        }
        QVERIFY2(named, j->notes.empty() ? "no notes" : j->notes[0].c_str());
    }

    // A gap in the stamps longer than the interpolation limit splits the run; a short one is bridged.
    void gapsSplitOrAreBridged() {
        FileSpec f;
        f.timeCell = [](double t) { return stamp(t, "%Y/%m/%d %H:%M:%S"); };
        std::string text = historianFile(f, kJune3, 700, 1.0);
        // Drop lines 302..306 (5 s: bridged) and lines 502..561 (60 s: split).
        std::vector<std::string> lines;
        std::size_t pos = 0;
        while (pos < text.size()) {
            const auto nl = text.find('\n', pos);
            lines.push_back(text.substr(pos, nl - pos));
            pos = nl + 1;
        }
        std::string cut;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const int line = static_cast<int>(i) + 1;
            if ((line >= 302 && line <= 306) || (line >= 502 && line <= 561)) {
                continue;
            }
            cut += lines[i] + "\n";
        }
        auto o = tagOptions(R"("runs": {"min_run_s": 100})");
        auto r = parsePlantText(cut, "gaps.csv", o);
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->runs.size(), std::size_t(2));
        QCOMPARE(r->runs[0].rows(), std::size_t(500));
        QCOMPARE(r->runs[0].run->interpolatedCells, std::size_t(5 * 7));
        QCOMPARE(r->runs[0].run->splitReason, std::string("gap"));
        QCOMPARE(r->runs[1].rows(), std::size_t(140));
    }

    // Loading a folder cuts a historian export into its runs; ambiguous dates ask for the format.
    void loadDataSetCutsRunsAndAmbiguousDatesAsk() {
        QTemporaryDir dir;
        FileSpec f;
        f.delimiter = ';';
        f.timeCell = [](double t) { return stamp(t, "%Y-%m-%dT%H:%M:%SZ"); };
        std::ofstream(dir.filePath("a_shift.csv").toStdString())
            << historianFile(f, kJune3, 2000, 1.0, [](double t) { return t >= 800 && t < 1000; });
        auto loaded = loadDataSet(dir.path().toStdString(), tagOptions());
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.dataSet.batches.size(), std::size_t(2));
        FileSpec g;
        g.timeCell = [](double t) { return stamp(t, "%m/%d/%Y %H:%M:%S"); };
        auto amb = parsePlantText(historianFile(g, kJune3, 50, 1.0), "us.csv", tagOptions());
        QVERIFY(!amb.ok());
        QVERIFY2(amb.error().message().find("m/d/Y") != std::string::npos, amb.error().message().c_str());
        auto told = parsePlantText(historianFile(g, kJune3, 400, 1.0), "us.csv",
                                   tagOptions(R"("time_s": {"header": "Timestamp", "format": "m/d/Y"})"));
        QVERIFY2(told.ok(), told ? "" : told.error().message().c_str());
        QCOMPARE(told->runs[0].run->startTimestamp, std::string("2025-06-03T08:00:00"));
    }

    // Quoted fields (an Excel export quotes headers and text) and cancel in the middle of a file.
    void quotedFieldsAndCancel() {
        FileSpec f;
        f.delimiter = ';';
        f.decimalComma = true;
        f.timeCell = [](double t) { return "\"" + stamp(t, "%Y-%m-%d %H:%M:%S") + "\""; };
        std::string text = historianFile(f, kJune3, 600, 1.0);
        const auto firstNl = text.find('\n');
        std::string quoted = "\"Timestamp\"";
        for (const char* tag : kTags) {
            quoted += ";\"" + std::string(tag) + "\"";
        }
        text.replace(0, firstNl, quoted);
        auto r = parsePlantText(text, "quoted.csv", tagOptions());
        QVERIFY2(r.ok(), r ? "" : r.error().message().c_str());
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(600));
        QVERIFY(std::abs((*r->runs[0].values(Column::XOut))[0] - tagValues(0, false)[5]) < 1e-3);
        // A long file stops where the user cancels (progress is reported per megabyte).
        const std::string big = historianFile(f, kJune3, 40000, 1.0);
        int calls = 0;
        auto c = parsePlantText(big, "big.csv", tagOptions(), [&](const ProgressInfo&) {
            return ++calls >= 2 ? ProgressAction::Stop : ProgressAction::Continue;
        });
        QVERIFY(!c.ok());
        QCOMPARE(c.error().kind, ErrorKind::Cancelled);
    }

    void timeCellsOfEveryFormat() {
        double s = 0;
        QVERIFY(parseTimeCell("2025-06-03T08:00:00.250+02:00", TimeFormat::Iso8601, s));
        QCOMPARE(s, kJune3 - 7200 + 0.25);
        QVERIFY(parseTimeCell("2025-06-03 08:00", TimeFormat::Iso8601, s));
        QCOMPARE(s, kJune3);
        QVERIFY(parseTimeCell("03.06.2025 08:00:00", TimeFormat::DmyDot, s));
        QCOMPARE(s, kJune3);
        QVERIFY(parseTimeCell("45811.3333333333", TimeFormat::ExcelDays, s));
        QVERIFY(std::abs(s - kJune3) < 0.01);
        QVERIFY(parseTimeCell("1748937600000", TimeFormat::EpochMillis, s));
        QCOMPARE(s, kJune3);
        QVERIFY(!parseTimeCell("2025-02-29T00:00:00", TimeFormat::Iso8601, s)); // not a leap year
        QVERIFY(!parseTimeCell("yesterday", TimeFormat::Iso8601, s));
    }
};

QTEST_APPLESS_MAIN(TestPlantFiles)
#include "TestPlantFiles.moc"
