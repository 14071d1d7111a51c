#pragma once

#include <QString>

namespace drytwin::widgets {

/// @brief Installs DryTwin's and Qt's own (qtbase: file dialogs, message-box buttons) translations
/// for @p language ("en", "zh_CN"), replacing those installed before; "en" removes them. Returns
/// false when DryTwin's translation file was not found (Qt's may still be missing: the package
/// qttranslations5-l10n ships them). Call on the GUI thread.
bool setLanguage(const QString& language);
/// @brief The language last set ("en" before any).
QString currentLanguage();

} // namespace drytwin::widgets
