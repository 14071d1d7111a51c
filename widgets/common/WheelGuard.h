#pragma once

class QWidget;

namespace drytwin::widgets {

/// @brief Spin boxes and combo boxes under @p root (and @p root itself) no longer take the mouse
/// wheel unless they have the keyboard focus: a wheel turned to scroll a form passes over them
/// to the scroll area instead of changing the value under the pointer (issue #72 item 7: the
/// What-if band went from 0.50 to 0.01 % wb unnoticed). A click or Tab gives them focus, after
/// which the wheel steps the value as usual. Call again for widgets added later (cell widgets).
void ignoreWheelUnlessFocused(QWidget* root);

} // namespace drytwin::widgets
