#pragma once

#include "properties/Parameters.h"

#include <QString>

namespace drytwin::widgets {

/// @brief A physics parameter's meaning in the user's language (the engine's table is English,
/// for the CLI and the model files); its English text when this version has no translation.
QString parameterMeaning(const properties::ParameterInfo& info);
/// @brief Where its value comes from (paper appendix, an engineering reason), translated alike.
QString parameterSource(const properties::ParameterInfo& info);

} // namespace drytwin::widgets
