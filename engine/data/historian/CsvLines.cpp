#include "data/historian/CsvLines.h"

#include <csv.h>

namespace drytwin::data::historian {

bool LineCursor::next(std::string_view& line) {
    if (m_pos >= m_text.size()) {
        return false;
    }
    const auto nl = m_text.find('\n', m_pos);
    line = m_text.substr(m_pos, nl == std::string_view::npos ? std::string_view::npos : nl - m_pos);
    m_pos = nl == std::string_view::npos ? m_text.size() : nl + 1;
    ++m_line;
    return true;
}

CsvLineSplitter::~CsvLineSplitter() {
    if (m_parser) {
        csv_free(m_parser);
        delete m_parser;
    }
}

void CsvLineSplitter::onField(void* s, std::size_t len, void* data) {
    auto* self = static_cast<CsvLineSplitter*>(data);
    self->m_owned.emplace_back(s ? static_cast<const char*>(s) : "", s ? len : 0);
}

bool CsvLineSplitter::split(std::string_view line) {
    m_fields.clear();
    if (!line.empty() && line.back() == '\r') {
        line.remove_suffix(1);
    }
    if (line.find('"') == std::string_view::npos) {
        std::size_t pos = 0;
        while (true) {
            const auto d = line.find(m_delimiter, pos);
            m_fields.push_back(
                line.substr(pos, d == std::string_view::npos ? std::string_view::npos : d - pos));
            if (d == std::string_view::npos) {
                break;
            }
            pos = d + 1;
        }
        return true;
    }
    if (!m_parser) {
        m_parser = new csv_parser{};
        if (csv_init(m_parser, CSV_STRICT | CSV_STRICT_FINI) != 0) {
            delete m_parser;
            m_parser = nullptr;
            return false;
        }
    }
    csv_set_delim(m_parser, static_cast<unsigned char>(m_delimiter));
    m_owned.clear();
    const auto noRow = [](int, void*) {};
    if (csv_parse(m_parser, line.data(), line.size(), onField, noRow, this) != line.size() ||
        csv_fini(m_parser, onField, noRow, this) != 0) {
        return false;
    }
    for (const auto& o : m_owned) {
        m_fields.emplace_back(o);
    }
    return true;
}

char detectDelimiter(std::string_view header) {
    int counts[4] = {0, 0, 0, 0};
    bool quoted = false;
    for (char c : header) {
        if (c == '"') {
            quoted = !quoted;
        } else if (!quoted) {
            counts[0] += c == ',';
            counts[1] += c == ';';
            counts[2] += c == '\t';
            counts[3] += c == '|';
        }
    }
    if (counts[1] > counts[0] && counts[1] >= counts[2]) {
        return ';';
    }
    if (counts[2] > counts[0] && counts[2] > counts[1]) {
        return '\t';
    }
    // A pipe (SAP, some MES and LIMS exports) only where the header has none of the others: a tag
    // name may hold a pipe ("L1|TT101") in a header of commas, which must stay a comma file.
    if (counts[0] == 0 && counts[1] == 0 && counts[2] == 0 && counts[3] > 0) {
        return '|';
    }
    return ',';
}

std::string delimiterName(char delimiter) {
    switch (delimiter) {
    case ';':
        return "semicolon";
    case '\t':
        return "tab";
    case '|':
        return "pipe";
    default:
        return "comma";
    }
}

} // namespace drytwin::data::historian
