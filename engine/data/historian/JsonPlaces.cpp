#include "data/historian/JsonPlaces.h"

#include <nlohmann/json.hpp>

namespace drytwin::data::historian {

namespace {

/// Deeper than any column mapping goes: beyond it values are skipped, not indexed, so that a
/// pathological nesting cannot exhaust the stack.
constexpr int kMaxDepth = 32;

} // namespace

JsonPlaces::JsonPlaces(std::string_view text) : m_text(text) {
    if (m_text.substr(0, 3) == "\xEF\xBB\xBF") {
        m_pos = 3; // nlohmann skips a UTF-8 byte-order mark too
    }
    scanValue("", 0);
}

std::string JsonPlaces::child(const std::string& pointer, const std::string& key) {
    std::string escaped;
    for (char c : key) {
        if (c == '~') {
            escaped += "~0";
        } else if (c == '/') {
            escaped += "~1";
        } else {
            escaped.push_back(c);
        }
    }
    return pointer + "/" + escaped;
}

std::size_t JsonPlaces::valueAt(const std::string& pointer) const {
    std::string p = pointer;
    while (true) {
        if (const auto it = m_values.find(p); it != m_values.end()) {
            return it->second;
        }
        const auto slash = p.rfind('/');
        if (slash == std::string::npos) {
            return 0;
        }
        p.resize(slash);
    }
}

std::size_t JsonPlaces::keyAt(const std::string& pointer) const {
    const auto it = m_keys.find(pointer);
    return it != m_keys.end() ? it->second : valueAt(pointer);
}

void JsonPlaces::skipBlanks() {
    while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\t' || m_text[m_pos] == '\n' ||
                                     m_text[m_pos] == '\r')) {
        ++m_pos;
    }
}

std::size_t JsonPlaces::skipString() {
    ++m_pos; // the opening quote
    while (m_pos < m_text.size() && m_text[m_pos] != '"') {
        m_pos += m_text[m_pos] == '\\' ? 2 : 1;
    }
    m_pos = std::min(m_pos + 1, m_text.size());
    return m_pos;
}

void JsonPlaces::skipValue() {
    int nesting = 0;
    while (m_pos < m_text.size()) {
        const char c = m_text[m_pos];
        if (c == '"') {
            skipString();
        } else {
            ++m_pos;
            nesting += c == '{' || c == '[' ? 1 : c == '}' || c == ']' ? -1 : 0;
        }
        if (nesting <= 0 && (c == '"' || c == '}' || c == ']' ||
                             (m_pos < m_text.size() &&
                              (m_text[m_pos] == ',' || m_text[m_pos] == '}' || m_text[m_pos] == ']')))) {
            return;
        }
    }
}

void JsonPlaces::scanValue(const std::string& pointer, int depth) {
    skipBlanks();
    if (m_pos >= m_text.size()) {
        return;
    }
    if (depth > kMaxDepth) {
        skipValue();
        return;
    }
    m_values[pointer] = m_pos;
    const char open = m_text[m_pos];
    if (open == '"') {
        skipString();
        return;
    }
    if (open != '{' && open != '[') {
        // A number or a literal: up to the next delimiter.
        while (m_pos < m_text.size() && m_text[m_pos] != ',' && m_text[m_pos] != '}' &&
               m_text[m_pos] != ']' && m_text[m_pos] != ' ' && m_text[m_pos] != '\t' &&
               m_text[m_pos] != '\n' && m_text[m_pos] != '\r') {
            ++m_pos;
        }
        return;
    }
    ++m_pos;
    const char close = open == '{' ? '}' : ']';
    for (std::size_t index = 0;; ++index) {
        skipBlanks();
        if (m_pos >= m_text.size()) {
            return;
        }
        if (m_text[m_pos] == close) {
            ++m_pos;
            return;
        }
        if (m_text[m_pos] == ',') {
            ++m_pos;
            skipBlanks();
        }
        std::string member = pointer + "/" + std::to_string(index);
        if (open == '{') {
            const std::size_t keyStart = m_pos;
            const std::size_t keyEnd = skipString();
            std::string key;
            try {
                key = nlohmann::json::parse(m_text.substr(keyStart, keyEnd - keyStart)).get<std::string>();
            } catch (const nlohmann::json::exception&) {
                key = std::string(m_text.substr(keyStart + 1, keyEnd - keyStart - 2)); // cannot happen
            }
            member = child(pointer, key);
            m_keys[member] = keyStart;
            skipBlanks();
            if (m_pos < m_text.size() && m_text[m_pos] == ':') {
                ++m_pos;
            }
        }
        scanValue(member, depth + 1);
    }
}

} // namespace drytwin::data::historian
