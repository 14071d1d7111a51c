// The plot stack's export: the plots drawn as PNG, SVG or PDF, their data as CSV.
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

void PlotStack::paintStack(QPainter& painter, const QRectF& area) const {
    QwtPlotRenderer renderer;
    renderer.setDiscardFlag(QwtPlotRenderer::DiscardBackground, false);
    double total = 0;
    for (auto* plot : m_plots) {
        total += plot->height() > 0 ? plot->height() : 1;
    }
    double y = area.top();
    for (auto* plot : m_plots) {
        const double h = area.height() * (plot->height() > 0 ? plot->height() : 1) / total;
        renderer.render(plot, &painter, QRectF(area.left(), y, area.width(), h));
        y += h;
    }
}

QByteArray PlotStack::renderSvg(const QSize& size) const {
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(tr("DryTwin plots"));
    QPainter painter(&svg);
    paintStack(painter, QRectF(QPointF(0, 0), size));
    painter.end();
    return buffer.data();
}

QImage PlotStack::renderImage(const QSize& size, double scale) const {
    QImage image(size * scale, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.scale(scale, scale);
    paintStack(painter, QRectF(QPointF(0, 0), size));
    painter.end();
    return image;
}

bool PlotStack::exportTo(const QString& path, QString* error) const {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QSize size(std::max(width(), 800), std::max(height(), 200 * static_cast<int>(m_plots.size())));
    const auto fail = [&] {
        if (error) {
            *error = tr("cannot write %1").arg(path);
        }
        return false;
    };
    if (suffix == QLatin1String("png")) {
        return renderImage(size).save(path) || fail();
    }
    if (suffix == QLatin1String("svg")) {
        QFile f(path);
        return (f.open(QIODevice::WriteOnly) && f.write(renderSvg(size)) > 0) || fail();
    }
    if (suffix == QLatin1String("pdf")) {
        QPdfWriter pdf(path);
        pdf.setPageSize(QPageSize(QPageSize::A4));
        pdf.setPageOrientation(QPageLayout::Landscape);
        pdf.setResolution(96);
        QPainter painter(&pdf);
        if (!painter.isActive()) {
            return fail();
        }
        paintStack(painter, QRectF(QPointF(0, 0), QSizeF(pdf.width(), pdf.height())));
        return painter.end();
    }
    if (suffix == QLatin1String("csv")) {
        QSaveFile f(path);
        return (f.open(QIODevice::WriteOnly) && f.write(csvText().toUtf8()) >= 0 && f.commit()) || fail();
    }
    if (error) {
        *error = tr("unknown format '%1': use .png, .svg, .pdf or .csv").arg(suffix);
    }
    return false;
}

QString PlotStack::csvText() const {
    // Long format: every curve's points under its plot's axis title (with the unit) and its name,
    // so curves of different lengths and x grids sit in one file a spreadsheet can pivot.
    const auto quoted = [](QString s) {
        s.replace(QLatin1Char('"'), QStringLiteral("\"\""));
        return QStringLiteral("\"%1\"").arg(s);
    };
    QString out =
        QStringLiteral("plot,curve,%1,y\n")
            .arg(quoted(m_plots.empty() ? QString() : m_plots.back()->axisTitle(QwtPlot::xBottom).text()));
    for (auto* plot : m_plots) {
        const QString plotName = quoted(plot->property("drytwinYTitle").toString());
        for (const auto* item : plot->itemList(QwtPlotItem::Rtti_PlotCurve)) {
            const auto* c = static_cast<const QwtPlotCurve*>(item);
            const QString curveName = quoted(c->title().text());
            const auto offset = m_drawnXOffset.find(c);
            const double dx = offset == m_drawnXOffset.end() ? 0.0 : offset->second;
            for (std::size_t i = 0; i < c->dataSize(); ++i) {
                const QPointF p = c->sample(i);
                out += QStringLiteral("%1,%2,%3,%4\n")
                           .arg(plotName, curveName, QString::number(p.x() - dx, 'g', 10),
                                QString::number(p.y(), 'g', 10));
            }
        }
    }
    return out;
}

void PlotStack::exportDialog() {
    // The format is the one chosen in the dialog when the name has no extension ("foo" with "Data
    // as CSV" chosen is foo.csv), the extension's otherwise.
    const QString path =
        askSaveFile(this, tr("Export plots"), QStringLiteral("plots.png"),
                    tr("PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf);;Data as CSV (*.csv)"));
    if (path.isEmpty()) {
        return;
    }
    QString error;
    if (!exportTo(path, &error)) {
        m_readout->setText(tr("Export failed: %1").arg(error));
    } else {
        m_readout->setText(tr("Saved %1").arg(path));
    }
}

} // namespace drytwin::widgets
