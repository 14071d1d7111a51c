#pragma once

#include <QString>
#include <string>

namespace drytwin::widgets {

// The engine writes its notes and reasons in English, for the command line and the logs
// (ARCHITECTURE.md rule 11). Every one of them that reaches the window goes through a function
// here (or errorText()), which words its known forms in the user's language from the numbers and
// names it carries; `translations_complete` (tests/app/CheckTranslations.cmake) fails on engine
// text passed to the screen any other way (issue #72 item 11).

/// @brief A note of the data checks or of reading a plant file ("shift.csv: column 'STATUS'
/// holds text; …", a tag/value export, a short run left out, a gap, a batch in another unit), in
/// the user's language; a form not known here as the engine wrote it.
QString dataNoteText(const std::string& note);

/// @brief Engine detail that only the English window shows as it is: in another language the
/// worded text @p worded (the same point without the engine's English details).
QString engineDetailText(const std::string& english, const QString& worded);

/// @brief Why the what-if controller kept its last plan at a decision (control/ the MPC's
/// fallback reason), in the user's language.
QString fallbackReasonText(const std::string& reason);

} // namespace drytwin::widgets
