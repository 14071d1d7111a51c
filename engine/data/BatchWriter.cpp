#include "data/BatchWriter.h"

#include "common/AtomicFile.h"

#include <charconv>
#include <cmath>

namespace drytwin::data {

std::string formatNumber(double v) {
    if (std::isnan(v)) {
        return {};
    }
    char buf[32];
    auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, ptr) : std::string{};
}

namespace {
std::string quoteIfNeeded(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) {
        return s;
    }
    std::string q = "\"";
    for (char c : s) {
        if (c == '"') {
            q += '"';
        }
        q += c;
    }
    return q + "\"";
}
} // namespace

std::string formatBatch(const Batch& batch, HeaderNames names) {
    std::string out;
    out.reserve(batch.rows() * batch.fileOrder.size() * 10 + 256);
    for (const auto& m : batch.metadataLines) {
        out += m;
        out += '\n';
    }
    bool first = true;
    for (int idx : batch.fileOrder) {
        out += first ? "" : ",";
        first = false;
        if (idx >= 0) {
            const auto& col = batch.numeric[static_cast<std::size_t>(idx)];
            out +=
                quoteIfNeeded(names == HeaderNames::Contract ? std::string(spec(col.id).name) : col.fileName);
        } else {
            out += quoteIfNeeded(batch.text[static_cast<std::size_t>(-1 - idx)].fileName);
        }
    }
    out += '\n';
    for (std::size_t r = 0; r < batch.rows(); ++r) {
        first = true;
        for (int idx : batch.fileOrder) {
            out += first ? "" : ",";
            first = false;
            if (idx >= 0) {
                out += formatNumber(batch.numeric[static_cast<std::size_t>(idx)].values[r]);
            } else {
                out += quoteIfNeeded(batch.text[static_cast<std::size_t>(-1 - idx)].cells[r]);
            }
        }
        out += '\n';
    }
    return out;
}

Status writeBatchFile(const Batch& batch, const std::string& path, HeaderNames names) {
    return writeFileAtomically(path, formatBatch(batch, names));
}

} // namespace drytwin::data
