#include "data/historian/TimeFormatDetection.h"

#include "data/historian/NumberFormat.h"
#include "data/historian/PlaceInFile.h"

#include <algorithm>
#include <cmath>

namespace drytwin::data::historian {

double medianPositiveStep(const std::vector<double>& v) {
    std::vector<double> steps;
    for (std::size_t i = 1; i < v.size(); ++i) {
        if (v[i] > v[i - 1]) {
            steps.push_back(v[i] - v[i - 1]);
        }
    }
    if (steps.empty()) {
        return -1;
    }
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    return steps[steps.size() / 2];
}

namespace {

std::string mappingHint(const std::string& header, const std::string& a, const std::string& b) {
    return "name the format in the column mapping (\"time_s\": {\"header\": \"" + header +
           "\", \"format\": \"" + a + "\"} or \"" + b + "\")";
}

} // namespace

TimeFormatGuess detectTimeFormat(const std::vector<std::string_view>& cells, const std::string& header) {
    TimeFormatGuess g;
    std::vector<std::string_view> stamps;
    for (auto c : cells) {
        std::string_view state;
        if (!isMissingCell(c, state)) {
            stamps.push_back(trimmed(c));
        }
    }
    if (stamps.empty()) {
        g.why = "no time stamps in the first rows";
        return g;
    }
    const std::string_view first = stamps.front();
    // The form decides, not whether the date exists: "2025-02-29 08:00:00" is an ISO stamp naming a
    // day that does not exist, which the reader refuses at its own line as an impossible date rather
    // than as a stamp of no known format.
    const auto fits = [&](TimeFormat f) {
        TimeStamp t;
        return readTimeStamp(first, f, t) != StampReading::NotThisFormat;
    };
    // Day/month or month/day: a cell that exists in one reading only is evidence (13/05/2025);
    // one that exists in neither (30/02/2025) is a damaged cell and tells nothing.
    const auto all = [&](TimeFormat f, TimeFormat other) {
        TimeStamp t;
        return std::all_of(stamps.begin(), stamps.end(), [&](auto c) {
            const StampReading r = readTimeStamp(c, f, t);
            return r == StampReading::Read ||
                   (r == StampReading::ImpossibleDate && readTimeStamp(c, other, t) != StampReading::Read);
        });
    };
    // The first stamp decides the family (a bad stamp further down is then reported at its own
    // line); only day/month against month/day needs more.
    std::size_t lead = 0;
    while (lead < first.size() && (first[lead] >= '0' && first[lead] <= '9')) {
        ++lead;
    }
    const char after = lead < first.size() ? first[lead] : '\0';
    if (lead == 4 && after == '-' && fits(TimeFormat::Iso8601)) {
        g.format = TimeFormat::Iso8601;
        return g;
    }
    if (lead == 4 && after == '/' && fits(TimeFormat::YmdSlash)) {
        g.format = TimeFormat::YmdSlash;
        return g;
    }
    if (lead >= 1 && lead <= 2 && after == '.' && fits(TimeFormat::DmyDot)) {
        g.format = TimeFormat::DmyDot;
        return g;
    }
    if (lead >= 1 && lead <= 2 && (after == '-' || after == ' ') && fits(TimeFormat::DayMonthNameYear)) {
        g.format = TimeFormat::DayMonthNameYear;
        return g;
    }
    if (lead >= 1 && lead <= 2 && after == '/') {
        const bool dmy = all(TimeFormat::DmySlash, TimeFormat::MdySlash);
        const bool mdy = all(TimeFormat::MdySlash, TimeFormat::DmySlash);
        if (dmy != mdy) {
            g.format = dmy ? TimeFormat::DmySlash : TimeFormat::MdySlash;
            return g;
        }
        if (dmy && mdy) {
            g.dayOrMonthFirst = true;
            return g;
        }
    }
    std::vector<double> values;
    for (auto c : stamps) {
        const NumberCell n = readNumberCell(c);
        if (!n.isNumber) {
            break;
        }
        values.push_back(n.value);
    }
    if (!values.empty()) {
        const double v = values.front();
        if (v >= 1e11) {
            g.format = TimeFormat::EpochMillis;
            return g;
        }
        if (v >= 1e8) {
            g.format = TimeFormat::EpochSeconds;
            return g;
        }
        // Excel's serial days of 1954–2119 step by a fraction of a day (1 s = 0.0000116): a step
        // below 0.05 would be sampling faster than 20 Hz in seconds, which no historian of a drying
        // line does. Whether the first stamp has a fraction does not matter (an export starting at
        // midnight begins with a whole number). The contract's own time_s is always seconds.
        const bool excelRange =
            std::all_of(values.begin(), values.end(), [](double x) { return x >= 20000 && x < 80000; });
        const double step = medianPositiveStep(values);
        const bool fraction =
            std::any_of(values.begin(), values.end(), [](double x) { return std::floor(x) != x; });
        if (header != "time_s" && excelRange &&
            (step > 0 ? step < 0.05 : fraction && namedLikeTime(header))) {
            g.format = TimeFormat::ExcelDays;
            return g;
        }
        // Excel cells holding a time of day alone: fractions of a day in [0, 1), 1 s apart being
        // 0.0000116. As seconds they would be a historian sampling faster than 20 Hz, the same
        // argument as for serial days; they are read as Excel's, without a date. A header that
        // states a unit ("Zeit [min]") says what the numbers are.
        const bool timeOfDayRange =
            std::all_of(values.begin(), values.end(), [](double x) { return x >= 0 && x < 1; });
        if (header != "time_s" && header.find('[') == std::string::npos && timeOfDayRange &&
            (step > 0 ? step < 0.05 : fraction && namedLikeTime(header))) {
            g.format = TimeFormat::ExcelDays;
            return g;
        }
        g.format = TimeFormat::Seconds;
        return g;
    }
    g.why =
        "'" + std::string(first) +
        "' is not a time stamp DryTwin knows (ISO 8601, Y/m/d, d.m.Y, d/m/Y, m/d/Y, " +
        "d-Mon-Y as PI writes it, Excel serial days, Unix seconds or milliseconds); name the format in the "
        "column mapping (\"time_s\": {\"header\": \"" +
        header + "\", \"format\": …}: " + timeFormatNames() + ")";
    return g;
}

void DayMonthOrderVote::add(std::string_view cell) {
    std::string_view state;
    if ((!m_dmyFits && !m_mdyFits) || isMissingCell(cell, state)) {
        return;
    }
    TimeStamp a, b;
    const StampReading asDmy = readTimeStamp(cell, TimeFormat::DmySlash, a);
    const StampReading asMdy = readTimeStamp(cell, TimeFormat::MdySlash, b);
    if (asDmy == StampReading::ImpossibleDate && asMdy == StampReading::ImpossibleDate) {
        return; // a day that exists in neither order (30/02/2025): the reader names it at its line
    }
    const bool dmy = m_dmyFits && asDmy == StampReading::Read;
    const bool mdy = m_mdyFits && asMdy == StampReading::Read;
    if (m_dmyFits && m_mdyFits && dmy && mdy) {
        m_differ = m_differ || a.seconds != b.seconds;
        if (m_started) {
            m_dmyTravel += std::abs(a.seconds - m_dmyPrev);
            m_mdyTravel += std::abs(b.seconds - m_mdyPrev);
        } else {
            m_first = trimmed(cell);
        }
        m_last = trimmed(cell);
        m_started = true;
        m_dmyPrev = a.seconds;
        m_mdyPrev = b.seconds;
    }
    m_dmyFits = dmy;
    m_mdyFits = mdy;
}

std::optional<TimeFormat> DayMonthOrderVote::decide(const std::string& header, std::string& why) const {
    if (m_dmyFits != m_mdyFits) {
        return m_dmyFits ? TimeFormat::DmySlash : TimeFormat::MdySlash;
    }
    if (!m_dmyFits) {
        why = "the slash dates fit neither day/month/year nor month/day/year; " +
              mappingHint(header, "d/m/Y", "m/d/Y");
        return std::nullopt;
    }
    if (!m_differ) {
        return TimeFormat::MdySlash; // every date has day = month: both read it alike
    }
    if (m_dmyTravel < 0.5 * m_mdyTravel) {
        return TimeFormat::DmySlash;
    }
    if (m_mdyTravel < 0.5 * m_dmyTravel) {
        return TimeFormat::MdySlash;
    }
    why = "the dates (" + m_first + " to " + m_last + ") read as day/month and as month/day alike; " +
          mappingHint(header, "m/d/Y", "d/m/Y");
    return std::nullopt;
}

bool namedLikeTime(const std::string& header) {
    const std::string l = lowerAscii(header);
    for (const char* k : {"timestamp", "time", "date", "zeit", "datum", "时间", "日期"}) {
        if (l.find(k) != std::string::npos) {
            return true;
        }
    }
    return false;
}

} // namespace drytwin::data::historian
