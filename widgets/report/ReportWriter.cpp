#include "report/ReportWriter.h"
#include "io/MethodsGlossary.h"

#include "common/DisplayNames.h"

#include "common/LibraryVersions.h"
#include "common/PlotStack.h"
#include "common/Series.h"
#include "common/Units.h"
#include "common/WidgetHelpers.h"

#include <QBuffer>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLayout>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>
#include <QUrl>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_symbol.h>

namespace drytwin::widgets {

namespace {

/// A number as the report and its tests write it.
QString num(double v, int decimals = 4) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("–");
}

QString esc(const std::string& s) {
    return QString::fromStdString(s).toHtmlEscaped();
}

/// Figures in two forms: inline SVG for the HTML, PNG images for the PDF.
struct Figures {
    QString html;                                   ///< figure markup for the HTML (inline SVG)
    QString pdf;                                    ///< the same figure as an <img> for the PDF
    std::vector<std::pair<QString, QImage>> images; ///< for the PDF, added once its text is set
    int count = 0;

    void add(const PlotStack& stack, const QString& caption, QSize size = QSize(900, 0)) {
        if (size.height() == 0) {
            size.setHeight(230 * stack.plotCount() + 60);
        }
        ++count;
        const QString name = QStringLiteral("figure%1.png").arg(count);
        QString svg = QString::fromUtf8(stack.renderSvg(size));
        svg.remove(QRegExp(QStringLiteral("^<\\?xml[^>]*>")));
        const QString label = QStringLiteral("Figure %1. %2").arg(count).arg(caption.toHtmlEscaped());
        html = QStringLiteral("<figure>%1<figcaption>%2</figcaption></figure>\n").arg(svg, label);
        images.emplace_back(name, stack.renderImage(size, 1.5));
        pdf = QStringLiteral("<p><img src=\"%1\" width=\"640\"><br><i>%2</i></p>\n").arg(name, label);
    }
};

/// A plot stack laid out at report size, offscreen.
std::unique_ptr<PlotStack> stack(const QStringList& yTitles, const QString& xTitle) {
    auto s = std::make_unique<PlotStack>();
    for (const auto& t : yTitles) {
        s->addPlot(t);
    }
    s->setXTitle(xTitle);
    s->resize(900, 230 * static_cast<int>(yTitles.size()) + 60);
    s->layout()->activate();
    return s;
}

QString sha256(const std::string& path) {
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly)) {
        return QStringLiteral("(unreadable)");
    }
    QCryptographicHash h(QCryptographicHash::Sha256);
    h.addData(&f);
    return QString::fromLatin1(h.result().toHex());
}

/// A table's start with its header row, each column given its share of the page's width: left to
/// the PDF's layout (QTextDocument), every column took an equal share and broke words inside
/// ("extrapolati-on", "controlle-r", "no_lv_correcti-on"), names in the first column most.
QString tableHead(const std::vector<std::pair<QString, int>>& columns) {
    // In <thead>: the PDF repeats the header row on every page a table runs over.
    QString head =
        QStringLiteral("<table border=\"1\" cellpadding=\"3\" cellspacing=\"0\" width=\"100%\"><thead><tr>");
    for (const auto& [title, percent] : columns) {
        head += QStringLiteral("<th width=\"%1%\">%2</th>").arg(percent).arg(title);
    }
    return head + QStringLiteral("</tr></thead>");
}

} // namespace

Expected<QStringList> writeHtmlPdfReport(const workflow::PipelineResult& r,
                                         const std::vector<data::SiBatch>& batches,
                                         const ReportContext& context, const QString& folder) {
    QTextDocument pdfDoc;
    // Two bodies, one text: sections are appended to both, figures differ by form.
    QString html, pdf;
    const auto both = [&](const QString& s) {
        html += s;
        pdf += s;
    };
    Figures fig;
    const auto figure = [&](const PlotStack& s, const QString& caption, QSize size = QSize(900, 0)) {
        fig.add(s, caption, size);
        html += fig.html;
        pdf += fig.pdf;
    };

    both(QStringLiteral("<h1>DryTwin pipeline report</h1><p>%1</p>")
             .arg(QDateTime::currentDateTimeUtc().toString(Qt::ISODate)));

    // Data overview.
    const auto& in = r.inspect;
    both(QStringLiteral(
             "<h2>Data</h2><p>%1 batches, %2 rows, %3 missing cells; the cleaning rules of §IV.A keep "
             "%4 rows.</p>")
             .arg(in.batches.size())
             .arg(in.rows)
             .arg(in.missing)
             .arg(in.cleaning.kept));
    {
        auto s =
            stack({QStringLiteral("X_out [% wb]"), QStringLiteral("T_hot [°C]")}, QStringLiteral("time [s]"));
        for (std::size_t b = 0; b < batches.size(); ++b) {
            const QVector<double> t = timeOf(batches[b]);
            s->addCurve(0, QString::fromStdString(batches[b].id), t,
                        valuesOf(batches[b], batchSeries()[kSeriesXOut]), seriesColour(static_cast<int>(b)),
                        Qt::SolidLine, 0.8);
            s->addCurve(1, QString::fromStdString(batches[b].id), t, valuesOf(batches[b], batchSeries()[0]),
                        seriesColour(static_cast<int>(b)), Qt::SolidLine, 0.8);
        }
        s->rescale();
        figure(*s, QStringLiteral("Outlet moisture and hot-air temperature of every batch, overlaid."));
    }

    // Calibration.
    const auto& c = r.calibrate.calibration;
    both((QStringLiteral("<h2>Calibration</h2><p>%1, %2 evaluations; loss %3 → %4; MAE of the outlet "
                         "moisture %5 → %6 % wb, "
                         "of the outlet temperature %8 → %9 °C. Intervals: %7.</p>") +
          tableHead({{QStringLiteral("parameter"), 30},
                     {QStringLiteral("estimate"), 20},
                     {QStringLiteral("95 % interval"), 35},
                     {QStringLiteral("unit"), 15}}))
             .arg(QString::fromLatin1(terminationName(r.calibrate.ending.termination)))
             .arg(c.evaluations)
             .arg(num(c.before.loss, 5), num(c.after.loss, 5), num(c.before.maeXOutPct, 3),
                  num(c.after.maeXOutPct, 3))
             .arg(esc(c.intervalMethod))
             .arg(num(c.before.maeTOutC, 3), num(c.after.maeTOutC, 3)));
    for (const auto& e : c.estimates) {
        const auto& info = properties::info(e.param);
        both(QStringLiteral("<tr><td>%1</td><td>%2</td><td>[%3, %4]</td><td>%5</td></tr>")
                 .arg(fromView(info.symbol), QString::number(e.value, 'g', 6),
                      QString::number(e.ci95Low, 'g', 6), QString::number(e.ci95High, 'g', 6),
                      fromView(info.unit)));
    }
    both(QStringLiteral("</table>"));
    if (!c.history.empty()) {
        auto s = stack({QStringLiteral("best loss [-]")}, QStringLiteral("loss evaluations [-]"));
        QVector<double> x, y;
        for (const auto& h : c.history) {
            x << h.evaluation;
            y << h.bestLoss;
        }
        s->addCurve(0, QStringLiteral("best loss"), x, y, QColor(214, 39, 40));
        s->rescale();
        figure(*s, QStringLiteral("Calibration: best loss over the evaluations (CRS2-LM, then BOBYQA)."));
    }

    // Held-out metrics.
    const auto& ev = r.evaluate.evaluation;
    both((QStringLiteral(
              "<h2>Held-out accuracy</h2><p>Split %1, %2 test rows; skill = MAE over the better of the two "
              "reference predictors at the same horizon (below 1 beats both).</p>") +
          tableHead({{QStringLiteral("model"), 32},
                     {QStringLiteral("MAE X_out [% wb]"), 17},
                     {QStringLiteral("R² X_out"), 17},
                     {QStringLiteral("MAE T_out [°C]"), 17},
                     {QStringLiteral("skill, 1 step"), 17}}))
             .arg(esc(ev.split))
             .arg(ev.testRows));
    for (const auto& m : ev.models) {
        both(QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>")
                 .arg(modelDisplayName(m.name, false).toHtmlEscaped(), num(m.moisture.mae),
                      num(m.moisture.r2, 3), num(m.temperature.mae), num(m.skillMoisture, 3)));
    }
    both(QStringLiteral("</table>"));
    {
        auto s = stack({QStringLiteral("X_out error [% wb]")}, QStringLiteral("held-out row [-]"));
        std::size_t rowsDrawn = 0;
        for (const auto& m : ev.models) {
            if (m.name != "pbm" && m.name != "pgrl_cc") {
                continue;
            }
            QVector<double> x, y;
            for (std::size_t k = 0; k < m.moistureResidual.size() && k < 3000; ++k) {
                x << static_cast<double>(k);
                y << m.moistureResidual[k];
            }
            rowsDrawn = std::max(rowsDrawn, static_cast<std::size_t>(x.size()));
            s->addCurve(0, modelDisplayName(m.name, false), x, y, modelColour(m.name), Qt::SolidLine, 0.8);
        }
        s->rescale();
        figure(*s, QStringLiteral("Paper Fig. 3: the outlet-moisture error of the calibrated PBM and of the "
                                  "hybrid PGRL-CC one step ahead, %1 held-out rows%2.")
                       .arg(rowsDrawn)
                       .arg(rowsDrawn < ev.testRows ? QStringLiteral(" (the first of %1)").arg(ev.testRows)
                                                    : QString()));
    }
    {
        // Two figures, each on its own axis: a stack's plots share their x axis, and the PSD's
        // logarithmic frequency axis once drew the ACF's lags 0–40 s on 0.001–1.
        auto acfStack = stack({QStringLiteral("ACF [-]")}, QStringLiteral("lag [s]"));
        auto psdStack = stack({QStringLiteral("PSD [(% wb)²/Hz]")}, QStringLiteral("frequency [Hz]"));
        psdStack->setLogScale(0, true, true);
        for (const auto& m : r.evaluate.diagnostics.models) {
            if (m.name != "pbm" && m.name != "pgrl_cc") {
                continue;
            }
            QVector<double> lag, acf, f, p;
            for (std::size_t k = 0; k < m.acf.size(); ++k) {
                lag << static_cast<double>(k);
                acf << m.acf[k];
            }
            for (std::size_t k = 1; k < m.psdFrequencyHz.size(); ++k) {
                f << m.psdFrequencyHz[k];
                p << std::max(1e-12, m.psdDensity[k]);
            }
            acfStack->addCurve(0, modelDisplayName(m.name, false), lag, acf, modelColour(m.name));
            psdStack->addCurve(0, modelDisplayName(m.name, false), f, p, modelColour(m.name));
        }
        acfStack->rescale();
        psdStack->rescale();
        figure(
            *acfStack,
            QStringLiteral("Paper Fig. 4 (a): the outlet-moisture error's autocorrelation over lags 0–40 s, "
                           "before (PBM) and after (PGRL-CC)."));
        figure(*psdStack, QStringLiteral("Paper Fig. 4 (b): its Welch power spectral density, before (PBM) "
                                         "and after (PGRL-CC)."));
    }
    {
        auto s = stack({QStringLiteral("skill [-]")}, QStringLiteral("forecast horizon [steps of 1 s]"));
        s->setLogScale(0, true, false);
        for (const auto& m : ev.models) {
            QVector<double> h, k;
            for (std::size_t i = 0; i < ev.horizons.size() && i < m.skillMoistureByHorizon.size(); ++i) {
                h << ev.horizons[i];
                k << m.skillMoistureByHorizon[i];
            }
            s->addCurve(0, modelDisplayName(m.name, false), h, k, modelColour(m.name));
        }
        s->rescale();
        // The horizons evaluated, not the log axis's next decade (it ran to 1,000 for 180).
        if (!ev.horizons.empty()) {
            s->plot(0)->setAxisScale(QwtPlot::xBottom, 1, ev.horizons.back());
        }
        s->plot(0)->setAxisScale(QwtPlot::yLeft, 0, 2.5);
        s->plot(0)->replot(); // the renderer reads the scales replot computes
        figure(*s, QStringLiteral(
                       "The horizon curve: moisture skill of every predictor, 1 to %1 steps ahead (a "
                       "skill above 2.5 leaves the frame at the top: worse than the references by far).")
                       .arg(ev.horizons.empty() ? 0 : ev.horizons.back()));
    }
    const auto& d = r.evaluate.diagnostics;
    if (d.hasPgrlCcEigenvalues) {
        auto s = stack({QStringLiteral("imaginary part")}, QStringLiteral("real part"));
        QVector<double> cx, cy, ax, ay;
        for (int i = 0; i <= 180; ++i) {
            cx << std::cos(2 * M_PI * i / 180);
            cy << std::sin(2 * M_PI * i / 180);
        }
        for (const auto& l : d.pgrlCcAfter.eigenvalues) {
            ax << l.real();
            ay << l.imag();
        }
        s->addCurve(0, QStringLiteral("unit circle"), cx, cy, Qt::black, Qt::DotLine, 1.0);
        auto* dots =
            s->addDots(0, QStringLiteral("eigenvalues of A (ρ = %1)").arg(num(d.pgrlCcAfter.spectralRadius)),
                       ax, ay, QColor(31, 119, 180));
        dots->setStyle(QwtPlotCurve::NoCurve);
        dots->setSymbol(
            new QwtSymbol(QwtSymbol::Ellipse, QBrush(QColor(31, 119, 180)), Qt::NoPen, QSize(5, 5)));
        s->rescale();
        s->plot(0)->setAxisScale(QwtPlot::xBottom, -2.6, 2.6);
        s->plot(0)->setAxisScale(QwtPlot::yLeft, -1.1, 1.1);
        s->plot(0)->replot();
        double slowest = INFINITY;
        for (double rate : d.pgrlCcAfter.contractionRatePerStep) {
            slowest = std::min(slowest, rate);
        }
        figure(*s,
               QStringLiteral(
                   "Paper Fig. 6: eigenvalues of the PGRL-CC state matrix with the unit circle; the slowest "
                   "mode contracts by %1 per step (half-life %2 s).")
                   .arg(QString::number(slowest, 'g', 3), num(std::log(2.0) / slowest, 0)),
               QSize(900, 400));
    }

    // Ablation (Table 3).
    both((QStringLiteral(
              "<h2>Ablation (paper Table 3)</h2><p>Every variant, the full one included, is fitted "
              "again for this table on the same split with the settings the trained model chose, so "
              "the full row can differ from the held-out table's PGRL-CC in the last digits.</p>") +
          tableHead({{QStringLiteral("variant"), 35},
                     {QStringLiteral("MAE X_out [% wb]"), 13},
                     {QStringLiteral("R² X_out"), 12},
                     {QStringLiteral("MAE T_out [°C]"), 13},
                     {QStringLiteral("MAE X_out, %1 steps [% wb]"), 13},
                     {QStringLiteral("MAE X_out, extra\u00ADpolation [% wb]"), 14}}))
             .arg(r.ablation.multiStepHorizon));
    for (const auto& a : r.ablation.rows) {
        // The paper's words for each variant, its key below them (as in ablation.json).
        both(QStringLiteral("<tr><td>%1<br/><small>%7</small></td><td>%2</td><td>%3</td><td>%4</td><td>%5</"
                            "td><td>%6</td></tr>")
                 .arg(esc(a.description.empty() ? a.variant : a.description), num(a.maeMoisture),
                      num(a.r2Moisture, 3), num(a.maeTemperature), num(a.maeMoistureMultiStep),
                      num(a.regimeMaeMoisture), esc(a.variant)));
    }
    both(QStringLiteral("</table>"));

    // Discovery.
    const auto& disc = r.discover.discovery;
    both(QStringLiteral("<h2>Discovery</h2><p>Verdict: %1.</p>").arg(esc(disc.verdict)));
    for (const auto& f : disc.findings) {
        both(QStringLiteral("<p><b>%1</b> = %2 [%3, %4]: %5</p>")
                 .arg(esc(f.cause), QString::number(f.value, 'g', 4), QString::number(f.ci95Low, 'g', 4),
                      QString::number(f.ci95High, 'g', 4), esc(f.evidence)));
    }
    {
        auto s = stack({QStringLiteral("X_out error [% wb]")},
                       QStringLiteral("time, batches one after another [h]"));
        const auto series = [&](const std::vector<discovery::OutputResidual>& rs, const QString& name,
                                const QColor& col) {
            for (const auto& o : rs) {
                if (o.output != "X_out") {
                    continue;
                }
                QVector<double> x, y;
                residualSeriesInHours(o.seriesBatch, o.seriesTimeS, o.seriesValue, x, y);
                s->addDots(0, name, x, y, col);
            }
        };
        series(disc.residuals, QStringLiteral("starting model"), QColor(214, 39, 40));
        series(disc.residualsAfter, QStringLiteral("extended model"), QColor(31, 119, 180));
        s->rescale();
        figure(
            *s,
            disc.findings.empty()
                ? QStringLiteral("Discovery: the physics model's outlet-moisture error; no cause was named, "
                                 "so the extended model is the starting model and its dots cover the "
                                 "starting model's.")
                : QStringLiteral("Discovery: the physics model's outlet-moisture error before and after the "
                                 "named causes."));
    }

    // Closed loop (Table 2, Fig. 5).
    const auto& cl = r.mpc.closedLoop;
    both((QStringLiteral(
              "<h2>Closed-loop MPC (paper Table 2)</h2><p>Scenario %1 on DryTwin's virtual %4 plant (%5 "
              "instruments), %2 steps, band ±%6 % wb; plant gain %3 % wb/K. A fallback is a decision that "
              "kept the previous plan (the model saw no effect of the hot air, or the solve failed).</p>"
              "") +
          tableHead({{QStringLiteral("controller"), 25},
                     {QStringLiteral("IAE [% wb·s]"), 10},
                     {QStringLiteral("effort [K²]"), 11},
                     {QStringLiteral("violations [%]"), 16},
                     {QStringLiteral("solve median [ms]"), 12},
                     {QStringLiteral("believed gain [%/K]"), 14},
                     {QStringLiteral("fallbacks"), 12}}))
             .arg(esc(cl.scenario.name))
             .arg(cl.scenario.lengthS)
             .arg(num(cl.plantGainPctPerK))
             .arg(QString::fromLatin1(plant::plantKindName(cl.scenario.plant).data()),
                  QString::fromLatin1(cl.scenario.instrumentsName().data()))
             .arg(num(cl.scenario.bandPct, 2)));
    double piEffort = 0, mpcEffort = 0;
    QString mostEffort;
    for (const auto& run : cl.runs) {
        if (!run.ran) {
            continue;
        }
        const bool pi = run.kind == control::ControllerKind::Pi;
        if (pi) {
            piEffort = std::max(piEffort, run.metrics.effortK2);
        } else if (run.metrics.effortK2 > mpcEffort) {
            mpcEffort = run.metrics.effortK2;
            mostEffort = controllerDisplayName(run.kind, false);
        }
        both(QStringLiteral(
                 "<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td><td>%6</td><td>%7</td></tr>")
                 .arg(controllerDisplayName(run.kind, false).toHtmlEscaped(), num(run.metrics.iaePctS, 1),
                      num(run.metrics.effortK2, 1), num(run.metrics.violationPct, 1),
                      pi ? QStringLiteral("–") : num(run.metrics.solveMsMedian, 2),
                      pi ? QStringLiteral("–") : num(run.metrics.gainPctPerKMedian),
                      pi ? QStringLiteral("–")
                         : QStringLiteral("%1 of %2").arg(run.metrics.fallbacks).arg(run.metrics.decisions)));
    }
    both(QStringLiteral("</table>"));
    // A learnt controller that loses usually believes the wrong gain: say which, and what it does.
    for (const auto& run : cl.runs) {
        const auto ratio =
            !run.ran || run.kind == control::ControllerKind::Pi
                ? std::nullopt
                : control::mismatchedGainRatio(run.metrics.gainPctPerKMedian, cl.plantGainPctPerK);
        if (ratio) {
            both(QStringLiteral("<p><b>Gain:</b> %1: its model's gain is %2 times the plant's; %3.</p>")
                     .arg(controllerDisplayName(run.kind, false).toHtmlEscaped(), num(*ratio, 2),
                          QString::fromStdString(control::gainMismatchEffect(*ratio)).toHtmlEscaped()));
        }
    }
    // The ranking is on IAE, as the paper's Table 2; a controller that gets there by moving the
    // burner every decision must not read as the better one without a word (docs/mpc.md, Limits).
    if (piEffort > 0 && mpcEffort > 10 * piEffort) {
        both(QStringLiteral(
                 "<p><b>Effort:</b> the MPC on the %4 moved the hot-air setpoint %1 times as much "
                 "as the plant's PI loop (%2 against %3 K²): its setpoint chatters, which IAE alone "
                 "does not show; see the lower plot of the closed-loop figure below (paper Fig. 5).</p>")
                 .arg(num(mpcEffort / piEffort, 0), num(mpcEffort, 0), num(piEffort, 1),
                      mostEffort.toHtmlEscaped()));
    }
    {
        auto s = stack({QStringLiteral("X_out, true [% wb]"), QStringLiteral("T_hot setpoint [°C]")},
                       QStringLiteral("time [s]"));
        bool setpoint = false;
        for (const auto& run : cl.runs) {
            if (!run.ran || run.kind == control::ControllerKind::Lstm ||
                run.kind == control::ControllerKind::ExtInputResidual) {
                continue;
            }
            const QVector<double> t(run.timeS.begin(), run.timeS.end());
            if (!setpoint) {
                s->addCurve(0, QStringLiteral("setpoint"), t,
                            QVector<double>(run.setpointPct.begin(), run.setpointPct.end()), Qt::black,
                            Qt::DashLine);
                // The specification band around the setpoint, as the What-if tab draws it.
                QVector<double> low, high;
                for (double v : run.setpointPct) {
                    low << v - cl.scenario.bandPct;
                    high << v + cl.scenario.bandPct;
                }
                s->addCurve(0, QStringLiteral("band"), t, low, Qt::gray, Qt::DotLine);
                s->addCurve(0, QStringLiteral("band"), t, high, Qt::gray, Qt::DotLine);
                setpoint = true;
            }
            const QString name = controllerDisplayName(run.kind, false);
            s->addCurve(0, name, t, QVector<double>(run.xOutTruePct.begin(), run.xOutTruePct.end()),
                        modelColour(control::controllerName(run.kind)));
            s->addCurve(1, name, t, QVector<double>(run.hotAirSetpointC.begin(), run.hotAirSetpointC.end()),
                        modelColour(control::controllerName(run.kind)));
        }
        s->rescale();
        figure(*s, QStringLiteral(
                       "Paper Fig. 5: closed-loop outlet moisture and hot-air setpoint under the PGRL-CC "
                       "MPC, the PBM MPC and the plant's PI loop."));
    }

    // The methods behind the workbench's plain words, by their technical names (issue #72 item 10).
    both(QStringLiteral("<h2>Appendix: the methods behind the workbench's words</h2>") +
         tableHead({{QStringLiteral("on screen"), 30},
                    {QStringLiteral("tab"), 15},
                    {QStringLiteral("method"), 55}}));
    for (const auto& t : io::methodsGlossary()) {
        both(QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                 .arg(esc(t.onScreen), esc(t.where), esc(t.method)));
    }
    both(QStringLiteral("</table>"));

    // Reproducibility.
    both(QStringLiteral("<h2>Reproducibility</h2><p>Command: <code>%1</code></p><p>DryTwin %2; Qt %3")
             .arg(context.command.toHtmlEscaped(), QString::fromStdString(dryTwinVersion()),
                  QString::fromLatin1(qVersion())));
    for (const auto& [name, version] : engineLibraryVersions()) {
        both(QStringLiteral("; %1 %2").arg(esc(name), esc(version)));
    }
    both((QStringLiteral(".</p><p>Closed-loop scenario seed %1; every other random choice uses the options' "
                         "fixed seeds, so the same steps on the same files give the same numbers.%2</p>") +
          tableHead({{QStringLiteral("data file"), 45}, {QStringLiteral("SHA-256"), 55}}))
             .arg(cl.scenario.seed)
             .arg(context.resultsFile.isEmpty()
                      ? QString()
                      : QStringLiteral(
                            " This report re-draws results made earlier, which the project keeps in "
                            "<code>%1</code> (SHA-256 <code>%2</code>): the command above drew the "
                            "report, it did not make the numbers.")
                            .arg(context.resultsFile.toHtmlEscaped(),
                                 sha256(context.resultsFile.toStdString()))));
    for (const auto& f : context.dataFiles) {
        both(QStringLiteral("<tr><td>%1</td><td><code>%2</code></td></tr>").arg(esc(f), sha256(f)));
    }
    both(QStringLiteral("</table>"));

    const QString htmlPath = QDir(folder).filePath(QStringLiteral("report.html"));
    const QString pdfPath = QDir(folder).filePath(QStringLiteral("report.pdf"));
    QSaveFile out(htmlPath);
    const QByteArray page =
        QStringLiteral("<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>DryTwin report</title>"
                       "<style>body{font-family:sans-serif;max-width:1000px;margin:auto}table{"
                       "border-collapse:collapse}figure{margin:1em 0}figure "
                       "svg{max-width:100%;height:auto}figcaption{font-style:italic}"
                       "</style></head><body>%1</body></html>\n")
            .arg(html)
            .toUtf8();
    if (!out.open(QIODevice::WriteOnly) || out.write(page) < 0 || !out.commit()) {
        return Error{ErrorKind::BadInput, htmlPath.toStdString(),
                     "cannot write the report: " + out.errorString().toStdString()};
    }
    // The PDF: the same text with the figures as images, printed page by page.
    const QString pdfTemp = pdfPath + QStringLiteral(".part");
    {
        QPdfWriter writer(pdfTemp);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setResolution(110);
        writer.setTitle(QStringLiteral("DryTwin pipeline report"));
        // Tables a size below the text: seven columns of Table 2 at the text's size broke numbers
        // and words inside ("1464.-1", "fallbac-ks") on A4.
        pdfDoc.setDefaultStyleSheet(QStringLiteral("td, th { font-size: 8pt; } small { font-size: 7pt; }"));
        pdfDoc.setHtml(pdf); // clears resources: the images go in after it
        for (const auto& [name, image] : fig.images) {
            pdfDoc.addResource(QTextDocument::ImageResource, QUrl(name), image);
        }
        pdfDoc.print(&writer);
    }
    QFile::remove(pdfPath);
    if (!QFile::rename(pdfTemp, pdfPath)) {
        return Error{ErrorKind::BadInput, pdfPath.toStdString(), "cannot write the PDF report"};
    }
    return QStringList{htmlPath, pdfPath};
}

} // namespace drytwin::widgets
