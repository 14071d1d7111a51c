#include "data/ColumnMapping.h"

#include "common/AtomicFile.h"
#include "data/Columns.h"
#include "data/historian/JsonPlaces.h"
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
    // Each place names the mapping file's key ("runs.step_s"), which readColumnMappingText turns
    // into the key's line and column.
    if (!(stepS > 0 && stepS <= 60)) {
        return Error{ErrorKind::BadInput, "column mapping: runs.step_s", "must lie in (0, 60] s"};
    }
    const std::pair<const char*, double> thresholds[] = {
        {"line_stop_feed_kg_h", lineStopFeedKgPerHour}, {"min_stop_s", minStopS}, {"min_run_s", minRunS}};
    for (const auto& [key, value] : thresholds) {
        if (!(value >= 0)) {
            return Error{ErrorKind::BadInput, std::string("column mapping: runs.") + key,
                         "must not be negative"};
        }
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

namespace {

/// The keys of a mapping file beside the contract columns.
constexpr const char* kMappingKeys[] = {"batch_id", "runs", "decimal_mark"};

std::string jsonKind(const nlohmann::json& j) {
    return j.is_array()     ? "an array"
           : j.is_string()  ? "a string"
           : j.is_number()  ? "a number"
           : j.is_boolean() ? "true or false"
           : j.is_null()    ? "null"
                            : "an object";
}

/// A column mapping's entries read with the place of each: what a valid JSON file says wrong is
/// named at its line and column, as a syntax error is.
class MappingFileReader {
public:
    MappingFileReader(const std::string& text, const std::string& path)
        : m_text(text), m_path(path), m_places(text) {}

    Error atValue(const std::string& pointer, std::string reason) const {
        return at(m_places.valueAt(pointer), std::move(reason));
    }
    Error atKey(const std::string& pointer, std::string reason) const {
        return at(m_places.keyAt(pointer), std::move(reason));
    }
    std::size_t offsetOf(const std::string& pointer) const { return m_places.valueAt(pointer); }
    /// An error of ColumnMapping::validate ("column mapping: runs.step_s") at the key it names.
    Error atSetting(const Error& e) const {
        const std::string prefix = "column mapping: ";
        std::string pointer;
        if (e.place.rfind(prefix, 0) == 0) {
            pointer = "/" + e.place.substr(prefix.size());
            std::replace(pointer.begin(), pointer.end(), '.', '/');
        }
        const std::string setting = pointer.empty() ? "" : e.place.substr(prefix.size()) + ": ";
        return atValue(pointer, setting + e.reason);
    }

private:
    Error at(std::size_t offset, std::string reason) const {
        int line = 0, column = 0;
        historian::lineAndColumnAt(m_text, offset, line, column);
        return historian::fileError(m_path, line, column, std::move(reason));
    }

    const std::string& m_text;
    const std::string& m_path;
    historian::JsonPlaces m_places;
};

/// "'T_hot' is not a column …; did you mean 'T_hot_C'?"
std::string unknownKeyReason(const std::string& key) {
    std::vector<std::string> known;
    for (const auto& s : columnSpecs()) {
        known.emplace_back(s.name);
    }
    known.insert(known.end(), std::begin(kMappingKeys), std::end(kMappingKeys));
    const std::string near = closestHeader(key, known);
    return "'" + key + "' is neither a column of the batch format (CONTRACT.md §1) nor a key of the column " +
           "mapping (batch_id, runs, decimal_mark)" + (near.empty() ? "" : "; did you mean '" + near + "'?");
}

Status readRuns(const nlohmann::json& value, const MappingFileReader& reader, RunSplitOptions& runs) {
    if (!value.is_object()) {
        return reader.atValue("/runs", "\"runs\" must be an object, not " + jsonKind(value));
    }
    const std::pair<const char*, double*> fields[] = {{"step_s", &runs.stepS},
                                                      {"line_stop_feed_kg_h", &runs.lineStopFeedKgPerHour},
                                                      {"min_stop_s", &runs.minStopS},
                                                      {"max_interpolated_gap_s", &runs.maxInterpolatedGapS},
                                                      {"min_run_s", &runs.minRunS}};
    for (const auto& [k, v] : value.items()) {
        const std::string here = historian::JsonPlaces::child("/runs", k);
        auto it =
            std::find_if(std::begin(fields), std::end(fields), [&](const auto& f) { return k == f.first; });
        if (it == std::end(fields)) {
            return reader.atKey(here, "runs." + k +
                                          " is not one of step_s, line_stop_feed_kg_h, min_stop_s, "
                                          "max_interpolated_gap_s, min_run_s");
        }
        if (!v.is_number()) {
            return reader.atValue(here, "runs." + k + " must be a number, not " + jsonKind(v));
        }
        *it->second = v.get<double>();
    }
    if (auto st = runs.validate(); !st) {
        return reader.atSetting(st.error());
    }
    return {};
}

/// One contract column's entry: "<header>" or {"header": …, "unit": …, "format": …}.
Status readColumnEntry(const std::string& key, const nlohmann::json& value, const MappingFileReader& reader,
                       ColumnMapping& mapping) {
    const std::string here = historian::JsonPlaces::child("", key);
    const auto column = columnByName(key);
    if (!column) {
        return reader.atKey(here, unknownKeyReason(key));
    }
    const std::string shape = "the value for '" + key + "' must be a header or {\"header\": …, \"unit\": …}";
    if (value.is_string()) {
        mapping.contractToFile[key] = value.get<std::string>();
        return {};
    }
    if (!value.is_object()) {
        return reader.atValue(here, shape + ", not " + jsonKind(value));
    }
    if (!value.contains("header")) {
        return reader.atValue(here, shape + "; this object has no \"header\"");
    }
    if (!value["header"].is_string()) {
        return reader.atValue(here + "/header", shape + "; its \"header\" is " + jsonKind(value["header"]));
    }
    mapping.contractToFile[key] = value["header"].get<std::string>();
    if (key == "time_s" && value.contains("format")) {
        const auto& format = value["format"];
        // "" leaves the format to detection, as it always has.
        if (!format.is_string() ||
            (!format.get<std::string>().empty() && !timeFormatByName(format.get<std::string>()))) {
            return reader.atValue(
                here + "/format",
                "the time format " +
                    (format.is_string() ? "'" + format.get<std::string>() + "'" : jsonKind(format)) +
                    " is not one of " + timeFormatNames());
        }
        mapping.timeFormat = format.get<std::string>();
    }
    if (value.contains("unit")) {
        const auto& unitValue = value["unit"];
        const auto units = unitsFor(*column);
        std::string list;
        for (const auto& u : units) {
            list += (list.empty() ? "" : ", ") + u;
        }
        if (!unitValue.is_string()) {
            return reader.atValue(here + "/unit",
                                  "the unit of '" + key + "' must be a string (" + list + ")");
        }
        // "°F" as a units row would say it is "degF": one spelling of a unit is accepted wherever a
        // unit is given.
        const std::string unit = unitValue.get<std::string>();
        const std::string canonical = historian::normalisedUnit(unit, *column);
        const std::string kept = canonical.empty() ? unit : canonical;
        if (std::find(units.begin(), units.end(), kept) == units.end()) {
            return reader.atValue(here + "/unit",
                                  "unit '" + unit + "' of '" + key + "' is not one of " + list);
        }
        mapping.contractToUnit[key] = kept;
    }
    return {};
}

} // namespace

Expected<ColumnMapping> readColumnMappingText(const std::string& text, const std::string& path) {
    ColumnMapping mapping;
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        return jsonSyntaxError(text, path, e.byte, e.what());
    } catch (const nlohmann::json::exception& e) {
        return Error{ErrorKind::BadInput, path, std::string("not valid JSON: ") + e.what()}; // 1e999
    }
    const MappingFileReader reader(text, path);
    if (!j.is_object()) {
        return reader.atValue("",
                              "a column mapping must be a JSON object ({\"<contract column>\": \"<header>\", "
                              "…}), not " +
                                  jsonKind(j));
    }
    for (const auto& [key, value] : j.items()) {
        const std::string here = historian::JsonPlaces::child("", key);
        if (key == "batch_id") {
            if (!value.is_object() || !value.contains("header") || !value["header"].is_string()) {
                return reader.atValue(here, "\"batch_id\" must be {\"header\": \"<column>\"}");
            }
            mapping.batchIdHeader = value["header"].get<std::string>();
        } else if (key == "decimal_mark") {
            if (!value.is_string() || (value.get<std::string>() != "." && value.get<std::string>() != ",")) {
                return reader.atValue(here, "\"decimal_mark\" must be \".\" or \",\"");
            }
            mapping.decimalMark = value.get<std::string>()[0];
        } else if (key == "runs") {
            if (auto st = readRuns(value, reader, mapping.runs); !st) {
                return st.error();
            }
        } else if (auto st = readColumnEntry(key, value, reader, mapping); !st) {
            return st.error();
        }
    }
    // A header given twice or empty: named at the later of the two in the file.
    std::map<std::string, std::string> keyOfHeader;
    for (const auto& [contract, header] : mapping.contractToFile) {
        const std::string here = historian::JsonPlaces::child("", contract);
        if (header.empty()) {
            return reader.atValue(here, "empty file header for '" + contract + "'");
        }
        const auto [seen, fresh] = keyOfHeader.emplace(header, contract);
        if (!fresh) {
            const std::string there = historian::JsonPlaces::child("", seen->second);
            const bool hereLater = reader.offsetOf(here) > reader.offsetOf(there);
            return reader.atValue(hereLater ? here : there, "file header '" + header +
                                                                "' is mapped to two contract columns ('" +
                                                                seen->second + "' and '" + contract + "')");
        }
    }
    if (auto st = mapping.validate(); !st) {
        return reader.atSetting(st.error());
    }
    mapping.sourceName = path;
    return mapping;
}

} // namespace drytwin::data
