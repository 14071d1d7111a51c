#pragma once

#include "common/Error.h"
#include "data/historian/TimeStamps.h"

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::data::historian {

/// @brief What one time stamp does after the one before.
enum class ClockStep {
    First,             ///< the first stamp
    Forward,           ///< later than the one before
    Duplicate,         ///< the same stamp again: the row is left out (counted, noted once)
    DaylightSavingEnd, ///< one hour back (daylight saving ends in naive local time): a new run
    NewBatchRestarts,  ///< back, where the batch column changes: each batch has its own clock
};

/// @brief Watches the time column row by row. A daylight-saving fall-back, stated by the stamps'
/// zone offset or seen as a step back of one hour, is a note; any other step back is an error with
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

} // namespace drytwin::data::historian
