#include "discovery/DiscoverPanel.h"
#include "common/EngineText.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/QueuedNote.h"
#include "common/Series.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "discovery/DiscoveryNotes.h"
#include "discovery/RankingWords.h"
#include "discovery/ReferenceMenu.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

namespace drytwin::widgets {

DiscoverPanel::DiscoverPanel(Workbench& workbench, QWidget* parent)
    : QWidget(parent), m_workbench(workbench) {
    auto* run = new QPushButton(tr("Discover"));
    run->setToolTip(tr("What does the simulation get wrong, and why? (score tests, fits, held-out gain)"));
    m_extend = new QPushButton(tr("Extend the model"));
    m_extend->setEnabled(false);
    m_extend->setToolTip(
        tr("Make the extended model (named causes, refitted h_HDT and k_HDT, residual models "
           "retrained) the session's model"));
    m_verdict = new QLabel(tr("Run discovery on the loaded data with the current model."));
    m_verdict->setWordWrap(true);
    m_ranking = makeResultTable({tr("Cause"), tr("Outcome"), QString(), QString(), tr("Fitted"), tr("Loss")});
    setRankingHeaders(m_ranking, false);
    m_gains = makeResultTable({tr("Held-out"), tr("Before"), tr("After"), tr("Unit")});
    setHeaderToolTips(m_gains,
                      {tr("The held-out part: the last 30 % of the rows, batches in time order (the "
                          "Residual model tab's split); every fit saw only the rows before it."),
                       // A review compared "Before" with the Residual tab's physics error and found
                       // them different: discovery refits its own start.
                       tr("Before: discovery's starting model, with h_HDT, k_HDT and the inlet gauge's "
                          "scatter fitted to these data's training rows (or as commissioned on the "
                          "reference period). It can differ from the Calibrate tab's model, and so "
                          "from the physics model's error on the Residual model tab."),
                       tr("After: the extended model, every named cause fitted together (a finding's "
                          "own sentence gives the gain when that cause was named).")});
    m_evidence = new QTextBrowser;
    m_plots = new PlotStack;
    m_plots->addPlot(tr("X_out residual [% wb]"));
    m_plots->addPlot(tr("T_out residual [°C]"));
    m_plots->setXTitle(tr("time, batches one after another [h]"));

    // What changed since the line ran well (issue #41): a reference period, the project keeps it.
    m_referenceButton = new QPushButton(tr("Compare with a reference period…"));
    m_referenceButton->setToolTip(
        tr("Choose batches from a time when the line ran as it should (the weeks after a cleaning, "
           "commissioning runs): Discover then says whether, from when and why the loaded data differ"));
    m_referenceButton->setMenu(makeReferenceMenu(m_workbench, m_referenceButton));
    m_referenceLabel = new QLabel;
    m_referenceLabel->setWordWrap(true);
    m_detection = new QLabel;
    m_detection->setWordWrap(true);
    m_detection->setTextFormat(Qt::RichText);
    m_monitorPlots = new PlotStack;
    m_monitorPlots->addPlot(tr("T² [-]"));
    m_monitorPlots->addPlot(tr("SPE [-]"));
    m_monitorPlots->setXTitle(tr("time, batches one after another [h]"));
    m_monitorPlots->setLogScale(0, false, true);
    m_monitorPlots->setLogScale(1, false, true);
    m_monitorPlots->setEmptyText(tr("Choose a reference period and run Discover to see the monitor"));
    m_monitorPlots->setHintVisible(false); // one mouse hint per tab: the model-error plots carry it
    m_contributions = makeResultTable({tr("Column"), tr("Share of the change"), tr("Detector")});
    m_contributions->setToolTip(
        tr("How much each column contributes to the monitor's statistic after the onset "
           "(reconstruction-based contributions: the column that, put back to normal, removes most of it)"));
    auto* monitorPage = new QSplitter(Qt::Vertical);
    monitorPage->addWidget(m_monitorPlots);
    monitorPage->addWidget(m_contributions);
    monitorPage->setStretchFactor(0, 3);
    m_views = new QTabWidget;
    m_views->addTab(m_plots, tr("Model error"));
    m_views->addTab(monitorPage, tr("Monitor against the reference"));

    auto* left = new QWidget;
    auto* ll = new QVBoxLayout(left);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(run);
    buttons->addWidget(m_extend);
    ll->addLayout(buttons);
    ll->addWidget(new QueuedNote(m_workbench, Action::Discover));
    ll->addWidget(m_referenceButton);
    ll->addWidget(m_referenceLabel);
    ll->addWidget(m_detection);
    ll->addWidget(m_verdict);
    ll->addWidget(new QLabel(tr("Candidate causes, first round:")));
    ll->addWidget(m_ranking, 1);
    m_gainsLabel = new QLabel(tr("Gain on the held-out part:"));
    m_gainsLabel->setWordWrap(true);
    ll->addWidget(m_gainsLabel);
    ll->addWidget(m_gains, 1);
    auto* right = new QSplitter(Qt::Vertical);
    right->addWidget(m_evidence);
    right->addWidget(m_views);
    right->setStretchFactor(1, 2);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(right);
    split->setSizes({660, 620}); // the ranking and gain tables wide, the evidence beside them
    split->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);
    connect(run, &QPushButton::clicked, &m_workbench, &Workbench::discover);
    connect(m_extend, &QPushButton::clicked, this, [this] {
        if (const auto& d = m_workbench.latest().discover) {
            const auto retrain =
                m_workbench.confirmInvalidation(this, tr("Extend the model"), &d->extendedModel);
            if (!retrain) {
                return;
            }
            // The verdict says "extended" once the model has changed (show() on modelChanged),
            // not while the extension still waits behind another job.
            m_workbench.setModel(d->extendedModel, QString::fromLatin1(staleReason::kExtended), *retrain);
            m_extend->setEnabled(false);
        }
    });
    connect(&m_workbench, &Workbench::modelChanged, this, &DiscoverPanel::show);
    connect(&m_workbench, &Workbench::discovered, this, &DiscoverPanel::show);
    connect(&m_workbench, &Workbench::referenceChanged, this, &DiscoverPanel::showReference);
    connect(&m_workbench, &Workbench::dataChanged, this, &DiscoverPanel::show);
    connect(&m_workbench, &Workbench::resultsRestored, this, &DiscoverPanel::show);
    m_plots->setEmptyText(tr("Run Discover to see the physics model's error over the batches"));
    m_workbench.bindButton(run, Action::Discover);
    showReference();
}

void DiscoverPanel::showReference() {
    const QString path = m_workbench.referencePath();
    m_referenceLabel->setText(path.isEmpty() ? tr("No reference period: the data are judged alone.")
                                             : tr("Reference period: %1").arg(QFileInfo(path).fileName()));
    m_referenceLabel->setToolTip(path);
}

void DiscoverPanel::showDetection() {
    const auto& r = m_workbench.latest().discover;
    m_monitorPlots->clearCurves();
    m_contributions->setRowCount(0);
    if (!r || !r->discovery.hasReference) {
        m_detection->clear();
        m_detection->setVisible(false);
        m_monitorPlots->rescale();
        return;
    }
    const auto& det = r->discovery.detection;
    const auto describe = [&](const QString& name, const monitoring::Detection& d) {
        QString line = d.changed ? tr("%1: <b>changed</b> (p = %2)").arg(name).arg(d.pValue, 0, 'g', 2)
                                 : tr("%1: no change (p = %2)").arg(name).arg(d.pValue, 0, 'g', 2);
        if (d.changed && d.hasFirstAlarm) {
            line += tr(", first alarm in %1 at %2 min")
                        .arg(QString::fromStdString(d.firstAlarmRun).toHtmlEscaped())
                        .arg(d.firstAlarmTimeS / 60, 0, 'f', 0);
        }
        if (d.changed && d.hasOnset) {
            line += tr(", from %1 at %2 min (95 %: %3 to %4 min)")
                        .arg(QString::fromStdString(d.onsetRun).toHtmlEscaped())
                        .arg(d.onsetS / 60, 0, 'f', 0)
                        .arg(d.onsetLowS / 60, 0, 'f', 0)
                        .arg(d.onsetHighS / 60, 0, 'f', 0);
        }
        return line;
    };
    // DryTwin's detector: its monitor of the model's error, or a cause's parameter beyond its spread.
    // A p below what a double tells from 0 reads "< 1e-15", not "p = 0".
    const QString causeP = det.causeTest.pValue < 1e-15
                               ? QStringLiteral("&lt; 1e-15") /* rich text: a bare "<" opens a tag */
                               : QStringLiteral("= %1").arg(det.causeTest.pValue, 0, 'g', 2);
    const QString movedCause = causeDisplayName(det.causeTest.cause).toHtmlEscaped();
    const std::string look = det.causeTest.look();
    const QString causes =
        !det.causeTest.changed
            ? tr("DryTwin (the causes' estimates): none moved beyond its normal spread (p %1)").arg(causeP)
        : look == "screen"
            ? tr("DryTwin (the causes' one-step estimates): <b>changed</b> (p %1): %2 moved beyond its "
                 "normal spread")
                  .arg(causeP, movedCause)
        : look == "gauge_scatter"
            ? tr("DryTwin (the inlet gauge's own scatter): <b>changed</b> (p %1): %2 rose beyond the "
                 "reference's")
                  .arg(causeP, movedCause)
            : tr("DryTwin (a named cause's fitted value): <b>changed</b> (p %1): %2 moved beyond its normal "
                 "spread")
                  .arg(causeP, movedCause);
    // Conditions the reference never saw, beside the verdict they may explain.
    QString unseenConditions;
    for (const auto& n : r->discovery.notes) {
        // ... and what puts the reference itself in doubt: its own drift, a unit its files seem to
        // have wrong, an output only one period measures (Session::discover's notes).
        if (n.find("outside what the reference saw") != std::string::npos ||
            n.find("the reference period itself drifts") != std::string::npos ||
            n.rfind("the reference period: ", 0) == 0 || n.find("is measured in ") != std::string::npos) {
            unseenConditions += QStringLiteral("<br><span style=\"color:#a05a00\">%1</span>")
                                    .arg(noteText(n).toHtmlEscaped());
        }
    }
    // A cause named beyond its normal spread is a change even where the detectors, judging the
    // data set as a whole, stayed below their limits: the headline must not say "no change" beside it.
    QString namedCauses;
    for (const auto& c : det.namedCauses) {
        namedCauses += (namedCauses.isEmpty() ? QString() : tr(", ")) + causeDisplayName(c);
    }
    m_detection->setText(
        (det.changed ? tr("<b>The line has changed since the reference period.</b>")
         : det.namedChange()
             ? tr("<b>A cause has changed since the reference period: %1.</b> The detectors, judging the "
                  "data "
                  "set as a whole, stayed below their limits; fitting the causes found it beyond its normal "
                  "spread with a gain on held-out data (below). Check it on the plots.")
                   .arg(namedCauses.toHtmlEscaped())
             : tr("<b>No change against the reference period.</b>")) +
        tr(" Each detector's false-alarm rate: %1 % per data set.").arg(100 * det.falseAlarmRate, 0, 'g', 2) +
        QStringLiteral("<br>") + describe(tr("DryTwin (the model's error)"), det.drytwin) +
        QStringLiteral("<br>") + causes + QStringLiteral("<br>") +
        describe(tr("Dynamic PCA (the measured columns)"), det.pca) + unseenConditions);
    m_detection->setVisible(true);
    // The windows of both monitors, batches one after another, each statistic over its limit's
    // scale so that both detectors share one axis: above 1 is beyond the reference's 99 %.
    const auto hoursOf = [](const monitoring::Detection& d, QVector<double>& x) {
        double offset = 0, last = 0;
        std::string run;
        for (const auto& w : d.series) {
            if (w.run != run) {
                offset += last;
                run = w.run;
            }
            last = w.timeS;
            x << (offset + w.timeS) / 3600.0;
        }
    };
    for (const auto* d : {&det.drytwin, &det.pca}) {
        const bool ours = d == &det.drytwin;
        QVector<double> x, t2, spe, t2Limit, speLimit;
        hoursOf(*d, x);
        for (const auto& w : d->series) {
            t2 << w.t2;
            spe << w.spe;
        }
        const QColor colour = ours ? QColor(214, 39, 40) : QColor(31, 119, 180);
        const QString name = ours ? tr("DryTwin") : tr("dynamic PCA");
        if (ours && !x.isEmpty()) { // the limits belong to one monitor: the one the plot is named after
            m_monitorPlots->addCurve(0, tr("99 % limit"), {x.front(), x.back()},
                                     {d->limits.t2Window, d->limits.t2Window}, Qt::black, Qt::DashLine);
            m_monitorPlots->addCurve(1, tr("99 % limit"), {x.front(), x.back()},
                                     {d->limits.speWindow, d->limits.speWindow}, Qt::black, Qt::DashLine);
        }
        if (ours) {
            m_monitorPlots->addCurve(0, name, x, t2, colour);
            m_monitorPlots->addCurve(1, name, x, spe, colour);
        }
    }
    for (const auto* d : {&det.drytwin, &det.pca}) {
        if (!d->changed) {
            continue;
        }
        const QString name = d == &det.drytwin ? tr("DryTwin") : tr("dynamic PCA");
        for (std::size_t i = 0; i < d->contributions.size() && i < 6; ++i) {
            const auto& c = d->contributions[i];
            const double share = d->statistic == "SPE" ? c.speReconstructionShare : c.t2ReconstructionShare;
            const int row = m_contributions->rowCount();
            m_contributions->insertRow(row);
            setTableRow(
                m_contributions, row,
                {columnDisplayName(c.column), QStringLiteral("%1 %").arg(100 * share, 0, 'f', 0), name});
        }
    }
    fitTableWidth(m_contributions);
    m_monitorPlots->rescale();
    m_views->setCurrentIndex(det.changed ? 1 : 0);
}

namespace {

/// What to look for on the plots, per cause. The engine has the same sentences in English for the
/// CLI's evidence sentence (lookFor in engine/discovery/Discovery.cpp, which has no Qt); they are
/// worded here again because the GUI translates them.
/// A parameter's unit after its value (" 1/h"), nothing for a dimensionless one ("-").
QString paramUnitSuffix(properties::Param p) {
    return unitSuffix(properties::info(p).unit);
}

QString lookForText(properties::Param p) {
    using properties::Param;
    switch (p) {
    case Param::theta_wall:
        return DiscoverPanel::tr("the outlet-temperature error grows with the hot-air excess over ambient "
                                 "(bias by T_amb and T_hot)");
    case Param::theta_gas:
        return DiscoverPanel::tr(
            "the errors grow with feed rate and inlet moisture (bias by feed rate and by inlet moisture)");
    case Param::theta_foul:
        return DiscoverPanel::tr(
            "the error drifts over each batch, or over the recording from the fouling's onset, "
            "and starts afresh with each new batch");
    case Param::tau_meter:
        return DiscoverPanel::tr(
            "the outlet-moisture error follows the rate of change of the simulated outlet "
            "moisture, and the tube-outlet error does not");
    case Param::X_meter_offset:
        return DiscoverPanel::tr(
            "a steady outlet-moisture bias that the tube-outlet moisture does not share");
    case Param::dtau_conv:
        return DiscoverPanel::tr("the outlet error correlates with tube-outlet changes at a shifted lag");
    case Param::theta_fall:
        return DiscoverPanel::tr(
            "the tube-outlet and outlet moisture are wetter than simulated, most where the "
            "tube dries furthest");
    case Param::theta_reabs:
        return DiscoverPanel::tr(
            "the outlet-moisture error grows with ambient humidity while the tube-outlet "
            "error does not");
    case Param::X_in_offset:
        return DiscoverPanel::tr(
            "a steady bias of the tube-outlet and outlet moisture alike, larger where the tube dries less");
    case Param::tau_hot_sensor:
        return DiscoverPanel::tr("after each hot-air setpoint step the outlet temperature and moisture move "
                                 "before the simulation, which follows the slow reading");
    case Param::phi_X_in_scatter:
        return DiscoverPanel::tr("the inlet-moisture reading scatters from second to second while the outlet "
                                 "does not follow it, and the simulated outlet does");
    default:
        return QString();
    }
}

/// The measurement that tells a look-alike group's members apart, in the GUI's language.
QString tellApartText(const std::string& group) {
    if (group == "outlet_response_time") {
        return DiscoverPanel::tr(
            "a step of the hot-air setpoint logged at 1 s: a transport-time error delays the outlet "
            "temperature's response as much as the moisture's, a meter lag delays the moisture reading "
            "alone; "
            "or grab samples timed against the meter");
    }
    if (group == "moisture_offset") {
        return DiscoverPanel::tr(
            "oven-dry laboratory samples at the outlet against the meter and at the inlet against the gauge; "
            "or a tube-outlet moisture channel (X_hdt), which an inlet-gauge offset moves and an "
            "outlet-meter "
            "offset does not");
    }
    if (group == "gas_temperature") {
        return DiscoverPanel::tr("a gas-temperature reading at the tube's outlet end at two feed rates: wall "
                                 "loss does not change with the feed, gas-phase cooling grows with it");
    }
    return QString::fromStdString(group);
}

/// Why a candidate that predicted better was not named, in the GUI's language (the engine's
/// sentence follows in the details).
/// The outcome column's words for a candidate not named (rejectionText() says it in full).
QString rejectionShortText(const std::string& code) {
    static const std::map<std::string, const char*> shortTexts{
        {"compensation", QT_TRANSLATE_NOOP("DiscoverPanel", "compensation")},
        {"inconsistent", QT_TRANSLATE_NOOP("DiscoverPanel", "inconsistent")},
        {"not_constant", QT_TRANSLATE_NOOP("DiscoverPanel", "not constant")},
        {"within_normal_spread", QT_TRANSLATE_NOOP("DiscoverPanel", "within normal range")},
        {"not_on_every_output", QT_TRANSLATE_NOOP("DiscoverPanel", "not on every output")},
        {"below_floor", QT_TRANSLATE_NOOP("DiscoverPanel", "below the floor")},
        {"no_held_out_gain", QT_TRANSLATE_NOOP("DiscoverPanel", "no held-out gain")},
        {"channels", QT_TRANSLATE_NOOP("DiscoverPanel", "its look-alike")},
        {"line_dynamics", QT_TRANSLATE_NOOP("DiscoverPanel", "line dynamics")}};
    const auto it = shortTexts.find(code);
    return it == shortTexts.end() ? DiscoverPanel::tr("not named")
                                  : QCoreApplication::translate("DiscoverPanel", it->second);
}

QString rejectionText(const std::string& code) {
    if (code == "compensation") {
        return DiscoverPanel::tr("it lowers one output's error by raising another's (compensation)");
    }
    if (code == "inconsistent") {
        return DiscoverPanel::tr("its size is not consistent across batches or operating regions");
    }
    if (code == "not_constant") {
        return DiscoverPanel::tr(
            "it does not change within a batch (an offset, the tube's wall or gas phase), "
            "but this error grows or shrinks within the batch (fouling, a drifting reading)");
    }
    if (code == "within_normal_spread") {
        return DiscoverPanel::tr("its value lies within the reference period's normal range: not a change");
    }
    if (code == "not_on_every_output") {
        return DiscoverPanel::tr("named after another cause, it must lower the error of every output it acts on, "
                                 "and on one it does not: what is left there is not this cause's");
    }
    if (code == "below_floor") {
        return DiscoverPanel::tr("it is below what the instruments can tell (practical floor)");
    }
    if (code == "no_held_out_gain") {
        return DiscoverPanel::tr("it does not predict the held-out part clearly better (too small a share of "
                                 "the error, or not significant)");
    }
    if (code == "channels") {
        return DiscoverPanel::tr(
            "the outlet channels' timing points to its look-alike (the moisture answers later "
            "than the temperature: a meter, not the transport)");
    }
    if (code == "line_dynamics") {
        return DiscoverPanel::tr("the outlet temperature lags the model as much: the line is slower than the "
                                 "model, not the meter");
    }
    return DiscoverPanel::tr("no clear held-out gain");
}

/// A signature no cause explains (Signature::type), in the GUI's language.
QString signatureText(const discovery::Signature& u) {
    if (u.type == "periodic") {
        return DiscoverPanel::tr("a periodic error of %1 s period (power %2 times its background)")
            .arg(u.periodS, 0, 'f', 0)
            .arg(u.strength, 0, 'g', 3);
    }
    if (u.type == "lagged_input") {
        return DiscoverPanel::tr("the error follows %1 %2 s later (correlation %3)")
            .arg(columnDisplayName(u.column))
            .arg(u.lagS, 0, 'f', 0)
            .arg(u.strength, 0, 'f', 2);
    }
    if (u.type == "batch_shift") {
        QStringList batches;
        for (const auto& b : u.batches) {
            batches << QString::fromStdString(b);
        }
        return DiscoverPanel::tr("batches %1 are shifted by %2 against the others")
            .arg(batches.join(QStringLiteral(", ")))
            .arg(u.strength, 0, 'g', 3);
    }
    if (u.type == "drift") {
        return DiscoverPanel::tr("the error drifts by %1 per hour within the batches")
            .arg(u.strength, 0, 'g', 3);
    }
    return QString::fromStdString(u.type);
}

/// Why a round stopped, worded here from the round's numbers (the engine's sentence is English).
QString roundReasonText(const discovery::Round& rd) {
    if (rd.named) {
        return DiscoverPanel::tr("named");
    }
    if (rd.best.empty()) {
        return DiscoverPanel::tr("no candidate passes the screening test");
    }
    for (const auto& x : rd.rejected) {
        if (x.cause == rd.best) {
            return rejectionText(x.code);
        }
    }
    return DiscoverPanel::tr("no fitted candidate lowers the training loss");
}

} // namespace

/// Discovery's notes, worded in the GUI's language from their forms in
/// engine/discovery/DiscoveryNotes.h (TestMainWindow's everyDiscoveryNoteIsWordedInChinese builds
/// each form there and checks it is worded here).
QString DiscoverPanel::noteText(const std::string& note) {
    const QString n = QString::fromStdString(note);
    const auto starts = [&](const char* prefix) { return n.startsWith(QLatin1String(prefix)); };
    const auto numbers = [&] {
        static const QRegularExpression number(QStringLiteral("[-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?"));
        QStringList found;
        for (auto it = number.globalMatch(n); it.hasNext();) {
            found << it.next().captured(0);
        }
        return found;
    };
    if (starts("X_hdt_pct is not measured")) {
        return tr("X_hdt_pct is not measured: without the tube-outlet moisture, meter and conveyor "
                  "causes cannot be told from tube causes; only the outlet channels are used.");
    }
    if (starts("T_hdt_C is not measured")) {
        return tr("T_hdt_C is not measured: the tube-outlet temperature is not used.");
    }
    if (starts("air_speed_m_s is constant")) {
        return tr("air_speed_m_s is constant (not measured?): the air cooling along the tube is "
                  "fitted with that one value.");
    }
    if (starts("the line's outlet mixing") && !numbers().isEmpty()) {
        return tr("The line's outlet mixing (belt and winnower): a first-order lag of %1 s fitted "
                  "with h_HDT and k_HDT (0: plug flow).")
            .arg(numbers().first());
    }
    if (starts("the inlet gauge's normal scatter") && numbers().size() >= 2) {
        return tr("The inlet gauge's normal scatter: %1 % of X_in's fast variation (%2 % wb) is taken "
                  "as gauge scatter, not moisture, in the starting model.")
            .arg(numbers().at(0), numbers().at(1));
    }
    // ReferenceDiscovery.cpp's withdrawTakenUp and its note on a short reference.
    static const QRegularExpression withdrawn(QStringLiteral(
        "^(\\S+): named first, then withdrawn: refitted with the causes named after it, it is (.*); it had "
        "taken up what they explain$"));
    if (const auto m = withdrawn.match(n); m.hasMatch()) {
        return tr("%1 was named first, then withdrawn: refitted together with the causes named "
                  "after it, it is no change of the line (it had taken up what they explain). "
                  "In detail: %2.")
            .arg(causeDisplayName(m.captured(1).toStdString()), m.captured(2));
    }
    // ReferenceDiscovery.cpp: the batches wholly before the change point left out of the causes' judgement.
    static const QRegularExpression fromChange(QStringLiteral(
        "^the causes are judged on the batches from (.+) on, where the change began; (.+) before it ran as "
        "the reference did$"));
    if (const auto m = fromChange.match(n); m.hasMatch()) {
        return tr("The causes are judged on the batches from %1 on, where the change began; %2 before it "
                  "ran as the reference did.")
            .arg(m.captured(1), m.captured(2));
    }
    // ReferenceDiscovery.cpp: the batches a change that began mid-batch goes on into.
    static const QRegularExpression goesOn(QStringLiteral(
        "^the change goes on from the start of (.+) \\(the monitor reads them changed before the onset time "
        "too\\): the causes act there from the batch's start$"));
    if (const auto m = goesOn.match(n); m.hasMatch()) {
        return tr("The change goes on from the start of %1 (the monitor reads them changed before the "
                  "onset time too): the causes act there from the batch's start.")
            .arg(m.captured(1));
    }
    if (starts("the reference holds ") && !numbers().isEmpty()) {
        return tr("The reference holds %1 batch(es): a period's normal spread comes from thirds of "
                  "them, which share their day and weather; a change named here may be a "
                  "difference of conditions the reference never showed. A reference of several "
                  "batches over the conditions the line runs in (weeks, seasons) judges better.")
            .arg(numbers().first());
    }
    // ReferenceDiscovery.cpp: "the reference period itself drifts: the model's X_out error changes by
    // 2.7 % wb within a mean batch (...)".
    static const QRegularExpression drifts(
        QStringLiteral("^the reference period itself drifts: the model's (\\S+) error changes by (\\S+) (.+) "
                       "within a mean batch"));
    if (const auto m = drifts.match(n); m.hasMatch()) {
        return tr("The reference period itself drifts: the model's %1 error changes by %2 %3 "
                  "within a mean batch. A reference should be a period when the line ran "
                  "well; against this one a change since may read as none.")
            .arg(m.captured(1), m.captured(2), m.captured(3));
    }
    // A batch's inputs outside a range seen elsewhere, one note a batch (DiscoveryNotes.cpp's
    // inputsOutside): "T_amb_C is typically 31.6 °C, outside what the reference saw (11 to 23 °C);
    // RH_pct is typically …". Each input worded, then joined.
    const auto inputsOutside = [](const QString& list, bool otherReferenceBatches) {
        static const QRegularExpression item(
            QStringLiteral("(\\S+) is typically (\\S+) ([^,;]+), outside what the (?:other reference batches|"
                           "reference) saw \\((\\S+) to (\\S+) [^)]*\\)"));
        QStringList worded;
        for (auto it = item.globalMatch(list); it.hasNext();) {
            const auto m = it.next();
            const QString column = columnDisplayName(m.captured(1).toStdString());
            worded << (otherReferenceBatches
                           ? tr("%1 is typically %2 %3, outside what the other reference batches saw (%4 to "
                                "%5 %3)")
                           : tr("%1 is typically %2 %3, outside what the reference saw (%4 to %5 %3)"))
                          .arg(column, m.captured(2), m.captured(3), m.captured(4), m.captured(5));
        }
        return worded.join(tr("; "));
    };
    // ReferenceDiscovery.cpp: "reference batch R03: T_amb_C is typically 30.4 °C, outside what the
    // other reference batches saw (12.1 to 19.4 °C)[; …]: the line's structure there …"
    static const QRegularExpression beyondOthers(
        QStringLiteral("^reference batch (.+?): (\\S+ is typically .+): the line's structure there is the "
                       "map's extrapolation"));
    if (const auto m = beyondOthers.match(n); m.hasMatch()) {
        return tr("Reference batch %1: %2: the line's structure there is the map's extrapolation, so the "
                  "batch is left out of the causes' normal spread.")
            .arg(m.captured(1), inputsOutside(m.captured(2), true));
    }
    // ReferenceDiscovery.cpp's operatingRangeNotes: "B04: T_amb_C is typically 31.6 °C, outside what
    // the reference saw (11 to 23 °C)[; …]: …"
    static const QRegularExpression outside(QStringLiteral(
        "^(.+?): (\\S+ is typically .+ outside what the reference saw \\([^)]*\\)): (?:the reference has|the "
        "model's error)"));
    if (const auto m = outside.match(n); m.hasMatch()) {
        // Whether the detectors judged the batch's level
        // (DiscoveryOptions::judgeOnlyChangesBeyondReferenceConditions).
        const QString text =
            n.contains(QStringLiteral("only changes within"))
                ? tr("%1: %2: the reference has no normal level for these conditions, so the detectors judge "
                     "only changes within this batch, not its level.")
                : tr("%1: %2: the model's error there is judged beyond the reference's conditions, and an "
                     "alarm "
                     "there may be that condition rather than a change of the line.");
        return text.arg(m.captured(1), inputsOutside(m.captured(2), false));
    }
    if (n.startsWith(QLatin1String(discovery::notes::kOnlyCausesAsked))) {
        QStringList causes;
        for (const auto& c : n.mid(static_cast<int>(std::strlen(discovery::notes::kOnlyCausesAsked)))
                                 .split(QStringLiteral(", "), Qt::SkipEmptyParts)) {
            causes << causeDisplayName(c.toStdString());
        }
        return tr("Only the causes asked were tried: %1. That the others are not named says nothing about "
                  "them.")
            .arg(causes.join(tr(", ")));
    }
    // ReferenceDiscovery.cpp: "commissioned on the reference period (6 batch(es), 45000 rows): h_HDT
    // 71.98 W/(m²·K), k_HDT 0.02392 m/s, held fixed on the data judged".
    static const QRegularExpression commissioned(QStringLiteral(
        "^commissioned on the reference period \\((\\d+) batch\\(es\\), (\\d+) rows\\): h_HDT (\\S+) "
        "W/\\(m²·K\\), k_HDT (\\S+) m/s"));
    if (const auto m = commissioned.match(n); m.hasMatch()) {
        return tr("Commissioned on the reference period (%1 batch(es), %2 rows): h_HDT %3 W/(m²·K) and "
                  "k_HDT %4 m/s, held fixed on the data judged.")
            .arg(m.captured(1), m.captured(2), m.captured(3), m.captured(4));
    }
    static const QRegularExpression structure(QStringLiteral(
        "^the line's own structure \\(what the model always gets wrong, a ridge regression on the inputs and "
        "the model's outputs, penalty (\\S+)\\)"));
    if (const auto m = structure.match(n); m.hasMatch()) {
        return tr("The line's own structure (what the model always gets wrong: a ridge regression on the "
                  "inputs and the model's outputs, penalty %1) was learnt on the reference and taken off "
                  "the measurements; the residuals shown are what is left.")
            .arg(m.captured(1));
    }
    // SessionDiscover.cpp: an output only one of the two periods measures.
    static const QRegularExpression onePeriod(
        QStringLiteral("^(\\S+) is measured in the (data|reference period) "
                       "but not in every batch of the"));
    if (const auto m = onePeriod.match(n); m.hasMatch()) {
        const QString column = columnDisplayName(m.captured(1).toStdString());
        return m.captured(2) == QLatin1String("data")
                   ? tr("%1 is measured in the data but not in every batch of the reference period: the "
                        "periods are compared on the outputs both measure, without it.")
                         .arg(column)
                   : tr("%1 is measured in the reference period but not in every batch of the data: the "
                        "periods are compared on the outputs both measure, without it.")
                         .arg(column);
    }
    // SessionData.cpp: the data checks' note on the reference's own files (the note itself is the
    // Data tab's, shown as the checks word it).
    if (n.startsWith(QLatin1String(discovery::notes::kAboutReferenceFiles))) {
        return tr("The reference period's files: %1")
            .arg(n.mid(static_cast<int>(std::strlen(discovery::notes::kAboutReferenceFiles))));
    }
    return n;
}

QString DiscoverPanel::specificityText(const discovery::Finding& f) {
    const auto& info = properties::info(f.parameter);
    const QString unit = QString::fromUtf8(info.unit.data(), static_cast<int>(info.unit.size()));
    QStringList parts;
    if (!f.perPart.empty()) {
        // Held within the parameter's range, as the CLI's text: a part that hardly informs the
        // estimate can step outside it (its uncertainty, not a value the line can have).
        double lo = std::clamp(f.perPart.front().value, info.lower, info.upper), hi = lo;
        bool held = false;
        for (const auto& e : f.perPart) {
            const double v = std::clamp(e.value, info.lower, info.upper);
            held = held || v != e.value;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        parts << tr("Fitted part by part (%1 parts) it lies between %2 and %3 %4: %5.")
                         .arg(f.perPart.size())
                         .arg(lo, 0, 'g', 3)
                         .arg(hi, 0, 'g', 3)
                         .arg(unit)
                         .arg(f.consistent ? tr("consistent") : tr("not consistent")) +
                     (held ? QStringLiteral(" ") +
                                 tr("A part whose estimate left the parameter's range is held at its bound.")
                           : QString());
    }
    if (f.transferChecked) {
        parts << tr("Fitted on the cooler half of the data it removes %1 % of the warmer half's error.")
                     .arg(100 * f.transferReduction, 0, 'f', 0);
    }
    if (f.hasOnset) {
        parts << tr("It starts %1 min into the batch (95 % interval %2–%3 min).")
                     .arg(f.onsetS / 60, 0, 'f', 0)
                     .arg(f.onsetLowS / 60, 0, 'f', 0)
                     .arg(f.onsetHighS / 60, 0, 'f', 0);
        if (!f.actsFromStartOf.empty()) {
            QStringList batches;
            for (const auto& b : f.actsFromStartOf) {
                batches << QString::fromStdString(b);
            }
            parts << tr("It goes on from the start of %1.").arg(batches.join(QStringLiteral(", ")));
        }
    }
    for (const auto& l : f.lookAlikes) {
        if (l.namedAfter) {
            parts << tr("%1 was named on top of it (a further %2 % of the held-out error): alone it predicts "
                        "worse (%3 times the held-out error), but the change needs both forms, so the data "
                        "cannot say which of them it is.")
                         .arg(causeDisplayName(l.cause))
                         .arg(100 * l.explainedAfter, 0, 'f', 0)
                         .arg(l.heldOutLossRatio, 0, 'g', 2);
            continue;
        }
        if (l.byChannels) {
            parts
                << (l.ruledOut
                        ? tr("Not %1: the moisture answers %2 s later than the model and the outlet "
                             "temperature "
                             "%3 s (each fitted alone, p = %4); a transport time delays both alike.")
                              .arg(causeDisplayName(l.cause))
                              .arg(l.moistureDelayS, 0, 'g', 3)
                              .arg(l.temperatureDelayS, 0, 'g', 3)
                        : tr("%1 fits too: the moisture answers %2 s later than the model and the outlet "
                             "temperature %3 s (each fitted alone, p = %4); the channels' timing cannot tell "
                             "them apart (the temperature has dynamics of its own, or the difference is "
                             "within "
                             "the noise).")
                              .arg(causeDisplayName(l.cause))
                              .arg(l.moistureDelayS, 0, 'g', 3)
                              .arg(l.temperatureDelayS, 0, 'g', 3))
                       .arg(l.pValue, 0, 'g', 2);
            continue;
        }
        if (!l.ruledOut && !l.worseOutput.empty()) {
            parts
                << tr("%1 fits too: overall it leaves %2 times the held-out error (p = %3), but it predicts "
                      "%4 better; which output a cause favours is the model's structure, so the data cannot "
                      "tell them apart.")
                       .arg(causeDisplayName(l.cause))
                       .arg(l.heldOutLossRatio, 0, 'g', 2)
                       .arg(l.pValue, 0, 'g', 2)
                       .arg(l.worseOutput == "X_out"   ? tr("the outlet moisture")
                            : l.worseOutput == "T_out" ? tr("the outlet temperature")
                            : l.worseOutput == "X_hdt" ? tr("the tube-outlet moisture")
                                                       : tr("the tube-outlet temperature"));
            continue;
        }
        parts << (l.ruledOut
                      ? tr("Not %1: fitted in its place it leaves %2 times the held-out error (p = %3).")
                      : tr("%1 fits these data about as well (held-out error %2 times, p = %3): the data "
                           "cannot tell them apart."))
                     .arg(causeDisplayName(l.cause))
                     .arg(l.heldOutLossRatio, 0, 'g', 2)
                     .arg(l.pValue, 0, 'g', 2);
    }
    if (!f.group.empty()) {
        parts << tr("To tell them apart: %1.").arg(tellApartText(f.group));
    }
    return parts.join(QLatin1Char(' '));
}

QString DiscoverPanel::evidenceText(const discovery::Finding& f) {
    const bool moisture = f.output == "X_out";
    const QString unit = moisture ? tr("% wb") : tr("°C");
    const auto& info = properties::info(f.parameter);
    const auto& g = f.gain;
    const QString share =
        f.onItsChannelsCounted
            ? (f.parameter == properties::Param::tau_meter
                   ? tr("it removes %1 % of the held-out squared error, and of the outlet moisture's, the "
                        "only "
                        "measured output it acts on, %2 % (%3 % of its fast part)")
                   : tr("it removes %1 % of the held-out squared error, and of the outlet moisture's and "
                        "temperature's, the only measured outputs it acts on, %2 % (%3 % of its fast part)"))
                  .arg(100 * f.explainedFraction, 0, 'f', 0)
                  .arg(100 * f.explainedFractionOnItsChannels, 0, 'f', 0)
                  .arg(100 * f.explainedFractionOnItsChannelsFast, 0, 'f', 0)
        : f.fastPartCounted
            ? tr("it removes %1 % of the held-out squared error and %2 % of its fast part (the error about "
                 "its moving average, where slow drift does not hide it)")
                  .arg(100 * f.explainedFraction, 0, 'f', 0)
                  .arg(100 * f.explainedFractionFast, 0, 'f', 0)
            : tr("it removes %1 % of the held-out squared error").arg(100 * f.explainedFraction, 0, 'f', 0);
    const QString commissioned = f.hasReference ? tr("h_HDT, k_HDT as commissioned on the reference period")
                                                : tr("h_HDT, k_HDT refitted");
    // Against a reference the finding is a change: the value it had there, and its normal range.
    const QString changed =
        f.hasReference
            ? tr(" On the reference period it was %1 %2 (a period's normal range %3 to %4): it changed.")
                  .arg(f.referenceValue, 0, 'g', 4)
                  .arg(QString::fromUtf8(info.unit.data(), static_cast<int>(info.unit.size())))
                  .arg(f.referenceCi95Low, 0, 'g', 3)
                  .arg(f.referenceCi95High, 0, 'g', 3)
            : QString();
    return tr("%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7%8, 95 % CI [%9, "
              "%10]) "
              "and %18, the held-out MAE of X_out goes from %11 to %12 % wb and of T_out "
              "from %13 to %14 °C (the chance that a gain this large is luck: %15); "
              "%16. Check on the plots: %17.")
               .arg(moisture ? tr("Outlet-moisture") : tr("Outlet-temperature"))
               .arg(f.biasBefore, 0, 'g', 3)
               .arg(unit)
               .arg(f.trendPerHourBefore, 0, 'g', 3)
               .arg(causeDisplayName(f.cause))
               .arg(QString::fromUtf8(info.symbol.data(), static_cast<int>(info.symbol.size())))
               .arg(f.restated ? f.valueWhenNamed : f.value, 0, 'g', 4)
               .arg(paramUnitSuffix(f.parameter))
               .arg(f.restated ? f.ci95LowWhenNamed : f.ci95Low, 0, 'g', 3)
               .arg(f.restated ? f.ci95HighWhenNamed : f.ci95High, 0, 'g', 3)
               .arg(g.maeMoistureBefore, 0, 'f', 3)
               .arg(g.maeMoistureAfter, 0, 'f', 3)
               .arg(g.maeTemperatureBefore, 0, 'f', 2)
               .arg(g.maeTemperatureAfter, 0, 'f', 2)
               .arg(g.pValue, 0, 'g', 2)
               .arg(share)
               .arg(lookForText(f.parameter))
               .arg(commissioned) +
           changed + responseSizeText(f);
}

QString DiscoverPanel::responseSizeText(const discovery::Finding& f) {
    // Against a reference a cause is judged by the direction of its effect on each output; where
    // the line moved by a different amount than the model form says, the engineer is told.
    QString text;
    static const char* const kChannels[] = {"X_out", "T_out", "X_hdt", "T_hdt"};
    for (int c : discovery::outputsMovedOtherThanModelled(f)) {
        const double scale = f.responseScale[static_cast<std::size_t>(c)];
        text +=
            (scale < 0 ? tr(" %1 moved against this cause's effect (%2 times what its model form says), by "
                            "less than that output's noise can tell from none: it counts neither for the "
                            "cause nor against it.")
                       : tr(" %1 moved %2 times as much as this cause's model form says: the direction "
                            "agrees, the size is the model's to answer."))
                .arg(QLatin1String(kChannels[c]))
                .arg(scale, 0, 'g', 2);
    }
    return text;
}

void DiscoverPanel::show() {
    const auto& r = m_workbench.latest().discover;
    if (!r) {
        // No discovery on this data set (new data loaded, or not run yet): nothing of another's shown.
        m_verdict->setText(
            m_workbench.hasData()
                ? tr("Run discovery on %1 with the current model.").arg(m_workbench.dataSetLabel())
                : tr("Open a data set, then run discovery on it."));
        m_extend->setEnabled(false);
        m_ranking->setRowCount(0);
        m_gains->setRowCount(0);
        m_gainsLabel->setText(tr("Gain on the held-out part:"));
        m_evidence->clear();
        m_plots->clearCurves();
        m_plots->rescale();
        showDetection();
        return;
    }
    showDetection();
    const auto& d = r->discovery;
    QStringList named;
    for (const auto& f : d.findings) {
        QString name = causeDisplayName(f.cause);
        for (const auto& l : f.lookAlikes) {
            if (!l.ruledOut) {
                name += tr(" or ") + causeDisplayName(l.cause);
            }
        }
        named << (f.group.empty() ? name : tr("%1, one of: %2").arg(groupDisplayName(f.group), name));
    }
    // A model that already holds every named cause (Extend was pressed, also before the project
    // was saved and reopened) is not extended again.
    const auto& mechanisms = m_workbench.model().mechanisms;
    const bool extended =
        !d.findings.empty() && std::all_of(d.findings.begin(), d.findings.end(),
                                           [&](const auto& f) { return mechanisms.count(f.cause) > 0; });
    // A candidate turned down by a specificity check that a reference period can settle (it
    // fitted and predicted better, but may be the line's own structure): not one below its
    // practical floor (real but too small to act on), nor one without a held-out gain.
    const bool aCauseFitsButFailedACheck =
        !d.hasReference && std::any_of(d.rounds.begin(), d.rounds.end(), [](const auto& round) {
            return std::any_of(round.rejected.begin(), round.rejected.end(), [](const auto& x) {
                return x.code == "compensation" || x.code == "inconsistent" || x.code == "not_constant" ||
                       x.code == "line_dynamics";
            });
        });
    const QString nextStep =
        extended ? QString() : verdictNextStep(d.verdict, aCauseFitsButFailedACheck, d.hasReference);
    m_verdict->setText(
        tr("%1. On %2.")
            .arg(verdictDisplayText(d.verdict, named.join(tr(", "))), m_workbench.dataSetLabel()) +
        (nextStep.isEmpty() ? QString() : QStringLiteral("\n") + nextStep) +
        (extended ? tr(" The model is extended.") : QString()));
    m_verdict->setToolTip(tr("Discovery's verdict key: %1").arg(QString::fromStdString(d.verdict)));
    m_extend->setEnabled(!d.findings.empty() && !extended);
    setRankingHeaders(m_ranking, d.hasReference);
    m_ranking->setRowCount(static_cast<int>(d.ranking.size()));
    // Each candidate's outcome beside its evidence: a significant candidate left unnamed with no
    // word on why read as a contradiction of the verdict (a newcomer's review, 2026-11-28). The
    // last round that judged it decides; the sentence behind it is the cell's tooltip.
    const auto outcome = [&d](const std::string& cause) -> std::pair<QString, QString> {
        for (const auto& f : d.findings) {
            if (f.cause == cause) {
                // Named on its fit, whatever the screen's p (a newcomer read "named" beside p 0.08 as
                // a contradiction).
                return {tr("named"),
                        tr("Named on its fit: it lowers the held-out error (p = %1) and passes the checks "
                           "that it is this cause; the screen's p only ranks the candidates for fitting.")
                            .arg(f.gain.pValue, 0, 'g', 3)};
            }
        }
        for (auto r = d.rounds.rbegin(); r != d.rounds.rend(); ++r) {
            for (const auto& x : r->rejected) {
                if (x.cause == cause) {
                    return {rejectionShortText(x.code), engineDetailText(x.reason, rejectionText(x.code))};
                }
            }
        }
        for (const auto& r : d.rounds) {
            if (std::any_of(r.candidates.begin(), r.candidates.end(),
                            [&](const discovery::Candidate& c) { return c.cause == cause && c.fitted; })) {
                return {tr("fitted, not the best"),
                        tr("Fitted in a round in which another cause explained more of the error; the "
                           "causes named after it were fitted on the model extended by it.")};
            }
        }
        return {QString(), QString()};
    };
    for (std::size_t i = 0; i < d.ranking.size(); ++i) {
        const auto& c = d.ranking[i];
        const auto [outcomeText, outcomeWhy] = outcome(c.cause);
        const QStringList cells{
            causeDisplayName(c.cause),
            outcomeText.isEmpty() ? (c.fitted ? QString() : tr("not fitted (weaker)")) : outcomeText,
            QString::number(c.score, 'f', 2),
            QString(), // setRankingPValue below
            c.fitted ? tr("yes") : tr("no"),
            c.fitted
                ? QStringLiteral("%1 → %2").arg(c.fitLossBefore, 0, 'g', 4).arg(c.fitLossAfter, 0, 'g', 4)
                : QStringLiteral("–")};
        setTableRow(m_ranking, static_cast<int>(i), cells);
        setRankingPValue(m_ranking->item(static_cast<int>(i), 3), c.pHolm, c.pFromOwnScreen);
        if (!outcomeWhy.isEmpty()) {
            m_ranking->item(static_cast<int>(i), 1)->setToolTip(outcomeWhy);
        }
        if (c.pFromOwnScreen) {
            m_ranking->item(static_cast<int>(i), 3)
                ->setToolTip(tr("* A timing cause: p is its own score test (how strongly the error points at "
                                "it), smaller than its change test's; a lag's one-step estimate understates "
                                "how far it moved, so the fit decides."));
        }
    }
    fitTableWidth(m_ranking);
    QString html;
    for (const auto& f : d.findings) {
        // The heading gives the final model's value (every named cause fitted jointly); the
        // sentence, the gain and the parts describe the fit when the cause was named. Where the
        // two differ, the heading says which is which.
        // Said wherever the two differ as shown (0.04521 above 0.04468 below read as a mistake).
        const bool moved =
            f.restated && QString::number(f.value, 'g', 4) != QString::number(f.valueWhenNamed, 'g', 4);
        const QString heading =
            tr("%1 = %2%3, 95 % CI [%4, %5]")
                .arg(causeDisplayName(f.cause))
                .arg(f.value, 0, 'g', 4)
                .arg(paramUnitSuffix(f.parameter))
                .arg(f.ci95Low, 0, 'g', 4)
                .arg(f.ci95High, 0, 'g', 4) +
            (moved
                 ? tr(" in the final model, fitted with every other named cause (%1%2 when it was named, as "
                      "below)")
                       .arg(f.valueWhenNamed, 0, 'g', 4)
                       .arg(paramUnitSuffix(f.parameter))
                 : QString());
        html += QStringLiteral("<h4>%1</h4><p>%2</p>")
                    .arg(heading.toHtmlEscaped(),
                         (evidenceText(f) + QLatin1Char(' ') + specificityText(f)).toHtmlEscaped());
    }
    // What the error moves with: the strongest cross-correlations of the differenced residuals
    // with the differenced inputs and proxies (lags 0–300 s), as the analysis found them.
    for (const auto& o : d.residuals) {
        QStringList items;
        for (const auto& c : o.correlates) {
            items << tr("%1, %2 s earlier (correlation %3%4)")
                         .arg(columnDisplayName(c.column))
                         .arg(c.lagS, 0, 'f', 0)
                         .arg(c.ccf, 0, 'f', 2)
                         .arg(c.significant ? tr(", significant") : QString());
        }
        if (!items.isEmpty()) {
            html += tr("<p><b>%1</b> error moves with: %2</p>")
                        .arg(columnDisplayName(o.output).toHtmlEscaped(),
                             items.join(QStringLiteral("; ")).toHtmlEscaped());
        }
    }
    // Why the selection stopped where it did: each round's best candidate and the decision.
    for (std::size_t i = 0; i < d.rounds.size(); ++i) {
        const auto& rd = d.rounds[i];
        // The evidence's details: here the test behind "the chance it is luck" is named.
        html +=
            tr("<p><b>Round %1</b>: %2 (chance the held-out gain is luck %3, Diebold-Mariano test; removes "
               "%4 % of the error, %5 % of its fast part): %6</p>")
                .arg(i + 1)
                .arg(rd.best.empty() ? QStringLiteral("–") : causeDisplayName(rd.best).toHtmlEscaped())
                .arg(rd.heldOutPValue, 0, 'g', 2)
                .arg(100 * rd.explainedFraction, 0, 'f', 0)
                .arg(100 * rd.explainedFractionFast, 0, 'f', 0)
                .arg(roundReasonText(rd).toHtmlEscaped());
        for (const auto& x : rd.rejected) {
            html +=
                tr("<p>&nbsp;&nbsp;Not named: %1, because %2.</p>")
                    .arg(causeDisplayName(x.cause).toHtmlEscaped(), rejectionText(x.code).toHtmlEscaped());
        }
    }
    if (!d.bounds.empty()) {
        QStringList items;
        for (const auto& b : d.bounds) {
            const auto& info = properties::info(b.parameter);
            items << QStringLiteral("%1: %2 ∈ [%3, %4] %5")
                         .arg(causeDisplayName(b.cause),
                              QString::fromUtf8(info.symbol.data(), int(info.symbol.size())))
                         .arg(b.ci95Low, 0, 'g', 3)
                         .arg(b.ci95High, 0, 'g', 3)
                         .arg(QString::fromUtf8(info.unit.data(), int(info.unit.size())))
                         .toHtmlEscaped();
        }
        html += tr("<p><b>Not named</b>; what the data allow (95 %): %1</p>")
                    .arg(items.join(QStringLiteral("; ")));
    }
    if (d.hasReference && !d.detection.lineChanged() && !d.unexplained.empty()) {
        html += tr("<p>The patterns left in the error below are within what the reference period shows: the "
                   "data did not change against it.</p>");
    }
    for (const auto& u : d.unexplained) {
        if (u.type == "dynamics") {
            html += tr("<p><b>Unexplained</b> (%1): the error follows the simulated rate of change (a lag of "
                       "%2 s "
                       "would explain %3 % of it): the line's dynamics differ from the model's.</p>")
                        .arg(columnDisplayName(u.output).toHtmlEscaped())
                        .arg(u.lagS, 0, 'g', 3)
                        .arg(100 * u.strength, 0, 'f', 0);
        } else {
            html += tr("<p><b>Unexplained</b> (%1): %2</p>")
                        .arg(columnDisplayName(u.output).toHtmlEscaped(), signatureText(u).toHtmlEscaped());
        }
    }
    if (r->keptStartingModel) {
        html += tr(
            "<p><b>The correction model learnt on the extended physics model predicts worse on the held-out "
            "part than the one on the starting model: Extend keeps the starting model and its correction "
            "model; the findings stand.</b></p>");
    }
    for (const auto& n : d.notes) {
        html += QStringLiteral("<p><i>%1</i></p>").arg(noteText(n).toHtmlEscaped());
    }
    m_evidence->setHtml(html.isEmpty() ? tr("<p>No structure that a mechanism explains.</p>") : html);
    m_gains->setRowCount(0);
    // Before and after the same numbers with no word said why: nothing named, nothing extended.
    m_gainsLabel->setText(
        d.findings.empty()
            ? tr("Held-out accuracy: nothing was named, so nothing was extended (before = after):")
        : d.findings.size() == 1 ? tr("Gain on the held-out part:")
                                 // Each finding's evidence gives its own gain when it was named; the
                                 // table is the final model's (a review read T_out "1.38 to 1.38"
                                 // above "1.381 → 0.859" below as a contradiction).
                                 : tr("Gain on the held-out part, with every named cause (each finding's "
                                      "own gain is in its evidence):"));
    const auto row = [&](const QString& what, double before, double after, const QString& unit) {
        const int r2 = m_gains->rowCount();
        m_gains->insertRow(r2);
        const QStringList cells{what, QString::number(before, 'g', 4), QString::number(after, 'g', 4), unit};
        setTableRow(m_gains, r2, cells);
    };
    if (!d.findings.empty()) {
        const auto& g = d.findings.back().gain;
        row(tr("MAE X_out (physics)"), d.findings.front().gain.maeMoistureBefore, g.maeMoistureAfter,
            tr("% wb"));
        row(tr("MAE T_out (physics)"), d.findings.front().gain.maeTemperatureBefore, g.maeTemperatureAfter,
            tr("°C"));
        row(tr("R² X_out"), d.findings.front().gain.r2MoistureBefore, g.r2MoistureAfter, QString());
        // An R² below 0 reads as an error to a newcomer: each cell says what its value means.
        const int r2Row = m_gains->rowCount() - 1;
        for (const auto& [column, value] :
             {std::pair{1, d.findings.front().gain.r2MoistureBefore}, std::pair{2, g.r2MoistureAfter}}) {
            if (auto* item = m_gains->item(r2Row, column)) {
                item->setToolTip(r2Explanation(value));
            }
        }
        row(tr("low-frequency share"), d.findings.front().gain.lowFrequencyShareBefore,
            g.lowFrequencyShareAfter, QString());
    }
    // PGRL-CC on each physics model, and the forecasts it must beat to earn its place on the same
    // rows, also where nothing was named (then before and after are the same model).
    if (r->hasHybrid) {
        const auto& ref = r->references;
        const bool references = std::isfinite(ref.persistenceMoisture);
        struct Forecasts {
            QString pgrlCc, lastValue, lastError, unit;
            double before, after, persistence, holdBefore, holdAfter;
        };
        for (const Forecasts& f :
             {Forecasts{tr("MAE X_out (PGRL-CC)"), tr("MAE X_out (last value held)"),
                        tr("MAE X_out (physics, last error held)"), tr("% wb"), r->hybridMaeMoistureBefore,
                        r->hybridMaeMoistureAfter, ref.persistenceMoisture, ref.pbmHoldMoistureBefore,
                        ref.pbmHoldMoistureAfter},
              Forecasts{tr("MAE T_out (PGRL-CC)"), tr("MAE T_out (last value held)"),
                        tr("MAE T_out (physics, last error held)"), tr("°C"), r->hybridMaeTemperatureBefore,
                        r->hybridMaeTemperatureAfter, ref.persistenceTemperature,
                        ref.pbmHoldTemperatureBefore, ref.pbmHoldTemperatureAfter}}) {
            row(f.pgrlCc, f.before, f.after, f.unit);
            if (references) {
                row(f.lastValue, f.persistence, f.persistence, f.unit);
                row(f.lastError, f.holdBefore, f.holdAfter, f.unit);
            }
        }
    }
    fitTableWidth(m_gains);
    m_plots->clearCurves();
    const auto curve = [&](const std::vector<discovery::OutputResidual>& rs, const QColor& colour,
                           const QString& name) {
        for (const auto& o : rs) {
            const int plot = o.output == "X_out" ? 0 : (o.output == "T_out" ? 1 : -1);
            if (plot < 0 || o.seriesValue.empty()) {
                continue;
            }
            QVector<double> x, y;
            residualSeriesInHours(o.seriesBatch, o.seriesTimeS, o.seriesValue, x, y);
            m_plots->addDots(plot, name, x, y, colour);
        }
    };
    // Nothing named, nothing extended: one model's error, not the same dots twice with the first
    // hidden under the second.
    if (d.findings.empty()) {
        curve(d.residuals, QColor(31, 119, 180), tr("model (nothing extended)"));
    } else {
        curve(d.residuals, QColor(214, 39, 40), tr("starting model"));
        curve(d.residualsAfter, QColor(31, 119, 180), tr("extended model"));
    }
    m_plots->rescale();
}

} // namespace drytwin::widgets
