#include "data/historian/LineLengthGuard.h"

#include "data/historian/PlaceInFile.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>

namespace drytwin::data::historian {

LineLengthGuard::LineLengthGuard(std::string file, std::size_t maxLineBytes)
    : m_file(std::move(file)), m_maxLineBytes(maxLineBytes) {}

Error LineLengthGuard::tooLong(std::size_t fileBytes) const {
    return fileError(m_file, m_line, 1,
                     "line " + std::to_string(m_line) + " is longer than " + byteCount(m_maxLineBytes) +
                         ", the most a line of a plant file may hold; reading stopped there" +
                         (fileBytes > 0 ? " (the file is " + byteCount(fileBytes) + ")" : std::string()) +
                         ". The line breaks are missing, or this is not a CSV export (export the data again "
                         "as CSV or text, one sample per line)");
}

Status LineLengthGuard::feed(std::string_view chunk, std::size_t fileBytes) {
    std::size_t i = 0;
    if (!m_started && !chunk.empty()) {
        m_started = true;
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(chunk[k]); };
        if (chunk.size() >= 2 &&
            ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))) {
            m_utf16 = true;
            m_littleEndian = byte(0) == 0xFF;
            i = 2;
        } else if (looksLikeUtf16(chunk, m_littleEndian)) {
            m_utf16 = true;
        } else if (chunk.substr(0, 3) == "\xEF\xBB\xBF") {
            i = 3; // a UTF-8 byte-order mark is no part of the first line
        }
    }
    if (m_utf16) {
        for (; i < chunk.size(); ++i) {
            const auto b = static_cast<unsigned char>(chunk[i]);
            if (!m_oddByte) {
                m_firstHalf = b;
                m_oddByte = true;
                continue;
            }
            m_oddByte = false;
            const unsigned unit = m_littleEndian ? (m_firstHalf | (b << 8)) : ((m_firstHalf << 8) | b);
            if (unit == '\n' || unit == '\r') {
                m_line += unit == '\r' || !m_afterCarriageReturn ? 1 : 0;
                m_afterCarriageReturn = unit == '\r';
                m_lineLength = 0;
            } else {
                m_afterCarriageReturn = false;
                if (++m_lineLength > m_maxLineBytes) {
                    return tooLong(fileBytes);
                }
            }
        }
        return {};
    }
    // Eight-bit text: from one line end to the next with memchr, which keeps a month's export fast.
    // The next '\n' is looked for again only once passed: a file of '\r' line ends has none, and
    // a search to the chunk's end per line would make the chunk's lines quadratic.
    const char* const data = chunk.data();
    const std::size_t n = chunk.size();
    std::size_t lineFeed = 0;
    bool lineFeedKnown = false;
    while (i < n) {
        if (!lineFeedKnown || lineFeed < i) {
            const auto* lf = static_cast<const char*>(std::memchr(data + i, '\n', n - i));
            lineFeed = lf ? static_cast<std::size_t>(lf - data) : n;
            lineFeedKnown = true;
        }
        const auto* cr = static_cast<const char*>(std::memchr(data + i, '\r', lineFeed - i));
        const std::size_t end = cr ? static_cast<std::size_t>(cr - data) : lineFeed;
        if (end > i) {
            m_afterCarriageReturn = false;
        }
        m_lineLength += end - i;
        if (m_lineLength > m_maxLineBytes) {
            return tooLong(fileBytes);
        }
        if (end == n) {
            break;
        }
        // '\r\n' ends one line, as does '\r' or '\n' alone.
        m_line += data[end] == '\r' || !m_afterCarriageReturn ? 1 : 0;
        m_afterCarriageReturn = data[end] == '\r';
        m_lineLength = 0;
        i = end + 1;
    }
    return {};
}

Expected<std::string> readWithLineLimit(std::istream& in, const std::string& file, std::size_t maxLineBytes,
                                        std::size_t fileBytes, std::size_t maxBytes) {
    LineLengthGuard guard(file, maxLineBytes);
    std::string text;
    // Room for a small file at once; a large one grows as its lines pass the guard, so that a
    // file without line breaks never has more than the limit reserved for it.
    text.reserve(std::min(fileBytes, 8 * maxLineBytes));
    std::string chunk(std::size_t(64) << 10, '\0');
    while (in) {
        std::size_t want = chunk.size();
        if (maxBytes > 0) {
            want = std::min(want, maxBytes - text.size());
        }
        in.read(chunk.data(), static_cast<std::streamsize>(want));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (got == 0) {
            break;
        }
        const std::string_view piece(chunk.data(), got);
        if (auto st = guard.feed(piece, fileBytes); !st) {
            return st.error();
        }
        text.append(piece);
        if (maxBytes > 0 && text.size() >= maxBytes && in.peek() != std::char_traits<char>::eof()) {
            // A head: cut after the last whole line, as a reader of whole lines needs it.
            if (const auto nl = text.rfind('\n'); nl != std::string::npos) {
                text.resize(nl + 1);
            }
            return text;
        }
    }
    if (in.bad()) {
        return Error{ErrorKind::BadInput, file, "read error"};
    }
    return text;
}

Expected<std::string> readFileWithLineLimit(const std::string& path, std::size_t maxLineBytes,
                                            std::size_t maxBytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return Error{ErrorKind::BadInput, path, std::string("cannot open: ") + std::strerror(errno)};
    }
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    return readWithLineLimit(in, path, maxLineBytes, ec ? 0 : static_cast<std::size_t>(size), maxBytes);
}

} // namespace drytwin::data::historian
