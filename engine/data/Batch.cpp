#include "data/Batch.h"

namespace drytwin::data {

const std::vector<double>* Batch::values(Column c) const {
    for (const auto& col : numeric) {
        if (col.id == c) {
            return &col.values;
        }
    }
    return nullptr;
}

std::vector<double>* Batch::values(Column c) {
    for (auto& col : numeric) {
        if (col.id == c) {
            return &col.values;
        }
    }
    return nullptr;
}

void Batch::setValues(Column c, std::vector<double> v) {
    if (auto* existing = values(c)) {
        *existing = std::move(v);
        return;
    }
    numeric.push_back({c, std::string(spec(c).name), std::move(v), 0});
    fileOrder.push_back(static_cast<int>(numeric.size()) - 1);
}

std::string Batch::metadata(const std::string& key) const {
    for (const auto& line : metadataLines) {
        // "# key: value"
        auto pos = line.find_first_not_of("# \t");
        if (pos == std::string::npos) {
            continue;
        }
        if (line.compare(pos, key.size(), key) == 0) {
            auto colon = line.find(':', pos + key.size());
            if (colon == pos + key.size()) {
                auto start = line.find_first_not_of(" \t", colon + 1);
                if (start == std::string::npos) {
                    return {};
                }
                auto end = line.find_last_not_of(" \t\r");
                return line.substr(start, end - start + 1);
            }
        }
    }
    return {};
}

std::size_t DataSet::totalRows() const {
    std::size_t n = 0;
    for (const auto& b : batches) {
        n += b.rows();
    }
    return n;
}

std::size_t DataSet::totalMissing() const {
    std::size_t n = 0;
    for (const auto& b : batches) {
        n += b.missing.size();
    }
    return n;
}

} // namespace drytwin::data
