// Time columns of historian exports (issue #72, items 12, 13 and 16): Excel cells holding a time
// of day alone, a step back of one hour read as daylight saving only in a night it ends in, and
// dates that do not exist refused as such at their place.
#include "data/ColumnMapping.h"
#include "data/PlantFileReader.h"
#include "data/historian/ClockSteps.h"
#include "data/historian/TimeStamps.h"

#include <QtTest>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace drytwin;
using namespace drytwin::data;

namespace {

const char* const kTags[] = {"HDT_TT101.PV",  "FEED_WT201.PV", "NIR_XIN.PV",  "HALL_TT301.PV",
                             "HALL_MT302.PV", "NIR_XOUT.PV",   "WIN_TT401.PV"};

/// A shift of the seven tags, one row per second, the time column first under @p timeHeader.
std::string shiftText(int rows, const std::function<std::string(int)>& stamp, char delimiter = ';',
                      const std::string& timeHeader = "Timestamp") {
    const std::string d(1, delimiter);
    std::string s = timeHeader;
    for (const char* tag : kTags) {
        s += d + tag;
    }
    s += "\n";
    for (int i = 0; i < rows; ++i) {
        char cells[160];
        std::snprintf(cells, sizeof cells, "%s%.3f%s%.3f%s%.3f%s24%s55%s%.3f%s55", d.c_str(),
                      170 + 5 * std::sin(i / 300.0), d.c_str(), 6200 + 100 * std::sin(i / 700.0), d.c_str(),
                      22 + 0.5 * std::sin(i / 900.0), d.c_str(), d.c_str(), d.c_str(),
                      13 + 0.2 * std::sin(i / 400.0), d.c_str());
        s += stamp(i) + cells + "\n";
    }
    return s;
}

/// The seven tags mapped, the time column under @p timeHeader with @p format ("" to detect it).
ReadOptions sevenTags(const std::string& timeHeader = "Timestamp", const std::string& format = {}) {
    std::string json = "{\"time_s\": {\"header\": \"" + timeHeader + "\"" +
                       (format.empty() ? "" : ", \"format\": \"" + format + "\"") + "}";
    const char* columns[] = {"T_hot_C",    "feed_kg_h", "X_in_pct", "T_amb_C",
                             "RH_amb_pct", "X_out_pct", "T_out_C"};
    for (int k = 0; k < 7; ++k) {
        json += std::string(", \"") + columns[k] + "\": \"" + kTags[k] + "\"";
    }
    auto m = readColumnMappingText(json + "}", "tags.json");
    if (!m) {
        qFatal("%s", m.error().message().c_str());
    }
    ReadOptions o;
    o.mapping = *m;
    return o;
}

/// An Excel cell of @p secondsOfDay as a fraction of a day, as Excel's "General" format writes
/// it: ten significant digits, small ones with an exponent (1.157407407E-05).
std::string excelFraction(double secondsOfDay) {
    const double days = std::fmod(secondsOfDay, 86400.0) / 86400.0;
    char buf[32];
    std::snprintf(buf, sizeof buf, days != 0 && days < 1e-4 ? "%.9E" : "%.10g", days);
    return buf;
}

/// "2025-10-26 02:59:59" of naive local seconds.
std::string localStamp(double seconds, const char* pattern = "%Y-%m-%d %H:%M:%S") {
    const auto t = static_cast<time_t>(seconds);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[48];
    std::strftime(buf, sizeof buf, pattern, &tm);
    return buf;
}

/// Naive local seconds of a date and time (as the reader counts them: UTC arithmetic).
double localSeconds(int y, int mo, int d, int h, int mi, int s) {
    std::tm tm{};
    tm.tm_year = y - 1900;
    tm.tm_mon = mo - 1;
    tm.tm_mday = d;
    tm.tm_hour = h;
    tm.tm_min = mi;
    tm.tm_sec = s;
    return static_cast<double>(timegm(&tm));
}

bool hasNote(const PlantFileRuns& r, const std::string& text) {
    return std::any_of(r.notes.begin(), r.notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

std::string notesOf(const PlantFileRuns& r) {
    std::string all;
    for (const auto& n : r.notes) {
        all += n + "\n";
    }
    return all.empty() ? "no notes" : all;
}

#define VERIFY_OK(r) QVERIFY2((r).ok(), (r) ? "" : (r).error().message().c_str())

} // namespace

class TestHistorianTimeStamps : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // 12. Excel cells holding a time of day alone: read as seconds since an undated midnight,
    // detected or named, whatever the column is called (time_s aside, which the contract keeps).
    void excelTimesOfDayLoad_data() {
        QTest::addColumn<QString>("header");
        QTest::addColumn<QString>("format");
        QTest::addColumn<double>("startS");
        QTest::addColumn<QString>("firstNote");
        QTest::addColumn<QString>("start");
        QTest::newRow("08:00, detected")
            << "Time"
            << "" << 8 * 3600.0
            << "tod.csv:2:1: column 'Time' holds times of day alone, without a date "
               "(Excel's fractions of a day: '0.3333333333' is 08:00:00); read as "
               "seconds since midnight of a day the file does not name"
            << "08:00:00 (no date)";
        QTest::newRow("08:00, excel_days named")
            << "Time"
            << "excel_days" << 8 * 3600.0 << "tod.csv:2:1: column 'Time' holds times of day alone"
            << "08:00:00 (no date)";
        QTest::newRow("from midnight, 1.157E-05 apart, detected")
            << "Uhrzeit"
            << "" << 0.0
            << "tod.csv:2:1: column 'Uhrzeit' holds times of day alone, without a date "
               "(Excel's fractions of a day: '0' is 00:00:00)"
            << "00:00:00 (no date)";
        QTest::newRow("from midnight, excel_days named under time_s")
            << "time_s"
            << "excel_days" << 0.0 << "tod.csv:2:1: column 'time_s' holds times of day alone"
            << "00:00:00 (no date)";
    }
    void excelTimesOfDayLoad() {
        QFETCH(QString, header);
        QFETCH(QString, format);
        QFETCH(double, startS);
        QFETCH(QString, firstNote);
        QFETCH(QString, start);
        const std::string text = shiftText(
            900, [&](int i) { return excelFraction(startS + i); }, ',', header.toStdString());
        QVERIFY(text.find(startS == 0 ? "\n1.157407407E-05," : "\n0.3333333333,") != std::string::npos);
        auto r = parsePlantText(text, "tod.csv", sevenTags(header.toStdString(), format.toStdString()));
        VERIFY_OK(r);
        QCOMPARE(r->shape.timeFormat, TimeFormat::ExcelDays);
        QVERIFY(r->shape.timesOfDayOnly);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(900)); // one per second, not 0.01 s of "seconds"
        QCOMPARE(r->runs[0].run->startTimestamp, start.toStdString());
        QVERIFY2(hasNote(*r, firstNote.toStdString()), notesOf(*r).c_str());
    }

    // The contract's own time_s without a format stays seconds, and says what its values are.
    void timesOfDayUnderTimeSWithoutAFormatAreExplained() {
        const std::string text = shiftText(
            400, [](int i) { return excelFraction(8 * 3600.0 + i); }, ',', "time_s");
        auto r = parsePlantText(text, "tod.csv", sevenTags("time_s"));
        QVERIFY(!r.ok());
        QCOMPARE(r.error().place, std::string("tod.csv:3:1"));
        QVERIFY2(r.error().reason.find(
                     "the column is not in seconds. Its values (0 to 1) are Excel times of day") !=
                     std::string::npos,
                 r.error().reason.c_str());
    }

    // A run across midnight (0.9999 then 0.0) goes on into the next day: one run, time continuous.
    void aRunAcrossMidnightGoesOnToTheNextDay_data() {
        QTest::addColumn<QString>("format");
        QTest::newRow("detected") << "";
        QTest::newRow("excel_days named") << "excel_days";
    }
    void aRunAcrossMidnightGoesOnToTheNextDay() {
        QFETCH(QString, format);
        const double start = 23 * 3600 + 50 * 60; // 23:50:00; midnight on line 602
        const std::string text = shiftText(
            1200, [&](int i) { return excelFraction(start + i); }, ';', "Zeit");
        auto r = parsePlantText(text, "night.csv", sevenTags("Zeit", format.toStdString()));
        VERIFY_OK(r);
        QCOMPARE(r->runs.size(), std::size_t(1));
        QCOMPARE(r->runs[0].rows(), std::size_t(1200));
        const auto& time = *r->runs[0].values(Column::Time);
        QCOMPARE(time[601] - time[599], 2.0);
        QVERIFY2(
            hasNote(*r, "night.csv:602:1: the times of day pass midnight here (23:59:59 then 00:00:00), read "
                        "as the next day"),
            notesOf(*r).c_str());
        QVERIFY(!hasNote(*r, "midnights in all"));
        QCOMPARE(historian::timeOfDayText(86400 + 5), std::string("day 2 00:00:05"));
    }

    // Without a date there is no daylight saving: any step back short of half a day is an error.
    void aTimeOfDayThatFallsBackIsAnError() {
        const auto stamp = [](int i) { return excelFraction(8 * 3600.0 + (i < 600 ? i : i - 3600)); };
        auto r = parsePlantText(shiftText(1200, stamp, ';', "Time"), "back.csv", sevenTags("Time"));
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::TimeNotIncreasing);
        QCOMPARE(r.error().message().substr(0, r.error().message().find(". Sort")),
                 std::string("back.csv:602:1: time goes back 3599 s (07:10:00 after 08:09:59 on line 601): a "
                             "step back of one hour, but these stamps have no local date and so no daylight "
                             "saving: rows out of order or a clock reset"));
    }

    // A column that mixes times of day alone with dated cells is refused at the first odd one.
    void aColumnMixingTimesOfDayAndDatesIsAnError() {
        // Past the 200 rows the format is detected on.
        const auto stamp = [](int i) {
            return i == 300 ? std::string("45811.3344") : excelFraction(8 * 3600.0 + i);
        };
        auto r = parsePlantText(shiftText(400, stamp, ';', "Time"), "mixed.csv", sevenTags("Time"));
        QVERIFY(!r.ok());
        QCOMPARE(r.error().message(),
                 std::string("mixed.csv:302:1: '45811.3344' holds a date, while the column's first stamp "
                             "('0.3333333333' on line 2) holds a time of day alone; export the column in one "
                             "form (Excel: one cell format for the whole column)"));
    }

    // 13. A step back of one hour in naive local time is daylight saving's end only in a night it
    // ends in: between 23:00 on the Saturday and 05:00 on the Sunday of the list.
    void anHourBackIsDaylightSavingOnlyInAFallBackNight_data() {
        QTest::addColumn<double>("repeatedHour"); // naive local seconds of the first stamp after the step
        QTest::addColumn<QString>("rule");        // "" for an error
        QTest::newRow("central Europe, 26 Oct 2025 03:00 -> 02:00")
            << localSeconds(2025, 10, 26, 2, 0, 0) << "the last Sunday of October (Europe";
        QTest::newRow("eastern Europe, 26 Oct 2025 04:00 -> 03:00")
            << localSeconds(2025, 10, 26, 3, 0, 0) << "the last Sunday of October (Europe";
        QTest::newRow("UK, 25 Oct 2026 02:00 -> 01:00")
            << localSeconds(2026, 10, 25, 1, 0, 0) << "the last Sunday of October (Europe";
        QTest::newRow("United States, 2 Nov 2025 02:00 -> 01:00")
            << localSeconds(2025, 11, 2, 1, 0, 0) << "the first Sunday of November";
        QTest::newRow("Australia, 6 Apr 2025 03:00 -> 02:00")
            << localSeconds(2025, 4, 6, 2, 0, 0) << "the first Sunday of April";
        // 1 April 2029 is a Sunday: Australia's night is that one, Chile's a week later.
        QTest::newRow("Australia, 1 Apr 2029")
            << localSeconds(2029, 4, 1, 2, 0, 0) << "the first Sunday of April";
        QTest::newRow("Chile, Saturday 7 Apr 2029 24:00 -> 23:00")
            << localSeconds(2029, 4, 7, 23, 0, 0) << "the Sunday on or after 2 April (Chile";
        QTest::newRow("3 June 2025") << localSeconds(2025, 6, 3, 2, 0, 0) << "";
        QTest::newRow("the Sunday before the last of October") << localSeconds(2025, 10, 19, 2, 0, 0) << "";
        QTest::newRow("the last Sunday of October, afternoon") << localSeconds(2025, 10, 26, 14, 0, 0) << "";
        QTest::newRow("the Monday after") << localSeconds(2025, 10, 27, 2, 0, 0) << "";
        QTest::newRow("Saturday before the last Sunday of October, 02:00")
            << localSeconds(2025, 10, 25, 2, 0, 0) << "";
    }
    void anHourBackIsDaylightSavingOnlyInAFallBackNight() {
        QFETCH(double, repeatedHour);
        QFETCH(QString, rule);
        // 600 rows before the step, the last one 3599 s after the first row past it.
        const double first = repeatedHour + 3600 - 600;
        const auto stamp = [&](int i) { return localStamp(i < 600 ? first + i : repeatedHour + (i - 600)); };
        auto r = parsePlantText(shiftText(1200, stamp), "dst.csv", sevenTags());
        QCOMPARE(historian::daylightSavingEndsIn(repeatedHour) != nullptr, !rule.isEmpty());
        if (!rule.isEmpty()) {
            VERIFY_OK(r);
            QCOMPARE(r->runs.size(), std::size_t(2));
            QCOMPARE(r->runs[0].run->splitReason, std::string("clock jump"));
            QVERIFY2(
                hasNote(*r, "dst.csv:602:1: the clock goes back 3599 s, one hour (daylight saving ends in "
                            "local time, " +
                                rule.toStdString()),
                notesOf(*r).c_str());
            return;
        }
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::TimeNotIncreasing);
        const std::string expected =
            "dst.csv:602:1: time goes back 3599 s (" + localStamp(repeatedHour, "%Y-%m-%dT%H:%M:%S") +
            " after " + localStamp(repeatedHour + 3599, "%Y-%m-%dT%H:%M:%S") +
            " on line 601): a step back of one hour, but not in a night daylight saving "
            "ends in (from 23:00 on the Saturday to 05:00 on the last Sunday of October, "
            "the first Sunday of November, the first Sunday of April, or the Sunday on "
            "or after 2 April): rows out of order or a clock reset. Sort the export";
        QCOMPARE(r.error().message().substr(0, expected.size()), expected);
    }

    // Stamps that state their zone, and Unix time, have no naive local hour to repeat.
    void anHourBackWithAZoneOrInUnixTimeIsAnError() {
        const double fallBack = localSeconds(2025, 10, 26, 1, 0, 0); // 01:00 UTC, Europe's moment
        const auto zoned = [&](int i) {
            return localStamp(i < 600 ? fallBack + i : fallBack + i - 3600, "%Y-%m-%dT%H:%M:%S") + "+01:00";
        };
        auto z = parsePlantText(shiftText(1200, zoned), "zone.csv", sevenTags());
        QVERIFY(!z.ok());
        QVERIFY2(z.error().message().find("zone.csv:602:1: time goes back 3599 s") != std::string::npos &&
                     z.error().message().find("although the stamps state their zone") != std::string::npos,
                 z.error().message().c_str());
        const auto epoch = [&](int i) {
            return std::to_string(static_cast<long>(i < 600 ? fallBack + i : fallBack + i - 600 - 3000));
        };
        auto e = parsePlantText(shiftText(1200, epoch), "epoch.csv", sevenTags());
        QVERIFY(!e.ok());
        QVERIFY2(e.error().message().find("epoch.csv:602:1: time goes back 3599 s") != std::string::npos &&
                     e.error().message().find("these stamps have no local date") != std::string::npos,
                 e.error().message().c_str());
    }

    // 16. A date or time that does not exist is refused as that, at its line and column, in every
    // date format; the same form with a day that exists is read.
    void impossibleDatesAreNamedAtTheirPlace_data() {
        QTest::addColumn<QString>("pattern"); // strftime pattern of the file's good stamps
        QTest::addColumn<QString>("bad");
        QTest::addColumn<int>("row"); // 0-based data row that holds it
        QTest::addColumn<QString>("why");
        const QString iso = "%Y-%m-%d %H:%M:%S";
        QTest::newRow("ISO 29 Feb 2025, first row")
            << iso << "2025-02-29 08:00:00" << 0 << "February 2025 has 28 days (2025 is no leap year)";
        QTest::newRow("ISO 29 Feb 2025, later row")
            << iso << "2025-02-29 08:00:00" << 300 << "February 2025 has 28 days (2025 is no leap year)";
        QTest::newRow("ISO 31 April") << iso << "2025-04-31T08:00:00" << 5 << "April has 30 days";
        QTest::newRow("ISO 30 February 2024")
            << iso << "2024-02-30 08:00:00" << 5 << "February 2024 has 29 days";
        QTest::newRow("ISO month 13") << iso << "2025-13-01 08:00:00" << 0 << "there is no month 13";
        QTest::newRow("ISO day 0") << iso << "2025-06-00 08:00:00" << 7 << "there is no day 0";
        QTest::newRow("ISO hour 25") << iso << "2025-06-13 25:00:00" << 9 << "there is no hour 25";
        QTest::newRow("ISO minute 61") << iso << "2025-06-13 08:61:00" << 9 << "there is no minute 61";
        QTest::newRow("d.m.Y 30 February")
            << "%d.%m.%Y %H:%M:%S"
            << "30.02.2025 08:00:00" << 0 << "February 2025 has 28 days (2025 is no leap year)";
        QTest::newRow("d/m/Y 31 April") << "%d/%m/%Y %H:%M:%S"
                                        << "31/04/2025 08:00:00" << 3 << "April has 30 days";
        QTest::newRow("m/d/Y 30 February")
            << "%m/%d/%Y %I:%M:%S %p"
            << "2/30/2025 8:00:00 AM" << 3 << "February 2025 has 28 days (2025 is no leap year)";
        QTest::newRow("m/d/Y 13 PM") << "%m/%d/%Y %I:%M:%S %p"
                                     << "6/13/2025 13:00:00 PM" << 3 << "a 12-hour clock has no hour 13";
        QTest::newRow("Y/m/d 31 June") << "%Y/%m/%d %H:%M:%S"
                                       << "2025/06/31 08:00:00" << 3 << "June has 30 days";
        QTest::newRow("d-Mon-Y 29 Feb")
            << "%d-%b-%Y %H:%M:%S"
            << "29-Feb-2025 08:00:00" << 3 << "February 2025 has 28 days (2025 is no leap year)";
    }
    void impossibleDatesAreNamedAtTheirPlace() {
        QFETCH(QString, pattern);
        QFETCH(QString, bad);
        QFETCH(int, row);
        QFETCH(QString, why);
        // 13 June: past the 12th, so that day/month is told from month/day by the good cells.
        const double start = localSeconds(2025, 6, 13, 8, 0, 0);
        const std::string format = pattern.toStdString();
        const auto stamp = [&](int i) {
            return i == row ? bad.toStdString() : localStamp(start + i, format.c_str());
        };
        auto r = parsePlantText(shiftText(400, stamp), "dates.csv", sevenTags());
        QVERIFY(!r.ok());
        QCOMPARE(QString::fromStdString(r.error().message()),
                 QString("dates.csv:%1:1: impossible date or time '%2': %3. The cell is damaged; correct or "
                         "remove the row")
                     .arg(row + 2)
                     .arg(bad, why));
        QCOMPARE(exitCodeFor(r.error().kind), 3);
    }

    // A day that exists is read: 29 February of a leap year, 30 April, 24:00.
    void datesThatExistAreRead() {
        historian::TimeStamp t;
        QCOMPARE(historian::readTimeStamp("2024-02-29 08:00:00", TimeFormat::Iso8601, t),
                 historian::StampReading::Read);
        QCOMPARE(t.seconds, localSeconds(2024, 2, 29, 8, 0, 0));
        QCOMPARE(historian::readTimeStamp("2000-02-29 24:00:00", TimeFormat::Iso8601, t),
                 historian::StampReading::Read);
        QCOMPARE(historian::readTimeStamp("1900-02-29 08:00:00", TimeFormat::Iso8601, t),
                 historian::StampReading::ImpossibleDate);
        QCOMPARE(historian::readTimeStamp("30/04/2025 08:00", TimeFormat::DmySlash, t),
                 historian::StampReading::Read);
        QCOMPARE(historian::readTimeStamp("hello", TimeFormat::Iso8601, t),
                 historian::StampReading::NotThisFormat);
        QCOMPARE(historian::readTimeStamp("0.5", TimeFormat::ExcelDays, t), historian::StampReading::Read);
        QVERIFY(t.timeOfDayOnly);
        QCOMPARE(t.seconds, 43200.0);
        QCOMPARE(historian::readTimeStamp("45811.5", TimeFormat::ExcelDays, t),
                 historian::StampReading::Read);
        QVERIFY(!t.timeOfDayOnly);
    }
};

QTEST_APPLESS_MAIN(TestHistorianTimeStamps)
#include "TestHistorianTimeStamps.moc"
