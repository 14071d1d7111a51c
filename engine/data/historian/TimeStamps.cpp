#include "data/historian/TimeStamps.h"

#include "data/historian/NumberFormat.h"
#include "data/historian/PlaceInFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace drytwin::data {

namespace {

constexpr TimeFormat kAllFormats[] = {
    TimeFormat::Seconds,      TimeFormat::Iso8601,    TimeFormat::YmdSlash,         TimeFormat::DmyDot,
    TimeFormat::DmySlash,     TimeFormat::MdySlash,   TimeFormat::DayMonthNameYear, TimeFormat::ExcelDays,
    TimeFormat::EpochSeconds, TimeFormat::EpochMillis};

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// Between @p minDigits and @p maxDigits digits from @p pos; @p pos is moved past them.
bool digits(std::string_view s, std::size_t& pos, std::size_t minDigits, std::size_t maxDigits, int& v) {
    std::size_t n = 0;
    v = 0;
    while (pos + n < s.size() && n < maxDigits && isDigit(s[pos + n])) {
        v = v * 10 + (s[pos + n] - '0');
        ++n;
    }
    if (n < minDigits) {
        return false;
    }
    pos += n;
    return true;
}

bool expect(std::string_view s, std::size_t& pos, char c) {
    if (pos < s.size() && s[pos] == c) {
        ++pos;
        return true;
    }
    return false;
}

/// A year of two digits or four: 25 → 2025, 99 → 1999 (as spreadsheets read them).
bool year(std::string_view s, std::size_t& pos, int& y) {
    const std::size_t start = pos;
    if (!digits(s, pos, 2, 4, y) || pos - start == 3) {
        return false;
    }
    if (pos - start == 2) {
        y += y < 70 ? 2000 : 1900;
    }
    return true;
}

/// What a cell names that does not exist (a day or month past its end, an hour past 24), once the
/// cell has had the form of a stamp: the first such thing found.
struct Impossible {
    std::string why;
    void found(std::string what) {
        if (why.empty()) {
            why = std::move(what);
        }
    }
};

constexpr const char* kMonthNames[] = {"January", "February", "March",     "April",   "May",      "June",
                                       "July",    "August",   "September", "October", "November", "December"};

/// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil); false, with
/// what does not exist in @p bad, for a date that does not (31 June, 29 February 2025, month 13).
bool civilDays(int y, int m, int d, long& days, Impossible& bad) {
    static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (m < 1 || m > 12) {
        bad.found("there is no month " + std::to_string(m));
        return false;
    }
    const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    const int daysInMonth = kDays[m - 1] + (m == 2 && leap ? 1 : 0);
    if (d < 1 || d > daysInMonth) {
        if (d < 1) {
            bad.found("there is no day 0");
        } else if (m == 2) {
            bad.found("February " + std::to_string(y) + " has " + std::to_string(daysInMonth) + " days" +
                      (leap ? "" : " (" + std::to_string(y) + " is no leap year)"));
        } else {
            bad.found(std::string(kMonthNames[m - 1]) + " has " + std::to_string(daysInMonth) + " days");
        }
        return false;
    }
    const long yy = y - (m <= 2 ? 1 : 0);
    const long era = (yy >= 0 ? yy : yy - 399) / 400;
    const long yoe = yy - era * 400;
    const long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    days = era * 146097 + doe - 719468;
    return true;
}

/// "h:mm[:ss[.fff]]" from @p pos, the hour of one digit or two, then optionally " AM"/" PM"
/// (12-hour clock) when @p amPm; @p pos is moved past it. False when the text has another form;
/// a time of that form that does not exist (25:00, 8:61, 13 PM) is noted in @p bad.
bool timeOfDay(std::string_view s, std::size_t& pos, bool amPm, double& secondsOfDay, Impossible& bad) {
    int h = 0, mi = 0, whole = 0;
    if (!digits(s, pos, 1, 2, h) || !expect(s, pos, ':') || !digits(s, pos, 2, 2, mi)) {
        return false;
    }
    double sec = 0;
    if (expect(s, pos, ':')) {
        if (!digits(s, pos, 2, 2, whole)) {
            return false;
        }
        sec = whole;
        if (pos < s.size() && (s[pos] == '.' || s[pos] == ',')) {
            ++pos;
            double scale = 0.1;
            while (pos < s.size() && isDigit(s[pos])) {
                sec += (s[pos] - '0') * scale;
                scale /= 10;
                ++pos;
            }
        }
    }
    if (amPm) {
        std::size_t p = pos;
        while (p < s.size() && s[p] == ' ') {
            ++p;
        }
        const std::string rest = historian::lowerAscii(s.substr(p));
        const bool am = rest == "am" || rest == "a.m.";
        const bool pm = rest == "pm" || rest == "p.m.";
        if (am || pm) {
            if (h < 1 || h > 12) {
                bad.found("a 12-hour clock has no hour " + std::to_string(h));
            }
            h = h % 12 + (pm ? 12 : 0);
            pos = s.size();
        }
    }
    if (h > 24) {
        bad.found("there is no hour " + std::to_string(h));
    } else if (h == 24 && (mi > 0 || sec > 0)) {
        bad.found("a day ends at 24:00");
    } else if (mi > 59) {
        bad.found("there is no minute " + std::to_string(mi));
    } else if (whole > 60) {
        bad.found("there is no second " + std::to_string(whole));
    }
    secondsOfDay = h * 3600.0 + mi * 60.0 + sec;
    return true;
}

/// One or more spaces (or an ISO 'T') between the date and the time of day.
bool dateTimeGap(std::string_view s, std::size_t& pos, bool allowT) {
    if (allowT && expect(s, pos, 'T')) {
        return true;
    }
    const std::size_t start = pos;
    while (pos < s.size() && s[pos] == ' ') {
        ++pos;
    }
    return pos > start;
}

bool monthByName(std::string_view s, std::size_t& pos, int& month) {
    static const char* const kMonths[] = {"jan", "feb", "mar", "apr", "may", "jun",
                                          "jul", "aug", "sep", "oct", "nov", "dec"};
    std::size_t n = 0;
    while (pos + n < s.size() && std::isalpha(static_cast<unsigned char>(s[pos + n]))) {
        ++n;
    }
    if (n < 3) {
        return false;
    }
    const std::string word = historian::lowerAscii(s.substr(pos, n));
    for (int m = 0; m < 12; ++m) {
        if (word == kMonths[m] || word == historian::lowerAscii(kMonthNames[m]) ||
            (m == 8 && word == "sept")) {
            month = m + 1;
            pos += n;
            return true;
        }
    }
    return false;
}

/// Seconds of a date and a time of day; a date that does not exist is noted in @p bad (the cell
/// still has a stamp's form, so true).
bool dateAndTime(int y, int mo, int d, double secondsOfDay, double& seconds, Impossible& bad) {
    long days = 0;
    if (civilDays(y, mo, d, days, bad)) {
        seconds = static_cast<double>(days) * 86400.0 + secondsOfDay;
    }
    return true;
}

/// The form of @p s in @p format: false when it has another; @p bad notes a date or time of that
/// form that does not exist.
bool readStampForm(std::string_view s, TimeFormat format, historian::TimeStamp& stamp, Impossible& bad) {
    std::size_t pos = 0;
    int y = 0, mo = 0, d = 0;
    double tod = 0;
    switch (format) {
    case TimeFormat::Seconds:
    case TimeFormat::EpochSeconds:
    case TimeFormat::EpochMillis:
    case TimeFormat::ExcelDays: {
        const historian::NumberCell n = historian::readNumberCell(s);
        if (!n.isNumber) {
            return false;
        }
        if (format == TimeFormat::EpochMillis) {
            stamp.seconds = n.value / 1000.0;
        } else if (format == TimeFormat::ExcelDays) {
            if (n.value < 0 || n.value > 2958465) {
                return false;
            }
            // A cell below 1 holds a time of day alone: Excel's calendar has no day 0 (its serial 1
            // is 1900-01-01), and it shows such a cell as a time, 0.3333 as 08:00:00. The seconds
            // then count from a midnight the file does not date.
            stamp.timeOfDayOnly = n.value < 1;
            // Excel's day 25569 is 1970-01-01 (its calendar counts from 1899-12-30).
            // To 10 ms: ten significant digits of a day resolve a millisecond, not better.
            const double days = stamp.timeOfDayOnly ? n.value : n.value - 25569.0;
            stamp.seconds = std::round(days * 86400.0 * 100.0) / 100.0;
        } else {
            stamp.seconds = n.value;
        }
        return true;
    }
    case TimeFormat::Iso8601: {
        if (!digits(s, pos, 4, 4, y) || !expect(s, pos, '-') || !digits(s, pos, 2, 2, mo) ||
            !expect(s, pos, '-') || !digits(s, pos, 2, 2, d) || !dateTimeGap(s, pos, true) ||
            !timeOfDay(s, pos, false, tod, bad) || !dateAndTime(y, mo, d, tod, stamp.seconds, bad)) {
            return false;
        }
        if (pos == s.size()) {
            return true; // naive local time
        }
        if (s[pos] == 'Z' && pos + 1 == s.size()) {
            stamp.hasOffset = true;
            return true;
        }
        if (s[pos] == '+' || s[pos] == '-') {
            const int sign = s[pos] == '+' ? 1 : -1;
            ++pos;
            int oh = 0, om = 0;
            if (!digits(s, pos, 2, 2, oh)) {
                return false;
            }
            expect(s, pos, ':');
            if (!digits(s, pos, 2, 2, om) || pos != s.size()) {
                return false;
            }
            stamp.hasOffset = true;
            stamp.offsetMinutes = sign * (oh * 60 + om);
            stamp.seconds -= stamp.offsetMinutes * 60.0; // to UTC
            return true;
        }
        return false;
    }
    case TimeFormat::YmdSlash:
        return digits(s, pos, 4, 4, y) && expect(s, pos, '/') && digits(s, pos, 1, 2, mo) &&
               expect(s, pos, '/') && digits(s, pos, 1, 2, d) && dateTimeGap(s, pos, false) &&
               timeOfDay(s, pos, true, tod, bad) && pos == s.size() &&
               dateAndTime(y, mo, d, tod, stamp.seconds, bad);
    case TimeFormat::DmyDot:
    case TimeFormat::DmySlash:
    case TimeFormat::MdySlash: {
        const char sep = format == TimeFormat::DmyDot ? '.' : '/';
        int a = 0, b = 0;
        if (!digits(s, pos, 1, 2, a) || !expect(s, pos, sep) || !digits(s, pos, 1, 2, b) ||
            !expect(s, pos, sep) || !year(s, pos, y) || !dateTimeGap(s, pos, false) ||
            !timeOfDay(s, pos, true, tod, bad) || pos != s.size()) {
            return false;
        }
        d = format == TimeFormat::MdySlash ? b : a;
        mo = format == TimeFormat::MdySlash ? a : b;
        return dateAndTime(y, mo, d, tod, stamp.seconds, bad);
    }
    case TimeFormat::DayMonthNameYear: {
        if (!digits(s, pos, 1, 2, d) || !(expect(s, pos, '-') || expect(s, pos, ' ')) ||
            !monthByName(s, pos, mo) || !(expect(s, pos, '-') || expect(s, pos, ' ')) || !year(s, pos, y) ||
            !dateTimeGap(s, pos, false) || !timeOfDay(s, pos, true, tod, bad) || pos != s.size()) {
            return false;
        }
        return dateAndTime(y, mo, d, tod, stamp.seconds, bad);
    }
    }
    return false;
}

} // namespace

std::string timeFormatName(TimeFormat f) {
    switch (f) {
    case TimeFormat::Seconds:
        return "seconds";
    case TimeFormat::Iso8601:
        return "iso8601";
    case TimeFormat::YmdSlash:
        return "Y/m/d";
    case TimeFormat::DmyDot:
        return "d.m.Y";
    case TimeFormat::DmySlash:
        return "d/m/Y";
    case TimeFormat::MdySlash:
        return "m/d/Y";
    case TimeFormat::DayMonthNameYear:
        return "d-Mon-Y";
    case TimeFormat::ExcelDays:
        return "excel_days";
    case TimeFormat::EpochSeconds:
        return "epoch_s";
    case TimeFormat::EpochMillis:
        return "epoch_ms";
    }
    return "seconds";
}

std::optional<TimeFormat> timeFormatByName(const std::string& name) {
    for (TimeFormat f : kAllFormats) {
        if (timeFormatName(f) == name) {
            return f;
        }
    }
    return std::nullopt;
}

std::string timeFormatNames() {
    std::string list;
    for (TimeFormat f : kAllFormats) {
        list += (list.empty() ? "" : ", ") + timeFormatName(f);
    }
    return list;
}

bool parseTimeCell(std::string_view cell, TimeFormat format, double& seconds) {
    historian::TimeStamp stamp;
    if (!historian::parseTimeStamp(cell, format, stamp)) {
        return false;
    }
    seconds = stamp.seconds;
    return true;
}

} // namespace drytwin::data

namespace drytwin::data::historian {

StampReading readTimeStamp(std::string_view cell, TimeFormat format, TimeStamp& stamp,
                           std::string* whyImpossible) {
    stamp = {};
    Impossible bad;
    if (!readStampForm(trimmed(cell), format, stamp, bad)) {
        return StampReading::NotThisFormat;
    }
    if (!bad.why.empty()) {
        if (whyImpossible) {
            *whyImpossible = bad.why;
        }
        return StampReading::ImpossibleDate;
    }
    return StampReading::Read;
}

std::string impossibleStampReason(std::string_view cell, const std::string& why) {
    return "impossible date or time '" + std::string(trimmed(cell)) + "': " + why +
           ". The cell is damaged; correct or remove the row";
}

bool parseTimeStamp(std::string_view cell, TimeFormat format, TimeStamp& stamp) {
    return readTimeStamp(cell, format, stamp) == StampReading::Read;
}

std::string timeOfDayText(double secondsSinceFirstMidnight) {
    const double day = std::floor(secondsSinceFirstMidnight / 86400.0);
    const double s = secondsSinceFirstMidnight - day * 86400.0;
    const int whole = static_cast<int>(std::floor(s));
    char buf[48];
    std::snprintf(buf, sizeof buf, "%02d:%02d:%02d", whole / 3600, whole / 60 % 60, whole % 60);
    std::string text(buf);
    if (const int ms = static_cast<int>(std::lround((s - whole) * 1000.0)); ms > 0 && ms < 1000) {
        std::snprintf(buf, sizeof buf, ".%03d", ms);
        text += buf;
    }
    return day > 0 ? "day " + std::to_string(static_cast<long>(day) + 1) + " " + text : text;
}

std::string isoTimestamp(double epochSeconds) {
    const auto whole = static_cast<time_t>(std::floor(epochSeconds));
    std::tm tm{};
    gmtime_r(&whole, &tm);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec);
    return buf;
}

} // namespace drytwin::data::historian
