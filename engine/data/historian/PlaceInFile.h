#pragma once

#include "common/Error.h"

#include <string>
#include <string_view>

/// The pieces of reading a plant file as a historian exports it (data/PlantFileReader.h puts them
/// together): where in a file a message points, the text's encoding, number and time-stamp formats,
/// the file's shape, the columns, the clock, and cutting the file into production runs.
namespace drytwin::data::historian {

/// @brief "file:line:column", the place every message of the plant-file reader starts with.
std::string placeInFile(const std::string& file, int line, int column);

/// @brief A bad-input error at a place in a file. Its arguments are ErrorCode::DataFileFormat's
/// {file, line, column, English reason} unless @p args gives those of another @p code.
Error fileError(const std::string& file, int line, int column, std::string reason,
                ErrorCode code = ErrorCode::DataFileFormat, std::vector<std::string> args = {});

/// @brief The 1-based line and column (in bytes) of byte @p offset of @p text.
void lineAndColumnAt(std::string_view text, std::size_t offset, int& line, int& column);

/// @brief @p s without leading and trailing blanks (space, tab, carriage return).
std::string_view trimmed(std::string_view s);

/// @brief @p s in ASCII lower case (other bytes as they are).
std::string lowerAscii(std::string_view s);

/// @brief A byte count for messages: "812 bytes", "1.5 MiB", "200.0 MiB".
std::string byteCount(std::size_t bytes);

} // namespace drytwin::data::historian
