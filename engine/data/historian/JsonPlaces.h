#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>

namespace drytwin::data::historian {

/// @brief Where each value and each object key of a JSON text starts, by JSON pointer ("/runs/step_s",
/// "/T_hot_C/unit"), so that a message about what a valid file says can name file:line:column.
///
/// A small index over the text rather than nlohmann::json's own means: the nlohmann 3.11 that
/// Debian 12 ships keeps no positions in its values (3.12's JSON_DIAGNOSTIC_POSITIONS does), and its
/// SAX and parser callbacks are told no position either; a scanner over text nlohmann has already
/// accepted needs no error handling of its own, so it cannot disagree with the parser on what the
/// file says. Keys are decoded by nlohmann (escapes included) and a repeated key keeps its last
/// place, as nlohmann keeps its last value. Thread-safe once built.
class JsonPlaces {
public:
    /// @param text JSON that nlohmann::json::parse accepted.
    explicit JsonPlaces(std::string_view text);

    /// @brief Byte offset of the value at @p pointer, or of its nearest enclosing value when the
    /// index has none there (0 for the whole text).
    std::size_t valueAt(const std::string& pointer) const;
    /// @brief Byte offset of the key of the object member at @p pointer; valueAt(pointer) when it
    /// names no object member.
    std::size_t keyAt(const std::string& pointer) const;

    /// @brief @p pointer with one more member or index: "/a" + "b~c" = "/a/b~0c" (RFC 6901).
    static std::string child(const std::string& pointer, const std::string& key);

private:
    void scanValue(const std::string& pointer, int depth);
    void skipBlanks();
    void skipValue();         ///< one value at m_pos, nested ones with it, without indexing
    std::size_t skipString(); ///< from an opening quote; returns the offset after the closing one

    std::string_view m_text;
    std::size_t m_pos = 0;
    std::map<std::string, std::size_t> m_values, m_keys;
};

} // namespace drytwin::data::historian
