#include "common/LegendLabel.h"

#include <QFontMetrics>
#include <algorithm>
#include <qwt_legend_label.h>
#include <qwt_plot.h>
#include <qwt_text.h>

namespace drytwin::widgets {

void compactLegendLabel(QwtLegendLabel& label) {
    label.setMargin(1);
    // The spacing also places the text after the key (Qwt sets the text's indent from margin, key
    // and spacing): an indent set here put the text of the last entry on top of its key.
    label.setSpacing(4);
    QFont f = label.font();
    f.setPointSizeF(8.5);
    label.setFont(f);
    // Qwt measures the text with its own cached layout, a few pixels short of what is drawn (more
    // in Chinese, with glyphs from a fallback font); the legend's grid then squeezed the last item
    // of a full row. Its least width is the drawn text's, with the key, spacing, margins and frame.
    const int text = QFontMetrics(f).horizontalAdvance(label.text().text());
    const int beforeText = std::max(label.indent(), label.margin() + label.icon().width() + label.spacing());
    const int around = beforeText + label.margin() + 2 * label.frameWidth() + 2;
    if (label.minimumWidth() == text + around) {
        return;
    }
    label.setMinimumWidth(text + around);
    // The plot lays its legend out from the items' sizes it measured before: told again, so that a
    // row that no longer fits goes onto another one instead of into a scroll area.
    for (QWidget* up = label.parentWidget(); up; up = up->parentWidget()) {
        if (auto* plot = qobject_cast<QwtPlot*>(up)) {
            plot->updateLayout();
            break;
        }
    }
}

} // namespace drytwin::widgets
