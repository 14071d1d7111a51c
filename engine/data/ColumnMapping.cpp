#include "data/ColumnMapping.h"

#include "common/AtomicFile.h"
#include "data/Columns.h"
#include "data/historian/PlaceInFile.h"
#include "data/historian/TimeStamps.h"
#include "data/historian/ValueColumns.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

namespace drytwin::data {

std::string ColumnMapping::contractNameFor(const std::string& fileHeader) const {
    for (const auto& [contract, file] : contractToFile) {
        if (file == fileHeader) {
            return contract;
        }
    }
    // A header that is itself a contract name maps to itself unless that contract column
    // was mapped to another header (then this one is kept as an extra column).
    if (columnByName(fileHeader) && contractToFile.find(fileHeader) == contractToFile.end()) {
        return fileHeader;
    }
    return {};
}

namespace {

enum class Quantity { Time, Temperature, Moisture, Feed, Humidity, Speed };

Quantity quantityOf(Column c) {
    switch (c) {
    case Column::Time:
        return Quantity::Time;
    case Column::XIn:
    case Column::XHdt:
    case Column::XOut:
        return Quantity::Moisture;
    case Column::Feed:
        return Quantity::Feed;
    case Column::RHAmb:
        return Quantity::Humidity;
    case Column::AirSpeed:
        return Quantity::Speed;
    default:
        return Quantity::Temperature;
    }
}

} // namespace

std::vector<std::string> unitsFor(Column column) {
    switch (quantityOf(column)) {
    case Quantity::Time:
        return {"s", "min"};
    case Quantity::Temperature:
        return {"degC", "degF", "K"};
    case Quantity::Moisture:
        return {"% wb", "% db", "fraction wb"};
    case Quantity::Feed:
        return {"kg/h", "kg/s", "kg/min", "t/h"};
    case Quantity::Humidity:
        return {"%", "fraction"};
    case Quantity::Speed:
        return {"m/s"};
    }
    return {};
}

double ColumnMapping::toContractUnit(Column column, double v) const {
    const auto it = contractToUnit.find(std::string(spec(column).name));
    if (it == contractToUnit.end()) {
        return v;
    }
    const std::string& u = it->second;
    if (u == "degF") {
        return (v - 32.0) * 5.0 / 9.0;
    }
    if (u == "K") {
        return v - 273.15;
    }
    if (u == "% db") {
        return 100.0 * v / (100.0 + v); // dry basis to wet basis
    }
    if (u == "fraction wb" || u == "fraction") {
        return 100.0 * v;
    }
    if (u == "kg/s") {
        return 3600.0 * v;
    }
    if (u == "kg/min") {
        return 60.0 * v;
    }
    if (u == "t/h") {
        return 1000.0 * v;
    }
    if (u == "min") {
        return 60.0 * v;
    }
    return v; // the contract's own unit
}

Status RunSplitOptions::validate() const {
    if (!(stepS > 0 && stepS <= 60)) {
        return Error{ErrorKind::BadInput, "column mapping: runs.step_s", "must lie in (0, 60] s"};
    }
    if (!(lineStopFeedKgPerHour >= 0 && minStopS >= 0 && minRunS >= 0)) {
        return Error{ErrorKind::BadInput, "column mapping: runs", "thresholds must not be negative"};
    }
    if (!(maxInterpolatedGapS >= stepS)) {
        return Error{ErrorKind::BadInput, "column mapping: runs.max_interpolated_gap_s",
                     "must be at least the step"};
    }
    return {};
}

Status ColumnMapping::validate() const {
    if (auto st = runs.validate(); !st) {
        return st;
    }
    if (!timeFormat.empty() && !timeFormatByName(timeFormat)) {
        return Error{ErrorKind::BadInput, "column mapping: time_s.format",
                     "'" + timeFormat + "' is not one of " + timeFormatNames()};
    }
    if (decimalMark != 0 && decimalMark != '.' && decimalMark != ',') {
        return Error{ErrorKind::BadInput, "column mapping: decimal_mark", "must be \".\" or \",\""};
    }
    for (const auto& [contract, unit] : contractToUnit) {
        const auto id = columnByName(contract);
        if (!id) {
            return Error{ErrorKind::BadInput, "column mapping",
                         "'" + contract + "' is not a column of the batch format (CONTRACT.md §1)"};
        }
        const auto units = unitsFor(*id);
        if (std::find(units.begin(), units.end(), unit) == units.end()) {
            std::string list;
            for (const auto& u : units) {
                list += (list.empty() ? "" : ", ") + u;
            }
            return Error{ErrorKind::BadInput, "column mapping",
                         "unit '" + unit + "' of '" + contract + "' is not one of " + list};
        }
    }
    std::set<std::string> used;
    for (const auto& [contract, file] : contractToFile) {
        if (!columnByName(contract)) {
            return Error{ErrorKind::BadInput, "column mapping",
                         "'" + contract + "' is not a column of the batch format (CONTRACT.md §1)"};
        }
        if (file.empty()) {
            return Error{ErrorKind::BadInput, "column mapping", "empty file header for '" + contract + "'"};
        }
        if (!used.insert(file).second) {
            return Error{ErrorKind::BadInput, "column mapping",
                         "file header '" + file + "' is mapped to two contract columns"};
        }
    }
    return {};
}

namespace {

/// Letters and digits in lower case: "Air_Speed.PV" and "AIR SPEED PV" are the same tag.
std::string tagKey(const std::string& s) {
    std::string k;
    for (char c : s) {
        if (std::isalnum(static_cast<unsigned char>(c))) {
            k.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
        } else if (static_cast<unsigned char>(c) >= 0x80) {
            k.push_back(c);
        }
    }
    return k;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

} // namespace

std::string closestHeader(const std::string& name, const std::vector<std::string>& headers) {
    const std::string key = tagKey(name);
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(2, key.size() / 3) + 1; // a third of the tag at most
    for (const auto& h : headers) {
        const std::string k = tagKey(h);
        const std::size_t d = k == key ? 0 : editDistance(key, k);
        if (d < bestDistance) {
            bestDistance = d;
            best = h;
        }
    }
    return best;
}

Status ColumnMapping::checkHeadersPresent(const std::vector<std::string>& headers, const std::string& file,
                                          int headerLine) const {
    std::vector<std::pair<std::string, std::string>> lacking; // contract column, header
    const auto has = [&](const std::string& h) {
        return std::find(headers.begin(), headers.end(), h) != headers.end();
    };
    for (const auto& [contract, header] : contractToFile) {
        if (!has(header)) {
            lacking.emplace_back(contract, header);
        }
    }
    if (!batchIdHeader.empty() && !has(batchIdHeader)) {
        lacking.emplace_back("batch_id", batchIdHeader);
    }
    if (lacking.empty()) {
        return {};
    }
    std::string list;
    for (const auto& [contract, header] : lacking) {
        const auto id = columnByName(contract);
        const std::string near = closestHeader(header, headers);
        list += std::string(list.empty() ? "" : "; ") + "'" + header + "' for " + contract +
                (id ? std::string(spec(*id).required ? " (required" : " (optional") + ", " +
                          std::string(spec(*id).meaning) + ")"
                    : std::string(" (the batch column)")) +
                (near.empty() ? "" : ", the file has '" + near + "'");
    }
    const std::string mappingName =
        sourceName.empty() ? "the column mapping" : "the column mapping " + sourceName;
    return historian::fileError(
        file, headerLine, 1,
        mappingName + " names " +
            (lacking.size() == 1 ? "a header" : std::to_string(lacking.size()) + " headers") +
            " that the file's header row lacks: " + list +
            ". Correct the header in the mapping (or remove the entry: an optional column then takes its "
            "documented default)");
}

Expected<ColumnMapping> readColumnMapping(const std::string& path) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return readColumnMappingText(*text, path);
}

namespace {

/// A JSON syntax error at file:line:column, with what the parser expected there (nlohmann words
/// it: "unexpected '}'; expected string literal") and the usual cause of that slip.
Error jsonSyntaxError(const std::string& text, const std::string& path, std::size_t byte,
                      const std::string& what) {
    // nlohmann counts bytes from 1 and points at the character it could not take.
    std::size_t offset = std::min(byte == 0 ? 0 : byte - 1, text.size());
    // It reports the last character of the token it could not take: point at the token's start.
    if (offset < text.size() && text[offset] == '"' && offset > 0) {
        const auto open = text.rfind('"', offset - 1);
        offset = open == std::string::npos ? offset : open;
    } else {
        while (offset > 0 && offset < text.size() && std::isalnum(static_cast<unsigned char>(text[offset])) &&
               (std::isalnum(static_cast<unsigned char>(text[offset - 1])) || text[offset - 1] == '.' ||
                text[offset - 1] == '-' || text[offset - 1] == '+')) {
            --offset;
        }
    }
    int line = 0, column = 0;
    historian::lineAndColumnAt(text, offset, line, column);
    std::string reason = what;
    if (const auto p = what.find("syntax error"); p != std::string::npos) {
        reason = what.substr(p);
    } else if (const auto q = what.find(": "); q != std::string::npos) {
        reason = what.substr(q + 2);
    }
    std::string hint;
    if (reason.find("unexpected end of input") != std::string::npos) {
        hint = " (a closing '}' or '\"' is missing)";
    } else if (reason.find("unexpected '}'") != std::string::npos ||
               reason.find("unexpected ']'") != std::string::npos) {
        hint = " (a comma after the last entry?)";
    } else if (reason.find("unexpected string literal") != std::string::npos) {
        hint = " (a comma missing after the previous entry?)";
    } else if (reason.find("invalid literal") != std::string::npos) {
        hint = " (text outside quotes? JSON needs \"…\" around every name and header)";
    }
    Error e{ErrorKind::BadInput, historian::placeInFile(path, line, column),
            "not valid JSON: " + reason + hint};
    return e;
}

} // namespace

Expected<ColumnMapping> readColumnMappingText(const std::string& text, const std::string& path) {
    ColumnMapping mapping;
    try {
        const auto j = nlohmann::json::parse(text);
        if (!j.is_object()) {
            return Error{ErrorKind::BadInput, path, "a column mapping must be a JSON object"};
        }
        for (const auto& [key, value] : j.items()) {
            if (key == "batch_id") {
                if (!value.is_object() || !value.contains("header") || !value["header"].is_string()) {
                    return Error{ErrorKind::BadInput, path,
                                 "\"batch_id\" must be {\"header\": \"<column>\"}"};
                }
                mapping.batchIdHeader = value["header"].get<std::string>();
                continue;
            }
            if (key == "decimal_mark") {
                if (!value.is_string() ||
                    (value.get<std::string>() != "." && value.get<std::string>() != ",")) {
                    return Error{ErrorKind::BadInput, path, "\"decimal_mark\" must be \".\" or \",\""};
                }
                mapping.decimalMark = value.get<std::string>()[0];
                continue;
            }
            if (key == "runs") {
                if (!value.is_object()) {
                    return Error{ErrorKind::BadInput, path, "\"runs\" must be an object"};
                }
                const std::pair<const char*, double*> fields[] = {
                    {"step_s", &mapping.runs.stepS},
                    {"line_stop_feed_kg_h", &mapping.runs.lineStopFeedKgPerHour},
                    {"min_stop_s", &mapping.runs.minStopS},
                    {"max_interpolated_gap_s", &mapping.runs.maxInterpolatedGapS},
                    {"min_run_s", &mapping.runs.minRunS}};
                for (const auto& [k, v] : value.items()) {
                    auto it = std::find_if(std::begin(fields), std::end(fields),
                                           [&](const auto& f) { return k == f.first; });
                    if (it == std::end(fields) || !v.is_number()) {
                        return Error{ErrorKind::BadInput, path,
                                     "runs." + k +
                                         ": not a number or not one of step_s, line_stop_feed_kg_h, "
                                         "min_stop_s, max_interpolated_gap_s, min_run_s"};
                    }
                    *it->second = v.get<double>();
                }
                continue;
            }
            if (value.is_object() && value.contains("header") && value["header"].is_string()) {
                if (key == "time_s" && value.contains("format")) {
                    if (!value["format"].is_string()) {
                        return Error{ErrorKind::BadInput, path, "the format of 'time_s' must be a string"};
                    }
                    mapping.timeFormat = value["format"].get<std::string>();
                }
                mapping.contractToFile[key] = value["header"].get<std::string>();
                if (value.contains("unit")) {
                    if (!value["unit"].is_string()) {
                        return Error{ErrorKind::BadInput, path,
                                     "the unit for '" + key + "' must be a string"};
                    }
                    // "°F" as a units row would say it is "degF": one spelling of a unit is
                    // accepted wherever a unit is given.
                    const std::string unit = value["unit"].get<std::string>();
                    const auto column = columnByName(key);
                    const std::string canonical =
                        column ? historian::normalisedUnit(unit, *column) : std::string();
                    mapping.contractToUnit[key] = canonical.empty() ? unit : canonical;
                }
                continue;
            }
            if (!value.is_string()) {
                return Error{ErrorKind::BadInput, path,
                             "the value for '" + key + "' must be a header or {\"header\": …, \"unit\": …}"};
            }
            mapping.contractToFile[key] = value.get<std::string>();
        }
    } catch (const nlohmann::json::parse_error& e) {
        return jsonSyntaxError(text, path, e.byte, e.what());
    } catch (const nlohmann::json::exception& e) {
        return Error{ErrorKind::BadInput, path, std::string("not a column mapping: ") + e.what()};
    }
    if (auto st = mapping.validate(); !st) {
        return Error{ErrorKind::BadInput, path, st.error().reason};
    }
    mapping.sourceName = path;
    return mapping;
}

} // namespace drytwin::data
