#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data::historian {

/// @brief What the marks of a number cell say about the file's number format.
enum class NumberMarks {
    None,             ///< no mark: "6497", "-12", "1e5"
    DecimalPoint,     ///< only a decimal point fits: "13.25", "6200.000", "6,497.25", "1,234,567"
    DecimalComma,     ///< only a decimal comma fits: "13,2", "6.497,25", "1.234.567"
    PointOrThousands, ///< "6.497": 6.497 with a decimal point, 6497 with a point grouping thousands
    CommaOrThousands, ///< "6,497": 6.497 with a decimal comma, 6497 with a comma grouping thousands
};

/// @brief A number cell as read before the file's number format is known.
struct NumberCell {
    bool isNumber = false;
    NumberMarks marks = NumberMarks::None;
    /// The value; an ambiguous mark ("6.497", "6,497") is read as the decimal mark here, and
    /// thousandsValue() gives the other reading.
    double value = 0;
};

/// @brief Reads a number written with a decimal point or comma and, optionally, thousands
/// grouped by the other mark (groups of three digits); an exponent is allowed without grouping.
NumberCell readNumberCell(std::string_view cell);

/// @brief The value of an ambiguous cell ("6.497") read with its mark grouping thousands (6497).
double thousandsValue(double decimalReading);

/// @brief What a column's cells say about its decimal mark, gathered over the whole file (a start-up
/// ramp below 1,000 must not decide it for the "6.497" that follow).
struct DecimalMarkEvidence {
    /// The first cell of one kind: its file line and text (line 0: none yet).
    struct FirstCell {
        int line = 0;
        std::string text;
    };
    std::size_t points = 0, commas = 0; ///< cells that fit only one mark
    FirstCell firstPoint, firstComma, firstPointOrThousands, firstCommaOrThousands;
    /// Rows of the cells that depend on the decision ("6.497", "6,497"), read with the mark as decimal.
    std::vector<std::uint32_t> pointOrThousandsRows, commaOrThousandsRows;

    /// @brief Counts @p cell (row @p row of the column, file line @p line).
    void add(const NumberCell& cell, std::uint32_t row, int line, std::string_view text);
};

/// @brief One column's evidence, with what messages call it.
struct ColumnMarks {
    const DecimalMarkEvidence* evidence = nullptr;
    std::string name;   ///< the column's header
    int fileColumn = 0; ///< 1-based
};

/// @brief The decimal mark of a file, decided on all its cells, or why it cannot be.
struct DecimalMarkDecision {
    char mark = '.';
    bool ok = true;
    std::string why; ///< when !ok: the cells that contradict each other; when guessed: the note
    int line = 0;    ///< when !ok: the place of the later of the two cells
    int fileColumn = 0;
    bool guessed = false; ///< no cell tells and some read either way: a guess, noted with its fix
};

/// @brief Decides a file's decimal mark: the mapping's `decimal_mark` when set (0: not set), else
/// what the cells that fit only one mark say, over every column and every row (a start-up ramp
/// below 1,000 does not decide it for the "6.497" that follow). Cells that contradict the mapping
/// or each other are an error. When no cell tells, a cell's only mark is taken as its decimal mark
/// (and with both kinds, a semicolon-separated file takes the decimal comma, a comma-separated one
/// the point); the guess is noted with the setting that overrides it. Where even that cannot
/// tell (both kinds in a tab-separated file), the setting is asked for.
DecimalMarkDecision decideDecimalMark(const std::vector<ColumnMarks>& columns, char mappingMark,
                                      char delimiter, const std::string& file);

/// @brief Puts a column decided as @p mark right: its ambiguous cells that group thousands
/// become thousands (6.497 → 6497).
void applyDecimalMark(const DecimalMarkEvidence& evidence, char mark, std::vector<double>& values);

/// @brief Cells that hold no value: empty, NaN, NULL, N/A, and the PI System's digital states
/// ("No Data", "Comm Fail", "Shutdown", "Bad Input", "Pt Created", "Scan Off", "I/O Timeout", …),
/// case-insensitive. @p state is set to the state's own spelling ("" for empty and NaN).
bool isMissingCell(std::string_view cell, std::string_view& state);

} // namespace drytwin::data::historian
