#include "MainWindow.h"

#include "calibration/CalibrationPanel.h"
#include "common/ErrorText.h"
#include "common/LibraryVersions.h"
#include "common/PlotStack.h"
#include "common/Translations.h"
#include "common/WidgetHelpers.h"
#include "data/DataPanel.h"
#include "diagnostics/DiagnosticsPanel.h"
#include "discovery/DiscoverPanel.h"
#include "model/ModelPanel.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "training/TrainingPanel.h"
#include "training/TrainingRunner.h"
#include "view3d/LineView3D.h"
#include "workflow/ResultArchive.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QIcon>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QWhatsThis>
#include <map>
#include <qwt_global.h>
#include <utility>
#include <vtkVersion.h>

// The widgets are a static library: its resources (window icon) must be registered by hand,
// and Q_INIT_RESOURCE must be called outside any namespace.
static void initDryTwinResources() {
    Q_INIT_RESOURCE(drytwin);
}

namespace drytwin::widgets {

namespace {
constexpr int kMaxRecent = 8;
const char* kTabKeys[] = {"data",     "model", "calibrate", "residual", "diagnostics",
                          "discover", "mpc",   "line3d",    "training"};
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("DryTwin"));
    initDryTwinResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/drytwin.svg")));
    resize(1280, 800);

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
        tr("<b>Calibrate</b>: fits the ticked parameters to the data (a global search, then "
           "BOBYQA) and gives each its 95 % interval. Stop keeps the best so far."));
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
    // Which data set the tabs show, and the others opened in this window.
    m_dataSetChooser = new QComboBox;
    m_dataSetChooser->setToolTip(
        tr("The data set every tab shows; the others opened in this window stay here"));
    m_dataSetChooser->setMinimumContentsLength(24);
    m_dataSetChooser->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    auto* chooserBox = new QWidget;
    auto* chooserLayout = new QHBoxLayout(chooserBox);
    chooserLayout->setContentsMargins(4, 0, 4, 0);
    chooserLayout->addWidget(new QLabel(tr("Data set:")));
    chooserLayout->addWidget(m_dataSetChooser);
    m_tabs->setCornerWidget(chooserBox, Qt::TopRightCorner);
    const auto fillChooser = [this] {
        m_dataSetChooser->blockSignals(true);
        m_dataSetChooser->clear();
        for (const auto& e : m_workbench.dataSets()) {
            m_dataSetChooser->addItem(e.label, e.path);
            m_dataSetChooser->setItemData(m_dataSetChooser->count() - 1, e.path, Qt::ToolTipRole);
        }
        if (m_workbench.dataSets().empty()) {
            m_dataSetChooser->addItem(tr("none loaded"));
        }
        m_dataSetChooser->setCurrentIndex(std::max(0, m_workbench.currentDataSet()));
        m_dataSetChooser->blockSignals(false);
    };
    fillChooser();
    connect(&m_workbench, &Workbench::dataSetsChanged, this, fillChooser);
    connect(m_dataSetChooser, QOverload<int>::of(&QComboBox::activated), &m_workbench,
            &Workbench::switchDataSet);

    m_statusLabel = new QLabel(noDataHint());
    m_progressBar = new QProgressBar;
    m_progressBar->setMaximumWidth(200);
    m_progressBar->setRange(0, 100);
    m_cancelButton = new QPushButton(tr("Cancel"));
    statusBar()->addWidget(m_statusLabel, 1);
    m_mapButton = new QPushButton(tr("Map its columns…"));
    m_mapButton->setToolTip(tr("Open the column-mapping dialog for the file that was not recognised"));
    m_mapButton->setVisible(false);
    connect(m_mapButton, &QPushButton::clicked, this, [this] {
        m_mapButton->setVisible(false);
        if (!m_mapFile.isEmpty()) {
            m_data->mapAndOpen(m_mapFile);
        }
    });
    statusBar()->addPermanentWidget(m_mapButton);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    setBusy(false);
    createMenus();

    auto& jobs = m_workbench.jobs();
    connect(&jobs, &JobRunner::busyChanged, this, &MainWindow::setBusy);
    // One bar per action across its stages: the action's own stage (the first it reports) moves
    // the bar, never back; the stages inside it (simulate, lstm …) are named in the status line.
    connect(&jobs, &JobRunner::started, this, [this](JobId id, const QString& name) {
        m_progressJob = id;
        m_progressStage.clear();
        m_progressBar->setValue(0);
        m_progressBar->setFormat(QStringLiteral("%1 %p%").arg(name));
    });
    connect(
        &jobs, &JobRunner::progress, this,
        [this](JobId id, const QString& stage, double fraction, const QString& detail) {
            if (id != m_progressJob) {
                return;
            }
            if (m_progressStage.isEmpty()) {
                m_progressStage = stage;
            }
            if (stage == m_progressStage) {
                m_progressBar->setValue(std::max(m_progressBar->value(), static_cast<int>(fraction * 100)));
            }
            // The engine's detail is English (the CLI prints it): shown in the English window; the
            // stage and its share in every language.
            m_statusLabel->setText(detail.isEmpty() || currentLanguage() != QLatin1String("en")
                                       ? tr("%1: %2 %").arg(stageText(stage)).arg(fraction * 100, 0, 'f', 0)
                                       : tr("%1: %2").arg(stageText(stage), detail));
            m_statusIsProgress = true;
        });
    connect(m_cancelButton, &QPushButton::clicked, &m_workbench, &Workbench::cancelAll);
    connect(&m_workbench, &Workbench::queued, this, [this](const QString& text) {
        m_statusLabel->setText(text);
        m_statusIsProgress = true;
    });
    connect(&m_workbench, &Workbench::status, this, [this](const QString& text) {
        m_lastStatus = text;
        m_statusIsProgress = false;
        m_statusLabel->setText(text);
    });
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        Q_EMIT loadFinished(true);
        m_mapButton->setVisible(false);
        m_workbench.simulate();
        if (!m_pendingModel.isEmpty()) {
            m_workbench.openModel(m_pendingModel, std::exchange(m_pendingParts, std::nullopt));
            m_workbench.simulate(); // again, with the project's model
            m_pendingModel.clear();
        }
        restorePending();
        startActions();
    });
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
    connect(&m_workbench, &Workbench::dataLoadFailed, this,
            [this](const QString&, const QString& path, bool mappingMayHelp) {
                // A file whose columns were not recognised: the way to the column mapping, at hand.
                m_mapFile = mappingMayHelp ? path : QString();
                m_mapButton->setVisible(mappingMayHelp);
                Q_EMIT loadFinished(false);
            });
    connect(&m_workbench, &Workbench::failed, this,
            [this](const QString& action, const QString& message, bool cancelled) {
                if (!cancelled) {
                    showError(action, message);
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
            // with; not set by default, because against three commissioning runs the change screen
            // misses the fouling that the recording alone shows (measured 2026-11-26: theta_foul's
            // change p 0.08; TestTrainingPanel names it alone).
            m_workbench.setReferencePath({});
            if (!reference.isEmpty()) {
                m_statusLabel->setText(
                    tr("The line's commissioning runs are in %1: choose them under \"Compare with "
                       "a reference period\" to ask what changed since commissioning.")
                        .arg(QDir::toNativeSeparators(reference)));
            }
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
}

// The job runner's destructor cancels every job and waits for the engine thread.
MainWindow::~MainWindow() = default;

void MainWindow::closeEvent(QCloseEvent* event) {
    // Closing mid-run cancels cleanly: the running job is told to stop, queued ones never start.
    m_workbench.cancelAll();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    event->accept();
}

void MainWindow::createMenus() {
    auto* file = menuBar()->addMenu(tr("&File"));
    auto* openFile = file->addAction(tr("&Open batch file…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open batch file"), tr("Batch files (*.csv)"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    openFile->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open data set &folder…"), this, [this] {
        const QString p = askFolder(this, tr("Open data set folder"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    file->addAction(tr("Open the bundled &demo"), this, &MainWindow::openBundledDemo);
    file->addAction(tr("&Generate virtual-plant data…"), this, [this] {
        const QString folder = askFolder(this, tr("Folder for the virtual plant's batches"));
        if (folder.isEmpty()) {
            return;
        }
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(2025); // the bundled demo: distributed plant, realistic sensors
        g.outFolder = folder.toStdString();
        m_workbench.generate(g);
    });
    file->addAction(tr("Open &model…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open model"), tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.openModel(p);
        }
    });
    file->addAction(tr("Save model &as…"), this, [this] {
        const QString p =
            askSaveFile(this, tr("Save model"), QStringLiteral("model.json"), tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.saveModel(p);
        }
    });
    file->addSeparator();
    file->addAction(tr("Open &project…"), this, [this] {
        const QString p = askOpenFile(this, tr("Open project"), tr("DryTwin projects (*.drytwin)"));
        QString error;
        if (!p.isEmpty() && !openProject(p, &error)) {
            showError(tr("Open project"), error);
        }
    });
    auto* save = file->addAction(tr("&Save project"), this, [this] {
        QString p = m_projectPath;
        if (p.isEmpty()) {
            p = askSaveFile(this, tr("Save project"), QStringLiteral("project.drytwin"),
                            tr("DryTwin projects (*.drytwin)"));
        }
        QString error;
        if (!p.isEmpty() && !saveProject(p, &error)) {
            showError(tr("Save project"), error);
        }
    });
    save->setShortcut(QKeySequence::Save);
    file->addAction(tr("Save project as…"), this, [this] {
        const QString p = askSaveFile(this, tr("Save project"), QStringLiteral("project.drytwin"),
                                      tr("DryTwin projects (*.drytwin)"));
        QString error;
        if (!p.isEmpty() && !saveProject(p, &error)) {
            showError(tr("Save project"), error);
        }
    });
    m_recent = file->addMenu(tr("Recent projects"));
    fillRecent();
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    auto* view = menuBar()->addMenu(tr("&View"));
    auto* language = view->addMenu(tr("&Language"));
    auto* group = new QActionGroup(this);
    const QString current = currentLanguage();
    for (const auto& [code, name] :
         {std::pair<QString, QString>{QStringLiteral("en"), QStringLiteral("English")},
          std::pair<QString, QString>{QStringLiteral("zh_CN"), QStringLiteral("简体中文")}}) {
        auto* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(current == code || (current.isEmpty() && code == QLatin1String("en")));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = code] {
            if (code == currentLanguage()) {
                return;
            }
            QString error;
            if (auto* w = reopenInLanguage(code, &error)) {
                w->show();
            } else {
                showError(tr("Language"), error);
            }
        });
    }
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&User guide"), this, &MainWindow::showUserGuide)
        ->setShortcut(QKeySequence::HelpContents);
    help->addAction(QWhatsThis::createAction(this));
    help->addAction(tr("&About DryTwin"), this,
                    [this] { QMessageBox::about(this, tr("About DryTwin"), aboutText()); });
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

QString MainWindow::userGuideHtml(const QString& language) {
    initDryTwinResources();
    QFile f(QStringLiteral(":/guide/user-guide.%1.html").arg(language));
    if (!f.open(QIODevice::ReadOnly)) {
        f.setFileName(QStringLiteral(":/guide/user-guide.en.html"));
        if (!f.open(QIODevice::ReadOnly)) {
            return {};
        }
    }
    return QString::fromUtf8(f.readAll());
}

void MainWindow::showUserGuide() {
    if (!m_guide) {
        m_guide = new QTextBrowser(this);
        m_guide->setWindowFlag(Qt::Window);
        m_guide->setWindowTitle(tr("DryTwin user guide"));
        m_guide->resize(720, 760);
        m_guide->setOpenExternalLinks(true);
    }
    m_guide->setHtml(userGuideHtml(currentLanguage()));
    m_guide->show();
    m_guide->raise();
}

QString MainWindow::noDataHint() {
    return tr("No data loaded. File ▸ Open data set folder… (or File ▸ Open the bundled demo)");
}

QString MainWindow::stageText(const QString& stage) {
    // The engine's stage keys, in the user's language.
    static const std::map<QString, const char*> words{
        {QStringLiteral("load"), QT_TR_NOOP("Loading")},
        {QStringLiteral("simulate"), QT_TR_NOOP("Simulating")},
        {QStringLiteral("calibrate"), QT_TR_NOOP("Calibrating")},
        {QStringLiteral("train"), QT_TR_NOOP("Learning the correction models")},
        {QStringLiteral("lstm"), QT_TR_NOOP("Training the LSTM")},
        {QStringLiteral("evaluate"), QT_TR_NOOP("Scoring on the held-out part")},
        {QStringLiteral("discover"), QT_TR_NOOP("Discovering")},
        {QStringLiteral("ablation"), QT_TR_NOOP("Ablation")},
        {QStringLiteral("mpc"), QT_TR_NOOP("What-if scenario")},
        {QStringLiteral("generate"), QT_TR_NOOP("Generating plant data")},
        {QStringLiteral("training"), QT_TR_NOOP("Training session")}};
    const auto it = words.find(stage);
    return it == words.end() ? stage : tr(it->second);
}

QString MainWindow::aboutText() {
    QString html = tr("<h3>DryTwin %1</h3><p>Digital-twin workbench for pneumatic drying lines, "
                      "implementing the PGRL-CC method.</p><table>")
                       .arg(QString::fromStdString(dryTwinVersion()));
    auto row = [&](const QString& name, const QString& version) {
        html += QStringLiteral("<tr><td>%1</td><td>&nbsp;%2</td></tr>")
                    .arg(name.toHtmlEscaped(), version.toHtmlEscaped());
    };
    row(QStringLiteral("Qt"), QString::fromLatin1(qVersion()));
    row(QStringLiteral("Qwt"), QStringLiteral(QWT_VERSION_STR));
    row(QStringLiteral("VTK"), QString::fromLatin1(vtkVersion::GetVTKVersion()));
    for (const auto& [name, version] : engineLibraryVersions()) {
        row(QString::fromStdString(name), QString::fromStdString(version));
    }
    html += QStringLiteral("</table>");
    return html;
}

void MainWindow::openBundledDemo() {
    // The demo of scripts/run.sh (drytwin generate --demo --seed 2025), written once per user.
    const QString folder = QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                               .filePath(QStringLiteral("demo-data"));
    if (!QDir(folder).entryList({QStringLiteral("*.csv")}, QDir::Files).isEmpty()) {
        openDataSet(folder);
        return;
    }
    workflow::GenerateOptions g;
    g.plant = plant::PlantOptions::demo(2025); // distributed plant, realistic sensors
    g.outFolder = folder.toStdString();
    m_statusLabel->setText(
        tr("Writing the bundled demo (10 batches of the virtual plant) to %1…").arg(folder));
    m_workbench.generate(g);
}

void MainWindow::openDataSet(const QString& path) {
    m_workbench.openData(path);
}

void MainWindow::setBusy(bool busy) {
    m_progressBar->setVisible(busy);
    m_cancelButton->setVisible(busy);
    if (!busy) {
        m_progressBar->setValue(0);
        // A progress line of a job that has ended ("Simulating: 0 %") would say it still runs.
        if (m_statusIsProgress) {
            m_statusLabel->setText(m_lastStatus.isEmpty() ? tr("Ready.") : m_lastStatus);
            m_statusIsProgress = false;
        }
    }
}

void MainWindow::showError(const QString& title, const QString& message) {
    m_statusLabel->setText(message);
    if (qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
        return;
    }
    QMessageBox::warning(this, title, message);
}

bool MainWindow::saveProject(const QString& path, QString* error, bool remember) {
    // The results beside the project, typed (workflow/ResultArchive.h): a reopened project shows
    // its calibration, evaluation, ablation, discovery and what-if run without re-running them.
    const QString resultsPath = path + QStringLiteral(".results.json");
    {
        QSaveFile results(resultsPath);
        if (!results.open(QIODevice::WriteOnly) ||
            results.write(QByteArray::fromStdString(workflow::latestResultsJson(m_workbench.latest()))) < 0 ||
            !results.commit()) {
            if (error) {
                *error = tr("cannot write %1: %2").arg(resultsPath, results.errorString());
            }
            return false;
        }
    }
    const QString savedMessage = tr("Project saved to %1 (model, results and view)").arg(path);
    QString modelPath = m_workbench.modelPath();
    bool modelQueued = false;
    if (modelPath.isEmpty() || m_workbench.model().calibration || m_workbench.model().hasResidualModels()) {
        // The session's model as it is now, beside the project.
        // The session writes it (atomically) on the engine thread, queued before anything else the
        // user starts; a project whose model file is missing opens with the data alone.
        modelPath = path + QStringLiteral(".model.json");
        m_workbench.saveModel(modelPath, savedMessage);
        modelQueued = true;
    }
    QJsonObject o;
    o[QStringLiteral("format")] = QStringLiteral("drytwin-project");
    o[QStringLiteral("format_version")] = 1;
    const QDir base = QFileInfo(path).absoluteDir();
    o[QStringLiteral("data_path")] =
        m_workbench.dataPath().isEmpty() ? QString() : base.relativeFilePath(m_workbench.dataPath());
    o[QStringLiteral("model_path")] = base.relativeFilePath(modelPath);
    o[QStringLiteral("mapping_path")] =
        m_workbench.mappingPath().isEmpty() ? QString() : base.relativeFilePath(m_workbench.mappingPath());
    // The reference period discovery compares with: the project remembers it (issue #41).
    o[QStringLiteral("reference_path")] = m_workbench.referencePath().isEmpty()
                                              ? QString()
                                              : base.relativeFilePath(m_workbench.referencePath());
    o[QStringLiteral("tab")] = QString::fromLatin1(kTabKeys[std::max(0, m_tabs->currentIndex())]);
    QJsonArray batches;
    for (const auto& r : m_data->batchTable()->selectionModel()->selectedRows()) {
        batches.append(r.row());
    }
    o[QStringLiteral("selected_batches")] = batches;
    o[QStringLiteral("results_path")] = base.relativeFilePath(resultsPath);
    QJsonArray parts;
    for (const auto& part : m_workbench.learntParts()) {
        parts.append(
            QJsonObject{{QStringLiteral("kind"), QString::fromLatin1(control::controllerName(part.kind))},
                        {QStringLiteral("state"), static_cast<int>(part.state)},
                        {QStringLiteral("learnt_on"), part.learntOn},
                        {QStringLiteral("stale_because"), part.staleBecause}});
    }
    o[QStringLiteral("learnt_parts")] = parts;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) {
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    f.write(QJsonDocument(o).toJson());
    if (!f.commit()) {
        if (error) {
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    if (remember) {
        m_projectPath = path;
        rememberRecent(path);
    }
    // With a model to write, the status says "saved" once the model file is written too.
    m_statusLabel->setText(modelQueued ? tr("Saving the project to %1…").arg(path) : savedMessage);
    return true;
}

bool MainWindow::openProject(const QString& path, QString* error, bool remember) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) {
            *error = tr("cannot open %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &parseError);
    if (doc.isNull() || !doc.isObject() ||
        doc.object().value(QStringLiteral("format")).toString() != QLatin1String("drytwin-project")) {
        if (error) {
            *error = tr("%1 is not a DryTwin project (%2)").arg(path, parseError.errorString());
        }
        return false;
    }
    const QJsonObject o = doc.object();
    const QDir base = QFileInfo(path).absoluteDir();
    const QString data = o.value(QStringLiteral("data_path")).toString();
    const QString model = o.value(QStringLiteral("model_path")).toString();
    m_pendingTab = -1;
    const QString tab = o.value(QStringLiteral("tab")).toString();
    for (int i = 0; i < 8; ++i) {
        if (tab == QLatin1String(kTabKeys[i])) {
            m_pendingTab = i;
        }
    }
    if (remember) {
        m_projectPath = path;
        rememberRecent(path);
    }
    // Results and the learnt parts' states, put back once the data and the model are in.
    m_pendingResults.reset();
    const QString resultsFile = o.value(QStringLiteral("results_path")).toString();
    if (!resultsFile.isEmpty() && QFileInfo::exists(base.filePath(resultsFile))) {
        QFile rf(base.filePath(resultsFile));
        if (rf.open(QIODevice::ReadOnly)) {
            auto parsed = workflow::parseLatestResults(rf.readAll().toStdString(),
                                                       base.filePath(resultsFile).toStdString());
            if (parsed) {
                m_pendingResults = std::move(*parsed);
            } else {
                m_statusLabel->setText(
                    tr("The project's results could not be read (%1); it opens without them.")
                        .arg(errorText(parsed.error())));
            }
        }
    }
    m_pendingParts.reset();
    const QJsonArray parts = o.value(QStringLiteral("learnt_parts")).toArray();
    if (parts.size() == 3) {
        std::array<LearntPart, 3> restored;
        for (int i = 0; i < 3; ++i) {
            const QJsonObject p = parts[i].toObject();
            const auto kind =
                control::controllerByName(p.value(QStringLiteral("kind")).toString().toStdString());
            restored[static_cast<std::size_t>(i)] =
                LearntPart{kind.value_or(control::ControllerKind::Pi),
                           static_cast<PartState>(std::clamp(p.value(QStringLiteral("state")).toInt(), 0, 2)),
                           p.value(QStringLiteral("learnt_on")).toString(),
                           p.value(QStringLiteral("stale_because")).toString()};
        }
        m_pendingParts = restored;
    }
    if (!model.isEmpty() && QFileInfo::exists(base.filePath(model))) {
        m_pendingModel = base.filePath(model);
    }
    const QString mapping = o.value(QStringLiteral("mapping_path")).toString();
    const QString reference = o.value(QStringLiteral("reference_path")).toString();
    m_workbench.setReferencePath(reference.isEmpty() ? QString() : base.filePath(reference));
    if (!data.isEmpty()) {
        m_workbench.openData(base.filePath(data), mapping.isEmpty() ? QString() : base.filePath(mapping));
    } else {
        if (!m_pendingModel.isEmpty()) {
            m_workbench.openModel(m_pendingModel, std::exchange(m_pendingParts, std::nullopt));
            m_pendingModel.clear();
        }
        restorePending(); // no data: the results (an MPC run needs none) come back at once
    }
    return true;
}

void MainWindow::restorePending() {
    if (m_pendingResults) {
        m_workbench.restoreResults(*m_pendingResults);
        m_pendingResults.reset();
    }
    if (m_pendingParts) { // a project without a model file: the states as saved, at once
        m_workbench.restoreLearntParts(*m_pendingParts);
        m_pendingParts.reset();
    }
}

MainWindow* MainWindow::reopenInLanguage(const QString& language, QString* error) {
    if (m_workbench.jobs().busy()) {
        if (error) {
            *error = tr("Wait until the running job has finished (or cancel it), then switch the language.");
        }
        return nullptr;
    }
    const QString temp =
        QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation))
            .filePath(QStringLiteral("drytwin-language-%1.drytwin").arg(QCoreApplication::applicationPid()));
    if (!saveProject(temp, error, false)) {
        return nullptr;
    }
    // The model file is written on the engine thread: wait for it before the new window reads it.
    QElapsedTimer waited;
    waited.start();
    while (m_workbench.jobs().busy() && waited.elapsed() < 60000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    QSettings().setValue(QStringLiteral("language"), language);
    setLanguage(language);
    auto* next = new MainWindow;
    next->setAttribute(Qt::WA_DeleteOnClose);
    next->restoreGeometry(saveGeometry());
    next->m_projectPath = m_projectPath;
    if (!next->openProject(temp, error, false)) {
        delete next;
        return nullptr;
    }
    next->m_tabs->setCurrentIndex(m_tabs->currentIndex());
    // This window stays alive until it is closed (the first one lives as long as the program): a
    // live training line in it must not run on hidden.
    if (m_training->runner().frame().started) {
        const QString kept = m_training->keepCurrentSession();
        m_training->runner().freeze();
        next->m_training->noteLabel()->setText(
            tr("The training session under way was saved in %1 when the language changed: the instructor "
               "window's Session file ▸ Open session… continues it.")
                .arg(QDir::toNativeSeparators(kept)));
    }
    hide();
    if (testAttribute(Qt::WA_DeleteOnClose)) {
        deleteLater();
    }
    return next;
}

void MainWindow::rememberRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentProjects")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) {
        recent.removeLast();
    }
    settings.setValue(QStringLiteral("recentProjects"), recent);
    fillRecent();
}

void MainWindow::fillRecent() {
    m_recent->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentProjects")).toStringList();
    for (const auto& p : recent) {
        m_recent->addAction(p, this, [this, p] {
            QString error;
            if (!openProject(p, &error)) {
                showError(tr("Open project"), error);
            }
        });
    }
    m_recent->setEnabled(!recent.isEmpty());
}

void MainWindow::runAfterLoad(const QStringList& actions) {
    m_pendingActions = actions;
    if (m_workbench.hasData()) {
        startActions();
    }
}

void MainWindow::startActions() {
    // Each is queued on the engine thread behind the one before; the panels show the results.
    for (const auto& a : std::exchange(m_pendingActions, {})) {
        if (a == QLatin1String("calibrate")) {
            m_calibration->run();
            m_workbench.simulate();
        } else if (a == QLatin1String("train")) {
            m_residual->train();
        } else if (a == QLatin1String("evaluate")) {
            m_workbench.evaluate();
        } else if (a == QLatin1String("discover")) {
            m_workbench.discover();
        } else if (a == QLatin1String("mpc")) {
            m_mpc->run();
        }
    }
}

bool MainWindow::hasPendingActions() const {
    return !m_pendingActions.isEmpty() || m_training->isOpening();
}

void MainWindow::openTrainingSession(const QString& sessionFile) {
    m_tabs->setCurrentWidget(m_training);
    m_training->openSession(sessionFile);
}

QStringList MainWindow::saveTabScreenshots(const QString& folder) {
    QDir().mkpath(folder);
    QStringList files;
    for (int i = 0; i < m_tabs->count(); ++i) {
        // A job finishing while the events are processed may bring its own tab forward (a reopened
        // training session does): the tab is set again until it stays.
        for (int attempt = 0; attempt < 3; ++attempt) {
            m_tabs->setCurrentIndex(i);
            for (int k = 0; k < 5; ++k) {
                QApplication::processEvents();
            }
            if (m_tabs->currentIndex() == i) {
                break;
            }
        }
        const QString file = QDir(folder).filePath(
            QStringLiteral("%1-%2.png").arg(i + 1, 2, 10, QLatin1Char('0')).arg(QLatin1String(kTabKeys[i])));
        if (grab().save(file)) {
            files << file;
        }
        if (m_tabs->widget(i) == m_training) { // the instructor's window at the same moment
            m_training->setInstructorView(true);
            for (int k = 0; k < 5; ++k) {
                QApplication::processEvents();
            }
            const QString instructor = QDir(folder).filePath(
                QStringLiteral("%1-training-instructor.png").arg(i + 2, 2, 10, QLatin1Char('0')));
            if (m_training->instructorWindow()->grab().save(instructor)) {
                files << instructor;
            }
            m_training->setInstructorView(false);
        }
    }
    return files;
}

} // namespace drytwin::widgets
