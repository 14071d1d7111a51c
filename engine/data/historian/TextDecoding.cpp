// Plant files come as Excel and the control systems save them: UTF-8, UTF-16 ("Unicode text",
// WinCC) or Windows-1252 (Excel's "CSV" on Western-European Windows). The two conversions are
// written here by hand rather than through iconv: glibc's Windows-1252 is a gconv module loaded at
// run time, which slim containers and static builds leave out, so the engine would read a file on
// one machine and refuse it on another; and a hand-written loop knows the line and column of a bad
// byte, which iconv reports only as an offset into a half-written buffer. Both encodings are small:
// UTF-16 is code units and surrogate pairs, Windows-1252 is Latin-1 with 27 characters in 0x80–0x9F.
#include "data/historian/TextDecoding.h"

#include "data/historian/PlaceInFile.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace drytwin::data::historian {

namespace {

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
        out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
        out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
        out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
}

std::string hexByte(unsigned char b) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", b);
    return buf;
}

Expected<DecodedText> fromUtf16(const std::string& raw, const std::string& file, bool littleEndian,
                                bool bom) {
    DecodedText d;
    d.encoding = littleEndian ? TextEncoding::Utf16LE : TextEncoding::Utf16BE;
    d.byteOrderMark = bom;
    d.isConverted = true;
    d.converted.reserve(raw.size() / 2 + 16);
    const auto* b = reinterpret_cast<const unsigned char*>(raw.data());
    const std::size_t n = raw.size();
    const auto unitAt = [&](std::size_t i) -> std::uint32_t {
        return littleEndian ? static_cast<std::uint32_t>(b[i] | (b[i + 1] << 8))
                            : static_cast<std::uint32_t>((b[i] << 8) | b[i + 1]);
    };
    int line = 1, column = 1;
    std::size_t i = bom ? 2 : 0;
    for (; i + 1 < n; i += 2) {
        std::uint32_t cp = unitAt(i);
        if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (i + 3 >= n) {
                break; // cut in the middle of a pair: the end of a file's head, or a cut-off file
            }
            const std::uint32_t low = unitAt(i + 2);
            if (low < 0xDC00 || low > 0xDFFF) {
                return fileError(file, line, column,
                                 "a UTF-16 high surrogate without its low half; the file is damaged");
            }
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            i += 2;
        } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            return fileError(file, line, column,
                             "a UTF-16 low surrogate without its high half; the file is damaged");
        }
        appendUtf8(d.converted, cp);
        if (cp == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    d.notes.push_back(
        file + ": the file is " + encodingName(d.encoding) +
        (bom ? " (with a byte-order mark)" : " (no byte-order mark; recognised by its zero bytes)") +
        "; read as UTF-8 text");
    if (i < n) {
        d.notes.push_back(
            file + ":" + std::to_string(line) +
            ": the file ends in the middle of a UTF-16 character; that last character is left out");
    }
    return d;
}

/// Windows-1252's characters at 0x80–0x9F (0: undefined); 0xA0–0xFF are Latin-1's.
constexpr std::uint16_t kWindows1252High[32] = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

Expected<DecodedText> fromWindows1252(const std::string& raw, const std::string& file, std::size_t firstBad) {
    DecodedText d;
    d.encoding = TextEncoding::Windows1252;
    d.isConverted = true;
    d.converted.reserve(raw.size() + raw.size() / 16);
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const auto c = static_cast<unsigned char>(raw[i]);
        if (c < 0x80) {
            d.converted.push_back(static_cast<char>(c));
            continue;
        }
        const std::uint32_t cp = c >= 0xA0 ? c : kWindows1252High[c - 0x80];
        if (cp == 0) {
            int line = 0, column = 0;
            lineAndColumnAt(raw, i, line, column);
            return fileError(
                file, line, column,
                "byte " + hexByte(c) +
                    " is neither UTF-8 nor Windows-1252 (is this a text file?); save the file as "
                    "UTF-8 (Excel: Save As > CSV UTF-8)");
        }
        appendUtf8(d.converted, cp);
    }
    int line = 0, column = 0;
    lineAndColumnAt(raw, firstBad, line, column);
    d.notes.push_back(placeInFile(file, line, column) + ": the file is not UTF-8 (byte " +
                      hexByte(static_cast<unsigned char>(raw[firstBad])) +
                      " here); read as Windows-1252, as Excel saves CSV on Western-European Windows. If "
                      "the text looks wrong, save the file as UTF-8 (Excel: Save As > CSV UTF-8)");
    return d;
}

} // namespace

bool looksLikeUtf16(std::string_view raw, bool& littleEndian) {
    const std::size_t n = std::min<std::size_t>(raw.size(), 4096) & ~std::size_t(1);
    if (n < 4) {
        return false;
    }
    std::size_t zeroEven = 0, zeroOdd = 0;
    for (std::size_t i = 0; i < n; i += 2) {
        zeroEven += raw[i] == '\0';
        zeroOdd += raw[i + 1] == '\0';
    }
    const std::size_t pairs = n / 2;
    if (zeroOdd * 10 >= pairs * 4 && zeroEven * 20 < pairs) {
        littleEndian = true;
        return true;
    }
    if (zeroEven * 10 >= pairs * 4 && zeroOdd * 20 < pairs) {
        littleEndian = false;
        return true;
    }
    return false;
}

std::string encodingName(TextEncoding encoding) {
    switch (encoding) {
    case TextEncoding::Utf8:
        return "UTF-8";
    case TextEncoding::Utf16LE:
        return "UTF-16 LE";
    case TextEncoding::Utf16BE:
        return "UTF-16 BE";
    case TextEncoding::Windows1252:
        return "Windows-1252";
    }
    return "UTF-8";
}

std::size_t firstInvalidUtf8(std::string_view text) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        // Eight ASCII bytes at a time: a plant file is almost all digits and delimiters.
        if (i + 8 <= n) {
            std::uint64_t word = 0;
            std::memcpy(&word, s + i, 8);
            if ((word & 0x8080808080808080ull) == 0) {
                i += 8;
                continue;
            }
        }
        const unsigned char c = s[i];
        if (c < 0x80) {
            ++i;
            continue;
        }
        std::size_t len = 0;
        std::uint32_t cp = 0;
        if (c >= 0xC2 && c <= 0xDF) {
            len = 2;
            cp = c & 0x1F;
        } else if (c >= 0xE0 && c <= 0xEF) {
            len = 3;
            cp = c & 0x0F;
        } else if (c >= 0xF0 && c <= 0xF4) {
            len = 4;
            cp = c & 0x07;
        } else {
            return i;
        }
        if (i + len > n) {
            return i;
        }
        for (std::size_t k = 1; k < len; ++k) {
            if ((s[i + k] & 0xC0) != 0x80) {
                return i;
            }
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        if ((len == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) ||
            (len == 4 && (cp < 0x10000 || cp > 0x10FFFF))) {
            return i;
        }
        i += len;
    }
    return std::string_view::npos;
}

Status checkLineLengths(std::string_view text, const std::string& file, std::size_t maxLineBytes) {
    std::size_t pos = 0;
    int line = 1;
    while (pos < text.size()) {
        const void* nl = std::memchr(text.data() + pos, '\n', text.size() - pos);
        const std::size_t end =
            nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) : text.size();
        if (end - pos > maxLineBytes) {
            return fileError(file, line, 1,
                             "line " + std::to_string(line) + " is " + byteCount(end - pos) +
                                 " long; a line of a plant file may be at most " + byteCount(maxLineBytes) +
                                 ". The line breaks are missing, or this is not a CSV export (export the "
                                 "data again as CSV or text, one sample per line)");
        }
        pos = end + 1;
        ++line;
    }
    return {};
}

Expected<DecodedText> decodeText(const std::string& raw, const std::string& file, std::size_t maxLineBytes) {
    if (raw.empty()) {
        return fileError(file, 1, 1, "empty file");
    }
    // A UTF-8 byte-order mark (Excel's "CSV UTF-8") is taken off before anything reads the text:
    // left on, a reader's first look at line 1 took "# batch:" for a title line, and a file that
    // is otherwise Windows-1252 turned it into "ï»¿". The text is then a copy without it.
    if (raw.size() >= 3 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) {
        std::string rest = raw.substr(3);
        auto decoded = decodeText(rest, file, maxLineBytes);
        if (!decoded) {
            return decoded;
        }
        if (!decoded->isConverted) {
            decoded->converted = std::move(rest);
            decoded->isConverted = true;
        }
        decoded->byteOrderMark = true;
        return decoded;
    }
    const auto u = [&](std::size_t i) { return static_cast<unsigned char>(raw[i]); };
    Expected<DecodedText> decoded = DecodedText{};
    bool littleEndian = true;
    if (raw.size() >= 2 && u(0) == 0xFF && u(1) == 0xFE) {
        decoded = fromUtf16(raw, file, true, true);
    } else if (raw.size() >= 2 && u(0) == 0xFE && u(1) == 0xFF) {
        decoded = fromUtf16(raw, file, false, true);
    } else if (looksLikeUtf16(raw, littleEndian)) {
        decoded = fromUtf16(raw, file, littleEndian, false);
    } else if (const auto bad = firstInvalidUtf8(raw); bad != std::string::npos) {
        decoded = fromWindows1252(raw, file, bad);
    }
    if (!decoded) {
        return decoded;
    }
    DecodedText& d = *decoded;
    const std::string& text = d.text(raw);
    if (const auto nul = text.find('\0'); nul != std::string::npos) {
        int line = 0, column = 0;
        lineAndColumnAt(text, nul, line, column);
        return fileError(file, line, column,
                         "NUL byte in a text file (a binary file, or UTF-32?); save the file as UTF-8 CSV");
    }
    // Classic Mac OS line ends (a carriage return alone): one line per CR, as Excel for Mac wrote them.
    if (text.find('\n') == std::string::npos && text.find('\r') != std::string::npos) {
        std::string lines = text;
        for (char& c : lines) {
            if (c == '\r') {
                c = '\n';
            }
        }
        d.converted = std::move(lines);
        d.isConverted = true;
        d.notes.push_back(file + ": lines end in a carriage return alone (classic Mac OS); read as lines");
    }
    if (auto st = checkLineLengths(d.text(raw), file, maxLineBytes); !st) {
        return st.error();
    }
    return decoded;
}

} // namespace drytwin::data::historian
