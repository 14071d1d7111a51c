#pragma once

#include "data/historian/TimeStamps.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data::historian {

/// @brief What the first cells of a time column say about its format.
struct TimeFormatGuess {
    std::optional<TimeFormat> format;
    /// Slash dates that read as day/month and as month/day alike in the first rows: the whole
    /// column decides (decideDayMonthOrder).
    bool dayOrMonthFirst = false;
    std::string why; ///< when neither: why no format fits
};

/// @brief The format of a time column (header @p header) from its first cells. Excel serial days
/// are told from seconds by their range and step, not by whether the first stamp has a fraction.
TimeFormatGuess detectTimeFormat(const std::vector<std::string_view>& cells, const std::string& header);

/// @brief Day/month or month/day for slash dates, decided on the whole column, cell by cell: the
/// reading every cell fits, or the one whose stamps follow each other closely (in the wrong one a
/// change of date is a jump of a month).
class DayMonthOrderVote {
public:
    /// @brief Counts one cell of the column (missing cells are passed over).
    void add(std::string_view cell);
    /// @brief The order, or nullopt with @p why (naming the mapping setting that decides) when both
    /// read the column equally well; @p header names the column in it.
    std::optional<TimeFormat> decide(const std::string& header, std::string& why) const;

private:
    bool m_dmyFits = true, m_mdyFits = true, m_differ = false, m_started = false;
    double m_dmyTravel = 0, m_mdyTravel = 0, m_dmyPrev = 0, m_mdyPrev = 0;
    std::string m_first, m_last;
};

/// @brief True for a header that names a time or date (Timestamp, Zeit, Datum, 时间 …).
bool namedLikeTime(const std::string& header);

/// @brief The median of a time column's positive steps; -1 when it has none.
double medianPositiveStep(const std::vector<double>& times);

} // namespace drytwin::data::historian
