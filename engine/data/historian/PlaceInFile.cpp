#include "data/historian/PlaceInFile.h"

#include <algorithm>
#include <cstdio>

namespace drytwin::data::historian {

std::string placeInFile(const std::string& file, int line, int column) {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

Error fileError(const std::string& file, int line, int column, std::string reason, ErrorCode code,
                std::vector<std::string> args) {
    if (args.empty()) {
        args = {file, std::to_string(line), std::to_string(column), reason};
    }
    return Error{ErrorKind::BadInput, placeInFile(file, line, column), std::move(reason), code,
                 std::move(args)};
}

void lineAndColumnAt(std::string_view text, std::size_t offset, int& line, int& column) {
    offset = std::min(offset, text.size());
    const std::string_view before = text.substr(0, offset);
    line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const auto lastNl = before.rfind('\n');
    column = static_cast<int>(lastNl == std::string_view::npos ? offset + 1 : offset - lastNl);
}

std::string_view trimmed(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) {
        return {};
    }
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::string lowerAscii(std::string_view s) {
    std::string l(s);
    for (char& c : l) {
        if (c >= 'A' && c <= 'Z') {
            c = static_cast<char>(c - 'A' + 'a');
        }
    }
    return l;
}

std::string byteCount(std::size_t bytes) {
    if (bytes < 1024) {
        return std::to_string(bytes) + " bytes";
    }
    char buf[32];
    const double kib = static_cast<double>(bytes) / 1024.0;
    if (kib < 1024) {
        std::snprintf(buf, sizeof buf, "%.1f KiB", kib);
    } else {
        std::snprintf(buf, sizeof buf, "%.1f MiB", kib / 1024.0);
    }
    return buf;
}

} // namespace drytwin::data::historian
