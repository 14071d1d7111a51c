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
    ExcelDays,        ///< days since 1899-12-30 (Excel's serial date), fraction = time of day;
                      ///< a cell in [0, 1) is a time of day alone (0.5 = 12:00:00, no date)
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
    /// An Excel cell holding a time of day alone (a fraction of a day in [0, 1)): @c seconds count
    /// from a midnight whose date the file does not give.
    bool timeOfDayOnly = false;
};

/// @brief How a cell reads in a format: a stamp, written in another form, or written in the form
/// but naming a date or time that does not exist (29 February 2025, month 13, 25:00). The last is
/// a damaged cell, not a sign that the column has another format.
enum class StampReading { Read, NotThisFormat, ImpossibleDate };

/// @brief Reads one time-stamp cell in @p format; for ImpossibleDate, @p whyImpossible (when given)
/// says what does not exist ("February 2025 has 28 days").
StampReading readTimeStamp(std::string_view cell, TimeFormat format, TimeStamp& stamp,
                           std::string* whyImpossible = nullptr);

/// @brief The reason an error gives for a cell that reads as ImpossibleDate because @p why.
std::string impossibleStampReason(std::string_view cell, const std::string& why);

/// @brief readTimeStamp as a yes or no: true only for a stamp that reads.
bool parseTimeStamp(std::string_view cell, TimeFormat format, TimeStamp& stamp);

/// @brief "08:00:00" of seconds since the first midnight of a column of times of day alone, with
/// "day 2 " and so on before it once midnight has passed.
std::string timeOfDayText(double secondsSinceFirstMidnight);

/// @brief "2025-06-03T08:00:00" of epoch seconds (UTC).
std::string isoTimestamp(double epochSeconds);

} // namespace drytwin::data::historian
