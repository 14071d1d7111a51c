#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

struct csv_parser;

namespace drytwin::data::historian {

/// @brief Walks a text line by line (without the '\n'), counting lines from 1.
class LineCursor {
public:
    explicit LineCursor(std::string_view text, std::size_t from = 0, int linesBefore = 0)
        : m_text(text), m_pos(from), m_line(linesBefore) {}
    /// @brief The next line; false at the end of the text.
    bool next(std::string_view& line);
    int lineNumber() const { return m_line; }      ///< of the line next() returned last
    std::size_t position() const { return m_pos; } ///< byte offset of the line after it

private:
    std::string_view m_text;
    std::size_t m_pos;
    int m_line;
};

/// @brief The fields of one CSV line. Lines without a quote are split on the delimiter in place
/// (which is what keeps a month at 1 s fast); lines with one go through libcsv (quoted fields,
/// doubled quotes). Not thread-safe; one per reader.
class CsvLineSplitter {
public:
    explicit CsvLineSplitter(char delimiter) : m_delimiter(delimiter) {}
    ~CsvLineSplitter();
    CsvLineSplitter(const CsvLineSplitter&) = delete;
    CsvLineSplitter& operator=(const CsvLineSplitter&) = delete;

    /// @brief Splits @p line (a trailing '\r' ignored); false for malformed quoting.
    bool split(std::string_view line);
    /// @brief The fields of the line split last; they point into it or into the splitter.
    const std::vector<std::string_view>& fields() const { return m_fields; }

private:
    static void onField(void* s, std::size_t len, void* data);
    char m_delimiter;
    std::vector<std::string_view> m_fields;
    std::vector<std::string> m_owned; // libcsv's unquoted copies
    csv_parser* m_parser = nullptr;
};

/// @brief The delimiter of a header line: the most frequent of ',', ';' and tab outside quotes;
/// '|' where the header has none of those but a pipe.
char detectDelimiter(std::string_view header);

/// @brief "comma", "semicolon", "tab", "pipe".
std::string delimiterName(char delimiter);

} // namespace drytwin::data::historian
