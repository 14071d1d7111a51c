#pragma once

class QwtLegendLabel;

namespace drytwin::widgets {

/// @brief A legend item as small as it can be and still be read and clicked (Qwt's checkable
/// items are framed buttons 30 px tall: the What-if tab's ten took the moisture plot's room at
/// 1280 x 800), and never narrower than its text: a legend short of room wraps onto another row
/// instead of cutting its last item ("(PGRL", Chinese "学员的回答": issue #72 item 11).
void compactLegendLabel(QwtLegendLabel& label);

} // namespace drytwin::widgets
