#pragma once

#include "common/Error.h"
#include "data/historian/TextDecoding.h"

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>

namespace drytwin::data::historian {

/// @brief Watches a file's bytes as they are read and stops at the first line longer than the
/// limit, so that a file without line breaks is refused after reading the limit, not the file: a
/// 600 MB "line" read whole took 1.7 GB and 12 s before decodeText refused it. Line ends are '\n',
/// '\r\n' and a '\r' alone (classic Mac OS). UTF-16 (told by its byte-order mark or its zero bytes
/// in the first chunk) is counted in code units: each is at least one byte of the UTF-8 text
/// decodeText makes, so nothing that would pass decodeText's own check is refused here.
/// Not thread-safe; one per file.
class LineLengthGuard {
public:
    LineLengthGuard(std::string file, std::size_t maxLineBytes = kMaxLineBytes);

    /// @brief Takes the next bytes of the file (chunks of any size, in order); fails with
    /// file:line:1 once a line has grown past the limit. @p fileBytes, when known, is named in the
    /// message.
    Status feed(std::string_view chunk, std::size_t fileBytes = 0);

private:
    Error tooLong(std::size_t fileBytes) const;

    std::string m_file;
    std::size_t m_maxLineBytes;
    bool m_started = false;
    bool m_utf16 = false, m_littleEndian = true;
    bool m_oddByte = false;        ///< UTF-16: the first byte of a code unit came last
    unsigned char m_firstHalf = 0; ///< …and it was this one
    bool m_afterCarriageReturn = false;
    std::size_t m_lineLength = 0; ///< bytes (code units in UTF-16) since the last line end
    int m_line = 1;
};

/// @brief Reads @p in to its end with a LineLengthGuard (@p file names it in messages, @p fileBytes
/// its size when known), in 64 KiB chunks: memory never holds more than the lines read so far,
/// whatever the file's size. @p maxBytes > 0 stops after that many bytes, cut after the last whole
/// line (a preview of the file's head).
Expected<std::string> readWithLineLimit(std::istream& in, const std::string& file,
                                        std::size_t maxLineBytes = kMaxLineBytes, std::size_t fileBytes = 0,
                                        std::size_t maxBytes = 0);

/// @brief readWithLineLimit of the file at @p path; the error names the file and the system's
/// reason when it cannot be opened.
Expected<std::string> readFileWithLineLimit(const std::string& path, std::size_t maxLineBytes = kMaxLineBytes,
                                            std::size_t maxBytes = 0);

} // namespace drytwin::data::historian
