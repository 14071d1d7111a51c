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
/// @brief Column whose header name is @p name, if it is a contract column.
std::optional<Column> columnByName(std::string_view name);

} // namespace drytwin::data
