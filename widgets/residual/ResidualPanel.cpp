#include "residual/ResidualPanel.h"

#include <map>

#include "common/DisplayNames.h"
#include "common/EqualAspect.h"
#include "common/ModelStateBar.h"
#include "common/PlotStack.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_symbol.h>

namespace drytwin::widgets {

ResidualPanel::ResidualPanel(Workbench& workbench, QWidget* parent)
    : QWidget(parent), m_workbench(workbench) {
    m_lags = new QComboBox;
    m_lags->addItems({tr("chosen by validation (16, 32, 60)"), QStringLiteral("8"), QStringLiteral("16"),
                      QStringLiteral("32"), QStringLiteral("60")});
    m_stability = new QComboBox;
    m_stability->addItems({tr("guaranteed stable (fit under a stability certificate)"),
                           tr("stabilised after the fit (eigenvalues pulled in)")});
    m_stability->setToolTip(tr("Paper Eq. 30: the correction model's state matrix A is fitted under the "
                               "constraint α²P − AᵀPA ≻ 0 with a certificate P; the alternative pulls A's "
                               "eigenvalues inside the unit circle after an unconstrained fit."));
    m_projection = new QCheckBox(tr("keep the correction out of the hot-air direction"));
    m_projection->setToolTip(tr("Paper Eq. 27: the orthogonal projection P⊥ removes from the correction what "
                                "the manipulated input explains, so that the control gain stays the physics "
                                "model's."));
    m_projection->setChecked(true);
    auto* train = new QPushButton(tr("Learn the correction models"));
    train->setToolTip(tr("Trains PGRL-CC (paper Eqs. 20–30) on the chronological 70 % of the data, and the "
                         "two models it is compared with: the input-only correction and an LSTM"));
    m_workbench.bindButton(train, Action::Train);
    m_lags->setToolTip(
        tr("How many past seconds of the error the correction model sees (paper: residual lags)"));
    auto* form = new QFormLayout;
    form->addRow(tr("memory of the error [s]"), m_lags);
    form->addRow(tr("stability"), m_stability);
    form->addRow(QString(), m_projection);
    form->addRow(QString(), train);
    m_note = new QLabel(
        tr("Trains on the chronological 70 % and evaluates on the rest; settings are chosen inside "
           "the training part."));
    m_note->setWordWrap(true);
    m_gains = new QLabel(tr("Run a What-if MPC scenario to compare each model's steady gain of X_out to the "
                            "hot air with the plant's."));
    m_gains->setWordWrap(true);
    m_metrics = makeResultTable({tr("Model"), tr("MAE X_out\n[% wb]"), tr("R² X_out\n[-]"),
                                 tr("MAE T_out\n[°C]"), tr("skill\n1 step"), tr("skill\n30 steps")});
    setHeaderToolTips(m_metrics,
                      {QString(), tr("Mean absolute error of the outlet moisture on the held-out part."),
                       tr("R²: the share of the outlet moisture's variation the model explains (1: all; "
                          "below 0: worse than the mean)."),
                       tr("Mean absolute error of the outlet temperature on the held-out part."),
                       tr("Skill one second ahead: the model's error over the better of two simple "
                          "forecasts; below 1 it beats both."),
                       tr("Skill 30 seconds ahead, alike.")});
    m_state = new ModelStateBar(m_workbench);
    m_eigen = new PlotStack;
    m_eigen->addPlot(tr("imaginary part"));
    m_eigen->setXTitle(tr("real part"));
    m_skill = new PlotStack;
    m_skill->addPlot(tr("skill [-]"));
    m_skill->plot(0)->setToolTip(tr("Skill: a model's MAE over the better of the two reference forecasts at "
                                    "that horizon; below 1 it beats both"));
    m_skill->setXTitle(tr("forecast horizon [steps of 1 s]"));
    m_skill->setLogScale(0, true, false);

    auto* runAblation = new QPushButton(tr("Ablation (paper Table 3)"));
    runAblation->setToolTip(tr("Train and evaluate every variant of Table 3 on this model (a few minutes)"));
    m_workbench.bindButton(runAblation, Action::Ablation);
    m_ablation = makeResultTable({tr("Variant"), tr("MAE X_out\n[% wb]"), tr("R² X_out\n[-]"),
                                  tr("MAE T_out\n[°C]"), tr("MAE X_out,\nextrapolation")});
    setDefaultEmptyTexts();
    m_eigen->setHintVisible(false);
    // Sensible empty axes until a model is evaluated (a log axis would autoscale to 1e-100).
    keepEqualAspect(m_eigen->plot(0), 1.15);
    m_skill->plot(0)->setAxisScale(QwtPlot::xBottom, 1, 200);
    m_skill->plot(0)->setAxisScale(QwtPlot::yLeft, 0, 2.5);
    auto* left = new QWidget;
    auto* ll = new QVBoxLayout(left);
    ll->addWidget(m_state);
    ll->addLayout(form);
    ll->addWidget(m_note);
    // The held-out table and the ablation each on a tab of the whole height: stacked, at 1280 x 800
    // each showed 3½ rows, the PGRL-CC row and most variants below the fold (a newcomer's review).
    auto* heldOut = new QWidget;
    auto* hl = new QVBoxLayout(heldOut);
    hl->setContentsMargins(0, 0, 0, 0);
    hl->addWidget(m_metrics, 1);
    hl->addWidget(m_gains);
    fitTableHeight(m_metrics, 6); // the four models and the two reference predictors
    auto* ablation = new QWidget;
    auto* al = new QVBoxLayout(ablation);
    al->setContentsMargins(0, 0, 0, 0);
    al->addWidget(runAblation);
    al->addWidget(m_ablation, 1);
    m_tables = new QTabWidget;
    m_tables->addTab(heldOut, tr("Held-out accuracy"));
    m_tables->addTab(ablation, tr("Ablation (paper Table 3)"));
    ll->addWidget(m_tables, 1);
    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(m_eigen);
    right->addWidget(m_skill);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    split->setSizes({640, 640}); // the held-out table's columns whole, the plots beside them
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);
    connect(train, &QPushButton::clicked, this, &ResidualPanel::train);
    connect(&m_workbench, &Workbench::evaluated, this, &ResidualPanel::showEvaluation);
    connect(&m_workbench, &Workbench::trained, this, [this] {
        m_learning = Learning::Scoring;
        showLearningState();
    });
    connect(&m_workbench, &Workbench::evaluated, this, [this] {
        if (m_learning == Learning::Scoring) {
            m_learning = Learning::Idle;
            setDefaultEmptyTexts();
        }
    });
    // A job ahead of the training or of its scoring ends, or another is queued: say it again.
    connect(&m_workbench, &Workbench::runningChanged, this, &ResidualPanel::showLearningState);
    connect(&m_workbench.jobs(), &JobRunner::started, this, &ResidualPanel::showLearningState);
    // Results of another data set or model are not shown as these.
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        showEvaluation();
        showAblation();
    });
    connect(runAblation, &QPushButton::clicked, &m_workbench, &Workbench::ablation);
    connect(&m_workbench, &Workbench::ablationFinished, this, &ResidualPanel::showAblation);
    // A finished ablation is what the user waited for: its tab comes to the front.
    connect(&m_workbench, &Workbench::ablationFinished, this, [this] { m_tables->setCurrentIndex(1); });
    connect(&m_workbench, &Workbench::mpcFinished, this, &ResidualPanel::showGains);
    // The note follows a cancel or a failure of the training it announced.
    connect(&m_workbench, &Workbench::failed, this,
            [this](const QString& action, const QString& message, bool) {
                if (action == Workbench::tr("Learn the correction models") ||
                    action == Workbench::tr("Ablation") ||
                    (action == Workbench::tr("Evaluate") && m_learning == Learning::Scoring)) {
                    m_learning = Learning::Idle;
                    setDefaultEmptyTexts();
                    m_note->setText(message);
                }
            });
    connect(&m_workbench, &Workbench::resultsRestored, this, [this] {
        showEvaluation();
        showAblation();
        showGains();
    });
}

QString ResidualPanel::gainsText(const control::ClosedLoopResult& result) {
    const double plant = result.plantGainPctPerK;
    QStringList parts;
    for (const auto& run : result.runs) {
        if (!run.ran || run.kind == control::ControllerKind::Pi || run.metrics.decisions == 0) {
            continue;
        }
        const double g = run.metrics.gainPctPerKMedian;
        const double off = plant != 0 ? 100.0 * (g / plant - 1.0) : 0.0;
        // Rounded first: -0.3 % printed as "-0 %".
        const double offRounded = std::round(off) == 0 ? 0.0 : std::round(off);
        parts << tr("%1 %2 (%3 %)")
                     .arg(controllerDisplayName(run.kind))
                     .arg(g, 0, 'f', 4)
                     .arg(offRounded > 0    ? QStringLiteral("+%1").arg(offRounded, 0, 'f', 0)
                          : offRounded == 0 ? QStringLiteral("±0")
                                            : QString::number(offRounded, 'f', 0));
    }
    return tr("Steady gain of X_out to the hot-air setpoint [% wb per K] at the scenario's start: the plant "
              "(open-loop step test) %1; each model as its MPC saw it, and how far from the plant's: %2. A "
              "learnt residual's response to the setpoint plan comes from the physics model, since data "
              "under the plant's own loop cannot tell it from the disturbances the loop answered.")
        .arg(plant, 0, 'f', 4)
        .arg(parts.join(QStringLiteral("; ")));
}

void ResidualPanel::showGains() {
    const auto& m = m_workbench.latest().mpc;
    if (m) {
        m_gains->setText(gainsText(m->closedLoop));
    }
}

void ResidualPanel::train() {
    workflow::TrainOptions o;
    if (m_lags->currentIndex() > 0) {
        o.selection.enabled = false;
        o.residual.residualLags = m_lags->currentText().toInt();
    }
    o.residual.orthogonalProjection = m_projection->isChecked();
    o.residual.stabilityMethod = m_stability->currentIndex() == 0 ? residual::StabilityMethod::Constrained
                                                                  : residual::StabilityMethod::EigenvaluePull;
    if (m_quick) {
        o.lstm.epochs = 2;
        o.lstm.hidden = 8;
        o.selection.lags = {4, 8};
    }
    m_workbench.train(o);
    m_learning = Learning::Training;
    showLearningState();
}

void ResidualPanel::setDefaultEmptyTexts() {
    m_eigen->setEmptyText(tr("Learn the correction models to see the eigenvalues of their state matrix"));
    m_skill->setEmptyText(tr("Learn the correction models to see their skill by forecast horizon"));
}

void ResidualPanel::showLearningState() {
    if (m_learning == Learning::Training) {
        const QString queued = m_workbench.queuedText(Action::Train);
        m_note->setText(queued.isEmpty() ? tr("Training…") : queued);
    } else if (m_learning == Learning::Scoring) {
        const QString queued = m_workbench.queuedText(Action::Evaluate);
        m_note->setText(queued.isEmpty()
                            ? tr("Learnt. Scoring the models on the held-out part…")
                            : tr("Learnt. Their scores on the held-out part come next: %1.").arg(queued));
        // The plots say the same: the models exist, their scores (and these plots) are on the way.
        m_eigen->setEmptyText(tr("Learnt: the eigenvalues are drawn once the models are scored on the "
                                 "held-out part"));
        m_skill->setEmptyText(tr("Learnt: the skill curves are drawn once the models are scored on the "
                                 "held-out part"));
    }
}

void ResidualPanel::showEvaluation() {
    const auto& ev = m_workbench.latest().evaluate;
    if (!ev) {
        m_metrics->setRowCount(0);
        m_skill->clearCurves();
        m_eigen->clearCurves();
        m_skill->rescale();
        m_eigen->rescale();
        m_note->setText(
            m_workbench.hasData()
                ? tr("Learn the correction models on %1: they train on the chronological 70 % "
                     "and are scored on the rest.")
                      .arg(m_workbench.dataSetLabel())
                : tr("Open a data set first (File ▸ Open data set folder…, or the bundled demo)."));
        return;
    }
    const auto& e = ev->evaluation;
    m_metrics->setRowCount(static_cast<int>(e.models.size()));
    std::size_t h30 = 0;
    for (std::size_t i = 0; i < e.horizons.size(); ++i) {
        if (e.horizons[i] == 30) {
            h30 = i;
        }
    }
    m_skill->clearCurves();
    for (std::size_t i = 0; i < e.models.size(); ++i) {
        const auto& m = e.models[i];
        const double s30 = h30 < m.skillMoistureByHorizon.size() ? m.skillMoistureByHorizon[h30] : NAN;
        const QStringList cells{modelDisplayName(m.name),
                                QString::number(m.moisture.mae, 'f', 4),
                                QString::number(m.moisture.r2, 'f', 3),
                                QString::number(m.temperature.mae, 'f', 4),
                                QString::number(m.skillMoisture, 'f', 3),
                                QString::number(s30, 'f', 3)};
        setTableRow(m_metrics, static_cast<int>(i), cells);
        m_metrics->item(static_cast<int>(i), 0)
            ->setToolTip(tr("Key: %1").arg(QString::fromStdString(m.name)));
        m_metrics->item(static_cast<int>(i), 2)->setToolTip(r2Explanation(m.moisture.r2));
        QVector<double> h, s;
        for (std::size_t k = 0; k < e.horizons.size() && k < m.skillMoistureByHorizon.size(); ++k) {
            h << e.horizons[k];
            s << m.skillMoistureByHorizon[k];
        }
        const bool reference = m.name == "persistence" || m.name == "pbm_residual_hold";
        m_skill->addCurve(0, modelDisplayName(m.name), h, s, modelColour(m.name),
                          reference ? Qt::DashLine : Qt::SolidLine, m.name == "pgrl_cc" ? 2.2 : 1.3);
    }
    fitTableWidth(m_metrics);
    m_skill->addCurve(0, tr("skill 1 (ties the better reference)"), {1, 180}, {1, 1}, Qt::black, Qt::DotLine,
                      1.0);
    m_skill->rescale();

    m_eigen->clearCurves();
    QVector<double> cx, cy;
    for (int i = 0; i <= 180; ++i) {
        cx << std::cos(2 * M_PI * i / 180);
        cy << std::sin(2 * M_PI * i / 180);
    }
    m_eigen->addCurve(0, tr("unit circle"), cx, cy, Qt::black, Qt::DotLine, 1.0);
    const auto& d = ev->diagnostics;
    if (d.hasPgrlCcEigenvalues) {
        QVector<double> bx, by, ax, ay;
        for (const auto& l : d.pgrlCcBefore.eigenvalues) {
            bx << l.real();
            by << l.imag();
        }
        for (const auto& l : d.pgrlCcAfter.eigenvalues) {
            ax << l.real();
            ay << l.imag();
        }
        // Open rings before, filled dots after: where the constraint moved nothing they nest.
        auto* before =
            m_eigen->addDots(0, tr("A unconstrained (ρ = %1)").arg(d.pgrlCcBefore.spectralRadius, 0, 'f', 4),
                             bx, by, QColor(255, 127, 14));
        before->setStyle(QwtPlotCurve::NoCurve);
        before->setSymbol(
            new QwtSymbol(QwtSymbol::Ellipse, Qt::NoBrush, QPen(QColor(255, 127, 14), 1.3), QSize(9, 9)));
        before->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true); // the ring, as drawn
        auto* after =
            m_eigen->addDots(0, tr("A with Eq. 30 (ρ = %1)").arg(d.pgrlCcAfter.spectralRadius, 0, 'f', 4), ax,
                             ay, QColor(31, 119, 180));
        after->setStyle(QwtPlotCurve::NoCurve);
        after->setSymbol(
            new QwtSymbol(QwtSymbol::Ellipse, QBrush(QColor(31, 119, 180)), Qt::NoPen, QSize(4, 4)));
        after->setLegendAttribute(QwtPlotCurve::LegendShowSymbol, true); // the dot, as drawn
    }
    m_eigen->rescale();
    // The rescaler keeps one unit the same length on both axes at any size of the plot, so the
    // unit circle stays a circle; the view holds the circle and every eigenvalue.
    double radius = 1.15;
    for (const auto* set : {&d.pgrlCcBefore.eigenvalues, &d.pgrlCcAfter.eigenvalues}) {
        for (const auto& l : *set) {
            radius = std::max(radius, 1.1 * std::abs(l));
        }
    }
    keepEqualAspect(m_eigen->plot(0), radius);
    // The curves start at 1 step; the open-loop PBM's skill (about 10) would flatten the rest, so
    // the axis reaches the highest of the other curves (the last measurement held climbs past 2.5
    // at long horizons and left the plot), up to 5.
    double highest = 2.0;
    for (const auto& m : ev->evaluation.models) {
        if (m.name != "pbm") {
            for (double v : m.skillMoistureByHorizon) {
                highest = std::isfinite(v) ? std::max(highest, v) : highest;
            }
        }
    }
    m_skill->plot(0)->setAxisScale(QwtPlot::xBottom, 1, 200);
    m_skill->plot(0)->setAxisScale(QwtPlot::yLeft, 0, std::min(5.0, 1.05 * highest));
    m_skill->plot(0)->replot();
    QString rates;
    if (d.hasPgrlCcEigenvalues && !d.pgrlCcAfter.contractionRatePerStep.empty()) {
        // The slowest mode decides how long a disturbance of the residual lingers.
        double slowest = d.pgrlCcAfter.contractionRatePerStep.front();
        for (double r : d.pgrlCcAfter.contractionRatePerStep) {
            slowest = std::min(slowest, r);
        }
        rates = tr(" Slowest contraction of A: %1 per step (half-life %2 s).")
                    .arg(slowest, 0, 'g', 3)
                    .arg(slowest > 0 ? std::log(2.0) / slowest : INFINITY, 0, 'f', 0);
    }
    m_note->setText(
        tr("On %1, held-out part: %2 rows. Skill below 1 beats both reference predictors (the last "
           "measurement held, and the physics model with its last error held). R² below 0 means "
           "a model predicts worse than the batch's mean (hover an R² for what it says).")
            .arg(m_workbench.dataSetLabel())
            .arg(e.testRows) +
        rates);
}

} // namespace drytwin::widgets

namespace drytwin::widgets {

namespace {

/// An ablation variant in the window's language (the engine's description is English, for the
/// report and the CLI); a variant this list does not know keeps the engine's words.
QString ablationVariantLabel(const std::string& key, const std::string& engineDescription) {
    static const std::map<std::string, const char*> labels = {
        {"full", QT_TRANSLATE_NOOP("ResidualPanel", "PGRL-CC, all components")},
        {"no_aw_clamp", QT_TRANSLATE_NOOP("ResidualPanel", "1. no a_w clamping")},
        {"no_lv_correction", QT_TRANSLATE_NOOP("ResidualPanel", "2. no L_v correction")},
        {"no_cp_moisture", QT_TRANSLATE_NOOP("ResidualPanel", "3. no C_p(X) dependency")},
        {"paper_energy_balance",
         QT_TRANSLATE_NOOP("ResidualPanel",
                           "E. energy balance as printed (Eqs. 12, 14, 19 count C_p,w (T - T_ref) twice)")},
        {"consistent_energy_balance",
         QT_TRANSLATE_NOOP("ResidualPanel", "E. consistent energy balance (L_v only)")},
        {"no_orthogonal_projection",
         QT_TRANSLATE_NOOP("ResidualPanel", "4. no orthogonal learning (P_perp)")},
        {"orthogonal_projection",
         QT_TRANSLATE_NOOP("ResidualPanel",
                           "4. with orthogonal learning (P_perp, Eq. 27; the trained model has none)")},
        {"literal_eq27",
         QT_TRANSLATE_NOOP("ResidualPanel",
                           "4b. Eq. 27 read literally (base part of e dropped from the prediction)")},
        {"no_cc_weights", QT_TRANSLATE_NOOP("ResidualPanel", "5. no control-consistent weights")},
        {"no_stability_constraint",
         QT_TRANSLATE_NOOP("ResidualPanel", "6. no stability constraint (EDMDc-S)")},
        {"eigenvalue_pull",
         QT_TRANSLATE_NOOP("ResidualPanel",
                           "6b. eigenvalues pulled in after an unconstrained fit instead of Eq. 30")},
        {"level_form",
         QT_TRANSLATE_NOOP("ResidualPanel",
                           "7. the paper's lifted model of e itself (the trivial predictors not nested)")},
    };
    if (const auto it = labels.find(key); it != labels.end()) {
        return QCoreApplication::translate("ResidualPanel", it->second);
    }
    return QString::fromStdString(engineDescription.empty() ? key : engineDescription);
}

} // namespace

void ResidualPanel::showAblation() {
    const auto& a = m_workbench.latest().ablation;
    if (!a) {
        m_ablation->setRowCount(0);
        return;
    }
    m_ablation->setRowCount(static_cast<int>(a->rows.size()));
    for (std::size_t i = 0; i < a->rows.size(); ++i) {
        const auto& r = a->rows[i];
        // The paper's words for the variant in the window's language; in full and with its key
        // (what the CLI and ablation.json call it) as tooltip, for a column too narrow to show it.
        setTableRow(m_ablation, static_cast<int>(i),
                    {ablationVariantLabel(r.variant, r.description), QString::number(r.maeMoisture, 'f', 4),
                     QString::number(r.r2Moisture, 'f', 3), QString::number(r.maeTemperature, 'f', 4),
                     // Not run on one batch (nothing to train on beside the warmest): a dash.
                     std::isfinite(r.regimeMaeMoisture) ? QString::number(r.regimeMaeMoisture, 'f', 4)
                                                        : QStringLiteral("–")});
    }
    for (std::size_t i = 0; i < a->rows.size(); ++i) {
        const auto& r = a->rows[i];
        m_ablation->item(static_cast<int>(i), 0)
            ->setToolTip(ablationVariantLabel(r.variant, r.description) + QStringLiteral("\n") +
                         tr("Key: %1").arg(QString::fromStdString(r.variant)));
    }
    fitTableWidth(m_ablation);
}

} // namespace drytwin::widgets
