#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data {

/// @brief How a time column is written. Day, month and hour may have one digit or two, a year
/// two digits or four; the date forms take a 12-hour clock with AM/PM as well.
enum class TimeFormat {
    Seconds,          ///< seconds since an arbitrary start (the contract's time_s)
    Iso8601,          ///< 2025-06-03T08:00:00(.fff)(Z|±hh:mm), 'T' or a space
    YmdSlash,         ///< 2025/06/03 08:00:00
    DmyDot,           ///< 03.06.2025 08:00:00
    DmySlash,         ///< 03/06/2025 08:00:00
    MdySlash,         ///< 06/03/2025 08:00:00, 6/3/2025 8:00:00 AM (US locale)
    DayMonthNameYear, ///< 03-Jun-2025 08:00:00 (PI DataLink, PI SMT)
    ExcelDays,        ///< days since 1899-12-30 (Excel's serial date), fraction = time of day
    EpochSeconds,     ///< Unix time
    EpochMillis,
};
/// @brief The mapping file's name of a format ("iso8601", "d.m.Y", "d-b-Y", …).
std::string timeFormatName(TimeFormat f);
/// @brief The format of a mapping file's name; nullopt for a name that is none.
std::optional<TimeFormat> timeFormatByName(const std::string& name);
/// @brief Every format's mapping name, for messages: "seconds, iso8601, …".
std::string timeFormatNames();

/// @brief Parses one time-stamp cell in @p format to seconds (epoch seconds for dates; naive
/// local time counts as UTC). False when the cell does not have the format.
bool parseTimeCell(std::string_view cell, TimeFormat format, double& seconds);

} // namespace drytwin::data

namespace drytwin::data::historian {

/// @brief A time stamp as read: seconds, and the zone's offset from UTC when the stamp states one.
struct TimeStamp {
    double seconds = 0;
    bool hasOffset = false;
    int offsetMinutes = 0;
};

/// @brief parseTimeCell that also returns the zone offset an ISO 8601 stamp states.
bool parseTimeStamp(std::string_view cell, TimeFormat format, TimeStamp& stamp);

/// @brief "2025-06-03T08:00:00" of epoch seconds (UTC).
std::string isoTimestamp(double epochSeconds);

} // namespace drytwin::data::historian
