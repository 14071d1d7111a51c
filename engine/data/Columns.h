#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace drytwin::data {

/// @brief The batch-file columns of CONTRACT.md §1.
enum class Column {
    Time,
    THotSp,
    THot,
    AirSpeed,
    Feed,
    XIn,
    TIn,
    TAmb,
    RHAmb,
    XHdt,
    THdt,
    XOut,
    TOut,
};
inline constexpr int kColumnCount = 13;

/// @brief What a column is for in the model.
enum class ColumnRole { Index, ManipulatedInput, Input, Disturbance, Output };

/// @brief Static description of one contract column.
struct ColumnSpec {
    Column id;
    std::string_view name;    ///< header name in the batch file
    std::string_view unit;    ///< unit as written in the file
    std::string_view meaning; ///< one line for help texts and reports
    ColumnRole role;
    bool required;
    /// Value used when an optional column is absent; NaN means "not measured"
    /// (the column is then simply not used, e.g. tube-outlet outputs).
    double defaultValue;
    std::string_view defaultReason;
};

/// @brief All contract columns in contract order.
const std::array<ColumnSpec, kColumnCount>& columnSpecs();
/// @brief Spec of one column.
const ColumnSpec& spec(Column c);
/// @brief Physically possible range of a contract column in file units; false for columns
/// without one (time). A value outside it is impossible: inspect lists it with file:line, the
/// cleaning drops its row and, for an input, the conversion to SI bridges it like a missing cell.
bool possibleRange(Column c, double& low, double& high);
/// @brief True when @p v lies outside the possible range of @p c (NaN is missing, not impossible).
bool impossibleValue(Column c, double v);

/// @brief Column whose header name is @p name, if it is a contract column.
std::optional<Column> columnByName(std::string_view name);

/// @brief Whether a file's header that is not a contract name looks like the contract column
/// @p c spelt another way: the same name in other case or separators ("x_out_pct"), or the
/// contract's symbol without its unit, each word abbreviated the same way ("T_inlet_C" for
/// T_in_C, "air_speed" for air_speed_m_s, "T_hot_setpoint_C" for T_hot_sp_C). A hint for the
/// user, never applied: a header read under a name it does not have would be a silent guess.
bool headerLooksLike(std::string_view header, Column c);

} // namespace drytwin::data
