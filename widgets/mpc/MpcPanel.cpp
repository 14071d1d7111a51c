#include "mpc/MpcPanel.h"
#include "common/EngineText.h"

#include "common/DisplayNames.h"
#include "common/ModelStateBar.h"
#include "common/PlotStack.h"
#include "common/QueuedNote.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "control/BundledScenarios.h"
#include "control/Scenario.h"
#include "mpc/ScenarioForm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace drytwin::widgets {

namespace {
const control::ControllerKind kKinds[] = {
    control::ControllerKind::Pbm, control::ControllerKind::ExtInputResidual, control::ControllerKind::Lstm,
    control::ControllerKind::PgrlCc, control::ControllerKind::Pi};
} // namespace

MpcPanel::MpcPanel(Workbench& workbench, QWidget* parent) : QWidget(parent), m_workbench(workbench) {
    m_scenario = new QComboBox;
    for (const auto& [name, text] : control::bundledScenarios()) {
        m_scenario->addItem(QString::fromStdString(name));
    }
    m_scenario->setCurrentText(QString::fromLatin1(control::kDefaultScenario));
    auto* openFile = new QPushButton(tr("Open scenario…"));
    m_editor = new QPlainTextEdit;
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setToolTip(
        tr("The scenario as JSON (schema in docs/mpc.md): setpoint steps, input steps and ramps, "
           "hidden mechanisms switched on mid-run, noise. Edits are checked when you run."));
    // Two to a row: three ("… (not learnt)") held the window 1,149 px wide at the least.
    auto* controllers = new QGridLayout;
    for (int i = 0; i < 5; ++i) {
        m_controllers[i] = new QCheckBox(controllerDisplayName(kKinds[i]));
        m_controllers[i]->setChecked(true);
        // The user's tick, kept while the box is greyed out (its model not learnt yet).
        connect(m_controllers[i], &QCheckBox::clicked, this, [this, i](bool on) { m_wanted[i] = on; });
        controllers->addWidget(m_controllers[i], i / 2, i % 2);
    }
    m_state = new ModelStateBar(m_workbench);
    m_run = new QPushButton(tr("Run scenario"));
    m_blocked = makeInlineError();
    m_prediction = new QComboBox;
    m_prediction->setToolTip(tr("Show the horizon the controllers predicted at this decision"));
    m_note = new QLabel(tr("Runs the scenario against the virtual plant once per controller."));
    m_note->setWordWrap(true);
    // Quantity and unit on two lines, as the Residual tab's tables: seven columns beside the
    // controllers' names fit the left half of a 1280-pixel window.
    m_table =
        makeResultTable({tr("Controller"), tr("IAE\n[% wb·s]"), tr("Effort\n[K²]"), tr("Violations\n[%]"),
                         tr("Solve median\n[ms]"), tr("Fallbacks"), tr("Model gain\n[%/K]")});
    setHeaderToolTips(
        m_table,
        {QString(),
         tr("IAE: the outlet moisture's distance from its setpoint, summed over every second of the run "
            "(% wb × s); smaller is tighter control."),
         tr("Effort: the squared moves of the hot-air setpoint, summed (K²); smaller is gentler on the "
            "burner."),
         tr("Share of the run with the product outside its specification band."),
         tr("Median time the controller took to decide, per decision."),
         tr("Decisions where the optimiser failed and the controller kept its last move, of all "
            "decisions."),
         tr("How much X_out changes per kelvin of hot air in the controller's model (median); compare "
            "with the plant's own gain below.")});
    m_plots = new PlotStack;
    m_plots->addPlot(tr("X_out, true [% wb]"));
    m_plots->addPlot(tr("T_hot setpoint [°C]"));

    auto* left = new QWidget;
    auto* ll = new QVBoxLayout(left);
    ll->addWidget(m_state);
    auto* top = new QHBoxLayout;
    top->addWidget(m_scenario, 1);
    top->addWidget(openFile);
    ll->addLayout(top);
    // The scenario as a form, its JSON one tab away; both edit the same text.
    m_form = new ScenarioForm;
    auto* formScroll = new QScrollArea;
    formScroll->setWidget(m_form);
    formScroll->setWidgetResizable(true);
    m_scenarioTabs = new QTabWidget;
    m_scenarioTabs->addTab(formScroll, tr("Form"));
    m_scenarioTabs->addTab(m_editor, tr("JSON"));
    // A row of the form (or the JSON) at least: on a small laptop screen the results table's five
    // rows and its two-line header come first, and the form scrolls.
    m_scenarioTabs->setMinimumHeight(m_scenarioTabs->tabBar()->sizeHint().height() +
                                     2 * m_scenarioTabs->fontMetrics().height() + 16);
    ll->addWidget(m_scenarioTabs, 2);
    auto* controllerBox = new QWidget;
    controllerBox->setLayout(controllers);
    ll->addWidget(controllerBox);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(m_run);
    runRow->addWidget(new QLabel(tr("prediction at")));
    runRow->addWidget(m_prediction, 1);
    ll->addLayout(runRow);
    ll->addWidget(new QueuedNote(m_workbench, Action::Mpc));
    ll->addWidget(m_blocked);
    ll->addWidget(m_note);
    ll->addWidget(m_table, 1);
    fitTableHeight(m_table, 5); // a row per controller; the form above scrolls instead
    m_table->setWordWrap(true);
    m_table->setTextElideMode(Qt::ElideNone);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(m_plots);
    split->setStretchFactor(1, 1);
    split->setSizes({640, 640}); // the plots need room as much as the form and the table
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);

    const auto load = [this] {
        const auto& all = control::bundledScenarios();
        const auto it = all.find(m_scenario->currentText().toStdString());
        if (it != all.end()) {
            m_editor->setPlainText(QString::fromStdString(it->second));
        }
    };
    connect(m_scenario, &QComboBox::currentTextChanged, this, load);
    // Another bundled scenario chosen by the user is an edit a project must keep.
    connect(m_scenario, QOverload<int>::of(&QComboBox::activated), this, &MpcPanel::scenarioEdited);
    connect(m_form, &ScenarioForm::edited, this, [this] {
        m_editor->blockSignals(true);
        m_editor->setPlainText(m_form->json());
        m_editor->blockSignals(false);
        updateRunState();
        Q_EMIT scenarioEdited();
    });
    // Text typed in the JSON tab goes into the form at once: its checks and Run's state follow
    // the text, whichever tab is in front.
    connect(m_editor, &QPlainTextEdit::textChanged, this, [this] {
        m_form->setJson(m_editor->toPlainText());
        updateRunState();
        if (!m_settingScenario) {
            Q_EMIT scenarioEdited();
        }
    });
    connect(m_form, &ScenarioForm::validityChanged, this, &MpcPanel::updateRunState);
    connect(&m_workbench, &Workbench::runningChanged, this, &MpcPanel::updateRunState);
    connect(m_scenarioTabs, &QTabWidget::currentChanged, this, [this](int index) {
        if (index == 0) {
            m_form->setJson(m_editor->toPlainText());
        }
    });
    m_settingScenario = true;
    load();
    m_settingScenario = false;
    connect(openFile, &QPushButton::clicked, this, [this] {
        const QString p = askOpenFile(this, tr("Open scenario"), tr("Scenarios (*.json)"));
        QFile f(p);
        if (!p.isEmpty() && f.open(QIODevice::ReadOnly)) {
            m_editor->setPlainText(QString::fromUtf8(f.readAll()));
        }
    });
    connect(m_run, &QPushButton::clicked, this, &MpcPanel::run);
    connect(&m_workbench, &Workbench::modelStateChanged, this, &MpcPanel::offerControllers);
    connect(&m_workbench, &Workbench::runningChanged, this, &MpcPanel::offerControllers);
    offerControllers();
    connect(m_prediction, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &MpcPanel::show);
    m_plots->setEmptyText(tr("Run a scenario to see each controller's outlet moisture and hot-air setpoint"));
    connect(&m_workbench, &Workbench::resultsRestored, this, &MpcPanel::showRun);
    connect(&m_workbench, &Workbench::mpcFinished, this, [this] {
        m_awaitingRun = false;
        m_note->setStyleSheet(QString());
        showRun();
    });
    // A run that fails or is cancelled says so under Run, where "Running…" stood; the results
    // shown stay those of the last complete run.
    connect(&m_workbench, &Workbench::failed, this,
            [this](const QString&, const QString& message, bool cancelled) {
                if (!m_awaitingRun || m_workbench.isRunning(Action::Mpc)) {
                    return; // another action's failure, while this run waits behind it
                }
                m_awaitingRun = false;
                QString text = message;
                // The editor's text runs from a temporary file, a name that means nothing to the user.
                text.replace(m_tempScenario, tr("the scenario"));
                text.replace(QDir::toNativeSeparators(m_tempScenario), tr("the scenario"));
                const bool shown = m_workbench.latest().mpc.has_value();
                if (cancelled) {
                    m_note->setStyleSheet(QString());
                    m_note->setText(
                        shown ? tr("The run was cancelled; the results below are from the last complete run.")
                              : tr("The run was cancelled."));
                } else {
                    m_note->setStyleSheet(QStringLiteral("color: #a40000;"));
                    m_note->setText(
                        shown ? tr("%1\nThe results below are from the last complete run.").arg(text) : text);
                }
            });
    updateRunState();
}

QString MpcPanel::gainMismatchText(const QString& controller, double ratio) {
    if (ratio < 0) {
        return tr("%1: its model's gain has the other sign than the plant's, so it steers the hot air the "
                  "wrong way.")
            .arg(controller);
    }
    if (ratio < 1) {
        return tr("%1: its model's gain is %2 times the plant's; it underrates the hot air's effect, so it "
                  "over-acts (the setpoint swings towards its limits).")
            .arg(controller)
            .arg(ratio, 0, 'f', 2);
    }
    return tr("%1: its model's gain is %2 times the plant's; it overrates the hot air's effect, so it acts "
              "too little.")
        .arg(controller)
        .arg(ratio, 0, 'f', 2);
}

QString MpcPanel::scenarioProblem() const {
    if (!m_form->isValid()) {
        const QStringList problems = m_form->problems();
        return problems.size() == 1
                   ? problems.first()
                   : tr("%1 (problems in the form: %2)").arg(problems.first()).arg(problems.size());
    }
    // Checked as the engine will read it: keys the form has no field for, JSON typed by hand.
    const auto parsed = control::parseScenario(m_editor->toPlainText().toStdString(), "json");
    if (parsed) {
        return {};
    }
    const std::string& place = parsed.error().place;
    const auto colon = place.rfind(':');
    const QString line =
        colon == std::string::npos ? QString() : QString::fromStdString(place.substr(colon + 1));
    // The parser's reason in English only where the window is: elsewhere the line it names and
    // that the scenario file's schema (docs/mpc.md) is not met.
    const QString reason =
        engineDetailText(parsed.error().reason, tr("a value or key the scenario's schema does not accept"));
    return line.isEmpty() ? tr("The scenario's JSON: %1").arg(reason)
                          : tr("The scenario's JSON, line %1: %2").arg(line, reason);
}

void MpcPanel::updateRunState() {
    const QString problem = scenarioProblem();
    m_blocked->setText(problem.isEmpty() ? QString() : tr("Run is off until this is fixed: %1").arg(problem));
    m_blocked->setVisible(!problem.isEmpty());
    m_run->setEnabled(problem.isEmpty() && !m_workbench.isRunning(Action::Mpc));
}

void MpcPanel::showRun() {
    {
        m_prediction->blockSignals(true);
        m_prediction->clear();
        if (const auto& r = m_workbench.latest().mpc) {
            for (const auto& run : r->closedLoop.runs) {
                for (const auto& p : run.predictions) {
                    if (m_prediction->findData(p.atS) < 0) {
                        m_prediction->addItem(tr("%1 s").arg(p.atS), p.atS);
                    }
                }
            }
        }
        m_prediction->blockSignals(false);
        show();
    }
}

QString MpcPanel::scenarioName() const {
    return m_scenario->currentText();
}

QString MpcPanel::scenarioText() const {
    return m_editor->toPlainText();
}

void MpcPanel::setScenario(const QString& name, const QString& text) {
    m_settingScenario = true;
    {
        // The list shows the bundled scenario it started from; the text is the one kept, edits
        // and all (choosing the name would load the bundled text over it).
        const QSignalBlocker blockList(m_scenario);
        if (m_scenario->findText(name) >= 0) {
            m_scenario->setCurrentText(name);
        }
    }
    m_editor->setPlainText(text);
    m_settingScenario = false;
}

MpcPanel::~MpcPanel() {
    // The panel's own file, rewritten by each of its runs (Run is off while one is queued): gone
    // with the panel, not left in the temporary folder.
    if (!m_tempScenario.isEmpty()) {
        QFile::remove(m_tempScenario);
    }
}

void MpcPanel::run() {
    if (const QString problem = scenarioProblem(); !problem.isEmpty()) {
        m_note->setStyleSheet(QStringLiteral("color: #a40000;"));
        m_note->setText(tr("Not run: %1").arg(problem));
        return;
    }
    // The editor's text goes through the engine's own scenario parser again when the run starts.
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::TempLocation);
    // One name a panel (each window has its own; a language switch opens a second): the
    // destructor removes its own file, never another panel's that a queued run may still read.
    static int panelsSoFar = 0;
    if (m_tempScenario.isEmpty()) {
        m_tempScenario = QDir(dir).filePath(QStringLiteral("drytwin-scenario-%1-%2.json")
                                                .arg(QCoreApplication::applicationPid())
                                                .arg(++panelsSoFar));
    }
    QFile f(m_tempScenario);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        m_note->setStyleSheet(QStringLiteral("color: #a40000;"));
        m_note->setText(tr("Cannot write %1").arg(m_tempScenario));
        return;
    }
    f.write(m_editor->toPlainText().toUtf8());
    f.close();
    workflow::MpcOptions o;
    o.scenarioPath = m_tempScenario.toStdString();
    o.closedLoop.controllers.clear();
    for (int i = 0; i < 5; ++i) {
        // A model being learnt right now counts: the run is queued behind the training (--run
        // train,mpc; a click on Run while Learn runs), and the engine skips what is still missing.
        const bool exists = m_controllers[i]->isEnabled() || m_workbench.isRunning(Action::Train);
        if (exists && (m_controllers[i]->isEnabled() ? m_controllers[i]->isChecked() : m_wanted[i])) {
            o.closedLoop.controllers.push_back(kKinds[i]);
        }
    }
    if (o.closedLoop.controllers.empty()) {
        m_note->setStyleSheet(QStringLiteral("color: #a40000;"));
        m_note->setText(tr("Choose at least one controller."));
        return;
    }
    m_note->setStyleSheet(QString());
    m_note->setText(tr("Running…"));
    m_awaitingRun = true;
    m_workbench.runMpc(o);
}

void MpcPanel::offerControllers() {
    // Exactly the models that exist: a stale or absent one is shown, unticked, with why.
    for (int i = 0; i < 5; ++i) {
        const auto kind = kKinds[i];
        const bool exists = m_workbench.hasController(kind);
        const auto& part = m_workbench.learntPart(kind);
        QString label = controllerDisplayName(kind);
        QString tip = tr("Contract key: %1").arg(QString::fromLatin1(control::controllerName(kind)));
        if (!exists && part.state == PartState::Stale && m_workbench.isRunning(Action::Train)) {
            // Not "retrain it" while a retraining is under way or queued (issue #72 item 8).
            label = tr("%1 (stale, being learnt again)").arg(label);
            tip =
                tr("Learnt before %1; it is being learnt again now.").arg(staleReasonText(part.staleBecause));
        } else if (!exists && part.state == PartState::Stale) {
            label = tr("%1 (stale)").arg(label);
            tip = tr("Learnt before %1: retrain it to run it.").arg(staleReasonText(part.staleBecause));
        } else if (!exists) {
            label = tr("%1 (not learnt)").arg(label);
            tip = tr("Learn the correction models on the Residual model tab to run it.");
        }
        m_controllers[i]->setText(label);
        m_controllers[i]->setToolTip(tip);
        m_controllers[i]->setChecked(exists && m_wanted[i]);
        m_controllers[i]->setEnabled(exists);
    }
}

void MpcPanel::show() {
    const auto& r = m_workbench.latest().mpc;
    if (!r) {
        return;
    }
    const auto& cl = r->closedLoop;
    m_table->setRowCount(0);
    m_plots->clearCurves();
    const double at = m_prediction->currentData().toDouble();
    bool setpointDrawn = false;
    // Every controller's prediction under one legend entry, drawn dash-dot in its controller's
    // colour: ten entries, five of them "… predicted at 60 s", took the legend a column of its own
    // and the plot's room. The entry's key is black; its check box shows or hides them all.
    const QString predictedName = tr("predicted at %1 s").arg(at);
    bool predictedKeyDrawn = false;
    QStringList gainWarnings;
    for (const auto& run : cl.runs) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        const auto& m = run.metrics;
        const bool pi = run.kind == control::ControllerKind::Pi;
        const QStringList cells{
            controllerDisplayName(run.kind),
            run.ran ? QString::number(m.iaePctS, 'f', 1) : tr("skipped"),
            run.ran ? QString::number(m.effortK2, 'f', 1) : tr("the model holds no such prediction model"),
            run.ran ? QString::number(m.violationPct, 'f', 1) : QString(),
            run.ran && !pi ? QString::number(m.solveMsMedian, 'f', 2) : QStringLiteral("–"),
            run.ran && !pi ? QStringLiteral("%1 / %2").arg(m.fallbacks).arg(m.decisions)
                           : QStringLiteral("–"),
            run.ran && !pi ? QString::number(m.gainPctPerKMedian, 'f', 4) : QStringLiteral("–")};
        setTableRow(m_table, row, cells);
        m_table->item(row, 0)->setToolTip(cells.front());
        if (!run.ran) {
            continue;
        }
        if (run.metrics.fallbacks > 0 && !run.metrics.lastFallbackReason.empty()) {
            m_table->item(row, 5)->setToolTip(
                tr("Decisions that kept the previous plan (the model saw no effect of the hot air, or the "
                   "solve failed); the last reason: %1")
                    .arg(fallbackReasonText(run.metrics.lastFallbackReason)));
        }
        if (const auto ratio =
                pi ? std::nullopt : control::mismatchedGainRatio(m.gainPctPerKMedian, cl.plantGainPctPerK)) {
            const QString why = gainMismatchText(controllerDisplayName(run.kind), *ratio);
            gainWarnings << why;
            m_table->item(row, 6)->setForeground(QColor(170, 20, 20));
            m_table->item(row, 6)->setToolTip(why);
        }
        const QColor colour = modelColour(control::controllerName(run.kind));
        const QVector<double> t(run.timeS.begin(), run.timeS.end());
        if (!setpointDrawn) {
            m_plots->addCurve(0, tr("setpoint"), t,
                              QVector<double>(run.setpointPct.begin(), run.setpointPct.end()), Qt::black,
                              Qt::DashLine, 1.4);
            QVector<double> hi, lo;
            for (double s : run.setpointPct) {
                hi << s + cl.scenario.bandPct;
                lo << s - cl.scenario.bandPct;
            }
            // Black like the setpoint it belongs to: grey is the physics model's colour.
            m_plots->addCurve(0, tr("band"), t, hi, Qt::black, Qt::DotLine, 1.0);
            m_plots->addCurve(0, QString(), t, lo, Qt::black, Qt::DotLine, 1.0);
            setpointDrawn = true;
        }
        const QString name = controllerDisplayName(run.kind);
        m_plots->addCurve(0, name, t, QVector<double>(run.xOutTruePct.begin(), run.xOutTruePct.end()), colour,
                          Qt::SolidLine, run.kind == control::ControllerKind::PgrlCc ? 1.8 : 1.1);
        m_plots->addCurve(1, name, t, QVector<double>(run.hotAirSetpointC.begin(), run.hotAirSetpointC.end()),
                          colour);
        for (const auto& p : run.predictions) {
            if (p.atS == at) {
                QVector<double> pt, px;
                for (std::size_t i = 0; i < p.xOutPct.size(); ++i) {
                    pt << p.atS + static_cast<double>(i);
                    px << p.xOutPct[i];
                }
                if (!predictedKeyDrawn) {
                    m_plots->addCurve(0, predictedName, {}, {}, Qt::black, Qt::DashDotLine, 1.6);
                    predictedKeyDrawn = true;
                }
                m_plots->addCurve(0, predictedName, pt, px, colour, Qt::DashDotLine, 1.6);
            }
        }
    }
    fitTableWidth(m_table);
    // The controllers' names are long ("Physics + learnt correction (PGRL-CC)"): wrapped on two
    // lines in a column half their width, not cut to "Physics + learnt …" beside six numbers in
    // the left half of a 1280-pixel window (a newcomer's review).
    int widest = 0;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        widest = std::max(widest, m_table->fontMetrics().horizontalAdvance(m_table->item(r, 0)->text()));
    }
    const int nameWidth = widest / 2 + 3 * m_table->fontMetrics().averageCharWidth();
    if (widest > 0 && nameWidth < m_table->columnWidth(0)) {
        m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Interactive);
        m_table->setColumnWidth(0, nameWidth);
        m_table->resizeRowsToContents();
    }
    m_plots->rescale();
    m_plots->setTimeCursor(at > 0 ? at : NAN);
    m_note->setText(
        tr("%1. IAE and violations on the product's true outlet moisture; the plant's own gain is %2 % "
           "wb/K.")
            .arg(mpcEndingText(cl))
            .arg(cl.plantGainPctPerK, 0, 'f', 4) +
        (gainWarnings.isEmpty() ? QString() : QLatin1Char(' ') + gainWarnings.join(QLatin1Char(' '))));
}

} // namespace drytwin::widgets
