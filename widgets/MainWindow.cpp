// How the window is put together: the tabs in their order with what each is for (Help ▸ What's
// This?), the pieces built in the files of widgets/mainwindow/, and the wiring between the tabs:
// the tab a project asked for, the training recording judged on the Discover tab, one time cursor
// for the 3D view and every plot. The rest, one file per question in widgets/mainwindow/: the menus
// (MainWindowMenus.cpp), Help (MainWindowHelp.cpp), projects (MainWindowProject.cpp), data loading
// and the column mapping (MainWindowData.cpp), the status bar and progress (MainWindowStatus.cpp),
// and what scripts drive (MainWindowScripting.cpp).

#include "MainWindow.h"

#include "calibration/CalibrationPanel.h"
#include "common/PlotStack.h"
#include "common/WheelGuard.h"
#include "common/WidgetHelpers.h"
#include "data/DataPanel.h"
#include "diagnostics/DiagnosticsPanel.h"
#include "discovery/DiscoverPanel.h"
#include "mainwindow/MainWindowInternal.h"
#include "model/ModelPanel.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "training/TrainingPanel.h"
#include "view3d/LineView3D.h"

#include <QCloseEvent>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QIcon>
#include <QLabel>
#include <QScreen>
#include <QSettings>
#include <QTabWidget>

namespace drytwin::widgets {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("DryTwin"));
    initDryTwinResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/drytwin.svg")));
    // 1280 x 800, or the room a smaller screen leaves (a 1366 x 768 laptop: its window manager then
    // fits the frame; the tabs ask for at most 690 px, theWindowFitsASmallLaptopScreen).
    QSize opening(1280, 800);
    if (const QScreen* screen = QGuiApplication::primaryScreen()) {
        opening = opening.boundedTo(screen->availableGeometry().size());
    }
    resize(opening);

    m_tabs = new QTabWidget;
    m_data = new DataPanel(m_workbench);
    m_model = new ModelPanel(m_workbench);
    m_calibration = new CalibrationPanel(m_workbench);
    m_residual = new ResidualPanel(m_workbench);
    m_diagnostics = new DiagnosticsPanel(m_workbench);
    m_discover = new DiscoverPanel(m_workbench);
    m_mpc = new MpcPanel(m_workbench);
    m_view3d = new LineView3D(m_workbench);
    m_tabs->addTab(m_data, tr("Data"));
    m_tabs->addTab(m_model, tr("Model"));
    m_tabs->addTab(m_calibration, tr("Calibrate"));
    m_tabs->addTab(m_residual, tr("Residual model"));
    m_tabs->addTab(m_diagnostics, tr("Diagnostics"));
    m_tabs->addTab(m_discover, tr("Discover"));
    m_tabs->addTab(m_mpc, tr("What-if MPC"));
    m_tabs->addTab(m_view3d, tr("3D line"));
    m_training = new TrainingPanel(m_workbench);
    m_tabs->addTab(m_training, tr("Training"));
    setCentralWidget(m_tabs);
    // Help ▸ What's This? (Shift+F1), then a click on a panel: what it shows and what to do there.
    m_data->setWhatsThis(
        tr("<b>Data</b>: the loaded batches, their rows kept by the cleaning, and every measured "
           "channel over time. Select several batches to overlay them; drop files here to open "
           "them. Files with other column names open through Column mapping…"));
    m_model->setWhatsThis(
        tr("<b>Model</b>: the physics model's parameters with units and bounds (paper Eqs. 1–19), "
           "and its simulation against the measurements. Edit a value to try it; Undo takes "
           "it back."));
    m_calibration->setWhatsThis(
        tr("<b>Calibrate</b>: fits the ticked parameters to the data (a global search, then a local "
           "polish: BOBYQA) and gives each its 95 % interval. Stop keeps the best so far."));
    m_residual->setWhatsThis(
        tr("<b>Residual model</b>: learns a correction of the physics model from the data "
           "(PGRL-CC, paper Eqs. 20–30) and scores it on held-out data beside the comparison "
           "models and the two trivial forecasts. Skill below 1 beats both."));
    m_diagnostics->setWhatsThis(
        tr("<b>Diagnostics</b>: the residuals' autocorrelation and spectrum (white noise is "
           "what a complete model leaves), where in the operating range the physics model "
           "errs, and what its error moves with."));
    m_discover->setWhatsThis(
        tr("<b>Discover</b>: what the simulation gets wrong, the physical cause when one is "
           "specific (better on every output it touches, consistent across batches, told "
           "apart from its look-alikes), and the gain of the extended model."));
    m_mpc->setWhatsThis(
        tr("<b>What-if MPC</b>: a scenario run against the virtual plant once per controller, "
           "an MPC on each model that exists and the plant's own PI loop, with the paper's "
           "Table 2 metrics."));
    m_view3d->setWhatsThis(
        tr("<b>3D line</b>: the drying tube, conveyor and winnower with the material parcels "
           "coloured by moisture at the time cursor; the slider moves every plot's cursor."));
    m_training->setWhatsThis(
        tr("<b>Training</b>: the line runs live for a trainee; the instructor's window injects "
           "faults, freezes the clock and scores the answers."));
    createDataSetChooser();
    trackUnsavedWork();
    createStatusBar();
    createMenus();
    // No value on any tab changes under a wheel turned to scroll past it (issue #72 item 7).
    ignoreWheelUnlessFocused(this);
    connectProgress();
    connectDataLoading();
    connect(&m_workbench, &Workbench::simulated, this, [this] {
        Q_EMIT simulationShown();
        if (m_pendingTab >= 0) {
            m_tabs->setCurrentIndex(m_pendingTab);
            m_pendingTab = -1;
        }
        if (!m_workbench.jobs().busy()) {
            Q_EMIT projectReady(true);
        }
    });
    // The trainee diagnoses the live line's recording on the Discover tab.
    // The recording opens beside the loaded data set (both stay in the data-set list).
    connect(
        m_training, &TrainingPanel::recordingReady, this,
        [this](const QString& csv, const QString& reference) {
            m_pendingTab = m_tabs->indexOf(m_discover);
            // The recording is judged alone: a reference chosen for the loaded data belongs to another
            // line. The line's commissioning runs are offered in the note as the reference to compare
            // with; not set by default: against three commissioning runs the change screen missed
            // the fouling that the recording alone shows (measured 2026-11-26: theta_foul's change
            // p 0.08; TestTrainingPanel names it alone). With six runs (since 2026-11-27) the
            // reference names 16 of 24 one-hour faults (docs/training.md).
            m_workbench.setReferencePath({});
            // Offered on the Discover tab's reference menu, first (its path was only text on the
            // Training tab, overwritten at once in the status line: issue #72 item 5).
            m_workbench.suggestReference(csv, reference);
            const QString before = m_workbench.dataSetLabel();
            m_workbench.openData(csv);
            if (!before.isEmpty()) {
                m_statusLabel->setText(
                    tr("Opening the recording beside %1; the data-set list at the top right switches back.")
                        .arg(before));
            }
        });
    // One time cursor for the 3D view and every time plot.
    const auto shareTime = [this](double t) {
        for (auto* stack : {m_data->plots(), m_model->plots()}) {
            stack->setTimeCursor(t);
        }
    };
    connect(m_view3d, &LineView3D::timeChanged, this, shareTime);
    for (auto* stack : {m_data->plots(), m_model->plots()}) {
        connect(stack, &PlotStack::timeCursorMoved, this, [this, shareTime](double t) {
            shareTime(t);
            m_view3d->setTime(t);
        });
    }
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    keepOnScreen(this); // saved on a monitor that is gone, it would open where nobody sees it
}

// The job runner's destructor cancels every job and waits for the engine thread.
MainWindow::~MainWindow() {
    if (!m_languageTempProject.isEmpty()) {
        for (const char* suffix : {"", ".model.json", ".results.json"}) {
            QFile::remove(m_languageTempProject + QLatin1String(suffix));
        }
        // The other data sets' results beside it (PROJECT.results.1.json, …).
        const QFileInfo temp(m_languageTempProject);
        for (const auto& f : temp.dir().entryList({temp.fileName() + QStringLiteral(".results.*.json")})) {
            QFile::remove(temp.dir().filePath(f));
        }
    }
}

} // namespace drytwin::widgets
