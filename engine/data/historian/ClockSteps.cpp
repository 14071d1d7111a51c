#include "data/historian/ClockSteps.h"

#include "common/NumberText.h"
#include "data/historian/PlaceInFile.h"

#include <cmath>
#include <cstdio>
#include <ctime>

namespace drytwin::data::historian {

namespace {

std::string zone(int offsetMinutes) {
    char buf[16];
    const int a = std::abs(offsetMinutes);
    std::snprintf(buf, sizeof buf, "%c%02d:%02d", offsetMinutes < 0 ? '-' : '+', a / 60, a % 60);
    return buf;
}

/// The nights daylight saving ends in, as the tz database's "Sun>=N" rules (2025): the Sunday on
/// or after day @c firstDay of @c month. A short list of the zones with the most plants rather than
/// the tz database itself: a naive local stamp says nothing of its zone, so the date can only tell
/// whether some zone's clocks went back that night, and a list of four nights is one a reader can
/// check. Dates outside it (a step back on 3 June) stay errors, as CONTRACT.md §1 wants.
struct FallBackRule {
    int month;
    int firstDay;
    const char* name;
};
constexpr FallBackRule kFallBackRules[] = {
    {10, 25, "the last Sunday of October (Europe, UK, Israel, Lebanon)"},
    {11, 1, "the first Sunday of November (United States, Canada, Cuba)"},
    {4, 1, "the first Sunday of April (south-eastern Australia, New Zealand)"},
    {4, 2, "the Sunday on or after 2 April (Chile, at midnight)"},
};

bool isDatedFormat(TimeFormat f) {
    return f != TimeFormat::Seconds && f != TimeFormat::EpochSeconds && f != TimeFormat::EpochMillis;
}

} // namespace

const char* daylightSavingEndsIn(double localSeconds) {
    // The night belongs to its Sunday: an hour later, a stamp of Saturday 23:xx is on the Sunday.
    const double shifted = localSeconds + 3600.0;
    const auto whole = static_cast<time_t>(std::floor(shifted));
    std::tm tm{};
    if (!gmtime_r(&whole, &tm) || tm.tm_wday != 0 || tm.tm_hour >= 6) {
        return nullptr;
    }
    for (const auto& rule : kFallBackRules) {
        if (tm.tm_mon + 1 == rule.month && tm.tm_mday >= rule.firstDay && tm.tm_mday < rule.firstDay + 7) {
            return rule.name;
        }
    }
    return nullptr;
}

ClockWatch::ClockWatch(std::string file, int timeColumn, TimeFormat format, double sampleSlackS)
    : m_file(std::move(file)), m_column(timeColumn), m_format(format), m_slackS(sampleSlackS) {}

std::string ClockWatch::when(double t) const {
    if (m_format == TimeFormat::Seconds) {
        return shortNumber(t) + " s";
    }
    if (m_previous.timeOfDayOnly) {
        return timeOfDayText(t);
    }
    return isoTimestamp(t) + (m_previous.hasOffset ? " UTC" : "");
}

std::string ClockWatch::whyNotDaylightSaving(const TimeStamp& before, const TimeStamp& after) const {
    if (!isDatedFormat(m_format) || after.timeOfDayOnly) {
        return "a step back of one hour, but these stamps have no local date and so no daylight saving";
    }
    if (after.hasOffset || before.hasOffset) {
        return "a step back of one hour although the stamps state their zone (where daylight saving ends, "
               "the offset changes and time goes on)";
    }
    return "a step back of one hour, but not in a night daylight saving ends in (from 23:00 on the "
           "Saturday to 05:00 on the last Sunday of October, the first Sunday of November, the first "
           "Sunday of April, or the Sunday on or after 2 April)";
}

Expected<ClockStep> ClockWatch::step(const TimeStamp& stamp, int line, bool batchChanged) {
    if (!m_started) {
        m_started = true;
        m_previous = stamp;
        m_previousLine = line;
        return ClockStep::First;
    }
    const TimeStamp before = m_previous;
    const int beforeLine = m_previousLine;
    if (stamp.hasOffset && before.hasOffset && stamp.offsetMinutes != before.offsetMinutes) {
        m_notes.push_back(placeInFile(m_file, line, m_column) + ": the stamps' time zone changes from " +
                          zone(before.offsetMinutes) + " to " + zone(stamp.offsetMinutes) +
                          (stamp.offsetMinutes < before.offsetMinutes ? " (daylight saving ends)"
                                                                      : " (daylight saving begins)") +
                          "; the stamps are read in UTC, so the run goes on");
    }
    if (stamp.seconds == before.seconds) {
        if (m_duplicates++ == 0) {
            m_firstDuplicateLine = line;
        }
        return ClockStep::Duplicate; // the first row with a stamp is kept
    }
    m_previous = stamp;
    m_previousLine = line;
    if (stamp.seconds > before.seconds) {
        return ClockStep::Forward;
    }
    const double back = before.seconds - stamp.seconds;
    if (batchChanged) {
        return ClockStep::NewBatchRestarts;
    }
    const bool oneHour = std::abs(back - 3600.0) <= m_slackS;
    const char* rule =
        oneHour && isDatedFormat(m_format) && !stamp.hasOffset && !before.hasOffset && !stamp.timeOfDayOnly
            ? daylightSavingEndsIn(stamp.seconds)
            : nullptr;
    if (rule) {
        m_notes.push_back(placeInFile(m_file, line, m_column) + ": the clock goes back " +
                          std::to_string(static_cast<long>(std::lround(back))) +
                          " s, one hour (daylight saving ends in local time, " + rule +
                          "); the run ends here and a new one starts, nothing is reordered");
        return ClockStep::DaylightSavingEnd;
    }
    const std::string why =
        oneHour ? whyNotDaylightSaving(before, stamp) + ": rows out of order or a clock reset"
                : "rows out of order or a clock reset. Only daylight saving's step back of one hour is "
                  "read (as a new run)";
    Error e = fileError(m_file, line, m_column,
                        "time goes back " + shortNumber(back) + " s (" + when(stamp.seconds) + " after " +
                            when(before.seconds) + " on line " + std::to_string(beforeLine) + "): " + why +
                            ". Sort the export by time or remove the overlapping rows; if each batch "
                            "restarts its clock, name the batch column in the column mapping "
                            "(\"batch_id\": {\"header\": …})",
                        ErrorCode::TimeNotIncreasing);
    e.args = {m_file, std::to_string(line), std::to_string(m_column)};
    return e;
}

std::vector<std::string> ClockWatch::notes() const {
    std::vector<std::string> all = m_notes;
    if (m_duplicates > 0) {
        all.push_back(placeInFile(m_file, m_firstDuplicateLine, m_column) + ": " +
                      std::to_string(m_duplicates) +
                      " row(s) repeat the time stamp of the row before (first here); each duplicate is left "
                      "out, the first row with the stamp kept");
    }
    return all;
}

DatelessDays::DatelessDays(std::string file, int timeColumn, std::string header)
    : m_file(std::move(file)), m_column(timeColumn), m_header(std::move(header)) {}

Status DatelessDays::place(TimeStamp& stamp, int line, std::string_view cell) {
    if (!m_started) {
        m_started = true;
        m_timesOfDayOnly = stamp.timeOfDayOnly;
        m_firstLine = line;
        m_firstCell = std::string(trimmed(cell));
        m_firstSecondsOfDay = stamp.seconds;
    } else if (stamp.timeOfDayOnly != m_timesOfDayOnly) {
        // Seconds since an undated midnight beside seconds since 1970 would be a step of decades.
        return fileError(m_file, line, m_column,
                         "'" + std::string(trimmed(cell)) + "' holds " +
                             (stamp.timeOfDayOnly ? "a time of day alone" : "a date") +
                             ", while the column's first stamp ('" + m_firstCell + "' on line " +
                             std::to_string(m_firstLine) + ") holds " +
                             (m_timesOfDayOnly ? "a time of day alone" : "a date and a time of day") +
                             "; export the column in one form (Excel: one cell format for the whole column)");
    }
    if (!m_timesOfDayOnly) {
        return {};
    }
    const double secondsOfDay = stamp.seconds;
    // Half a day back is no clock reset or row out of order but the next day: a run across
    // midnight (0.9999 then 0.0000). Smaller steps back stay steps back for ClockWatch to judge.
    if (secondsOfDay < m_previousSecondsOfDay - 43200.0) {
        if (m_midnights++ == 0) {
            m_firstMidnightLine = line;
            m_firstMidnightStep =
                timeOfDayText(m_previousSecondsOfDay) + " then " + timeOfDayText(secondsOfDay);
        }
        m_daysPassed += 86400.0;
    }
    m_previousSecondsOfDay = secondsOfDay;
    stamp.seconds = secondsOfDay + m_daysPassed;
    return {};
}

std::vector<std::string> DatelessDays::notes() const {
    std::vector<std::string> notes;
    if (!m_timesOfDayOnly) {
        return notes;
    }
    notes.push_back(placeInFile(m_file, m_firstLine, m_column) + ": column '" + m_header +
                    "' holds times of day alone, without a date (Excel's fractions of a day: '" +
                    m_firstCell + "' is " + timeOfDayText(m_firstSecondsOfDay) +
                    "); read as seconds since midnight of a day the file does not name");
    if (m_midnights > 0) {
        notes.push_back(placeInFile(m_file, m_firstMidnightLine, m_column) +
                        ": the times of day pass midnight here (" + m_firstMidnightStep +
                        "), read as the next day" +
                        (m_midnights > 1 ? "; " + std::to_string(m_midnights) + " midnights in all" : ""));
    }
    return notes;
}

} // namespace drytwin::data::historian
