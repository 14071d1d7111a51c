#pragma once

#include "common/Error.h"
#include "data/historian/TimeStamps.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data::historian {

/// @brief What one time stamp does after the one before.
enum class ClockStep {
    First,             ///< the first stamp
    Forward,           ///< later than the one before
    Duplicate,         ///< the same stamp again: the row is left out (counted, noted once)
    DaylightSavingEnd, ///< one hour back in the night daylight saving ends (naive local time): a new run
    NewBatchRestarts,  ///< back, where the batch column changes: each batch has its own clock
};

/// @brief The rule by which daylight saving ends in the night of naive local time @p localSeconds
/// ("the last Sunday of October (Europe, …)"), or nullptr when it ends in no such night. A night
/// runs from 23:00 on the Saturday to 05:00 on the Sunday: the repeated hour is 01:00–02:00 in the UK
/// and North America, 02:00–03:00 in central Europe, Australia and New Zealand, 03:00–04:00 in
/// eastern Europe, and 23:00–24:00 on the Saturday in Chile. Thread-safe.
const char* daylightSavingEndsIn(double localSeconds);

/// @brief Watches the time column row by row. A daylight-saving fall-back, stated by the stamps'
/// zone offset, or seen in naive local time as a step back of one hour in a night daylight saving
/// ends in (daylightSavingEndsIn), is a note; any other step back is an error with
/// file:line:column (CONTRACT.md §1: time going backwards rejects the file). Not thread-safe.
class ClockWatch {
public:
    /// @param timeColumn 1-based, for messages; @p sampleSlackS: how far from exactly one hour a
    /// daylight-saving step may land (the sample period and gaps).
    ClockWatch(std::string file, int timeColumn, TimeFormat format, double sampleSlackS);

    /// @brief The step of @p stamp on file line @p line; @p batchChanged when the batch column's
    /// value differs from the row before.
    Expected<ClockStep> step(const TimeStamp& stamp, int line, bool batchChanged);
    /// @brief Notes of the whole file (duplicates, zone changes, daylight-saving steps), file:line.
    std::vector<std::string> notes() const;

private:
    std::string when(double t) const;
    std::string whyNotDaylightSaving(const TimeStamp& before, const TimeStamp& after) const;

    std::string m_file;
    int m_column;
    TimeFormat m_format;
    double m_slackS;
    bool m_started = false;
    TimeStamp m_previous;
    int m_previousLine = 0;
    std::size_t m_duplicates = 0;
    int m_firstDuplicateLine = 0;
    std::vector<std::string> m_notes;
};

/// @brief Times of day without a date (Excel cells holding a time alone, 0.3333 for 08:00) on one
/// running clock: a fall of more than half a day (0.99 then 0.0) is midnight passed, and the stamps
/// from there count a day more. A column that mixes such cells with dated ones is an error with
/// file:line:column. Dated stamps pass through unchanged. Not thread-safe.
class DatelessDays {
public:
    /// @param timeColumn 1-based, for messages.
    DatelessDays(std::string file, int timeColumn, std::string header);

    /// @brief Adds the midnights passed before @p stamp (file line @p line, @p cell as written) to
    /// its seconds.
    Status place(TimeStamp& stamp, int line, std::string_view cell);
    /// @brief True once the column's first stamp was a time of day alone.
    bool timesOfDayOnly() const { return m_timesOfDayOnly; }
    /// @brief What was read without a date, and where midnight passed; file:line:column.
    std::vector<std::string> notes() const;

private:
    std::string m_file;
    int m_column;
    std::string m_header;
    bool m_started = false;
    bool m_timesOfDayOnly = false;
    int m_firstLine = 0;
    std::string m_firstCell;
    double m_firstSecondsOfDay = 0;
    double m_previousSecondsOfDay = 0;
    double m_daysPassed = 0;
    int m_midnights = 0;
    int m_firstMidnightLine = 0;
    std::string m_firstMidnightStep; ///< "23:59:59 then 00:00:00"
};

} // namespace drytwin::data::historian
