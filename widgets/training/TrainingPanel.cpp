#include "training/TrainingPanel.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "control/BundledScenarios.h"
#include "control/ClosedLoop.h"
#include "training/FaultWords.h"
#include "training/TrainingPanelInternal.h"
#include "training/TrainingRunner.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_text.h>
#include <utility>

namespace drytwin::widgets {

using namespace training_panel;

TrainingPanel::TrainingPanel(Workbench& workbench, QWidget* parent)
    : QWidget(parent), m_workbench(workbench), m_runner(new TrainingRunner(this)) {
    // Session row: scenario, start, role switch, clock.
    m_scenario = new QComboBox;
    for (const auto& [name, text] : control::bundledScenarios()) {
        m_scenario->addItem(QString::fromStdString(name));
    }
    m_scenario->setCurrentText(QString::fromLatin1(kDefaultTrainingScenario));
    m_scenario->setToolTip(tr("The line's conditions: initial levels, load changes, seed (docs/mpc.md)"));
    m_start = new QPushButton(tr("Start session"));
    // The instructor's controls, the faults, the true moisture and the score live in a window of
    // their own (on the instructor's screen), never on the trainee's; a password can guard it.
    m_instructor = new QPushButton(tr("Instructor window…"));
    m_instructor->setToolTip(tr("Opens the instructor's window: clock, snapshots, faults, the true moisture "
                                "and the score. Not on the trainee's screen."));
    m_clock = new QLabel(tr("No session"));
    QFont big = m_clock->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    big.setBold(true);
    m_clock->setFont(big);

    // Operator.
    m_speed = new QComboBox;
    for (int f : {1, 2, 5, 10, 20, 50}) {
        m_speed->addItem(tr("%1×").arg(f), f);
    }
    m_speed->setCurrentIndex(3);
    m_setpoint = new QDoubleSpinBox;
    m_setpoint->setRange(8, 20);
    m_setpoint->setDecimals(2);
    m_setpoint->setSingleStep(0.1);
    m_setpoint->setSuffix(tr(" % wb"));
    m_setpoint->setValue(13);
    auto* applySetpoint = new QPushButton(tr("Apply"));
    m_controller = new QComboBox;
    for (auto k : kControllers) {
        m_controller->addItem(controllerLabel(k), static_cast<int>(k));
    }
    m_controllerNote = new QLabel;
    m_controllerNote->setWordWrap(true);
    connect(&m_workbench, &Workbench::modelStateChanged, this, &TrainingPanel::offerControllers);
    offerControllers();
    auto* operatorBox = new QGroupBox(tr("Operator"));
    auto* of = new QFormLayout(operatorBox);
    of->addRow(tr("Speed"), m_speed);
    auto* spRow = new QHBoxLayout;
    spRow->addWidget(m_setpoint, 1);
    spRow->addWidget(applySetpoint);
    of->addRow(tr("X_out setpoint"), spRow);
    of->addRow(tr("Controller"), m_controller);
    of->addRow(m_controllerNote);

    // Trainee.
    m_diagnose = new QPushButton(tr("Diagnose the recording…"));
    m_diagnose->setToolTip(tr("Saves what the line recorded so far as a batch file and opens it, so that the "
                              "Discover tab can show what the model gets wrong"));
    m_cause = new QComboBox;
    m_cause->addItem(tr("No fault"), QStringLiteral("no_fault"));
    for (const auto& mi : plant::mechanisms()) {
        m_cause->addItem(mechanismLabel(mi.id), fromView(mi.name));
    }
    m_answer = new QPushButton(tr("Name the cause"));
    m_answers = new QListWidget;
    m_answers->setMaximumHeight(64);
    m_pause = new QPushButton(tr("Pause"));
    m_pause->setToolTip(tr("Stops the line's clock while you think; press again to continue"));
    auto* traineeBox = new QGroupBox(tr("Trainee"));
    auto* tl = new QVBoxLayout(traineeBox);
    auto* traineeRow = new QHBoxLayout;
    traineeRow->addWidget(m_diagnose, 1);
    traineeRow->addWidget(m_pause);
    tl->addLayout(traineeRow);
    auto* causeRow = new QHBoxLayout;
    causeRow->addWidget(m_cause, 1);
    causeRow->addWidget(m_answer);
    tl->addLayout(causeRow);
    tl->addWidget(new QLabel(tr("Causes named (session time):")));
    tl->addWidget(m_answers);

    // Instructor.
    m_freeze = new QPushButton(tr("Freeze"));
    m_aheadMin = new QSpinBox;
    m_aheadMin->setRange(1, 120);
    m_aheadMin->setValue(5);
    m_aheadMin->setSuffix(tr(" min"));
    auto* ahead = new QPushButton(tr("Run ahead"));
    ahead->setToolTip(tr("Runs the line this much further at full speed"));
    m_snapshotLabel = new QLineEdit;
    m_snapshotLabel->setPlaceholderText(tr("label (default: the time)"));
    m_snapshot = new QPushButton(tr("Take snapshot"));
    m_snapshots = new QListWidget;
    m_snapshots->setMaximumHeight(70);
    m_restore = new QPushButton(tr("Restore selected"));
    m_faultKind = new QComboBox;
    for (const auto& mi : plant::mechanisms()) {
        m_faultKind->addItem(mechanismLabel(mi.id), static_cast<int>(mi.id));
    }
    m_faultKind->setCurrentIndex(static_cast<int>(plant::Mechanism::MoistureMeterOffset));
    m_faultStrength = new QDoubleSpinBox;
    m_faultStrength->setDecimals(3);
    m_faultDelay = new QSpinBox;
    m_faultDelay->setRange(0, 7200);
    m_faultDelay->setSuffix(tr(" s from now"));
    m_inject = new QPushButton(tr("Inject fault"));
    m_faults = makeResultTable({tr("Fault"), tr("Strength"), tr("Acts from"), tr("Found")});
    m_faults->setMaximumHeight(100);
    m_score = new QLabel;
    m_score->setWordWrap(true);
    auto* save = new QPushButton(tr("Save session…"));
    auto* open = new QPushButton(tr("Open session…"));
    m_instructorBox = new QGroupBox(tr("Instructor"));
    auto* il = new QVBoxLayout(m_instructorBox);
    il->addWidget(m_score);
    auto* pages = new QTabWidget;
    auto* clockPage = new QWidget;
    auto* cl = new QGridLayout(clockPage);
    cl->addWidget(m_freeze, 0, 0);
    cl->addWidget(m_aheadMin, 0, 1);
    cl->addWidget(ahead, 0, 2);
    cl->addWidget(m_snapshotLabel, 1, 0, 1, 2);
    cl->addWidget(m_snapshot, 1, 2);
    cl->addWidget(m_snapshots, 2, 0, 1, 2);
    cl->addWidget(m_restore, 2, 2, Qt::AlignTop);
    pages->addTab(clockPage, tr("Clock and snapshots"));
    auto* faultPage = new QWidget;
    auto* fl = new QGridLayout(faultPage);
    // Each field says what it is: a bare number and unit left the instructor guessing.
    fl->addWidget(new QLabel(tr("Fault")), 0, 0);
    fl->addWidget(m_faultKind, 0, 1, 1, 2);
    fl->addWidget(new QLabel(tr("Strength")), 1, 0);
    fl->addWidget(m_faultStrength, 1, 1);
    fl->addWidget(new QLabel(tr("Acts from")), 2, 0);
    fl->addWidget(m_faultDelay, 2, 1);
    fl->addWidget(m_inject, 1, 2, 2, 1);
    fl->addWidget(m_faults, 3, 0, 1, 3);
    pages->addTab(faultPage, tr("Faults"));
    auto* filePage = new QWidget;
    auto* filesLayout = new QVBoxLayout(filePage);
    auto* filesNote =
        new QLabel(tr("A session file holds the scenario, every event (faults, snapshots, answers) and "
                      "the recording as a batch file; reopening replays it to the same data."));
    filesNote->setWordWrap(true);
    filesLayout->addWidget(filesNote);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(save);
    fileRow->addWidget(open);
    filesLayout->addLayout(fileRow);
    auto* password = new QPushButton(tr("Set instructor password…"));
    password->setToolTip(tr("Asked before the instructor window opens (empty: no password)"));
    filesLayout->addWidget(password);
    connect(password, &QPushButton::clicked, this, [this] {
        bool ok = false;
        const QString given =
            QInputDialog::getText(m_instructorWindow, tr("Instructor"),
                                  tr("New instructor password (empty: none):"), QLineEdit::Password, {}, &ok);
        if (ok) {
            QSettings().setValue(QStringLiteral("training/instructorPasswordHash"),
                                 given.isEmpty() ? QString() : passwordHash(given));
        }
    });
    filesLayout->addStretch(1);
    pages->addTab(filePage, tr("Session file"));
    il->addWidget(pages);

    m_note = new QLabel(tr("Start a session: the line runs live under its PI loop."));
    m_note->setWordWrap(true);
    m_monitorLabel = new QLabel;
    m_monitorLabel->setWordWrap(true);
    m_monitorLabel->setTextFormat(Qt::RichText);
    m_monitorLabel->setToolTip(tr(
        "Two detectors commissioned on healthy runs of this line: the physics model's error, and a dynamic "
        "PCA monitor of the screens' signals. Each alarms when the line leaves its normal (1 % chance of a "
        "false alarm over the session)"));

    auto* side = new QWidget;
    auto* sl = new QVBoxLayout(side);
    sl->addWidget(operatorBox);
    sl->addWidget(traineeBox);
    sl->addWidget(m_monitorLabel);
    sl->addWidget(m_note);
    sl->addStretch(1);
    auto* scroll = new QScrollArea;
    scroll->setWidget(side);
    scroll->setWidgetResizable(true);
    scroll->setMinimumWidth(400);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    m_plots = new PlotStack;
    m_plots->addPlot(tr("X_out [% wb]"));
    m_plots->addPlot(tr("T_hot [°C]"));
    m_plots->addPlot(tr("Feed [kg/h]")); // the unit of the batch files and the Data tab
    m_plots->addPlot(tr("X_in [% wb]"));
    m_plots->setXTitle(tr("session time [min]"));
    const QVector<double> none;
    m_bandHigh = m_plots->addCurve(0, tr("band"), none, none, Qt::gray, Qt::DotLine, 1.0);
    m_bandLow = m_plots->addCurve(0, QString(), none, none, Qt::gray, Qt::DotLine, 1.0);
    m_xSetpoint = m_plots->addCurve(0, tr("setpoint"), none, none, Qt::black, Qt::DashLine, 1.4);
    m_xMeasured = m_plots->addCurve(0, tr("X_out measured"), none, none, seriesColour(0), Qt::SolidLine, 1.3);
    // The instructor's window: its controls beside the true outlet moisture against the measured.
    m_instructorWindow = new QWidget(this, Qt::Window);
    m_instructorWindow->setWindowTitle(tr("DryTwin — instructor"));
    m_instructorWindow->resize(980, 640);
    m_truthPlots = new PlotStack;
    m_truthPlots->addPlot(tr("X_out [% wb]"));
    m_truthPlots->setXTitle(tr("session time [min]"));
    m_truthPlots->setHintVisible(false);
    m_truthMeasured =
        m_truthPlots->addCurve(0, tr("X_out measured"), none, none, seriesColour(0), Qt::SolidLine, 1.3);
    m_xTrue =
        m_truthPlots->addCurve(0, tr("X_out true"), none, none, QColor(200, 40, 40), Qt::SolidLine, 1.3);
    // The band the score counts out-of-band time against, as on the trainee's plot.
    m_truthBandHigh = m_truthPlots->addCurve(0, tr("band"), none, none, Qt::gray, Qt::DotLine, 1.0);
    m_truthBandLow = m_truthPlots->addCurve(0, QString(), none, none, Qt::gray, Qt::DotLine, 1.0);
    m_truthSetpoint = m_truthPlots->addCurve(0, tr("setpoint"), none, none, Qt::black, Qt::DashLine, 1.4);
    // The legend says what the vertical lines are; each line's label names its cause.
    m_truthPlots->addCurve(0, tr("fault began"), none, none, kFaultColour, Qt::DashLine, 1.5);
    m_truthPlots->addCurve(0, tr("trainee's answer"), none, none, kAnswerColour, Qt::DashLine, 1.5);
    m_instructorWindow->restoreGeometry(
        QSettings().value(QStringLiteral("training/instructorGeometry")).toByteArray());
    m_instructorWindow->installEventFilter(this);
    auto* instructorLayout = new QHBoxLayout(m_instructorWindow);
    instructorLayout->addWidget(m_truthPlots, 1);
    instructorLayout->addWidget(m_instructorBox);
    m_hotSetpoint =
        m_plots->addCurve(1, tr("T_hot setpoint"), none, none, seriesColour(4), Qt::DashLine, 1.2);
    m_hot = m_plots->addCurve(1, tr("T_hot"), none, none, seriesColour(2));
    m_feed = m_plots->addCurve(2, tr("feed"), none, none, seriesColour(5));
    m_xIn = m_plots->addCurve(3, tr("X_in"), none, none, seriesColour(3));
    m_plots->addPlot(tr("T² [-]")); // the legend says whose (the monitor's, of the model's error)
    m_plots->setLogScale(4, false, true);
    m_monitorLimit = m_plots->addCurve(4, tr("99 % limit"), none, none, Qt::black, Qt::DashLine, 1.0);
    m_monitorT2 = m_plots->addCurve(4, tr("T² of the model's error"), none, none, QColor(214, 39, 40),
                                    Qt::SolidLine, 1.3);
    // The alarm and the change's start where the monitor's sentence says them: on the plot,
    // where a trainee looks (the alarm at 13 min was a sentence beside a plot of minutes 15–30).
    const auto verticalMarker = [this](const QString& label, const QColor& colour) {
        auto* m = new QwtPlotMarker(label);
        m->setLineStyle(QwtPlotMarker::VLine);
        m->setLinePen(colour, 1.5, Qt::DashDotLine);
        QwtText text(label);
        text.setColor(colour);
        m->setLabel(text);
        // Beside the line, low in the plot: a vertical label was longer than the plot is tall.
        m->setLabelAlignment(Qt::AlignRight | Qt::AlignBottom);
        m->setVisible(false);
        m->attach(m_plots->plot(4));
        return m;
    };
    m_alarmMarker = verticalMarker(tr("alarm"), QColor(214, 39, 40));
    m_onsetMarker = verticalMarker(tr("change began"), QColor(120, 60, 160));
    // Before a session runs, each plot shows its quantity's usual range on the line, not 0–1000.
    m_plots->setEmptyRange(0, 10, 16);     // X_out [% wb]
    m_plots->setEmptyRange(1, 140, 200);   // T_hot [°C]
    m_plots->setEmptyRange(2, 5000, 8000); // feed [kg/h]
    m_plots->setEmptyRange(3, 18, 26);     // X_in [% wb]
    m_plots->setEmptyRange(4, 0.1, 100);   // T² (log scale)
    m_plots->setEmptyXRange(0, kWindowS / 60.0);
    m_plots->setEmptyText(tr("Start a session to see the line run"));
    m_plots->setPlotEmptyText(4, tr("The monitor's T² shows once it has a minute of the model's error"));
    m_truthPlots->setEmptyRange(0, 10, 16);
    m_truthPlots->setEmptyXRange(0, kWindowS / 60.0);
    m_truthPlots->setEmptyText(tr("Start a session to see the true outlet moisture beside the measured"));

    m_progress = new QProgressBar;
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(160);
    m_stop = new QPushButton(tr("Stop"));
    m_stop->setToolTip(tr("Stops the replay or the run ahead; the line stays where it got to"));
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Scenario")));
    top->addWidget(m_scenario);
    top->addWidget(m_start);
    top->addSpacing(20);
    top->addWidget(m_clock, 1);
    top->addWidget(m_progress);
    top->addWidget(m_stop);
    top->addWidget(m_instructor);
    auto* split = new QSplitter;
    split->addWidget(m_plots);
    split->addWidget(scroll);
    split->setStretchFactor(0, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(split, 1);

    connect(m_start, &QPushButton::clicked, this, &TrainingPanel::startSession);
    connect(m_instructor, &QPushButton::clicked, this, [this] {
        // A password, when the instructor set one (View ▸ Training ▸ set in the instructor window).
        const QString hash = QSettings().value(QStringLiteral("training/instructorPasswordHash")).toString();
        if (!hash.isEmpty() && !qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
            bool ok = false;
            const QString given = QInputDialog::getText(this, tr("Instructor"), tr("Instructor password:"),
                                                        QLineEdit::Password, {}, &ok);
            if (!ok || passwordHash(given) != hash) {
                m_note->setText(tr("Wrong password: the instructor window stays closed."));
                return;
            }
        }
        setInstructorView(true);
    });
    connect(m_pause, &QPushButton::clicked, this, [this] {
        if (m_runner->frame().frozen) {
            m_runner->resume();
        } else {
            m_runner->freeze();
        }
    });
    connect(m_speed, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            [this] { m_runner->setSpeed(m_speed->currentData().toDouble()); });
    connect(applySetpoint, &QPushButton::clicked, this,
            [this] { m_runner->setSetpoint(m_setpoint->value()); });
    connect(m_controller, QOverload<int>::of(&QComboBox::activated), this, [this] {
        m_runner->setController(static_cast<control::ControllerKind>(m_controller->currentData().toInt()));
    });
    connect(m_answer, &QPushButton::clicked, this,
            [this] { m_runner->answer(m_cause->currentData().toString()); });
    connect(m_diagnose, &QPushButton::clicked, this, [this] {
        // Each diagnosis gets its own folder, so an earlier one stays as it was opened.
        m_diagnoseFolder = QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation))
                               .filePath(QStringLiteral("drytwin-training-%1-%2")
                                             .arg(QCoreApplication::applicationPid())
                                             .arg(QDateTime::currentMSecsSinceEpoch()));
        m_diagnosePending = true;
        m_runner->save(m_diagnoseFolder);
    });
    connect(m_freeze, &QPushButton::clicked, this, [this] {
        if (m_runner->frame().frozen) {
            m_runner->resume();
        } else {
            m_runner->freeze();
        }
    });
    connect(ahead, &QPushButton::clicked, this, [this] {
        setLongWork(true);
        m_runner->runAhead(60 * m_aheadMin->value());
    });
    connect(m_stop, &QPushButton::clicked, m_runner, &TrainingRunner::cancelLongWork);
    connect(m_runner, &TrainingRunner::progress, this,
            [this](double fraction) { m_progress->setValue(static_cast<int>(100 * fraction)); });
    connect(m_snapshot, &QPushButton::clicked, this, [this] {
        QString label = m_snapshotLabel->text().trimmed();
        if (label.isEmpty()) {
            label = clockText(m_runner->frame().timeS);
        }
        m_runner->takeSnapshot(label);
        m_snapshotLabel->clear();
    });
    connect(m_restore, &QPushButton::clicked, this, [this] {
        if (auto* item = m_snapshots->currentItem()) {
            m_runner->restore(item->data(Qt::UserRole).toString());
        } else {
            m_note->setText(tr("Select a snapshot to restore."));
        }
    });
    connect(m_faultKind, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            &TrainingPanel::updateFaultUnit);
    connect(m_inject, &QPushButton::clicked, this, [this] {
        const auto m = static_cast<plant::Mechanism>(m_faultKind->currentData().toInt());
        m_runner->injectFault(m, m_faultStrength->value(), m_faultDelay->value());
    });
    connect(save, &QPushButton::clicked, this, [this] {
        // A new folder named here is created (a folder dialog refuses one that does not exist yet).
        const QString folder =
            askSaveFile(this, tr("Save the session as a folder"),
                        QStringLiteral("training-%1")
                            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm"))),
                        tr("Session folder (*)"));
        if (!folder.isEmpty()) {
            saveSession(folder);
        }
    });
    connect(open, &QPushButton::clicked, this, [this] {
        const QString file = askOpenFile(this, tr("Open a training session"), tr("Sessions (*.json)"));
        if (!file.isEmpty()) {
            openSession(file);
        }
    });
    connect(m_runner, &TrainingRunner::frameReady, this, &TrainingPanel::showFrame);
    connect(m_runner, &TrainingRunner::failed, this, [this](const QString& action, const QString& message) {
        const bool wasOpening = std::exchange(m_opening, false);
        setLongWork(false);
        m_note->setText(tr("%1: %2").arg(action, message));
        if (wasOpening) {
            Q_EMIT sessionOpenFinished(m_openingFile, false, m_note->text());
        }
    });
    connect(m_runner, &TrainingRunner::saved, this,
            [this](const QString& sessionFile, const QStringList& csv, const QString& referenceFolder) {
                if (m_diagnosePending && sessionFile.startsWith(m_diagnoseFolder)) {
                    m_diagnosePending = false;
                    m_note->setText(referenceFolder.isEmpty()
                                        ? tr("Recording opened for diagnosis: %1. Run Discover on it, then "
                                             "name the cause here.")
                                              .arg(QDir::toNativeSeparators(csv.value(0)))
                                        : tr("Recording opened for diagnosis: %1; the line's commissioning "
                                             "runs are in %2. Run "
                                             "Discover on it, then name the cause here.")
                                              .arg(QDir::toNativeSeparators(csv.value(0)),
                                                   QDir::toNativeSeparators(referenceFolder)));
                    Q_EMIT recordingReady(csv.value(0), referenceFolder);
                } else {
                    m_note->setText(tr("Session saved: %1").arg(QDir::toNativeSeparators(sessionFile)));
                }
            });
    updateFaultUnit();
    setInstructorView(false);
    setLongWork(false);
}

TrainingPanel::~TrainingPanel() {
    if (m_instructorWindow->isVisible()) { // the program quits with it open: its place is kept too
        QSettings().setValue(QStringLiteral("training/instructorGeometry"),
                             m_instructorWindow->saveGeometry());
    }
}

bool TrainingPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_instructorWindow) {
        const auto type = event->type();
        if (type == QEvent::WindowStateChange && !m_instructorWindow->isMinimized() &&
            m_runner->frame().started) {
            // Back from minimised: the axes are recomputed from the curves as they are now (an
            // opening is redrawn by setInstructorView()).
            QMetaObject::invokeMethod(
                this, [this] { redrawPlots(); }, Qt::QueuedConnection);
        } else if (type == QEvent::Hide) {
            // Its place, for the next time it opens (closed, or hidden with the panel).
            QSettings().setValue(QStringLiteral("training/instructorGeometry"),
                                 m_instructorWindow->saveGeometry());
        }
    }
    return QWidget::eventFilter(watched, event);
}

QString TrainingPanel::keepCurrentSession() {
    if (!m_runner->frame().started) {
        return {};
    }
    // Queued before the new session replaces it, so the file holds the old one.
    const QString folder =
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
            .filePath(QStringLiteral("training-autosave/%1")
                          .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz"))));
    m_runner->save(folder);
    return folder;
}

void TrainingPanel::startSession() {
    const auto& all = control::bundledScenarios();
    const auto it = all.find(m_scenario->currentText().toStdString());
    if (it == all.end()) {
        return;
    }
    const QString kept = keepCurrentSession();
    m_runner->setSpeed(m_speed->currentData().toDouble());
    m_runner->start(QString::fromStdString(it->second), m_workbench.model());
    m_controller->setCurrentIndex(0);
    QString note = tr("Session started: the line runs under its PI loop. The MPC controllers use the model "
                      "loaded now.");
    if (!kept.isEmpty()) {
        note += QLatin1Char(' ') +
                tr("The previous session was saved in %1.").arg(QDir::toNativeSeparators(kept));
    }
    m_note->setText(note);
}

void TrainingPanel::saveSession(const QString& folder) {
    m_runner->save(folder);
}

void TrainingPanel::openSession(const QString& sessionFile) {
    keepCurrentSession();
    m_opening = true;
    m_openingFile = sessionFile;
    setLongWork(true);
    m_note->setText(tr("Replaying %1…").arg(QDir::toNativeSeparators(sessionFile)));
    m_runner->open(sessionFile, m_workbench.model());
}

void TrainingPanel::setInstructorView(bool on) {
    m_instructorWindow->setVisible(on);
    if (on) {
        // Its saved place may be on a monitor that is gone.
        keepOnScreen(m_instructorWindow);
        m_instructorWindow->raise();
        if (m_runner->frame().started) {
            redrawPlots(); // its plot is drawn only while it is open; a frozen line sends no frames
        }
    }
}

void TrainingPanel::offerControllers() {
    // Exactly the models that exist; a stale or missing one is listed, greyed, with why.
    auto* model = qobject_cast<QStandardItemModel*>(m_controller->model());
    for (int i = 0; i < m_controller->count(); ++i) {
        const auto kind = static_cast<control::ControllerKind>(m_controller->itemData(i).toInt());
        const bool exists = m_workbench.hasController(kind);
        QString label = controllerLabel(kind);
        if (!exists) {
            label = m_workbench.learntPart(kind).state == PartState::Stale
                        ? tr("%1 (stale: retrain)").arg(label)
                        : tr("%1 (not learnt)").arg(label);
        }
        m_controller->setItemText(i, label);
        if (model && model->item(i)) {
            model->item(i)->setEnabled(exists);
        }
    }
    if (!m_workbench.hasController(
            static_cast<control::ControllerKind>(m_controller->currentData().toInt()))) {
        m_controller->setCurrentIndex(0); // the PI loop always exists
    }
}

bool TrainingPanel::instructorView() const {
    return m_instructorWindow->isVisible();
}

QString TrainingPanel::passwordHash(const QString& password) {
    return QString::fromLatin1(
        QCryptographicHash::hash(password.toUtf8(), QCryptographicHash::Sha256).toHex());
}

void TrainingPanel::setLongWork(bool on) {
    m_progress->setVisible(on);
    m_stop->setVisible(on);
    if (on) {
        m_progress->setValue(0);
    }
}

void TrainingPanel::updateFaultUnit() {
    const auto& mi = plant::info(static_cast<plant::Mechanism>(m_faultKind->currentData().toInt()));
    m_faultStrength->setRange(0, mi.maxStrength);
    m_faultStrength->setSingleStep(mi.maxStrength / 50);
    m_faultStrength->setValue(mi.defaultStrength * 2); // clearly visible to a trainee, still realistic
    m_faultStrength->setSuffix(faultStrengthUnit(mi.id));
    m_faultStrength->setToolTip(faultStrengthToolTip(mi.id));
}

} // namespace drytwin::widgets
