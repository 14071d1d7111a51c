#include "data/ColumnMapping.h"

#include "common/AtomicFile.h"
#include "data/Columns.h"

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

Status ColumnMapping::validate() const {
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
    ColumnMapping mapping;
    try {
        const auto j = nlohmann::json::parse(*text);
        if (!j.is_object()) {
            return Error{ErrorKind::BadInput, path, "a column mapping must be a JSON object"};
        }
        for (const auto& [key, value] : j.items()) {
            if (!value.is_string()) {
                return Error{ErrorKind::BadInput, path, "the value for '" + key + "' must be a string"};
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
