#include "data/historian/NumberFormat.h"

#include "data/historian/PlaceInFile.h"

#include <charconv>
#include <cmath>

namespace drytwin::data::historian {

namespace {

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

/// "6.497.250" grouped by @p mark: 1–3 digits (not starting with 0), then groups of exactly three.
bool validGrouping(std::string_view part, char mark) {
    std::size_t groups = 0;
    std::size_t start = 0;
    while (true) {
        const auto end = part.find(mark, start);
        const std::string_view g =
            part.substr(start, end == std::string_view::npos ? part.size() - start : end - start);
        for (char c : g) {
            if (!isDigit(c)) {
                return false;
            }
        }
        if (groups == 0 ? (g.empty() || g.size() > 3 || g[0] == '0') : g.size() != 3) {
            return false;
        }
        ++groups;
        if (end == std::string_view::npos) {
            break;
        }
        start = end + 1;
    }
    return groups >= 2;
}

} // namespace

NumberCell readNumberCell(std::string_view cell) {
    NumberCell r;
    const std::string_view s = trimmed(cell);
    if (s.empty() || s.size() > 64) {
        return r;
    }
    std::size_t i = 0;
    const bool negative = s[0] == '-';
    if (s[0] == '+' || s[0] == '-') {
        ++i;
    }
    const std::size_t mantissaStart = i;
    std::size_t digits = 0, dots = 0, commas = 0, lastDot = 0, lastComma = 0;
    for (; i < s.size() && (isDigit(s[i]) || s[i] == '.' || s[i] == ','); ++i) {
        if (s[i] == '.') {
            ++dots;
            lastDot = i - mantissaStart;
        } else if (s[i] == ',') {
            ++commas;
            lastComma = i - mantissaStart;
        } else {
            ++digits;
        }
    }
    if (digits == 0) {
        return r;
    }
    const std::string_view mantissa = s.substr(mantissaStart, i - mantissaStart);
    const std::string_view exponent = s.substr(i);
    if (!exponent.empty()) {
        std::size_t k = 1;
        if (exponent[0] != 'e' && exponent[0] != 'E') {
            return r;
        }
        if (k < exponent.size() && (exponent[k] == '+' || exponent[k] == '-')) {
            ++k;
        }
        if (k == exponent.size()) {
            return r;
        }
        for (; k < exponent.size(); ++k) {
            if (!isDigit(exponent[k])) {
                return r;
            }
        }
    }
    char decimal = 0, group = 0;
    if (dots + commas == 0) {
        r.marks = NumberMarks::None;
    } else if (dots + commas == 1) {
        decimal = dots ? '.' : ',';
        const std::size_t at = dots ? lastDot : lastComma;
        const std::string_view whole = mantissa.substr(0, at);
        const std::string_view fraction = mantissa.substr(at + 1);
        const bool couldGroup = exponent.empty() && fraction.size() == 3 && !whole.empty() &&
                                whole.size() <= 3 && whole[0] != '0';
        r.marks = couldGroup ? (dots ? NumberMarks::PointOrThousands : NumberMarks::CommaOrThousands)
                             : (dots ? NumberMarks::DecimalPoint : NumberMarks::DecimalComma);
    } else if (dots == 0 || commas == 0) {
        // One mark several times: it groups thousands, so the decimal mark is the other one.
        group = dots ? '.' : ',';
        if (!exponent.empty() || !validGrouping(mantissa, group)) {
            return r;
        }
        r.marks = dots ? NumberMarks::DecimalComma : NumberMarks::DecimalPoint;
    } else {
        // Both marks: the last one is the decimal mark and appears once; the other groups thousands.
        decimal = lastDot > lastComma ? '.' : ',';
        group = decimal == '.' ? ',' : '.';
        if ((decimal == '.' ? dots : commas) != 1 || !exponent.empty() ||
            !validGrouping(mantissa.substr(0, decimal == '.' ? lastDot : lastComma), group)) {
            return r;
        }
        r.marks = decimal == '.' ? NumberMarks::DecimalPoint : NumberMarks::DecimalComma;
    }
    char buf[80];
    std::size_t n = 0;
    if (negative) {
        buf[n++] = '-';
    }
    for (char c : mantissa) {
        if (c == group) {
            continue;
        }
        buf[n++] = c == decimal ? '.' : c;
    }
    for (char c : exponent) {
        buf[n++] = c;
    }
    double v = 0;
    const auto [ptr, ec] = std::from_chars(buf, buf + n, v);
    if (ec != std::errc() || ptr != buf + n || !std::isfinite(v)) {
        return r;
    }
    r.isNumber = true;
    r.value = v;
    return r;
}

double thousandsValue(double decimalReading) {
    return std::round(decimalReading * 1000.0);
}

void DecimalMarkEvidence::add(const NumberCell& cell, std::uint32_t row, int line, std::string_view text) {
    const auto first = [&](FirstCell& f) {
        if (f.line == 0) {
            f.line = line;
            f.text = trimmed(text);
        }
    };
    switch (cell.marks) {
    case NumberMarks::None:
        return;
    case NumberMarks::DecimalPoint:
        ++points;
        first(firstPoint);
        return;
    case NumberMarks::DecimalComma:
        ++commas;
        first(firstComma);
        return;
    case NumberMarks::PointOrThousands:
        first(firstPointOrThousands);
        pointOrThousandsRows.push_back(row);
        return;
    case NumberMarks::CommaOrThousands:
        first(firstCommaOrThousands);
        commaOrThousandsRows.push_back(row);
        return;
    }
}

namespace {

/// The first cell of one kind over all columns, in file order (line, then column).
struct FoundCell {
    const ColumnMarks* column = nullptr;
    const DecimalMarkEvidence::FirstCell* cell = nullptr;
    explicit operator bool() const { return column != nullptr; }
    int line() const { return cell->line; }
    std::string describe() const {
        return "'" + cell->text + "' (column '" + column->name + "', line " + std::to_string(cell->line) +
               ")";
    }
};

FoundCell firstOfKind(const std::vector<ColumnMarks>& columns,
                      const DecimalMarkEvidence::FirstCell DecimalMarkEvidence::*kind) {
    FoundCell found;
    for (const auto& c : columns) {
        const auto& cell = c.evidence->*kind;
        if (cell.line > 0 && (!found || cell.line < found.line() ||
                              (cell.line == found.line() && c.fileColumn < found.column->fileColumn))) {
            found = {&c, &cell};
        }
    }
    return found;
}

} // namespace

DecimalMarkDecision decideDecimalMark(const std::vector<ColumnMarks>& columns, char mappingMark,
                                      char delimiter, const std::string& file) {
    DecimalMarkDecision d;
    const FoundCell point = firstOfKind(columns, &DecimalMarkEvidence::firstPoint);
    const FoundCell comma = firstOfKind(columns, &DecimalMarkEvidence::firstComma);
    const FoundCell pointOrThousands = firstOfKind(columns, &DecimalMarkEvidence::firstPointOrThousands);
    const FoundCell commaOrThousands = firstOfKind(columns, &DecimalMarkEvidence::firstCommaOrThousands);
    const auto fail = [&](const FoundCell& at, std::string why) {
        d.ok = false;
        d.line = at.line();
        d.fileColumn = at.column->fileColumn;
        d.why = std::move(why);
        return d;
    };
    if (mappingMark != 0) {
        d.mark = mappingMark;
        if (mappingMark == '.' && comma) {
            return fail(comma, "a decimal comma " + comma.describe() +
                                   ", but the column mapping's \"decimal_mark\" is \".\"");
        }
        if (mappingMark == ',' && point) {
            return fail(point, "a decimal point " + point.describe() +
                                   ", but the column mapping's \"decimal_mark\" is \",\"");
        }
        return d;
    }
    if (point && comma) {
        return fail(comma.line() >= point.line() ? comma : point,
                    "the file mixes a decimal point " + point.describe() + " and a decimal comma " +
                        comma.describe() + "; export it with one number format");
    }
    if (point || comma) {
        d.mark = point ? '.' : ',';
        return d;
    }
    if (!pointOrThousands && !commaOrThousands) {
        return d; // only whole numbers: the mark does not matter
    }
    // Nothing in the file tells. One kind of cell: its mark is the decimal mark (a comma between
    // fields cannot be one). Both kinds: the delimiter's convention; a tab's and a pipe's have none.
    std::string cells;
    if (pointOrThousands && commaOrThousands) {
        if (delimiter == '\t' || delimiter == '|') {
            const FoundCell& later =
                pointOrThousands.line() >= commaOrThousands.line() ? pointOrThousands : commaOrThousands;
            return fail(later,
                        "numbers such as " + pointOrThousands.describe() + " and " +
                            commaOrThousands.describe() +
                            " read with a decimal point and a comma grouping thousands or the other way "
                            "round, and no cell of the file tells which; set \"decimal_mark\": \",\" or "
                            "\".\" in the column mapping");
        }
        d.mark = delimiter == ';' ? ',' : '.';
        cells = pointOrThousands.describe() + " and " + commaOrThousands.describe();
    } else if (commaOrThousands) {
        d.mark = delimiter == ',' ? '.' : ',';
        cells = commaOrThousands.describe();
    } else {
        d.mark = '.';
        cells = pointOrThousands.describe();
    }
    d.guessed = true;
    const FoundCell& at = pointOrThousands ? pointOrThousands : commaOrThousands;
    d.why = placeInFile(file, at.line(), at.column->fileColumn) + ": numbers such as " + cells +
            " read with either mark as the decimal mark and the other grouping thousands, and no cell of "
            "the file tells which; read with a decimal " +
            (d.mark == '.' ? "point" : "comma") + ". If that is wrong, set \"decimal_mark\": \"" +
            (d.mark == '.' ? "," : ".") + "\" in the column mapping";
    return d;
}

void applyDecimalMark(const DecimalMarkEvidence& e, char mark, std::vector<double>& values) {
    for (std::uint32_t r : mark == '.' ? e.commaOrThousandsRows : e.pointOrThousandsRows) {
        values[r] = thousandsValue(values[r]);
    }
}

bool isMissingCell(std::string_view cell, std::string_view& state) {
    const std::string_view s = trimmed(cell);
    state = {};
    if (s.empty()) {
        return true;
    }
    if (s.size() > 16 || isDigit(s.back())) {
        return false;
    }
    // Ordinary spellings of "no value", then the PI System's digital states that stand for one.
    static const char* const kNoValue[] = {"nan", "null", "n/a", "#n/a", "na", "-nan"};
    static const char* const kStates[] = {
        "No Data",      "Comm Fail",    "Shutdown",    "Bad Input",  "Pt Created",   "Scan Off",
        "Scan Timeout", "I/O Timeout",  "Bad",         "Bad Data",   "Bad Quality",  "Calc Failed",
        "Calc Off",     "Calc Timeout", "Configure",   "Equip Fail", "Invalid Data", "Out of Serv",
        "Over Range",   "Under Range",  "Not Connect", "No Sample",  "No Result",    "Intf Shut",
        "Doubtful",     "Arc Off-line", "Failed",      "Unit Down",  "Not Sampled"};
    const std::string l = lowerAscii(s);
    for (const char* k : kNoValue) {
        if (l == k) {
            return true;
        }
    }
    for (const char* k : kStates) {
        if (l == lowerAscii(k)) {
            state = k;
            return true;
        }
    }
    return false;
}

} // namespace drytwin::data::historian
