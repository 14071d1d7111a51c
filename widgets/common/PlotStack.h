#pragma once

#include <QColor>
#include <QString>
#include <QVector>
#include <QWidget>
#include <map>
#include <vector>

class QLabel;
class QPainter;
class QImage;
class QVBoxLayout;
class QwtPlot;
class QwtPlotCurve;
class QwtPlotMarker;
class QwtPlotTextLabel;
class QwtPlotZoomer;

namespace drytwin::widgets {

/// @brief A column of Qwt plots on one linked time axis, as PlotJuggler and OMEdit users expect:
/// plot areas lined up, zoom (left drag, right click back) and pan (middle drag) on one plot
/// move them all, a picker readout, two measuring cursors (Ctrl+click: A, Shift+click: B) with a
/// delta readout, a shared time cursor (Alt+click, or setTimeCursor), legend items that toggle
/// curves, and export of the whole stack to PNG, SVG or PDF. Long series (63,000 samples) are
/// drawn with Qwt's point filtering, so redraws stay smooth.
class PlotStack : public QWidget {
    Q_OBJECT
public:
    explicit PlotStack(QWidget* parent = nullptr);

    /// @brief Appends a plot with a y-axis title (with its unit); returns its index.
    int addPlot(const QString& yTitle);
    int plotCount() const { return static_cast<int>(m_plots.size()); }
    QwtPlot* plot(int index) const { return m_plots.at(static_cast<std::size_t>(index)); }
    /// @brief The y-axis title of plot @p index as given to addPlot (on screen its unit may be on a
    /// second line where the plot is short).
    QString yTitle(int index) const;
    /// @brief The x-axis title of the bottom plot (default "time [s]").
    void setXTitle(const QString& title);
    /// @brief Adds a curve to plot @p index; returns it (owned by the plot).
    QwtPlotCurve* addCurve(int index, const QString& name, const QVector<double>& x, const QVector<double>& y,
                           const QColor& colour, Qt::PenStyle style = Qt::SolidLine, double width = 1.2);
    /// @brief Adds dots (scatter) instead of a line.
    QwtPlotCurve* addDots(int index, const QString& name, const QVector<double>& x, const QVector<double>& y,
                          const QColor& colour);
    /// @brief Removes every curve (keeps plots, grids and cursors).
    void clearCurves();
    /// @brief Number of curves in plot @p index.
    int curveCount(int index) const;
    /// @brief Rescales every plot to its data and redraws (call after adding curves).
    void rescale();
    /// @brief Moves the shared time cursor (drawn in every plot); NaN hides it.
    void setTimeCursor(double t);
    double timeCursor() const { return m_timeCursor; }
    /// @brief Places measuring cursor A (0) or B (1) at @p x, updating the readout.
    void setMeasuringCursor(int which, double x);
    /// @brief The readout under the plots ("A … B … Δ …").
    QString readout() const;
    /// @brief The whole stack drawn at @p size as SVG text (reports embed it inline).
    QByteArray renderSvg(const QSize& size) const;
    /// @brief The whole stack drawn at @p size (pixels, times @p scale for sharpness).
    QImage renderImage(const QSize& size, double scale = 2.0) const;
    /// @brief Writes the whole stack to @p path; the format follows the suffix (png, svg, pdf; csv:
    /// the plotted data, one row per point: plot, curve, x, y).
    bool exportTo(const QString& path, QString* error = nullptr) const;
    /// @brief @p curve is drawn @p dx to the right of its data (bars at one lag set side by side);
    /// the CSV export writes its data's own x. Forgotten with clearCurves().
    void setDrawnXOffset(const QwtPlotCurve* curve, double dx) { m_drawnXOffset[curve] = dx; }
    /// @brief Shows the x range [lo, hi] in every plot.
    void setXRange(double lo, double hi);
    /// @brief Log scale on the x and/or y axis of plot @p index (PSD plots).
    void setLogScale(int index, bool logX, bool logY);
    /// @brief What fills these plots, said in each plot while it has no data ("Run Calibrate to
    /// see the loss"); empty: nothing said.
    void setEmptyText(const QString& text);
    /// @brief What the empty plots say (setEmptyText()).
    QString emptyText() const { return m_emptyText; }
    /// @brief True while the empty text is shown (no curve with data in any plot).
    bool showsEmptyText() const;
    /// @brief The y range plot @p index shows while it has no data: its quantity's usual range
    /// (X_out 10–16 % wb), never Qwt's made-up 0–1000. Without one, an empty plot hides its y-axis
    /// and says so in words (the empty text, or plotEmptyText()).
    void setEmptyRange(int index, double lo, double hi);
    /// @brief The x range shown while no plot has data (without one, the x-axis is hidden then).
    void setEmptyXRange(double lo, double hi);
    /// @brief What plot @p index says while it has no data but another plot has ("The parameters'
    /// paths are drawn when the calibration ends"); default "No data yet".
    void setPlotEmptyText(int index, const QString& text);
    /// @brief The note plot @p index shows now (empty: none).
    QString noteShown(int index) const;
    /// @brief Shows or hides the mouse hint under the plots (one hint per tab is enough).
    void setHintVisible(bool visible);

Q_SIGNALS:
    void timeCursorMoved(double t);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    /// A narrow plot gets fewer time ticks, so that their labels ("6,000") never run together.
    void resizeEvent(QResizeEvent* event) override;
    /// The y-axis title on one line where the plot is tall enough, else its unit on a second line.
    void fitYTitle(QwtPlot* plot);

private:
    void linkXFrom(QwtPlot* source);
    void alignAxes();
    void updateReadout();
    void exportDialog();
    void paintStack(QPainter& painter, const QRectF& area) const;
    void updateEmptyText();
    QString hintText() const;
    QString csvText() const;

    QVBoxLayout* m_layout = nullptr;
    QLabel* m_readout = nullptr;
    std::vector<QwtPlot*> m_plots;
    std::map<const QwtPlotCurve*, double> m_drawnXOffset; ///< see setDrawnXOffset()
    std::vector<QwtPlotZoomer*> m_zoomers;
    std::vector<QwtPlotMarker*> m_timeMarkers;
    std::vector<QwtPlotMarker*> m_cursorMarkers[2];
    double m_cursor[2];
    double m_timeCursor;
    bool m_linking = false;
    bool m_alignQueued = false; ///< alignAxes() is due once the event loop is back
    bool m_hintVisible = true;
    QString m_emptyText;
    std::vector<QwtPlotTextLabel*> m_emptyLabels;
    std::vector<QString> m_plotEmptyTexts;
    std::vector<std::pair<double, double>> m_emptyRanges; ///< NaN: none
    std::pair<double, double> m_emptyXRange;              ///< NaN: none
    bool m_showingEmptyText = false;
    QString m_xTitle; ///< the time axis' title, kept when a plot is added below
};

} // namespace drytwin::widgets
