// The plot stack's cursors: the time cursor every plot shares, the two measuring cursors and the
// readout of the values under them.
#include "common/LegendLabel.h"
#include "common/PlotStack.h"

#include "common/WidgetHelpers.h"

#include <QBuffer>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPdfWriter>
#include <QPointer>
#include <QPushButton>
#include <QResizeEvent>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <qwt_legend.h>
#include <qwt_legend_label.h>
#include <qwt_plot.h>
#include <qwt_plot_canvas.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <qwt_plot_marker.h>
#include <qwt_plot_panner.h>
#include <qwt_plot_renderer.h>
#include <qwt_plot_textlabel.h>
#include <qwt_plot_zoomer.h>
#include <qwt_scale_draw.h>
#include <qwt_scale_engine.h>
#include <qwt_scale_widget.h>
#include <qwt_symbol.h>

namespace drytwin::widgets {

namespace {

/// Value of the first visible curve of a plot at x (linear interpolation), NaN outside.
double valueAt(const QwtPlot* plot, double x) {
    for (const auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
        const auto* c = static_cast<const QwtPlotCurve*>(item);
        if (!c->isVisible() || c->dataSize() < 2) {
            continue;
        }
        const auto* d = c->data();
        const std::size_t n = d->size();
        if (x < d->sample(0).x() || x > d->sample(n - 1).x()) {
            continue;
        }
        std::size_t lo = 0, hi = n - 1;
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            (d->sample(mid).x() <= x ? lo : hi) = mid;
        }
        const QPointF a = d->sample(lo), b = d->sample(hi);
        const double w = b.x() > a.x() ? (x - a.x()) / (b.x() - a.x()) : 0.0;
        return a.y() + w * (b.y() - a.y());
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

void PlotStack::setTimeCursor(double t) {
    m_timeCursor = t;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        m_timeMarkers[i]->setXValue(t);
        m_timeMarkers[i]->setVisible(std::isfinite(t));
        m_plots[i]->replot();
    }
    updateReadout();
}

void PlotStack::setMeasuringCursor(int which, double x) {
    m_cursor[which] = x;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        m_cursorMarkers[which][i]->setXValue(x);
        m_cursorMarkers[which][i]->setVisible(std::isfinite(x));
        m_plots[i]->replot();
    }
    updateReadout();
}

QString PlotStack::readout() const {
    return m_readout->text();
}

void PlotStack::updateReadout() {
    QStringList parts;
    const auto fmt = [](double v) {
        return std::isfinite(v) ? QString::number(v, 'g', 5) : QStringLiteral("–");
    };
    if (std::isfinite(m_cursor[0])) {
        parts << tr("A %1").arg(fmt(m_cursor[0]));
    }
    if (std::isfinite(m_cursor[1])) {
        parts << tr("B %1").arg(fmt(m_cursor[1]));
    }
    if (std::isfinite(m_cursor[0]) && std::isfinite(m_cursor[1])) {
        parts << tr("Δx %1").arg(fmt(m_cursor[1] - m_cursor[0]));
        for (auto* plot : m_plots) {
            const double a = valueAt(plot, m_cursor[0]);
            const double b = valueAt(plot, m_cursor[1]);
            parts << tr("%1: Δ %2").arg(plot->property("drytwinYTitle").toString(), fmt(b - a));
        }
    }
    if (std::isfinite(m_timeCursor)) {
        parts << tr("time cursor %1 s").arg(fmt(m_timeCursor));
    }
    if (!parts.isEmpty()) {
        m_readout->setText(parts.join(QStringLiteral("   ")));
    }
}

} // namespace drytwin::widgets
