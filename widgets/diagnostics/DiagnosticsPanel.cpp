#include "diagnostics/DiagnosticsPanel.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/Series.h"
#include "common/Units.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>

namespace drytwin::widgets {

DiagnosticsPanel::DiagnosticsPanel(Workbench& workbench, QWidget* parent)
    : QWidget(parent), m_workbench(workbench) {
    m_models = new QListWidget;
    m_models->setMaximumWidth(240);
    auto* evaluate = new QPushButton(tr("Evaluate"));
    m_tests = new QLabel(tr("Evaluate a trained model to see its residuals."));
    m_tests->setWordWrap(true);
    m_acf = new PlotStack;
    m_acf->addPlot(tr("ACF [-]"));
    m_acf->setXTitle(tr("lag [s]"));
    m_psd = new PlotStack;
    m_psd->addPlot(tr("PSD [(% wb)²/Hz]"));
    m_psd->setXTitle(tr("frequency [Hz]"));
    m_psd->setLogScale(0, true, true);
    auto* left = new QWidget;
    auto* ll = new QVBoxLayout(left);
    ll->addWidget(evaluate);
    auto* shownLabel = new QLabel(tr("Models shown (tick to overlay):"));
    shownLabel->setWordWrap(true); // lines that do not wrap set the window's least width
    ll->addWidget(shownLabel);
    ll->addWidget(m_models, 1);
    ll->addWidget(m_tests);
    m_scatter = new PlotStack;
    m_scatter->addPlot(tr("error [% wb]"));
    m_operating = new QComboBox;
    for (const auto& series : batchSeries()) {
        if (!series.title.startsWith(QLatin1String("X_out")) &&
            !series.title.startsWith(QLatin1String("T_out")) &&
            !series.title.startsWith(QLatin1String("X_HDT"))) {
            m_operating->addItem(series.title);
        }
    }
    // Sensible empty axes until there is something to show (log axes would autoscale to 1e-100).
    m_acf->setXRange(0, 40);
    m_acf->plot(0)->setAxisScale(QwtPlot::yLeft, -0.5, 1.0);
    m_psd->setXRange(1e-3, 1.0);
    m_psd->plot(0)->setAxisScale(QwtPlot::yLeft, 1e-4, 1.0);
    auto* scatterBox = new QWidget;
    auto* sb = new QVBoxLayout(scatterBox);
    // The words above the choice, not beside it: side by side they held the window 1,026 px wide
    // at the least.
    sb->addWidget(new QLabel(tr("Physics model's error against")));
    sb->addWidget(m_operating);
    sb->addWidget(m_scatter, 1);
    m_ccf = new PlotStack;
    m_ccf->addPlot(tr("CCF [-]"));
    m_ccf->setXTitle(tr("lag of the input [s] (run Discover)"));
    m_ccf->setXRange(0, 300);
    auto* lower = new QSplitter;
    lower->addWidget(scatterBox);
    lower->addWidget(m_ccf);
    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(m_acf);
    right->addWidget(m_psd);
    right->addWidget(lower);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);
    connect(evaluate, &QPushButton::clicked, &m_workbench, &Workbench::evaluate);
    connect(&m_workbench, &Workbench::evaluated, this, &DiagnosticsPanel::fill);
    connect(m_models, &QListWidget::itemChanged, this, &DiagnosticsPanel::redraw);
    connect(&m_workbench, &Workbench::simulated, this, &DiagnosticsPanel::redrawScatter);
    connect(m_operating, &QComboBox::currentTextChanged, this, &DiagnosticsPanel::redrawScatter);
    connect(&m_workbench, &Workbench::discovered, this, &DiagnosticsPanel::redrawCrossCorrelation);
    // New data, or results put back from a project: show exactly what latest() holds.
    for (auto signal : {&Workbench::dataChanged, &Workbench::resultsRestored}) {
        connect(&m_workbench, signal, this, [this] {
            fill();
            redrawCrossCorrelation();
        });
    }
    m_workbench.bindButton(evaluate, Action::Evaluate);
    m_acf->setEmptyText(
        tr("Learn the correction models (Residual model tab) to see the residuals' autocorrelation"));
    m_psd->setEmptyText(tr("… and their spectrum"));
    m_scatter->setEmptyText(tr("Open data to see where in the operating range the physics model errs"));
    m_ccf->setEmptyText(tr("Run Discover to see what the error moves with"));
    m_psd->setHintVisible(false);
    m_scatter->setHintVisible(false);
    m_ccf->setHintVisible(false);
}

void DiagnosticsPanel::fill() {
    const auto& ev = m_workbench.latest().evaluate;
    if (!ev) {
        m_models->clear();
        m_acf->clearCurves();
        m_psd->clearCurves();
        m_acf->rescale();
        m_psd->rescale();
        m_tests->setText(tr("Evaluate a trained model to see its residuals."));
        return;
    }
    m_models->blockSignals(true);
    m_models->clear();
    for (const auto& m : ev->diagnostics.models) {
        auto* item = new QListWidgetItem(modelDisplayName(m.name), m_models);
        item->setData(Qt::UserRole, modelDisplayName(m.name));
        item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
        item->setCheckState(m.name == "pbm" || m.name == "pgrl_cc" ? Qt::Checked : Qt::Unchecked);
    }
    m_models->blockSignals(false);
    QStringList lines;
    for (const auto& m : ev->evaluation.models) {
        double mean = 0;
        for (double r : m.moistureResidual) {
            mean += r / static_cast<double>(std::max<std::size_t>(1, m.moistureResidual.size()));
        }
        lines << tr("%1: Ljung-Box p %2, residual mean %3 % wb")
                     .arg(modelDisplayName(m.name))
                     // A p below what a double resolves prints as 0, which reads as "exactly zero".
                     .arg(m.moisture.ljungBoxP < 1e-15 ? QStringLiteral("< 1e-15")
                                                       : QString::number(m.moisture.ljungBoxP, 'g', 3))
                     .arg(mean, 0, 'f', 4);
    }
    // The test by name, with what its p says in plain words on the line beside it.
    lines << tr("Ljung-Box p: the chance that errors this patterned come from pure noise; below 0.05 a "
                "pattern is left that a model could still learn.");
    m_tests->setText(lines.join(QLatin1Char('\n')));
    redraw();
}

void DiagnosticsPanel::redraw() {
    const auto& ev = m_workbench.latest().evaluate;
    if (!ev) {
        return;
    }
    m_acf->clearCurves();
    m_psd->clearCurves();
    const double band = 1.96 / std::sqrt(std::max<double>(1.0, static_cast<double>(ev->evaluation.testRows)));
    for (std::size_t i = 0; i < ev->diagnostics.models.size(); ++i) {
        const auto& m = ev->diagnostics.models[i];
        const auto* item = m_models->item(static_cast<int>(i));
        if (!item || item->checkState() != Qt::Checked) {
            continue;
        }
        QVector<double> lag, acf;
        for (std::size_t k = 0; k < m.acf.size(); ++k) {
            lag << static_cast<double>(k);
            acf << m.acf[k];
        }
        m_acf->addCurve(0, modelDisplayName(m.name), lag, acf, modelColour(m.name), Qt::SolidLine, 1.6);
        if (m.hasPsd) {
            QVector<double> f, p;
            for (std::size_t k = 1; k < m.psdFrequencyHz.size(); ++k) { // k = 0 is f = 0 (log axis)
                f << m.psdFrequencyHz[k];
                p << std::max(1e-12, m.psdDensity[k]);
            }
            m_psd->addCurve(0,
                            tr("%1 (%2 % below 0.01 Hz)")
                                .arg(modelDisplayName(m.name))
                                .arg(100 * m.lowFrequencyShareBelow0p01Hz, 0, 'f', 0),
                            f, p, modelColour(m.name));
        }
    }
    m_acf->addCurve(0, tr("95 % band of white noise"), {0, 40}, {band, band}, Qt::black, Qt::DotLine, 1.0);
    m_acf->addCurve(0, QString(), {0, 40}, {-band, -band}, Qt::black, Qt::DotLine, 1.0);
    m_acf->rescale();
    m_psd->rescale();
}

} // namespace drytwin::widgets

namespace drytwin::widgets {

void DiagnosticsPanel::redrawScatter() {
    // Where in the operating range does the physics model err? Every 10th kept row of every
    // batch: the measured outlet moisture minus the simulated one, against the chosen input.
    const auto& sim = m_workbench.latest().simulate;
    const auto& si = m_workbench.siBatches();
    m_scatter->clearCurves();
    const auto all = batchSeries(); // kept: chosen points into it
    const SeriesInfo* chosen = nullptr;
    for (const auto& series : all) {
        if (series.title == m_operating->currentText()) {
            chosen = &series;
        }
    }
    if (!sim || !chosen) {
        return;
    }
    QVector<double> x, y;
    for (std::size_t b = 0; b < si.size() && b < sim->simulations.size(); ++b) {
        const auto& batch = si[b];
        const auto& r = sim->simulations[b];
        for (std::size_t k = 0; k < batch.rows() && k < r.xOutDb.size(); k += 10) {
            if (!batch.keep[k]) {
                continue;
            }
            const double e = units::dryToWetPct(batch.xOutDb[k]) - units::dryToWetPct(r.xOutDb[k]);
            if (std::isfinite(e)) {
                x << chosen->value(batch, k);
                y << e;
            }
        }
    }
    m_scatter->addDots(0, tr("every 10th kept row"), x, y, QColor(31, 119, 180));
    m_scatter->setXTitle(chosen->title);
    m_scatter->rescale();
}

} // namespace drytwin::widgets

namespace drytwin::widgets {

void DiagnosticsPanel::redrawCrossCorrelation() {
    // The cross-correlations of the physics model's differenced outlet-moisture error with the
    // differenced inputs and proxies that discovery found strongest, at their lags.
    const auto& d = m_workbench.latest().discover;
    m_ccf->clearCurves();
    if (!d) {
        return;
    }
    // Lags are 0–300 s: from 0, and wide enough to read when every correlate sits at one lag.
    double longest = 0;
    for (const auto& o : d->discovery.residuals) {
        for (const auto& c : o.correlates) {
            longest = o.output == "X_out" ? std::max(longest, c.lagS) : longest;
        }
    }
    const double xMax = std::max(60.0, 1.1 * longest);
    // Bars at the same lag side by side, not one hidden behind the other (a model's tube-outlet
    // moisture and its moisture on the conveyor both at 0 s): the group centred on its lag, each
    // a bar's width apart; the CSV export writes the lag itself.
    std::map<double, int> countAtLag, drawnAtLag;
    for (const auto& o : d->discovery.residuals) {
        for (const auto& c : o.correlates) {
            countAtLag[c.lagS] += o.output == "X_out" ? 1 : 0;
        }
    }
    const double barWidth = 0.012 * (xMax + 5);
    int i = 0;
    for (const auto& o : d->discovery.residuals) {
        if (o.output != "X_out") {
            continue;
        }
        for (const auto& c : o.correlates) {
            const double dx = barWidth * (drawnAtLag[c.lagS]++ - 0.5 * (countAtLag[c.lagS] - 1));
            const double x = c.lagS + dx;
            auto* curve = m_ccf->addCurve(0, columnDisplayName(c.column), {x, x}, {0.0, c.ccf},
                                          seriesColour(i++), Qt::SolidLine, 4.0);
            curve->setStyle(QwtPlotCurve::Lines);
            m_ccf->setDrawnXOffset(curve, dx);
        }
    }
    m_ccf->setXTitle(tr("lag of the input [s]; the outlet-moisture error's correlation with each input"));
    m_ccf->rescale();
    m_ccf->setXRange(-5, xMax);
}

} // namespace drytwin::widgets
