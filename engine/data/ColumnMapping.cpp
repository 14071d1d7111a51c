#include "data/ColumnMapping.h"

#include "common/AtomicFile.h"
#include "data/Columns.h"
#include "data/PlantFileReader.h"

#include <algorithm>
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
                     "'" + timeFormat +
                         "' is not one of seconds, iso8601, Y/m/d, d.m.Y, d/m/Y, m/d/Y, excel_days, epoch_s, "
                         "epoch_ms"};
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

Expected<ColumnMapping> readColumnMapping(const std::string& path) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return readColumnMappingText(*text, path);
}

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
                    mapping.contractToUnit[key] = value["unit"].get<std::string>();
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
        return Error{ErrorKind::BadInput, path + ":byte " + std::to_string(e.byte), "invalid JSON"};
    }
    if (auto st = mapping.validate(); !st) {
        return Error{ErrorKind::BadInput, path, st.error().reason};
    }
    return mapping;
}

} // namespace drytwin::data
