// Qwt 6.1.4's qwt_plot_layout.h default-initialises a QFlags from 0x00, which Qt 5.15 no longer
// accepts once QT_DISABLE_DEPRECATED_BEFORE=0x050F00 (set for every target, to stay Qt 6-clean)
// removes that constructor. This file alone needs the layout (its canvas margins), so it alone
// relaxes the macro, before any Qt header is read.
#undef QT_DISABLE_DEPRECATED_BEFORE
#define QT_DISABLE_DEPRECATED_BEFORE 0x050000

#include "common/EqualAspect.h"

#include <qwt_interval.h>
#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_layout.h>
#include <qwt_plot_rescaler.h>

namespace drytwin::widgets {

void keepEqualAspect(QwtPlot* plot, double radius) {
    // The rescaler is the canvas's child (Qwt finds the canvas as its parent). Found by its name:
    // QwtPlotRescaler has no Q_OBJECT, so findChild<QwtPlotRescaler*> would match any child.
    const QString name = QStringLiteral("drytwin-equal-aspect");
    auto* rescaler =
        static_cast<QwtPlotRescaler*>(plot->canvas()->findChild<QObject*>(name, Qt::FindDirectChildrenOnly));
    if (!rescaler) {
        // The rescaler measures the canvas without the layout's canvas margins (4 px a side) and
        // the scale maps with them: without margins the two agree.
        plot->plotLayout()->setCanvasMargin(0); // every axis
        rescaler = new QwtPlotRescaler(plot->canvas(), QwtPlot::xBottom, QwtPlotRescaler::Fitting);
        rescaler->setObjectName(name);
        rescaler->setExpandingDirection(QwtPlotRescaler::ExpandBoth); // the origin stays in the middle
        rescaler->setAspectRatio(QwtPlot::yLeft, 1.0);
        rescaler->setAspectRatio(QwtPlot::yRight, 0.0);
        rescaler->setAspectRatio(QwtPlot::xTop, 0.0);
    }
    rescaler->setIntervalHint(QwtPlot::xBottom, QwtInterval(-radius, radius));
    rescaler->setIntervalHint(QwtPlot::yLeft, QwtInterval(-radius, radius));
    rescaler->rescale();
}

} // namespace drytwin::widgets
