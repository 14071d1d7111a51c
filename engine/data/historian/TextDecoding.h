#pragma once

#include "common/Error.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace drytwin::data::historian {

/// @brief The encodings plant files come in: UTF-8 (the contract's), UTF-16 as Excel's "Unicode
/// text" and WinCC save it, and Windows-1252 as Excel's "CSV" saves it on Western-European Windows.
enum class TextEncoding { Utf8, Utf16LE, Utf16BE, Windows1252 };

/// @brief "UTF-8", "UTF-16 LE", "UTF-16 BE", "Windows-1252".
std::string encodingName(TextEncoding encoding);

/// @brief The longest line a plant file may hold. A longer one is a file without line breaks
/// (or no CSV at all); refusing it early keeps a 200 MB "line" from taking gigabytes.
inline constexpr std::size_t kMaxLineBytes = std::size_t(1) << 20;

/// @brief A file's text as UTF-8 with '\n' line ends, and what was done to get it.
struct DecodedText {
    TextEncoding encoding = TextEncoding::Utf8;
    bool byteOrderMark = false;
    /// True when the text had to be converted; it is then in @c converted. Otherwise the raw
    /// text is UTF-8 already and is read as it is, without a copy.
    bool isConverted = false;
    std::string converted;
    std::vector<std::string> notes; ///< what was converted, with the file's name
    /// @brief The UTF-8 text: @c converted, or @p raw when nothing was converted.
    const std::string& text(const std::string& raw) const { return isConverted ? converted : raw; }
};

/// @brief Decodes a plant file's bytes to UTF-8: a UTF-8 byte-order mark is taken off (the text is
/// then a copy); UTF-16 LE or BE with or without a byte-order mark, and text that is not UTF-8
/// (read as Windows-1252), are converted; lines that end in a carriage return only are split.
/// Fails with file:line:column on bytes no encoding explains (NUL bytes in 8-bit text, a lone
/// UTF-16 surrogate, bytes Windows-1252 leaves undefined) and on a line longer than @p maxLineBytes.
/// Thread-safe.
Expected<DecodedText> decodeText(const std::string& raw, const std::string& file,
                                 std::size_t maxLineBytes = kMaxLineBytes);

/// @brief True when @p raw, a file's first bytes, is UTF-16 without a byte-order mark: text of
/// mostly ASCII (digits, delimiters, tag names) has a zero in every other byte. Looks at 4 KiB.
bool looksLikeUtf16(std::string_view raw, bool& littleEndian);

/// @brief The byte offset of the first byte of @p text that is not valid UTF-8 (overlong forms,
/// surrogates and code points past U+10FFFF are invalid), or npos when all of it is valid.
std::size_t firstInvalidUtf8(std::string_view text);

/// @brief Fails with file:line on the first line of @p text longer than @p maxLineBytes.
Status checkLineLengths(std::string_view text, const std::string& file,
                        std::size_t maxLineBytes = kMaxLineBytes);

} // namespace drytwin::data::historian
