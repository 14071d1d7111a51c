#include "common/PlotStack.h"
#include "common/LegendLabel.h"

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

/// The legend's key drawn as the curve's line, long enough to show its style: Qwt's default, a
/// filled square, made a setpoint (dashed), its band (dotted) and a prediction (dash-dot) look
/// alike, and the physics model and its prediction one grey square twice.
void showLineInLegend(QwtPlotCurve& curve) {
    curve.setLegendAttribute(QwtPlotCurve::LegendShowLine, true);
    curve.setLegendIconSize(QSize(22, 8));
}

/// A canvas note that wraps within the canvas: QwtPlotTextLabel lays its text out at its unwrapped
/// size, so a sentence wider than a narrow plot was cut at both ends.
class WrappingTextLabel : public QwtPlotTextLabel {
protected:
    QRectF textRect(const QRectF& rect, const QSizeF&) const override { return rect.adjusted(8, 0, -8, 0); }
};

} // namespace

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QwtPlotMarker* verticalLine(QwtPlot* plot, const QColor& colour, Qt::PenStyle style) {
    auto* m = new QwtPlotMarker;
    m->setLineStyle(QwtPlotMarker::VLine);
    m->setLinePen(colour, 1.2, style);
    m->setItemAttribute(QwtPlotItem::Legend, false);
    m->setZ(50);
    m->setVisible(false);
    m->attach(plot);
    return m;
}

} // namespace

PlotStack::PlotStack(QWidget* parent)
    : QWidget(parent), m_cursor{kNaN, kNaN}, m_timeCursor(kNaN), m_emptyXRange{kNaN, kNaN} {
    m_layout = new QVBoxLayout(this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(2);
    auto* bottom = new QHBoxLayout;
    m_readout = new QLabel(hintText());
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setWordWrap(true);
    auto* exportButton = new QPushButton(tr("Export…"));
    exportButton->setToolTip(tr("Save these plots as PNG, SVG or PDF, or their data as CSV"));
    connect(exportButton, &QPushButton::clicked, this, &PlotStack::exportDialog);
    bottom->addWidget(m_readout, 1);
    bottom->addWidget(exportButton);
    m_layout->addLayout(bottom);
}

int PlotStack::addPlot(const QString& yTitle) {
    auto* plot = new QwtPlot(this);
    plot->setCanvasBackground(Qt::white);
    plot->setAxisTitle(QwtPlot::yLeft, yTitle);
    auto* grid = new QwtPlotGrid;
    grid->setMajorPen(QColor(220, 220, 220), 0, Qt::DotLine);
    grid->attach(plot);
    // Compact axes, so that many plots fit one above the other and their titles stay whole.
    QFont titleFont = plot->axisTitle(QwtPlot::yLeft).font();
    titleFont.setPointSizeF(8.5);
    titleFont.setBold(false);
    QwtText title(yTitle);
    title.setFont(titleFont);
    plot->setAxisTitle(QwtPlot::yLeft, title);
    plot->setAxisMaxMajor(QwtPlot::yLeft, 4);
    // Its title on one line where the plot is tall enough, else its unit on a second line
    // (fitYTitle): "PSD [(% wb)²/Hz]" was cut to "3D [(% wb)²/H" on a small laptop's screen.
    plot->setProperty("drytwinYTitle", yTitle);
    plot->installEventFilter(this);
    // The time axis ends where the data end, not at the next round tick (a 6,300 s batch on a
    // 0–10,000 s axis when the plot is narrow and the ticks are 5,000 s apart).
    plot->axisScaleEngine(QwtPlot::xBottom)->setAttribute(QwtScaleEngine::Floating, true);
    QFont tickFont = plot->axisFont(QwtPlot::yLeft);
    tickFont.setPointSizeF(8);
    plot->setAxisFont(QwtPlot::yLeft, tickFont);
    plot->setAxisFont(QwtPlot::xBottom, tickFont);
    // One legend, on the top plot: its items toggle the curves of that name in every plot.
    if (m_plots.empty()) {
        auto* legend = new QwtLegend;
        legend->setDefaultItemMode(QwtLegendData::Checkable);
        legend->setMaxColumns(8);
        // Up to 0.6 of the plot for the legend (Qwt's default, a third, cut its second row in
        // half on Training's short top plot); a legend takes only the rows it needs.
        plot->insertLegend(legend, QwtPlot::TopLegend, 0.6);
        connect(legend, &QwtLegend::checked, this, [this, plot](const QVariant& info, bool on, int) {
            auto* item = plot->infoToItem(info);
            if (!item) {
                return;
            }
            const QString name = item->title().text();
            for (auto* p : m_plots) {
                for (auto* other : p->itemList(QwtPlotItem::Rtti_PlotCurve)) {
                    if (other->title().text() == name) {
                        other->setVisible(on);
                    }
                }
                p->replot();
            }
        });
    }
    // Only the bottom plot labels the shared time axis.
    for (auto* p : m_plots) {
        p->setAxisTitle(QwtPlot::xBottom, QString());
        p->enableAxis(QwtPlot::xBottom, false);
    }
    auto* zoomer = new QwtPlotZoomer(plot->canvas());
    zoomer->setRubberBandPen(QPen(Qt::darkGray, 1, Qt::DashLine));
    zoomer->setTrackerMode(QwtPicker::AlwaysOn);
    zoomer->setTrackerPen(QPen(Qt::darkBlue));
    auto* panner = new QwtPlotPanner(plot->canvas());
    panner->setMouseButton(Qt::MiddleButton);
    connect(plot->axisWidget(QwtPlot::xBottom), &QwtScaleWidget::scaleDivChanged, this,
            [this, plot] { linkXFrom(plot); });
    // A y scale set by hand (the Training tab's live plots), not through rescale(): the axes are
    // lined up again once the event loop is back, once however many scales changed.
    connect(plot->axisWidget(QwtPlot::yLeft), &QwtScaleWidget::scaleDivChanged, this, [this] {
        if (!m_alignQueued) {
            m_alignQueued = true;
            QTimer::singleShot(0, this, [this] {
                m_alignQueued = false;
                alignAxes();
            });
        }
    });
    plot->canvas()->installEventFilter(this); // after the zoomer: modifier clicks come here first
    m_timeMarkers.push_back(verticalLine(plot, QColor(230, 120, 0), Qt::SolidLine));
    m_cursorMarkers[0].push_back(verticalLine(plot, QColor(40, 40, 40), Qt::DashLine));
    m_cursorMarkers[1].push_back(verticalLine(plot, QColor(120, 0, 160), Qt::DashLine));
    m_plots.push_back(plot);
    m_zoomers.push_back(zoomer);
    m_emptyRanges.emplace_back(kNaN, kNaN);
    m_plotEmptyTexts.emplace_back();
    m_layout->insertWidget(static_cast<int>(m_plots.size()) - 1, plot, 4);
    // The top plot holds the legend, the bottom one the time axis: each a little more room, in its
    // share of the height (stretch) and in its least height. Each plot at least 110 px tall; in a
    // stack of five or more (Training's) less, so that the window fits the height a 1366 x 768
    // laptop leaves it (about 700 px below its title bar, above a taskbar:
    // theWindowFitsASmallLaptopScreen), every canvas still about as tall as its axis title. In a
    // stack of four or more the legend may take two rows: the top plot gets more, so that its
    // canvas keeps room for its title (at five, in a window of the 700 px a small laptop leaves,
    // "X_out [% 湿基]" needed 7).
    const bool many = m_plots.size() >= 5;
    const int topStretch = many ? 7 : m_plots.size() > 3 || m_plots.size() == 2 ? 6 : 5;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        const bool top = i == 0 && m_plots.size() > 1;
        const bool bottom = !top && i + 1 == m_plots.size();
        m_layout->setStretch(static_cast<int>(i), top ? topStretch : bottom ? 5 : 4);
        m_plots[i]->setMinimumHeight(!many ? 110 : top ? 136 : bottom ? 100 : 84);
    }
    // A plot added after setXTitle() keeps that title (Training's monitor plot, below the rest).
    setXTitle(m_xTitle.isEmpty() ? tr("time [s]") : m_xTitle);
    return static_cast<int>(m_plots.size()) - 1;
}

void PlotStack::setXTitle(const QString& title) {
    m_xTitle = title;
    if (!m_plots.empty()) {
        QwtText t(title);
        QFont f = t.font();
        f.setPointSizeF(8.5);
        t.setFont(f);
        m_plots.back()->setAxisTitle(QwtPlot::xBottom, t);
    }
}

QString PlotStack::hintText() const {
    return tr(
        "Ctrl+click: cursor A, Shift+click: cursor B, Alt+click: time cursor; drag to zoom, right click "
        "to zoom out, middle drag to pan");
}

void PlotStack::setHintVisible(bool visible) {
    m_hintVisible = visible;
    if (m_readout->text() == hintText() || m_readout->text().isEmpty()) {
        m_readout->setText(visible ? hintText() : QString());
    }
}

void PlotStack::setEmptyText(const QString& text) {
    m_emptyText = text;
    updateEmptyText();
}

bool PlotStack::showsEmptyText() const {
    return m_showingEmptyText;
}

void PlotStack::setEmptyRange(int index, double lo, double hi) {
    m_emptyRanges.at(static_cast<std::size_t>(index)) = {lo, hi};
    updateEmptyText();
}

void PlotStack::setEmptyXRange(double lo, double hi) {
    m_emptyXRange = {lo, hi};
    updateEmptyText();
}

void PlotStack::setPlotEmptyText(int index, const QString& text) {
    m_plotEmptyTexts.at(static_cast<std::size_t>(index)) = text;
    updateEmptyText();
}

QString PlotStack::noteShown(int index) const {
    const auto i = static_cast<std::size_t>(index);
    return i < m_emptyLabels.size() && m_emptyLabels[i]->plot() ? m_emptyLabels[i]->text().text() : QString();
}

void PlotStack::updateEmptyText() {
    bool hasData = false;
    for (int i = 0; i < plotCount(); ++i) {
        hasData = hasData || curveCount(i) > 0;
    }
    while (m_emptyLabels.size() < m_plots.size()) {
        auto* label = new WrappingTextLabel;
        label->setZ(100);
        m_emptyLabels.push_back(label);
    }
    m_showingEmptyText = !hasData && !m_emptyText.isEmpty();
    const bool xRanged = std::isfinite(m_emptyXRange.first);
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        auto* plot = m_plots[i];
        auto* label = m_emptyLabels[i];
        const bool empty = curveCount(static_cast<int>(i)) == 0;
        const bool ranged = std::isfinite(m_emptyRanges[i].first);
        // An empty plot says why in words: the stack's text while nothing has data (once, on the
        // first plot: six copies of "Open a data set" down the Data tab read as six problems),
        // else its own.
        QString note;
        if (m_showingEmptyText) {
            note = i == 0 ? m_emptyText : QString();
        } else if (empty) {
            note = m_plotEmptyTexts[i].isEmpty() ? tr("No data yet") : m_plotEmptyTexts[i];
        }
        if (!note.isEmpty()) {
            QwtText text(note);
            text.setColor(QColor(110, 110, 110));
            QFont font = text.font();
            font.setPointSizeF(font.pointSizeF() * 1.1);
            text.setFont(font);
            text.setRenderFlags(Qt::AlignCenter | Qt::TextWordWrap);
            label->setText(text);
            if (label->plot() != plot) {
                label->attach(plot);
            }
        } else if (label->plot()) {
            label->detach();
        }
        // No made-up 0–1000 axes without data: the quantity's own range, or no axis at all.
        if (empty && ranged) {
            plot->setAxisScale(QwtPlot::yLeft, m_emptyRanges[i].first, m_emptyRanges[i].second);
        }
        plot->enableAxis(QwtPlot::yLeft, !empty || ranged);
        if (!hasData && xRanged) {
            plot->setAxisScale(QwtPlot::xBottom, m_emptyXRange.first, m_emptyXRange.second);
        }
        plot->enableAxis(QwtPlot::xBottom, (hasData || xRanged) && i + 1 == m_plots.size());
        plot->replot();
    }
}

QwtPlotCurve* PlotStack::addCurve(int index, const QString& name, const QVector<double>& x,
                                  const QVector<double>& y, const QColor& colour, Qt::PenStyle style,
                                  double width) {
    auto* plot = m_plots.at(static_cast<std::size_t>(index));
    auto* c = new QwtPlotCurve(name);
    showLineInLegend(*c);
    // Colours unique within a plot: a second named series in the same colour and line style
    // (two batches, two models mapped alike) takes the next free colour of the palette.
    QColor unique = colour;
    const auto taken = [&](const QColor& col) {
        for (auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
            const auto* other = static_cast<const QwtPlotCurve*>(item);
            if (other->dataSize() > 0 && !other->title().text().isEmpty() && other->title().text() != name &&
                other->pen().color() == col && other->pen().style() == style) {
                return true;
            }
        }
        return false;
    };
    for (int k = 0; !name.isEmpty() && taken(unique) && k < 20; ++k) {
        unique = seriesColour(k);
    }
    c->setPen(unique, width, style);
    // Long series: drop points that fall on the same pixel, clip to the canvas.
    c->setPaintAttribute(QwtPlotCurve::FilterPoints, true);
    c->setPaintAttribute(QwtPlotCurve::ClipPolygons, true);
    // Missing samples (NaN: a sensor dropout, a cell the cleaning rejected) are left out: Qwt maps
    // a NaN to a pixel far off the canvas and draws a fan of lines to it.
    bool allFinite = true;
    for (int i = 0; i < x.size() && i < y.size() && allFinite; ++i) {
        allFinite = std::isfinite(x[i]) && std::isfinite(y[i]);
    }
    if (allFinite) {
        c->setSamples(x, y);
    } else {
        QVector<double> fx, fy;
        fx.reserve(x.size());
        fy.reserve(y.size());
        for (int i = 0; i < x.size() && i < y.size(); ++i) {
            if (std::isfinite(x[i]) && std::isfinite(y[i])) {
                fx << x[i];
                fy << y[i];
            }
        }
        c->setSamples(fx, fy);
    }
    c->attach(plot);
    // One legend entry per name, on the top plot; curves elsewhere share it.
    bool named = false;
    for (auto* p : m_plots) {
        for (auto* other : p->itemList(QwtPlotItem::Rtti_PlotCurve)) {
            named = named || (other != c && other->title().text() == name &&
                              other->testItemAttribute(QwtPlotItem::Legend));
        }
    }
    c->setItemAttribute(QwtPlotItem::Legend, !named && !name.isEmpty());
    // The stack's own empty text sits on the first plot only: data on any plot takes it away.
    if (!x.isEmpty() && (m_showingEmptyText || !noteShown(index).isEmpty())) {
        updateEmptyText();
    }
    if (plot != m_plots.front() && !named && !name.isEmpty()) {
        // Its entry goes on the top plot's legend: a stand-in there, without data.
        auto* standIn = new QwtPlotCurve(name);
        standIn->setPen(c->pen());
        standIn->setStyle(c->style());
        showLineInLegend(*standIn);
        standIn->attach(m_plots.front());
        c->setItemAttribute(QwtPlotItem::Legend, false);
        m_plots.front()->updateLegend();
        if (auto* legend = qobject_cast<QwtLegend*>(m_plots.front()->legend())) {
            if (auto* label = qobject_cast<QwtLegendLabel*>(
                    legend->legendWidget(m_plots.front()->itemToInfo(standIn)))) {
                label->setChecked(true);
                compactLegendLabel(*label);
            }
        }
    }
    plot->updateLegend();
    if (auto* legend = qobject_cast<QwtLegend*>(plot->legend())) {
        if (auto* label = qobject_cast<QwtLegendLabel*>(legend->legendWidget(plot->itemToInfo(c)))) {
            label->setChecked(true);
            compactLegendLabel(*label);
        }
    }
    return c;
}

QwtPlotCurve* PlotStack::addDots(int index, const QString& name, const QVector<double>& x,
                                 const QVector<double>& y, const QColor& colour) {
    auto* c = addCurve(index, name, x, y, colour);
    c->setStyle(QwtPlotCurve::Dots);
    c->setPen(colour, 3.0);
    // Dots are keyed by a square of their colour (Qwt's default), not by a line they are not.
    c->setLegendAttribute(QwtPlotCurve::LegendShowLine, false);
    c->setLegendIconSize(QSize(8, 8));
    return c;
}

void PlotStack::clearCurves() {
    m_drawnXOffset.clear();
    for (auto* plot : m_plots) {
        plot->detachItems(QwtPlotItem::Rtti_PlotCurve, true);
        plot->updateLegend();
    }
    // A readout of the old curves would describe data no longer shown.
    for (auto& c : m_cursor) {
        c = kNaN;
    }
    for (auto& markers : m_cursorMarkers) {
        for (auto* m : markers) {
            m->setVisible(false);
        }
    }
    m_readout->setText(m_hintVisible ? hintText() : QString());
    updateEmptyText();
}

int PlotStack::curveCount(int index) const {
    int n = 0;
    for (const auto* item :
         m_plots.at(static_cast<std::size_t>(index))->itemList(QwtPlotItem::Rtti_PlotCurve)) {
        n += static_cast<const QwtPlotCurve*>(item)->dataSize() > 0 ? 1 : 0; // not the legend stand-ins
    }
    return n;
}

void PlotStack::rescale() {
    bool hasData = false;
    for (int i = 0; i < plotCount(); ++i) {
        hasData = hasData || curveCount(i) > 0;
    }
    m_linking = true;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        auto* plot = m_plots[i];
        // Autoscaling an axis without data gives Qwt's 0–1000: updateEmptyText() sets those.
        if (hasData) {
            plot->setAxisAutoScale(QwtPlot::xBottom, true);
        }
        if (curveCount(static_cast<int>(i)) > 0) {
            plot->setAxisAutoScale(QwtPlot::yLeft, true);
        }
    }
    updateEmptyText();
    QwtPlot* withData = nullptr;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        m_plots[i]->updateAxes();
        if (!withData && curveCount(static_cast<int>(i)) > 0) {
            withData = m_plots[i];
        }
    }
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        auto* plot = m_plots[i];
        // An empty plot shares the time axis of the plots with data (the bottom one labels it).
        if (withData && curveCount(static_cast<int>(i)) == 0) {
            const QwtScaleDiv div = withData->axisScaleDiv(QwtPlot::xBottom);
            plot->setAxisScale(QwtPlot::xBottom, div.lowerBound(), div.upperBound());
            plot->updateAxes();
        }
        plot->replot();
        m_zoomers[i]->setZoomBase(true);
    }
    m_linking = false;
    alignAxes();
}

void PlotStack::setXRange(double lo, double hi) {
    m_linking = true;
    for (auto* plot : m_plots) {
        plot->setAxisScale(QwtPlot::xBottom, lo, hi);
        plot->replot();
    }
    m_linking = false;
}

void PlotStack::setLogScale(int index, bool logX, bool logY) {
    auto* plot = m_plots.at(static_cast<std::size_t>(index));
    if (logX) {
        plot->setAxisScaleEngine(QwtPlot::xBottom, new QwtLogScaleEngine);
    }
    if (logY) {
        plot->setAxisScaleEngine(QwtPlot::yLeft, new QwtLogScaleEngine);
    }
}

void PlotStack::linkXFrom(QwtPlot* source) {
    if (m_linking) {
        return;
    }
    m_linking = true;
    const QwtScaleDiv div = source->axisScaleDiv(QwtPlot::xBottom);
    for (auto* plot : m_plots) {
        if (plot != source) {
            plot->setAxisScale(QwtPlot::xBottom, div.lowerBound(), div.upperBound());
            plot->replot();
        }
    }
    m_linking = false;
}

void PlotStack::alignAxes() {
    // Equal y-axis widths, so that the plot areas (and the time axes) line up.
    double extent = 0;
    for (auto* plot : m_plots) {
        auto* sw = plot->axisWidget(QwtPlot::yLeft);
        sw->scaleDraw()->setMinimumExtent(0);
        extent = std::max(extent, sw->scaleDraw()->extent(sw->font()));
    }
    for (auto* plot : m_plots) {
        plot->axisWidget(QwtPlot::yLeft)->scaleDraw()->setMinimumExtent(extent);
        plot->updateLayout();
        plot->replot();
    }
}

QString PlotStack::yTitle(int index) const {
    return plot(index)->property("drytwinYTitle").toString();
}

void PlotStack::fitYTitle(QwtPlot* plot) {
    const QString oneLine = plot->property("drytwinYTitle").toString();
    const int unitAt = oneLine.lastIndexOf(QStringLiteral(" ["));
    if (oneLine.isEmpty() || unitAt <= 0) {
        return;
    }
    QwtText title = plot->axisTitle(QwtPlot::yLeft);
    // The axis runs along the plot's height less the bottom axis and the legend: about the canvas.
    const int room = plot->canvas()->height() > 0 ? plot->canvas()->height() : plot->height();
    const bool fits = QFontMetrics(title.font()).horizontalAdvance(oneLine) <= room - 6;
    const QString wanted =
        fits ? oneLine : oneLine.left(unitAt) + QLatin1Char('\n') + oneLine.mid(unitAt + 1);
    if (title.text() != wanted) {
        title.setText(wanted);
        plot->setAxisTitle(QwtPlot::yLeft, title);
    }
}

void PlotStack::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // About one label per 90 pixels: "6,000" at 8 pt is 35 pixels wide, with room either side.
    const int ticks = std::clamp(width() / 90, 3, 10);
    for (auto* plot : m_plots) {
        if (plot->axisMaxMajor(QwtPlot::xBottom) != ticks) {
            plot->setAxisMaxMajor(QwtPlot::xBottom, ticks);
            plot->replot();
        }
    }
}

bool PlotStack::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize) {
        if (auto* plot = qobject_cast<QwtPlot*>(watched)) {
            // Once the plot has laid out its canvas for the new size (the filter sees the event first).
            QMetaObject::invokeMethod(
                this,
                [this, guarded = QPointer<QwtPlot>(plot)] {
                    if (guarded) {
                        fitYTitle(guarded);
                    }
                },
                Qt::QueuedConnection);
        }
    }
    if (event->type() == QEvent::MouseButtonPress) {
        auto* me = static_cast<QMouseEvent*>(event);
        const auto mods = me->modifiers();
        if (me->button() == Qt::LeftButton &&
            (mods & (Qt::ControlModifier | Qt::ShiftModifier | Qt::AltModifier))) {
            for (auto* plot : m_plots) {
                if (plot->canvas() == watched) {
                    const double x = plot->invTransform(QwtPlot::xBottom, me->pos().x());
                    if (mods & Qt::AltModifier) {
                        setTimeCursor(x);
                        Q_EMIT timeCursorMoved(x);
                    } else {
                        setMeasuringCursor((mods & Qt::ControlModifier) ? 0 : 1, x);
                    }
                    return true;
                }
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace drytwin::widgets
