#pragma once

#include "common/Error.h"
#include "data/Batch.h"

#include <string>

namespace drytwin::data {

/// @brief How to name the columns when writing.
enum class HeaderNames { AsRead, Contract };

/// @brief Formats a batch as CSV text: metadata lines, header, rows. Numbers are written in
/// their shortest exact form, so reading the text back gives bit-identical values; missing
/// cells are written empty.
std::string formatBatch(const Batch& batch, HeaderNames names = HeaderNames::AsRead);

/// @brief Writes a batch file atomically (never a half-written file).
Status writeBatchFile(const Batch& batch, const std::string& path, HeaderNames names = HeaderNames::AsRead);

/// @brief Shortest decimal text that reads back as exactly @p v (std::to_chars).
std::string formatNumber(double v);

} // namespace drytwin::data
