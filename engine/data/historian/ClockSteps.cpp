#include "data/historian/ClockSteps.h"

#include "common/NumberText.h"
#include "data/historian/PlaceInFile.h"

#include <cmath>
#include <cstdio>

namespace drytwin::data::historian {

namespace {

std::string zone(int offsetMinutes) {
    char buf[16];
    const int a = std::abs(offsetMinutes);
    std::snprintf(buf, sizeof buf, "%c%02d:%02d", offsetMinutes < 0 ? '-' : '+', a / 60, a % 60);
    return buf;
}

} // namespace

ClockWatch::ClockWatch(std::string file, int timeColumn, TimeFormat format, double sampleSlackS)
    : m_file(std::move(file)), m_column(timeColumn), m_format(format), m_slackS(sampleSlackS) {}

std::string ClockWatch::when(double t) const {
    if (m_format == TimeFormat::Seconds) {
        return shortNumber(t) + " s";
    }
    return isoTimestamp(t) + (m_previous.hasOffset ? " UTC" : "");
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
    if (std::abs(back - 3600.0) <= m_slackS) {
        m_notes.push_back(
            placeInFile(m_file, line, m_column) + ": the clock goes back " +
            std::to_string(static_cast<long>(std::lround(back))) +
            " s, one hour (daylight saving ends in local time); the run ends here and a new one "
            "starts, nothing is reordered");
        return ClockStep::DaylightSavingEnd;
    }
    Error e =
        fileError(m_file, line, m_column,
                  "time goes back " + shortNumber(back) + " s (" + when(stamp.seconds) + " after " +
                      when(before.seconds) + " on line " + std::to_string(beforeLine) +
                      "): rows out of order or a clock reset. Only daylight saving's step back of one hour "
                      "is read (as a new run). Sort the export by time or remove the overlapping rows; if "
                      "each batch restarts its clock, name the batch column in the column mapping "
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

} // namespace drytwin::data::historian
