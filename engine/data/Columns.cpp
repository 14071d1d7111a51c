#include "data/Columns.h"

#include <cctype>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <limits>

namespace drytwin::data {

namespace {
constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();
} // namespace

const std::array<ColumnSpec, kColumnCount>& columnSpecs() {
    static const std::array<ColumnSpec, kColumnCount> specs{{
        {Column::Time, "time_s", "s", "time since batch start", ColumnRole::Index, true, kNotMeasured, ""},
        {Column::THotSp, "T_hot_sp_C", "°C", "hot-air temperature setpoint", ColumnRole::ManipulatedInput,
         false, kNotMeasured,
         "when absent the measured hot-air temperature T_hot_C is taken as the setpoint"},
        {Column::THot, "T_hot_C", "°C", "measured hot-air temperature at the tube inlet", ColumnRole::Input,
         true, kNotMeasured, ""},
        {Column::AirSpeed, "air_speed_m_s", "m/s", "air speed in the drying tube", ColumnRole::Input, false,
         16.0, "typical design air speed of a cut-tobacco pneumatic dryer"},
        {Column::Feed, "feed_kg_h", "kg/h", "wet feed rate entering the tube", ColumnRole::Disturbance, true,
         kNotMeasured, ""},
        {Column::XIn, "X_in_pct", "% wb", "inlet moisture", ColumnRole::Disturbance, true, kNotMeasured, ""},
        {Column::TIn, "T_in_C", "°C", "inlet material temperature", ColumnRole::Disturbance, false, 25.0,
         "cut tobacco leaves conditioning at about 25 °C"},
        {Column::TAmb, "T_amb_C", "°C", "ambient air temperature", ColumnRole::Disturbance, true,
         kNotMeasured, ""},
        {Column::RHAmb, "RH_amb_pct", "%", "ambient relative humidity", ColumnRole::Disturbance, true,
         kNotMeasured, ""},
        {Column::XHdt, "X_hdt_pct", "% wb", "moisture at the tube outlet", ColumnRole::Output, false,
         kNotMeasured, "not measured: tube-outlet fit terms are skipped"},
        {Column::THdt, "T_hdt_C", "°C", "material temperature at the tube outlet", ColumnRole::Output, false,
         kNotMeasured, "not measured: tube-outlet fit terms are skipped"},
        {Column::XOut, "X_out_pct", "% wb", "final outlet moisture after the winnower", ColumnRole::Output,
         true, kNotMeasured, ""},
        {Column::TOut, "T_out_C", "°C", "final outlet temperature after the winnower", ColumnRole::Output,
         true, kNotMeasured, ""},
    }};
    return specs;
}

const ColumnSpec& spec(Column c) {
    return columnSpecs()[static_cast<size_t>(c)];
}

std::optional<Column> columnByName(std::string_view name) {
    for (const auto& s : columnSpecs()) {
        if (s.name == name) {
            return s.id;
        }
    }
    return std::nullopt;
}

namespace {

std::vector<std::string> lowerWords(std::string_view text) {
    std::vector<std::string> words(1);
    for (const char ch : text) {
        if (ch == '_' || ch == ' ' || ch == '-' || ch == '.' || ch == '/' || ch == '[' || ch == ']' ||
            ch == '(' || ch == ')') {
            if (!words.back().empty()) {
                words.emplace_back();
            }
        } else {
            words.back() += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        }
    }
    if (words.back().empty()) {
        words.pop_back();
    }
    return words;
}

/// "sp" in "setpoint", "in" in "inlet": the same first letter, the rest in order.
bool abbreviates(const std::string& shortWord, const std::string& longWord) {
    if (shortWord.empty() || longWord.empty() || shortWord.front() != longWord.front()) {
        return false;
    }
    std::size_t at = 0;
    for (const char ch : longWord) {
        at += at < shortWord.size() && shortWord[at] == ch ? 1 : 0;
    }
    return at == shortWord.size();
}

std::string joined(const std::vector<std::string>& words, std::size_t count) {
    std::string out;
    for (std::size_t i = 0; i < count && i < words.size(); ++i) {
        out += words[i];
    }
    return out;
}

} // namespace

bool headerLooksLike(std::string_view header, Column c) {
    const auto name = lowerWords(spec(c).name);
    const auto words = lowerWords(header);
    if (words.empty() || joined(words, words.size()) == joined(name, name.size())) {
        return !words.empty();
    }
    // The contract's symbol: its name without the unit words at its end ("T_in" of "T_in_C").
    static const std::set<std::string> unitWords{"c", "pct", "m", "s", "kg", "h"};
    std::size_t symbol = name.size();
    while (symbol > 1 && unitWords.count(name[symbol - 1]) > 0) {
        --symbol;
    }
    const std::string stem = joined(name, symbol);
    if (stem.size() >= 4 && joined(words, words.size()).rfind(stem, 0) == 0) {
        return true; // "Tamb_degC", "airspeed"
    }
    if (words.size() < symbol) {
        return false;
    }
    for (std::size_t i = 0; i < symbol; ++i) {
        if (!abbreviates(name[i], words[i])) {
            return false;
        }
    }
    return true;
}

bool possibleRange(Column c, double& low, double& high) {
    switch (c) {
    case Column::RHAmb:
    case Column::XIn:
    case Column::XHdt:
    case Column::XOut:
        low = 0;
        high = 100; // % (relative humidity, wet-basis moisture)
        return true;
    case Column::Feed:
        low = 0;
        high = 1e6; // kg/h: a pneumatic line never carries 1,000 t/h
        return true;
    case Column::AirSpeed:
        low = 0;
        high = 100; // m/s
        return true;
    case Column::THotSp:
    case Column::THot:
        low = -50;
        high = 600; // °C: hot air of a drying line
        return true;
    case Column::TIn:
    case Column::TAmb:
    case Column::THdt:
    case Column::TOut:
        low = -50;
        high = 300; // °C: material and ambient
        return true;
    default:
        return false;
    }
}

bool impossibleValue(Column c, double v) {
    double low = 0, high = 0;
    return !std::isnan(v) && possibleRange(c, low, high) && (v < low || v > high);
}

} // namespace drytwin::data
