#include "data/historian/ValueColumns.h"

#include "common/TextList.h"
#include "data/historian/PlaceInFile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace drytwin::data::historian {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// "T_hot [°F]" -> ("T_hot", "°F"); a header without a bracketed unit at its end -> (header, "").
std::pair<std::string, std::string> headerAndUnit(const std::string& header) {
    const auto open = header.rfind('[');
    if (header.empty() || header.back() != ']' || open == std::string::npos || open == 0) {
        return {header, ""};
    }
    std::string name = header.substr(0, open);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t' || name.back() == '_')) {
        name.pop_back();
    }
    return {name, header.substr(open + 1, header.size() - open - 2)};
}

} // namespace

std::string normalisedUnit(std::string_view raw, Column column) {
    std::string u;
    for (char c : trimmed(raw)) {
        if (c != '[' && c != ']' && c != '(' && c != ')' && c != ' ') {
            u.push_back(c);
        }
    }
    const std::string l = lowerAscii(u);
    if (l.empty()) {
        return {};
    }
    if (l == "°c" || l == "degc" || l == "c" || l == "℃") {
        return "degC";
    }
    if (l == "°f" || l == "degf" || l == "f") {
        return "degF";
    }
    if (u == "K") {
        return "K";
    }
    if (l == "kg/h" || l == "kg/hr") {
        return "kg/h";
    }
    if (l == "t/h") {
        return "t/h";
    }
    if (l == "kg/s" || l == "kg/min" || l == "m/s" || l == "s" || l == "min") {
        return l;
    }
    if (l == "%db" || l == "%d.b.") {
        return "% db";
    }
    if (l == "%" || l == "%wb" || l == "%rh" || l == "%w.b.") {
        return spec(column).unit == "%" ? "%" : (l == "%rh" ? "" : "% wb");
    }
    return {};
}

std::string ValueColumn::label() const {
    return "'" + header + "'" + (contract ? " (" + std::string(spec(*contract).name) + ")" : "");
}

bool ValueColumn::readCell(std::string_view cell, int line, const std::string& file, Error& error) {
    const auto row = static_cast<std::uint32_t>(values.size());
    std::string_view state;
    if (isMissingCell(cell, state)) {
        if (!state.empty() && digitalStates[std::string(state)]++ == 0 && firstStateLine == 0) {
            firstStateLine = line;
        }
        values.push_back(kNan);
        return true;
    }
    const NumberCell n = readNumberCell(cell);
    if (!n.isNumber) {
        if (contract) {
            const std::string text(trimmed(cell));
            Error e = fileError(
                file, line, static_cast<int>(field) + 1,
                "text '" + text + "' in numeric column " + label() +
                    " (a number, an empty cell or a PI digital state such as 'No Data' is expected)",
                ErrorCode::TextInNumber);
            e.args = {file, std::to_string(line), std::to_string(field + 1), text, header};
            error = std::move(e);
            return false;
        }
        numeric = false; // a text column that is no contract column: not kept in runs
        values.push_back(kNan);
        return true;
    }
    marks.add(n, row, line, cell);
    values.push_back(n.value);
    return true;
}

Expected<ColumnLayout> layOutColumns(const FileShape& shape, const ColumnMapping& mapping,
                                     const std::string& file) {
    if (auto st = mapping.checkHeadersPresent(shape.headers, file, shape.headerLine); !st) {
        return st.error();
    }
    ColumnLayout layout;
    const std::size_t nCols = shape.headers.size();
    layout.batchIndex = nCols;
    std::set<Column> seen;
    for (std::size_t c = 0; c < nCols; ++c) {
        const std::string& h = shape.headers[c];
        if (h == shape.timeHeader) {
            layout.timeIndex = c;
            continue;
        }
        if (!mapping.batchIdHeader.empty() && h == mapping.batchIdHeader) {
            layout.batchIndex = c;
            continue;
        }
        ValueColumn v;
        v.header = h;
        v.field = c;
        // A unit in the header ("T_hot [°F]", "T_hot_C [°C]"), as many exports write it: the name
        // before it finds the column where the whole header does not, and the unit is read as a
        // units row's would be (°F data were read as °C before, with exit 0).
        const auto [bareHeader, headerUnit] = headerAndUnit(h);
        std::string contract = mapping.contractNameFor(h);
        if (contract.empty() && !headerUnit.empty()) {
            contract = mapping.contractNameFor(bareHeader);
        }
        if (!contract.empty() && contract != "time_s") {
            v.contract = columnByName(contract);
            if (!seen.insert(*v.contract).second) {
                return fileError(file, shape.headerLine, static_cast<int>(c) + 1,
                                 "column '" + h + "' maps to '" + contract +
                                     "', which another column already gives");
            }
            if (const auto u = mapping.contractToUnit.find(contract); u != mapping.contractToUnit.end()) {
                v.unit = u->second;
                // The mapping's unit wins over the file's own units row; where they differ, said
                // (one of them is wrong, and a silent choice converts 150 °C as 150 K).
                // A bare "%" does not say wet or dry basis: no contradiction to note.
                if (shape.unitsRow && c < shape.units.size() && !shape.units[c].empty() &&
                    shape.units[c] != "%") {
                    const std::string fileUnit = normalisedUnit(shape.units[c], *v.contract);
                    if (!fileUnit.empty() && fileUnit != normalisedUnit(v.unit, *v.contract)) {
                        layout.notes.push_back(
                            placeInFile(file, shape.headerLine + 1, static_cast<int>(c) + 1) + ": column '" +
                            h + "' (" + contract + ") is read in '" + v.unit +
                            "', the column mapping's unit, while the file's units row says '" +
                            shape.units[c] + "'; check which is right");
                    }
                }
            } else if (shape.unitsRow && c < shape.units.size() && !shape.units[c].empty()) {
                v.unit = normalisedUnit(shape.units[c], *v.contract);
                const auto known = unitsFor(*v.contract);
                if (v.unit.empty() || std::find(known.begin(), known.end(), v.unit) == known.end()) {
                    return fileError(file, shape.headerLine + 1, static_cast<int>(c) + 1,
                                     "unit '" + shape.units[c] + "' of column '" + h + "' (" + contract +
                                         ") is not one of " + commaList(known) +
                                         "; give the unit in the column mapping ({\"header\": \"" + h +
                                         "\", \"unit\": …})");
                }
            } else if (!headerUnit.empty()) {
                v.unit = normalisedUnit(headerUnit, *v.contract);
                const auto known = unitsFor(*v.contract);
                if (v.unit.empty() || std::find(known.begin(), known.end(), v.unit) == known.end()) {
                    return fileError(file, shape.headerLine, static_cast<int>(c) + 1,
                                     "unit '" + headerUnit + "' in the header '" + h + "' (" + contract +
                                         ") is not one of " + commaList(known) +
                                         "; give the unit in the column mapping ({\"header\": \"" + h +
                                         "\", \"unit\": …})");
                }
            }
        }
        if (v.contract && !v.unit.empty()) {
            v.conversion.contractToUnit[std::string(spec(*v.contract).name)] = v.unit;
        }
        layout.values.push_back(std::move(v));
    }
    for (const auto& s : columnSpecs()) {
        if (s.required && s.id != Column::Time && !seen.count(s.id)) {
            Error e = fileError(file, shape.headerLine, 1,
                                "missing required column '" + std::string(s.name) + "' [" +
                                    std::string(s.unit) + ", " + std::string(s.meaning) +
                                    "] (map the file's tag to it: --mapping, or the column-mapping dialog)",
                                ErrorCode::MissingColumn);
            e.args = {file, std::string(s.name)};
            return e;
        }
    }
    if (shape.timeFormat == TimeFormat::Seconds) {
        const auto u = mapping.contractToUnit.find("time_s");
        if ((u != mapping.contractToUnit.end() && u->second == "min") ||
            (u == mapping.contractToUnit.end() && shape.unitsRow && layout.timeIndex < shape.units.size() &&
             normalisedUnit(shape.units[layout.timeIndex], Column::Time) == "min") ||
            (u == mapping.contractToUnit.end() && !shape.unitsRow &&
             normalisedUnit(headerAndUnit(shape.timeHeader).second, Column::Time) == "min")) {
            layout.timeScale = 60.0;
        }
    }
    return layout;
}

Expected<char> finishColumns(std::vector<ValueColumn>& columns, const ColumnMapping& mapping,
                             const FileShape& shape, const std::string& file,
                             std::vector<std::string>& notes) {
    // Only the contract columns' cells decide: a tag no column takes may come from another source.
    std::vector<ColumnMarks> marks;
    for (const auto& c : columns) {
        if (c.numeric && c.contract) {
            marks.push_back({&c.marks, c.header, static_cast<int>(c.field) + 1});
        }
    }
    const DecimalMarkDecision d = decideDecimalMark(marks, mapping.decimalMark, shape.delimiter, file);
    if (!d.ok) {
        return fileError(file, d.line, d.fileColumn, d.why);
    }
    if (d.guessed) {
        notes.push_back(d.why);
    }
    for (auto& c : columns) {
        if (!c.digitalStates.empty()) {
            std::size_t total = 0;
            std::string kinds;
            for (const auto& [state, count] : c.digitalStates) {
                total += count;
                kinds += (kinds.empty() ? "" : ", ") + state + " " + std::to_string(count);
            }
            notes.push_back(placeInFile(file, c.firstStateLine, static_cast<int>(c.field) + 1) + ": column " +
                            c.label() + ": " + std::to_string(total) + " cell(s) hold PI digital states (" +
                            kinds + "), the first here; read as missing values");
        }
        if (!c.numeric) {
            notes.push_back(file + ": column '" + c.header + "' holds text; it is not kept in the runs");
            continue;
        }
        applyDecimalMark(c.marks, d.mark, c.values);
        if (c.contract && !c.unit.empty()) {
            for (double& v : c.values) {
                v = c.conversion.toContractUnit(*c.contract, v);
            }
        }
    }
    return d.mark;
}

} // namespace drytwin::data::historian
