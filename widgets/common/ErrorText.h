#pragma once

#include "common/Error.h"

#include <QString>

namespace drytwin::widgets {

/// @brief An engine error worded in the user's language from its code and arguments
/// (ARCHITECTURE.md rule 11); codes without a wording fall back on the engine's English text.
QString errorText(const Error& error);

} // namespace drytwin::widgets
