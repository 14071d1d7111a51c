// Historian exports that loaded wrong or not at all (issue #43, items 1–7), and the proof that every
// export format gives the same cells as the same batch written in the contract's form.
#include "data/BatchReader.h"
#include "data/ColumnMapping.h"
#include "data/DataSetSummary.h"
#include "data/PlantFileReader.h"
#include "data/SiBatch.h"
#include "data/historian/NumberFormat.h"
#include "physics/LineInputs.h"

#include "data/MappingGuess.h"
#include <QString>

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>

using namespace drytwin;
using namespace drytwin::data;

namespace {

/// A tag of the plant's historian for every contract column, and the unit its units row names.
struct Tag {
    Column column;
    const char* tag;
    const char* unit;
};
const Tag kTags[] = {
    {Column::THotSp, "HDT_TC101.SP", "°C"},    {Column::THot, "HDT_TT101.PV", "°C"},
    {Column::AirSpeed, "HDT_ST102.PV", "m/s"}, {Column::Feed, "FEED_WT201.PV", "kg/h"},
    {Column::XIn, "NIR_XIN.PV", "%"},          {Column::TIn, "FEED_TT202.PV", "°C"},
    {Column::TAmb, "HALL_TT301.PV", "°C"},     {Column::RHAmb, "HALL_MT302.PV", "%"},
    {Column::XHdt, "HDT_MT103.PV", "%"},       {Column::THdt, "HDT_TT104.PV", "°C"},
    {Column::XOut, "NIR_XOUT.PV", "%"},        {Column::TOut, "WIN_TT401.PV", "°C"},
};
constexpr int kRows = 420;

/// The value of tag @p k at second @p i; NaN where the historian had no value (a PI state).
double valueAt(int k, int i) {
    if ((k == 6 && i == 50) || (k == 10 && (i == 120 || i == 121)) || (k == 3 && i == 333)) {
        return std::nan("");
    }
    switch (kTags[k].column) {
    case Column::Feed:
        return i < 200 ? 600.0 + 29.5 * i : 6400 + 150 * std::sin(i / 70.0); // a start-up ramp below 1,000
    case Column::THotSp:
        return 170;
    case Column::THot:
        return 170 + 5 * std::sin(i / 30.0);
    case Column::AirSpeed:
        return 16 + 0.25 * std::sin(i / 40.0);
    case Column::XIn:
        return 22 + 0.5 * std::sin(i / 90.0);
    case Column::TIn:
        return 25.125;
    case Column::TAmb:
        return 24 + 0.1 * std::sin(i / 200.0);
    case Column::RHAmb:
        return 55.5;
    case Column::XHdt:
        return 14 + 0.3 * std::sin(i / 50.0);
    case Column::THdt:
        return 58 + std::sin(i / 60.0);
    case Column::XOut:
        return 13 + 0.2 * std::sin(i / 40.0);
    default:
        return 55 + 0.5 * std::sin(i / 45.0);
    }
}

/// "%.3f" with a decimal @p mark and, when @p thousands, the other mark grouping thousands.
std::string number(double v, char mark = '.', char thousands = 0) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string s(buf);
    const auto dot = s.find('.');
    s[dot] = mark;
    if (thousands != 0) {
        const std::size_t digitsStart = s[0] == '-' ? 1 : 0;
        for (std::size_t p = dot; p > digitsStart + 3; p -= 3) {
            s.insert(p - 3, 1, thousands);
        }
    }
    return s;
}

std::string strftimeUtc(double epoch, const char* pattern) {
    const auto t = static_cast<time_t>(epoch);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[64];
    std::strftime(buf, sizeof buf, pattern, &tm);
    return buf;
}

constexpr double kJune3 = 1748908800; // 2025-06-03T00:00:00Z

/// How one kind of export writes the same shift.
struct ExportFormat {
    char delimiter = ';';
    char decimal = '.';
    char thousands = 0;
    bool quoteNumbers = false;
    bool unitsRow = false;
    std::string timeHeader = "Timestamp";
    std::function<std::string(int)> stamp;
    std::string encoding = "UTF-8"; ///< UTF-8, UTF-8 BOM, Windows-1252, UTF-16LE(+BOM), UTF-16BE(+BOM)
    std::string state = "No Data";  ///< what a cell without a value holds
};

std::string contractText() {
    std::string s = "time_s";
    for (const auto& t : kTags) {
        s += "," + std::string(spec(t.column).name);
    }
    s += "\n";
    for (int i = 0; i < kRows; ++i) {
        s += std::to_string(i);
        for (int k = 0; k < 12; ++k) {
            const double v = valueAt(k, i);
            s += "," + (std::isnan(v) ? std::string() : number(v));
        }
        s += "\n";
    }
    return s;
}

/// The tags in the export's own order (reversed: columns may come in any order).
std::string exportText(const ExportFormat& f) {
    const std::string d(1, f.delimiter);
    std::string s = f.timeHeader;
    for (int k = 11; k >= 0; --k) {
        s += d + kTags[k].tag;
    }
    s += "\n";
    if (f.unitsRow) {
        for (int k = 11; k >= 0; --k) {
            s += d + kTags[k].unit;
        }
        s += "\n";
    }
    for (int i = 0; i < kRows; ++i) {
        s += f.stamp(i);
        for (int k = 11; k >= 0; --k) {
            const double v = valueAt(k, i);
            const std::string cell = std::isnan(v) ? f.state : number(v, f.decimal, f.thousands);
            s += d + (f.quoteNumbers && !std::isnan(v) ? "\"" + cell + "\"" : cell);
        }
        s += "\r\n";
    }
    return s;
}

std::string encoded(const std::string& utf8, const std::string& encoding) {
    if (encoding == "UTF-8") {
        return utf8;
    }
    if (encoding == "UTF-8 BOM") {
        return "\xEF\xBB\xBF" + utf8;
    }
    const QString text = QString::fromUtf8(utf8.data(), static_cast<int>(utf8.size()));
    if (encoding == "Windows-1252") {
        std::string out;
        for (QChar c : text) {
            Q_ASSERT(c.unicode() < 0x100);
            out.push_back(static_cast<char>(c.unicode()));
        }
        return out;
    }
    const bool le = encoding.rfind("UTF-16LE", 0) == 0;
    std::string out;
    if (encoding.find("BOM") != std::string::npos) {
        out += le ? "\xFF\xFE" : "\xFE\xFF";
    }
    for (QChar c : text) {
        const char lo = static_cast<char>(c.unicode() & 0xFF), hi = static_cast<char>(c.unicode() >> 8);
        out += le ? std::string{lo, hi} : std::string{hi, lo};
    }
    return out;
}

ReadOptions mappingOptions(const std::string& timeHeader, const std::string& extra = {}) {
    std::string json = "{\"time_s\": {\"header\": \"" + timeHeader + "\"}";
    for (const auto& t : kTags) {
        json += ", \"" + std::string(spec(t.column).name) + "\": \"" + t.tag + "\"";
    }
    json += extra.empty() ? "}" : ", " + extra + "}";
    auto m = readColumnMappingText(json, "tags.json");
    if (!m) {
        qFatal("%s", m.error().message().c_str());
    }
    ReadOptions o;
    o.mapping = *m;
    return o;
}

/// A shift of the seven tags of TestPlantFiles in one of @p n rows; @p cell may change a row's cells.
std::string shiftText(int n, const std::function<std::string(int)>& stamp, char delimiter = ';',
                      const std::function<void(int, std::vector<std::string>&)>& cell = {},
                      const std::string& timeHeader = "Timestamp") {
    const std::string d(1, delimiter);
    std::string s = timeHeader;
    const int used[] = {1, 3, 4, 6, 7, 10, 11};
    for (int k : used) {
        s += d + kTags[k].tag;
    }
    s += "\n";
    for (int i = 0; i < n; ++i) {
        std::vector<std::string> row;
        for (int k : used) {
            row.push_back(number(valueAt(k, i) == valueAt(k, i) ? valueAt(k, i) : 1.0));
        }
        if (cell) {
            cell(i, row);
        }
        s += stamp(i);
        for (const auto& c : row) {
            s += d + c;
        }
        s += "\n";
    }
    return s;
}

ReadOptions sevenTags(const std::string& timeHeader = "Timestamp", const std::string& extra = {}) {
    std::string json = "{\"time_s\": {\"header\": \"" + timeHeader + "\"}";
    for (int k : {1, 3, 4, 6, 7, 10, 11}) {
        json += ", \"" + std::string(spec(kTags[k].column).name) + "\": \"" + kTags[k].tag + "\"";
    }
    json += extra.empty() ? "}" : ", " + extra + "}";
    auto m = readColumnMappingText(json, "tags.json");
    if (!m) {
        qFatal("%s", m.error().message().c_str());
    }
    ReadOptions o;
    o.mapping = *m;
    return o;
}

std::string iso(int i, double start = kJune3 + 8 * 3600) {
    return strftimeUtc(start + i, "%Y-%m-%d %H:%M:%S");
}

bool hasNote(const PlantFileRuns& r, const std::string& text) {
    for (const auto& n : r.notes) {
        if (n.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

std::string notesOf(const PlantFileRuns& r) {
    std::string all;
    for (const auto& n : r.notes) {
        all += n + "\n";
    }
    return all.empty() ? "no notes" : all;
}

#define VERIFY_OK(r) QVERIFY2((r).ok(), (r) ? "" : (r).error().message().c_str())
#define VERIFY_MESSAGE(msg, text) QVERIFY2((msg).find(text) != std::string::npos, (msg).c_str())

/// A plain export of @p rows rows @p step seconds apart, in the contract's column order; @p suffix
/// per column (a unit in the header); @p fahrenheit writes the temperatures in °F, @p tonnes the
/// feed in t/h. Time stamps under "Timestamp" unless @p relative (then time_s in seconds).
std::string plainExport(int rows, int step, bool relative, const std::vector<std::string>& suffix = {},
                        bool fahrenheit = false, bool tonnes = false) {
    const char* names[] = {"T_hot_sp_C", "T_hot_C",    "air_speed_m_s", "feed_kg_h", "X_in_pct",  "T_in_C",
                           "T_amb_C",    "RH_amb_pct", "X_hdt_pct",     "T_hdt_C",   "X_out_pct", "T_out_C"};
    const double values[] = {170, 169.0, 16, 6200, 22, 25, 24, 55, 14.0, 58, 12.0, 55.2};
    const bool temperature[] = {true, true, false, false, false, true, true, false, false, true, false, true};
    std::ostringstream text;
    text << (relative ? "time_s" : "Timestamp");
    for (int c = 0; c < 12; ++c) {
        text << ',' << names[c] << (c < static_cast<int>(suffix.size()) ? suffix[c] : "");
    }
    text << '\n';
    for (int i = 0; i < rows; ++i) {
        if (relative) {
            text << i * step;
        } else {
            const int t = 8 * 3600 + i * step;
            char stamp[32];
            std::snprintf(stamp, sizeof stamp, "2026-11-28 %02d:%02d:%02d", t / 3600, t / 60 % 60, t % 60);
            text << stamp;
        }
        for (int c = 0; c < 12; ++c) {
            double v = values[c] + (c == 1 ? 3 * std::sin(i / 20.0) : 0);
            if (fahrenheit && temperature[c]) {
                v = v * 1.8 + 32;
            }
            if (tonnes && c == 3) {
                v /= 1000;
            }
            text << ',' << v;
        }
        text << '\n';
    }
    return text.str();
}

} // namespace

class TestHistorianExports : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // Every export format gives the batch of the contract's form, cell for cell.
    void everyExportFormatLoadsTheSameCells_data() {
        QTest::addColumn<int>("format");
        const char* names[] = {"ISO, ';', decimal comma and thousands point, units row, UTF-8 BOM",
                               "PI DataLink d-Mon-Y, tab, digital states",
                               "US locale m/d/Y AM/PM across midnight, quoted 6,497.250",
                               "Excel serial days from midnight, comma",
                               "Unix milliseconds, tab",
                               "d.m.Y, ';', decimal comma, units row, Windows-1252",
                               "ISO with zone offset, tab, UTF-16 LE with BOM",
                               "ISO, ';', decimal comma, UTF-16 BE without BOM",
                               "Y/m/d, tab, UTF-16 LE without BOM"};
        for (int i = 0; i < 9; ++i) {
            QTest::newRow(names[i]) << i;
        }
    }
    void everyExportFormatLoadsTheSameCells() {
        QFETCH(int, format);
        const double eight = kJune3 + 8 * 3600;
        ExportFormat f;
        switch (format) {
        case 0:
            f.decimal = ',';
            f.thousands = '.';
            f.unitsRow = true;
            f.encoding = "UTF-8 BOM";
            f.stamp = [&](int i) { return iso(i); };
            break;
        case 1:
            f.delimiter = '\t';
            f.state = "Shutdown";
            f.stamp = [&](int i) { return strftimeUtc(eight + i, "%d-%b-%Y %H:%M:%S"); };
            break;
        case 2:
            f.delimiter = ',';
            f.thousands = ',';
            f.quoteNumbers = true;
            f.state = "Comm Fail";
            f.stamp = [&](int i) {
                const double t = kJune3 + 23 * 3600 + 55 * 60 + i; // 11:55 PM, past midnight
                std::tm tm{};
                const auto tt = static_cast<time_t>(t);
                gmtime_r(&tt, &tm);
                char buf[48];
                std::snprintf(buf, sizeof buf, "%d/%d/%d %d:%02d:%02d %s", tm.tm_mon + 1, tm.tm_mday,
                              tm.tm_year + 1900, (tm.tm_hour + 11) % 12 + 1, tm.tm_min, tm.tm_sec,
                              tm.tm_hour < 12 ? "AM" : "PM");
                return std::string(buf);
            };
            break;
        case 3:
            f.delimiter = ',';
            f.timeHeader = "Stamp"; // not named like a date: the range and step tell Excel days
            f.state = "Bad Input";
            f.stamp = [](int i) {
                char buf[32];
                std::snprintf(buf, sizeof buf, "%.10f", 45811.0 + i / 86400.0);
                std::string s(buf);
                s.erase(s.find_last_not_of('0') + 1);
                if (s.back() == '.') {
                    s.pop_back(); // Excel writes midnight as the whole number 45811
                }
                return s;
            };
            break;
        case 4:
            f.delimiter = '\t';
            f.timeHeader = "t";
            f.state = "Pt Created";
            f.stamp = [&](int i) { return std::to_string(static_cast<long long>(eight + i) * 1000); };
            break;
        case 5:
            f.decimal = ',';
            f.thousands = '.';
            f.unitsRow = true;
            f.timeHeader = "Zeitstempel";
            f.encoding = "Windows-1252";
            f.state = "Scan Off";
            f.stamp = [&](int i) { return strftimeUtc(eight + i, "%d.%m.%Y %H:%M:%S"); };
            break;
        case 6:
            f.delimiter = '\t';
            f.encoding = "UTF-16LE BOM";
            f.stamp = [&](int i) { return strftimeUtc(eight + i, "%Y-%m-%dT%H:%M:%S+02:00"); };
            break;
        case 7:
            f.decimal = ',';
            f.encoding = "UTF-16BE";
            f.state = "no data";
            f.stamp = [&](int i) { return iso(i); };
            break;
        default:
            f.delimiter = '\t';
            f.encoding = "UTF-16LE";
            f.stamp = [&](int i) { return strftimeUtc(eight + i, "%Y/%m/%d %H:%M:%S"); };
            break;
        }
        auto contract = parsePlantText(contractText(), "contract.csv");
        VERIFY_OK(contract);
        QCOMPARE(contract->runs.size(), std::size_t(1));
        const Batch& want = contract->runs[0];
        auto exported =
            parsePlantText(encoded(exportText(f), f.encoding), "export.csv", mappingOptions(f.timeHeader));
        VERIFY_OK(exported);
        QVERIFY(exported->shape.historian);
        QCOMPARE(exported->runs.size(), std::size_t(1));
        const Batch& got = exported->runs[0];
        QCOMPARE(got.rows(), want.rows());
        for (const auto& s : columnSpecs()) {
            const auto* w = want.values(s.id);
            const auto* g = got.values(s.id);
            QVERIFY2(w && g, s.name.data());
            for (std::size_t r = 0; r < want.rows(); ++r) {
                if ((*w)[r] != (*g)[r] && !(std::isnan((*w)[r]) && std::isnan((*g)[r]))) {
                    QFAIL(qPrintable(QStringLiteral("%1 row %2: contract %3, export %4")
                                         .arg(s.name.data())
                                         .arg(r)
                                         .arg((*w)[r], 0, 'g', 17)
                                         .arg((*g)[r], 0, 'g', 17)));
                }
            }
        }
        // The same missing cells (listed in another order: the contract's reader goes line by line).
        const auto columnsOf = [](const Batch& b) {
            std::vector<std::string> names;
            for (const auto& m : b.missing) {
                names.push_back(m.columnName);
            }
            std::sort(names.begin(), names.end());
            return names;
        };
        QCOMPARE(got.missing.size(), std::size_t(4));
        QVERIFY(columnsOf(got) == columnsOf(want));
        QVERIFY2(hasNote(*exported, "hold PI digital states"), notesOf(*exported).c_str());
    }

    // 1. Excel serial days from 00:00: the first stamp is a whole number, and still days.
    // The column mapping's unit wins over the file's units row; where they differ, said with the
    // place (a newcomer's mapping said K for a column the file logs in °C: -122 °C of hot air).
    void aMappingUnitTheUnitsRowContradictsIsNoted() {
        std::string text = "Time;HotAir;Feed;Xin;Tamb;RH;Xout;Tout\n;°C;kg/h;%;°C;%;%;°C\n";
        for (int i = 0; i < 400; ++i) { // a run longer than the 300 s a production run needs
            char stamp[64];
            std::snprintf(stamp, sizeof stamp, "2025-06-03 08:%02d:%02d", i / 60, i % 60);
            text += std::string(stamp) + ";165;6200;22;25;55;12,8;55\n";
        }
        const auto read = [&](const std::string& hotAirUnit) {
            auto m = readColumnMappingText(
                R"({"time_s": {"header": "Time"}, "T_hot_C": {"header": "HotAir", "unit": ")" + hotAirUnit +
                    R"("}, "feed_kg_h": "Feed", "X_in_pct": "Xin", "T_amb_C": "Tamb", "RH_amb_pct": "RH",
                    "X_out_pct": "Xout", "T_out_C": "Tout"})",
                "m.json");
            if (!m) {
                qFatal("%s", m.error().message().c_str());
            }
            ReadOptions o;
            o.mapping = *m;
            auto runs = parsePlantText(text, "w.csv", o);
            if (!runs) {
                qFatal("%s", runs.error().message().c_str());
            }
            return runs->notes;
        };
        const auto contradicted = read("K");
        QVERIFY2(std::any_of(contradicted.begin(), contradicted.end(),
                             [](const std::string& n) {
                                 return n.find(
                                            "w.csv:2:2: column 'HotAir' (T_hot_C) is read in 'K', the column "
                                            "mapping's unit, while the file's units row says '°C'") !=
                                        std::string::npos;
                             }),
                 contradicted.empty() ? "no note" : contradicted.front().c_str());
        const auto agreed = read("°C");
        QVERIFY(std::none_of(agreed.begin(), agreed.end(), [](const std::string& n) {
            return n.find("units row says") != std::string::npos;
        }));
    }

    void excelDaysFromMidnightAreDays() {
        const auto excel = [](int i) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.10f", 45811.0 + i / 86400.0);
            std::string cell(buf);
            cell.erase(cell.find_last_not_of('0') + 1);
            if (cell.back() == '.') {
                cell.pop_back(); // 00:00 is the whole number 45811
            }
            return cell;
        };
        for (const std::string header : {"Date", "Stamp"}) {
            auto r =
                parsePlantText(shiftText(1200, excel, ',', {}, header), "midnight.csv", sevenTags(header));
            VERIFY_OK(r);
            QCOMPARE(r->shape.timeFormat, TimeFormat::ExcelDays);
            QCOMPARE(r->runs.size(), std::size_t(1));
            QCOMPARE(r->runs[0].rows(), std::size_t(1200)); // not 0.014 s of "seconds"
            QCOMPARE(r->runs[0].run->startTimestamp, std::string("2025-06-03T00:00:00"));
        }
        // The contract's own time_s stays seconds, even where its values lie in Excel's range.
        const auto seconds = [](int i) { return std::to_string(30000 + i); };
        auto s =
            parsePlantText(shiftText(400, seconds, ';', {}, "time_s"), "seconds.csv", sevenTags("time_s"));
        VERIFY_OK(s);
        QCOMPARE(s->shape.timeFormat, TimeFormat::Seconds);
        QCOMPARE(s->runs[0].rows(), std::size_t(400));
    }

    // 2. A mapping that names a header the file lacks is an error, whatever the column.
    void mappedHeaderTheFileLacksIsAnError_data() {
        QTest::addColumn<QString>("extra");
        QTest::addColumn<QString>("expected");
        QTest::newRow("optional air speed") << "\"air_speed_m_s\": \"HDT_SPD.PV\""
                                            << "'HDT_SPD.PV' for air_speed_m_s (optional";
        QTest::newRow("optional T_in") << "\"T_in_C\": \"FEED_TT202\""
                                       << "'FEED_TT202' for T_in_C (optional";
        QTest::newRow("batch column") << "\"batch_id\": {\"header\": \"Charge\"}"
                                      << "'Charge' for batch_id (the batch column)";
    }
    void mappedHeaderTheFileLacksIsAnError() {
        QFETCH(QString, extra);
        QFETCH(QString, expected);
        auto r = parsePlantText(shiftText(400, [](int i) { return iso(i); }), "shift.csv",
                                sevenTags("Timestamp", extra.toStdString()));
        QVERIFY(!r.ok());
        const std::string m = r.error().message();
        VERIFY_MESSAGE(
            m, "shift.csv:1:1: the column mapping tags.json names a header that the file's header row lacks");
        VERIFY_MESSAGE(m, expected.toStdString());
        QCOMPARE(r.error().code, ErrorCode::DataFileFormat); // the column may be optional
        QCOMPARE(r.error().args.size(), std::size_t(4));
        QCOMPARE(exitCodeFor(r.error().kind), 3);
        // The contract's own form is read by the batch reader: the same rule holds there.
        ColumnMapping m2;
        m2.contractToFile["T_in_C"] = "Tin";
        ReadOptions o;
        o.mapping = m2;
        auto c = parsePlantText(contractText(), "contract.csv", o);
        QVERIFY(!c.ok());
        VERIFY_MESSAGE(c.error().message(), "contract.csv:1:1: the column mapping names a header");
        VERIFY_MESSAGE(c.error().message(), "'Tin' for T_in_C (optional");
        // A near miss is named.
        auto near = parsePlantText(shiftText(400, [](int i) { return iso(i); }), "shift.csv",
                                   sevenTags("Timestamp", "\"X_in_pct\": \"NIR_XIN_PV\""));
        QVERIFY(!near.ok());
        VERIFY_MESSAGE(near.error().message(),
                       "'NIR_XIN_PV' for X_in_pct (required, inlet moisture), the file has "
                       "'NIR_XIN.PV'");
    }

    // 3. Thousands points after a start-up ramp below 1,000: decided on the whole file.
    void thousandsAfterARampAreThousands() {
        const auto german = [](int i, std::vector<std::string>& row) {
            const int feed = i < 300 ? 600 + i : 6497;
            row[1] = feed >= 1000 ? "6.497" : std::to_string(feed); // FEED_WT201.PV
            for (std::size_t c : {0u, 2u, 3u, 4u, 5u, 6u}) {
                if (i < 250) {
                    row[c] = row[c].substr(0, row[c].find('.')); // whole numbers in the first rows
                } else {
                    std::replace(row[c].begin(), row[c].end(), '.', ',');
                }
            }
        };
        auto r = parsePlantText(shiftText(
                                    600, [](int i) { return iso(i); }, ';', german),
                                "german.csv", sevenTags());
        VERIFY_OK(r);
        QVERIFY(r->shape.decimalComma); // every cell has three decimals: the semicolon's convention decides
        QVERIFY2(hasNote(*r, "read with a decimal comma. If that is wrong, set \"decimal_mark\": \".\""),
                 notesOf(*r).c_str());
        QCOMPARE(r->runs.size(), std::size_t(1)); // not a line stop at 6.497 kg/h
        const auto& feed = *r->runs[0].values(Column::Feed);
        QCOMPARE(feed[299], 899.0);
        QCOMPARE(feed[300], 6497.0);
        QVERIFY(std::abs((*r->runs[0].values(Column::THot))[300] - valueAt(1, 300)) < 1e-3);
        QCOMPARE((*r->runs[0].values(Column::TAmb))[300], 24.1); // "24,100", not 24100
        // A decimal point and a decimal comma in one file: both cells named, the later one's place.
        const auto mixed = [](int i, std::vector<std::string>& row) {
            if (i == 30) {
                row[3] = "24,5"; // HALL_TT301.PV
            }
        };
        auto m = parsePlantText(shiftText(
                                    400, [](int i) { return iso(i); }, ';', mixed),
                                "mixed.csv", sevenTags());
        QVERIFY(!m.ok());
        QCOMPARE(
            m.error().message(),
            std::string("mixed.csv:32:5: the file mixes a decimal point '1013.000' (column 'FEED_WT201.PV', "
                        "line 16) and a decimal comma '24,5' (column 'HALL_TT301.PV', line 32); export it "
                        "with one number format"));
        // Nothing tells (every number has three decimals and lies below 1,000): read with points,
        // noted with the setting; the setting reads them as thousands.
        const auto threeDecimals = [](int, std::vector<std::string>& row) { row[1] = "900.250"; };
        auto guessed = parsePlantText(shiftText(
                                          400, [](int i) { return iso(i); }, '\t', threeDecimals),
                                      "tab.csv", sevenTags());
        VERIFY_OK(guessed);
        QVERIFY2(hasNote(*guessed, "set \"decimal_mark\": \",\" in the column mapping"),
                 notesOf(*guessed).c_str());
        QCOMPARE((*guessed->runs[0].values(Column::Feed))[0], 900.25);
        auto told = parsePlantText(shiftText(
                                       400, [](int i) { return iso(i); }, '\t', threeDecimals),
                                   "tab.csv", sevenTags("Timestamp", "\"decimal_mark\": \",\""));
        VERIFY_OK(told);
        QCOMPARE((*told->runs[0].values(Column::Feed))[0], 900250.0);
    }

    // 3. What one cell's marks say, before the file's decimal mark is known.
    void numberCells_data() {
        QTest::addColumn<QString>("cell");
        QTest::addColumn<bool>("isNumber");
        QTest::addColumn<int>("marks");
        QTest::addColumn<double>("value");
        using M = historian::NumberMarks;
        QTest::newRow("6.497") << "6.497" << true << int(M::PointOrThousands) << 6.497;
        QTest::newRow("-6,497") << "-6,497" << true << int(M::CommaOrThousands) << -6.497;
        QTest::newRow("6.497,25") << "6.497,25" << true << int(M::DecimalComma) << 6497.25;
        QTest::newRow("6,497.25") << "6,497.25" << true << int(M::DecimalPoint) << 6497.25;
        QTest::newRow("1.234.567") << "1.234.567" << true << int(M::DecimalComma) << 1234567.0;
        QTest::newRow("0.497") << "0.497" << true << int(M::DecimalPoint) << 0.497;
        QTest::newRow("6200.000") << "6200.000" << true << int(M::DecimalPoint) << 6200.0;
        QTest::newRow("13,2") << " 13,2 " << true << int(M::DecimalComma) << 13.2;
        QTest::newRow("1,5E3") << "1,5E3" << true << int(M::DecimalComma) << 1500.0;
        QTest::newRow("+5") << "+5" << true << int(M::None) << 5.0;
        QTest::newRow("12.34.5") << "12.34.5" << false << int(M::None) << 0.0;
        QTest::newRow("6 497") << "6 497" << false << int(M::None) << 0.0;
        QTest::newRow("1.234,5,6") << "1.234,5,6" << false << int(M::None) << 0.0;
    }
    void numberCells() {
        QFETCH(QString, cell);
        QFETCH(bool, isNumber);
        QFETCH(int, marks);
        QFETCH(double, value);
        const auto n = historian::readNumberCell(cell.toStdString());
        QCOMPARE(n.isNumber, isNumber);
        if (isNumber) {
            QCOMPARE(int(n.marks), marks);
            QCOMPARE(n.value, value);
        }
        QCOMPARE(historian::thousandsValue(6.497), 6497.0);
    }

    // 4. Time going backwards: a daylight-saving fall-back is a note, any other step back an error.
    void timeGoingBackIsAnErrorUnlessDaylightSaving() {
        std::string text = shiftText(400, [](int i) { return iso(i); });
        // Swap lines 101 and 102.
        std::vector<std::string> lines;
        for (std::size_t p = 0; p < text.size();) {
            const auto nl = text.find('\n', p);
            lines.push_back(text.substr(p, nl - p));
            p = nl + 1;
        }
        std::swap(lines[100], lines[101]);
        std::string swapped;
        for (const auto& l : lines) {
            swapped += l + "\n";
        }
        auto r = parsePlantText(swapped, "swapped.csv", sevenTags());
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::TimeNotIncreasing);
        QCOMPARE(r.error().place, std::string("swapped.csv:102:1"));
        VERIFY_MESSAGE(r.error().reason,
                       "time goes back 1 s (2025-06-03T08:01:39 after 2025-06-03T08:01:40 on line 101)");
        // Daylight saving ends, stated by the zone: one run, a note.
        const auto zoned = [](int i) {
            const double utc = 1761436800 - 600 + i; // 2025-10-26T00:50:00Z
            return strftimeUtc(utc + (utc < 1761440400 ? 7200 : 3600), "%Y-%m-%dT%H:%M:%S") +
                   (utc < 1761440400 ? "+02:00" : "+01:00");
        };
        auto z = parsePlantText(shiftText(7800, zoned), "zone.csv", sevenTags());
        VERIFY_OK(z);
        QCOMPARE(z->runs.size(), std::size_t(1));
        QVERIFY2(
            hasNote(*z,
                    "zone.csv:4202:1: the stamps' time zone changes from +02:00 to +01:00 (daylight saving "
                    "ends)"),
            notesOf(*z).c_str());
        // A batch column whose batches each restart their clock: no error, one run per batch.
        const auto relative = [](int i) { return std::to_string(i % 400); };
        std::string batches = shiftText(800, relative, ';', {}, "time_s");
        {
            std::string withBatch;
            int line = 0;
            for (std::size_t p = 0; p < batches.size(); ++line) {
                const auto nl = batches.find('\n', p);
                const std::string l = batches.substr(p, nl - p);
                withBatch += l + ";" + (line == 0 ? "Batch" : line <= 400 ? "B1" : "B2") + "\n";
                p = nl + 1;
            }
            batches = withBatch;
        }
        auto b = parsePlantText(batches, "batches.csv",
                                sevenTags("time_s", "\"batch_id\": {\"header\": \"Batch\"}"));
        VERIFY_OK(b);
        QCOMPARE(b->runs.size(), std::size_t(2));
        auto noBatch = parsePlantText(batches, "batches.csv", sevenTags("time_s"));
        QVERIFY(!noBatch.ok());
        VERIFY_MESSAGE(noBatch.error().message(), "batches.csv:402:1: time goes back 399 s");
        VERIFY_MESSAGE(noBatch.error().message(), "\"batch_id\"");
    }

    // 5. PI DataLink stamps, the US locale's, PI digital states, UTF-16 and Windows-1252.
    void realExportFormatsAreRead() {
        double s = 0;
        QVERIFY(parseTimeCell("03-Jun-2025 08:00:00", TimeFormat::DayMonthNameYear, s));
        QCOMPARE(s, kJune3 + 8 * 3600);
        QVERIFY(parseTimeCell("3-jun-25 8:00:00.5", TimeFormat::DayMonthNameYear, s));
        QCOMPARE(s, kJune3 + 8 * 3600 + 0.5);
        QVERIFY(parseTimeCell("6/3/2025 8:00:00 AM", TimeFormat::MdySlash, s));
        QCOMPARE(s, kJune3 + 8 * 3600);
        QVERIFY(parseTimeCell("6/3/2025 12:00:00 AM", TimeFormat::MdySlash, s));
        QCOMPARE(s, kJune3);
        QVERIFY(parseTimeCell("6/3/2025 12:30 PM", TimeFormat::MdySlash, s));
        QCOMPARE(s, kJune3 + 12.5 * 3600);
        QVERIFY(!parseTimeCell("6/3/2025 13:00:00 PM", TimeFormat::MdySlash, s));
        QCOMPARE(timeFormatByName("d-Mon-Y"), std::optional<TimeFormat>(TimeFormat::DayMonthNameYear));
        // PI digital states are missing values, counted per tag.
        const auto states = [](int i, std::vector<std::string>& row) {
            if (i == 40 || i == 41) {
                row[1] = "Shutdown";
            }
            if (i == 90) {
                row[5] = "COMM FAIL";
            }
        };
        auto pi = parsePlantText(
            shiftText(
                400, [](int i) { return strftimeUtc(kJune3 + 8 * 3600 + i, "%d-%b-%Y %H:%M:%S"); }, '\t',
                states),
            "pi.csv", sevenTags());
        VERIFY_OK(pi);
        QCOMPARE(pi->shape.timeFormat, TimeFormat::DayMonthNameYear);
        QVERIFY2(hasNote(*pi,
                         "pi.csv:42:3: column 'FEED_WT201.PV' (feed_kg_h): 2 cell(s) hold PI digital states "
                         "(Shutdown 2)"),
                 notesOf(*pi).c_str());
        QVERIFY2(hasNote(*pi,
                         "pi.csv:92:7: column 'NIR_XOUT.PV' (X_out_pct): 1 cell(s) hold PI digital states "
                         "(Comm Fail 1)"),
                 notesOf(*pi).c_str());
        QVERIFY(std::isnan((*pi->runs[0].values(Column::XOut))[90]));
        // One day of US dates: day/month cannot be told; the message names the setting.
        const auto us = [](int i) {
            return "6/3/2025 8:" + std::string(i / 60 < 10 ? "0" : "") + std::to_string(i / 60) + ":" +
                   (i % 60 < 10 ? "0" : "") + std::to_string(i % 60) + " AM";
        };
        auto amb = parsePlantText(shiftText(400, us, ','), "us.csv", sevenTags());
        QVERIFY(!amb.ok());
        VERIFY_MESSAGE(amb.error().message(),
                       "us.csv:2:1: time column 'Timestamp': the dates (6/3/2025 8:00:00 AM to "
                       "6/3/2025 8:06:39 AM) read as day/month and as month/day alike; name the "
                       "format in the column mapping (\"time_s\": {\"header\": \"Timestamp\", "
                       "\"format\": \"m/d/Y\"} or \"d/m/Y\")");
        // Bytes no encoding explains are named with their place.
        std::string undefined = shiftText(400, [](int i) { return iso(i); });
        undefined.insert(undefined.find('\n') + 3, "\x81");
        auto u = parsePlantText(undefined, "bytes.csv", sevenTags());
        QVERIFY(!u.ok());
        VERIFY_MESSAGE(u.error().message(), "bytes.csv:2:3: byte 0x81 is neither UTF-8 nor Windows-1252");
        const std::string loneSurrogate("\xFF\xFEt\0\x00\xDC", 6);
        auto l = parsePlantText(loneSurrogate, "utf16.csv", sevenTags());
        QVERIFY(!l.ok());
        VERIFY_MESSAGE(l.error().message(), "utf16.csv:1:2: a UTF-16 low surrogate without its high half");
    }

    // 5b. A tag/value export (one row per tag and stamp, PI's archive export sorted by tag, with a
    // quality column) reads the same cells as the wide export of the same shift; a tag sampled at
    // other stamps is bridged like gaps; the note says what was done.
    void tagValueExportReadsAsTheWideOne() {
        const std::string wide = shiftText(
            400, [](int i) { return iso(i); }, ',');
        auto w = parsePlantText(wide, "wide.csv", sevenTags());
        VERIFY_OK(w);
        // Pivot the wide text back to narrow, tag by tag (the order PI writes).
        std::vector<std::vector<std::string>> table;
        std::stringstream in(wide);
        for (std::string line; std::getline(in, line);) {
            std::vector<std::string> cells;
            std::stringstream ls(line);
            for (std::string c; std::getline(ls, c, ',');) {
                cells.push_back(c);
            }
            table.push_back(cells);
        }
        const auto narrowText = [&](bool sparse) {
            std::string text = "# exported from the plant historian\nTag,Timestamp,Value,Quality\n";
            for (std::size_t col = 1; col < table[0].size(); ++col) {
                for (std::size_t row = 1; row < table.size(); ++row) {
                    if (sparse && col == 3 && row % 2 == 0) {
                        continue; // this tag every other second only (a deadband)
                    }
                    text += table[0][col] + "," + table[row][0] + "," + table[row][col] + ",Good\n";
                }
            }
            return text;
        };
        auto n = parsePlantText(narrowText(false), "narrow.csv", sevenTags());
        VERIFY_OK(n);
        QVERIFY2(
            hasNote(
                *n,
                "narrow.csv: a tag/value export (one row per tag and time stamp: columns 'Timestamp', "
                "'Tag', 'Value'), read as one column per tag: 7 tags over 400 time stamps; 0 cells where a "
                "tag has no sample at a stamp hold its last sample"),
            notesOf(*n).c_str());
        QCOMPARE(n->runs.size(), w->runs.size());
        for (const auto c : {Column::THot, Column::Feed, Column::XOut}) {
            QCOMPARE(*n->runs[0].values(c), *w->runs[0].values(c));
        }
        // Wonderware's History query writes seven columns, four of them about the sample.
        std::string wonderware = narrowText(false);
        wonderware.replace(wonderware.find("Tag,Timestamp,Value,Quality\n"), 28,
                           "Tag,Timestamp,Value,Quality,QualityDetail,OPCQuality,wwTimeZone\n");
        for (auto at = wonderware.find(",Good\n"); at != std::string::npos;
             at = wonderware.find(",Good\n", at + 1)) {
            wonderware.replace(at, 6, ",Good,192,192,W. Europe Standard Time\n");
        }
        auto ww = parsePlantText(wonderware, "wonderware.csv", sevenTags());
        VERIFY_OK(ww);
        QCOMPARE(*ww->runs[0].values(Column::THot), *w->runs[0].values(Column::THot));
        auto sparse = parsePlantText(narrowText(true), "sparse.csv", sevenTags());
        VERIFY_OK(sparse);
        QVERIFY2(hasNote(*sparse, "200 cells where a tag has no sample at a stamp hold its last sample"),
                 notesOf(*sparse).c_str());
        const auto& x = *sparse->runs[0].values(static_cast<Column>(kTags[4].column));
        QVERIFY(std::none_of(x.begin(), x.end(), [](double v) { return std::isnan(v); }));
        QCOMPARE(x[5], x[4]); // held from the second before
        // The mapping dialog's guess sees the tags as the headers they stand for.
        auto guess = guessMapping(narrowText(false), "narrow.csv");
        VERIFY_OK(guess);
        QCOMPARE(guess->shape.headers.size(), std::size_t(8));
        QCOMPARE(guess->shape.headers[1], std::string("HDT_TT101.PV"));
        // A row of the wrong width is named by its line.
        std::string broken = narrowText(false);
        broken.insert(broken.find("Good\n") + 5, "HDT_TT101.PV,2025-06-03 08:00:01\n");
        auto b = parsePlantText(broken, "broken.csv", sevenTags());
        QVERIFY(!b.ok());
        VERIFY_MESSAGE(b.error().message(),
                       "broken.csv:4:3: expected 4 fields as in the header of this tag/value "
                       "export, found 2");
    }

    // 6. Impossible values name line and column; the model's refusal names batch, file:line, time,
    // column and value; a line longer than 1 MiB is refused at once.
    void placesOfImpossibleValuesAndTooLongLines() {
        std::string text = contractText();
        auto b = parsePlantText(text, "c.csv");
        VERIFY_OK(b);
        DataSet ds;
        ds.batches = std::move(b->runs);
        (*ds.batches[0].values(Column::XOut))[5] = 140; // line 7 of the file, column 12
        const auto summary = summarize(ds);
        QCOMPARE(summary.impossible.size(), std::size_t(1));
        QCOMPARE(summary.impossible[0].line, 7);
        QCOMPARE(summary.impossible[0].fileColumn, 12);
        QCOMPARE(summary.impossible[0].contractColumn, std::string("X_out_pct"));
        // A run cut from a historian export: the column is the tag's column in the export.
        ExportFormat f;
        f.stamp = [](int i) { return iso(i); };
        auto e = parsePlantText(exportText(f), "e.csv", mappingOptions("Timestamp"));
        VERIFY_OK(e);
        DataSet es;
        es.batches = std::move(e->runs);
        (*es.batches[0].values(Column::XOut))[5] = 140;
        const auto runSummary = summarize(es);
        QCOMPARE(runSummary.impossible[0].line, 7);
        QCOMPARE(runSummary.impossible[0].fileColumn, 3); // Timestamp, WIN_TT401.PV, NIR_XOUT.PV, …
        // An inlet moisture the line model cannot take (95 % wb, on line 5).
        (*ds.batches[0].values(Column::XOut))[5] = 13;
        (*ds.batches[0].values(Column::XIn))[3] = 95;
        const auto si = toSi(ds, clean(ds));
        const auto st = physics::toLineInputs(si[0]).validate();
        QVERIFY(!st.ok());
        QCOMPARE(st.error().place, std::string("batch c (c.csv:5), row 4, t = 3 s"));
        VERIFY_MESSAGE(st.error().reason,
                       "input X_in_pct = 95 % wb lies outside the range the line model takes (0 "
                       "to 90.91 % wb)");
        // A line of 2 MiB: refused with its number, by either reader.
        std::string longLine = "time_s,T_hot_C\n" + std::string(2u << 20, '1') + "\n";
        auto big = parsePlantText(longLine, "long.csv");
        QVERIFY(!big.ok());
        QCOMPARE(big.error().place, std::string("long.csv:2:1"));
        VERIFY_MESSAGE(big.error().reason,
                       "line 2 is 2.0 MiB long; a line of a plant file may be at most 1.0 MiB");
        auto bigBatch = parseBatchText(longLine, "long.csv");
        QVERIFY(!bigBatch.ok());
        QCOMPARE(bigBatch.error().place, std::string("long.csv:2:1"));
    }

    // 7. A broken mapping file: line, column and what was expected.
    // What a fresh user's files did (2026-11-28): units in the header ignored (°F read as °C with
    // exit 0), a cut-off last line loaded, 15 s sampling refused as "no production run", time in
    // milliseconds calibrated on, a folder's B01.CSV skipped.
    void unitsInTheHeaderAreReadAsAUnitsRowsAre() {
        std::vector<std::string> units{" [°F]", " [°F]", " [m/s]", " [t/h]", " [%]", " [°F]",
                                       " [°F]", " [%]",  " [%]",   " [°F]",  " [%]", " [°F]"};
        for (bool relative : {false, true}) {
            auto r = parsePlantText(plainExport(600, 1, relative, units, true, true), "units.csv", {});
            VERIFY_OK(r);
            QCOMPARE(r->runs.size(), std::size_t(1));
            const auto& b = r->runs[0];
            QVERIFY2(std::abs((*b.values(Column::THot))[0] - 169.0) < 1e-6,
                     qPrintable(QString::number((*b.values(Column::THot))[0])));
            QVERIFY(std::abs((*b.values(Column::TOut))[0] - 55.2) < 1e-6);
            QVERIFY(std::abs((*b.values(Column::Feed))[0] - 6200) < 1e-6);
        }
        // A unit the column cannot have is an error naming the header.
        std::vector<std::string> wrong{"", " [kg/h]"};
        auto bad = parsePlantText(plainExport(600, 1, false, wrong), "wrong.csv", {});
        QVERIFY(!bad.ok());
        VERIFY_MESSAGE(bad.error().message(), "T_hot_C [kg/h]");
    }

    void aLastLineWithoutLineEndIsLeftOutWithANote() {
        std::string text = plainExport(400, 1, true);
        text.erase(text.size() - 6); // "…,55.2\n" cut to "…,5"
        auto r = parsePlantText(text, "cut.csv", {});
        VERIFY_OK(r);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(399));
        QVERIFY(std::abs(r->runs[0].values(Column::TOut)->back() - 55.2) < 1e-9);
        bool said = false;
        for (const auto& n : r->notes) {
            said = said || n.find("cut.csv:401:1: the last line has no line end") != std::string::npos;
        }
        QVERIFY(said);
        // A file whose only data line lacks its line end is read as it is.
        auto one = parsePlantText(plainExport(1, 1, true).substr(0, plainExport(1, 1, true).size() - 1),
                                  "one.csv", {});
        QVERIFY(!one.ok() || one->runs.empty() || one->runs[0].rows() == 1);
    }

    void anExportSampledEvery15sIsNotAllGaps() {
        auto r = parsePlantText(plainExport(240, 15, false), "every15s.csv", {});
        VERIFY_OK(r);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QVERIFY2(r->runs[0].rows() > 3000, qPrintable(QString::number(r->runs[0].rows())));
        bool said = false;
        for (const auto& n : r->notes) {
            said = said || n.find("rows are 15 s apart (median)") != std::string::npos;
        }
        QVERIFY(said);
    }

    void titleLinesAboveTheHeaderAreComments() {
        const std::string text = "PI DataLink export\nServer: PIPROD01\nStart: 28-Nov-2026 08:00:00\n\n" +
                                 plainExport(400, 1, false);
        auto r = parsePlantText(text, "titled.csv", {});
        VERIFY_OK(r);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(400));
        bool said = false;
        for (const auto& n : r->notes) {
            said = said || n.find("titled.csv:1-3: title lines above the header") != std::string::npos;
        }
        QVERIFY(said);
    }

    void aDateAndATimeColumnAreOneStamp() {
        // "Date,Time": the stamp "2026-11-28 08:00:00" written as two cells.
        std::string text = plainExport(400, 1, false);
        text.replace(0, 9, "Date,Time");
        for (auto at = text.find("2026-11-28 "); at != std::string::npos; at = text.find("2026-11-28 ", at)) {
            text[at + 10] = ',';
        }
        auto r = parsePlantText(text, "split.csv", {});
        VERIFY_OK(r);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(400));
        QCOMPARE(r->runs[0].run->startTimestamp, std::string("2026-11-28T08:00:00"));
        bool said = false;
        for (const auto& n : r->notes) {
            said = said || n.find("the date and the time of day in two columns ('Date', 'Time')") !=
                               std::string::npos;
        }
        QVERIFY(said);
    }

    void timeInMillisecondsIsRefused() {
        std::string text = plainExport(400, 1000, true);
        auto r = parsePlantText(text, "ms.csv", {});
        QVERIFY(!r.ok());
        VERIFY_MESSAGE(r.error().message(), "milliseconds");
    }

    void aFolderReadsUpperCaseCsvAndSaysWhatItSkips() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        for (const char* name : {"B01.CSV", "B02.csv"}) {
            std::ofstream(dir.filePath(name).toStdString()) << plainExport(400, 1, true);
        }
        std::ofstream(dir.filePath("B03.xlsx").toStdString()) << "PK";
        const auto loaded = loadDataSet(dir.path().toStdString());
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.dataSet.batches.size(), std::size_t(2));
        bool said = false;
        for (const auto& n : loaded.notes) {
            said = said || n.find("not read: B03.xlsx") != std::string::npos;
        }
        QVERIFY(said);
        const auto workbook = loadDataSet(dir.filePath("B03.xlsx").toStdString());
        QVERIFY(!workbook.ok());
        VERIFY_MESSAGE(workbook.errors.front().message(), "not workbooks");
    }

    void brokenMappingNamesLineColumnAndExpectation_data() {
        QTest::addColumn<QString>("json");
        QTest::addColumn<QString>("expected");
        QTest::newRow("comma after the last entry")
            << "{\n  \"T_hot_C\": \"HDT_TT101.PV\",\n  \"X_out_pct\": \"NIR_XOUT.PV\",\n}\n"
            << "m.json:4:1: not valid JSON: syntax error while parsing object key - unexpected '}'; expected "
               "string "
               "literal (a comma after the last entry?)";
        QTest::newRow("comma missing")
            << "{\n  \"T_hot_C\": \"HDT_TT101.PV\"\n  \"X_out_pct\": \"NIR_XOUT.PV\"\n}\n"
            << "m.json:3:3: not valid JSON: syntax error while parsing object - unexpected "
               "string literal; expected '}' (a comma missing after the previous entry?)";
        QTest::newRow("cut short")
            << "{\n  \"T_hot_C\": \"HDT_TT101.PV\",\n"
            << "m.json:3:1: not valid JSON: syntax error while parsing object key - unexpected "
               "end of input; expected string literal (a closing '}' or '\"' is missing)";
    }
    void brokenMappingNamesLineColumnAndExpectation() {
        QFETCH(QString, json);
        QFETCH(QString, expected);
        auto m = readColumnMappingText(json.toStdString(), "m.json");
        QVERIFY(!m.ok());
        QCOMPARE(QString::fromStdString(m.error().message()), expected);
        QCOMPARE(exitCodeFor(m.error().kind), 3);
    }
};

QTEST_APPLESS_MAIN(TestHistorianExports)
#include "TestHistorianExports.moc"
