#include "MainWindow.h"

#include "calibration/CalibrationPanel.h"
#include "common/ErrorText.h"
#include "common/LibraryVersions.h"
#include "common/PlotStack.h"
#include "data/DataPanel.h"
#include "diagnostics/DiagnosticsPanel.h"
#include "discovery/DiscoverPanel.h"
#include "model/ModelPanel.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "training/TrainingPanel.h"
#include "view3d/LineView3D.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
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
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
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

    m_statusLabel = new QLabel(tr("No data loaded. File ▸ Open data set…"));
    m_progressBar = new QProgressBar;
    m_progressBar->setMaximumWidth(200);
    m_progressBar->setRange(0, 100);
    m_cancelButton = new QPushButton(tr("Cancel"));
    statusBar()->addWidget(m_statusLabel, 1);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    setBusy(false);
    createMenus();

    auto& jobs = m_workbench.jobs();
    connect(&jobs, &JobRunner::busyChanged, this, &MainWindow::setBusy);
    connect(&jobs, &JobRunner::progress, this,
            [this](JobId, const QString& stage, double fraction, const QString& detail) {
                m_progressBar->setValue(static_cast<int>(fraction * 100));
                m_progressBar->setFormat(QStringLiteral("%1 %p%").arg(stage));
                if (!detail.isEmpty()) {
                    m_statusLabel->setText(QStringLiteral("%1: %2").arg(stage, detail));
                }
            });
    connect(m_cancelButton, &QPushButton::clicked, &m_workbench, &Workbench::cancelAll);
    connect(&m_workbench, &Workbench::status, m_statusLabel, &QLabel::setText);
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        Q_EMIT loadFinished(true);
        m_workbench.simulate();
        if (!m_pendingModel.isEmpty()) {
            m_workbench.openModel(m_pendingModel);
            m_workbench.simulate(); // again, with the project's model
            m_pendingModel.clear();
        }
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
    connect(&m_workbench, &Workbench::dataLoadFailed, this, [this] { Q_EMIT loadFinished(false); });
    connect(&m_workbench, &Workbench::failed, this,
            [this](const QString& action, const QString& message, bool cancelled) {
                if (!cancelled) {
                    showError(action, message);
                }
            });
    // The trainee diagnoses the live line's recording on the Discover tab.
    connect(m_training, &TrainingPanel::recordingReady, this, [this](const QString& csv) {
        m_pendingTab = m_tabs->indexOf(m_discover);
        m_workbench.openData(csv);
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
        const QString p =
            QFileDialog::getOpenFileName(this, tr("Open batch file"), {}, tr("Batch files (*.csv)"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    openFile->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open data set &folder…"), this, [this] {
        const QString p = QFileDialog::getExistingDirectory(this, tr("Open data set folder"));
        if (!p.isEmpty()) {
            openDataSet(p);
        }
    });
    file->addAction(tr("&Generate virtual-plant data…"), this, [this] {
        const QString folder =
            QFileDialog::getExistingDirectory(this, tr("Folder for the virtual plant's batches"));
        if (folder.isEmpty()) {
            return;
        }
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(2025); // the bundled demo: distributed plant, realistic sensors
        g.outFolder = folder.toStdString();
        m_workbench.generate(g);
    });
    file->addAction(tr("Open &model…"), this, [this] {
        const QString p =
            QFileDialog::getOpenFileName(this, tr("Open model"), {}, tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.openModel(p);
        }
    });
    file->addAction(tr("Save model &as…"), this, [this] {
        const QString p = QFileDialog::getSaveFileName(this, tr("Save model"), QStringLiteral("model.json"),
                                                       tr("Model files (*.json)"));
        if (!p.isEmpty()) {
            m_workbench.saveModel(p);
        }
    });
    file->addSeparator();
    file->addAction(tr("Open &project…"), this, [this] {
        const QString p =
            QFileDialog::getOpenFileName(this, tr("Open project"), {}, tr("DryTwin projects (*.drytwin)"));
        QString error;
        if (!p.isEmpty() && !openProject(p, &error)) {
            showError(tr("Open project"), error);
        }
    });
    auto* save = file->addAction(tr("&Save project"), this, [this] {
        QString p = m_projectPath;
        if (p.isEmpty()) {
            p = QFileDialog::getSaveFileName(this, tr("Save project"), QStringLiteral("project.drytwin"),
                                             tr("DryTwin projects (*.drytwin)"));
        }
        QString error;
        if (!p.isEmpty() && !saveProject(p, &error)) {
            showError(tr("Save project"), error);
        }
    });
    save->setShortcut(QKeySequence::Save);
    file->addAction(tr("Save project as…"), this, [this] {
        const QString p = QFileDialog::getSaveFileName(
            this, tr("Save project"), QStringLiteral("project.drytwin"), tr("DryTwin projects (*.drytwin)"));
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
    const QString current = QSettings().value(QStringLiteral("language")).toString();
    for (const auto& [code, name] :
         {std::pair<QString, QString>{QStringLiteral("en"), QStringLiteral("English")},
          std::pair<QString, QString>{QStringLiteral("zh_CN"), QStringLiteral("简体中文")}}) {
        auto* a = language->addAction(name);
        a->setCheckable(true);
        a->setChecked(current == code || (current.isEmpty() && code == QLatin1String("en")));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = code] {
            QSettings().setValue(QStringLiteral("language"), code);
            m_statusLabel->setText(tr("The language changes when DryTwin is started again."));
        });
    }
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About DryTwin"), this,
                    [this] { QMessageBox::about(this, tr("About DryTwin"), aboutText()); });
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
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

void MainWindow::openDataSet(const QString& path) {
    m_workbench.openData(path);
}

void MainWindow::setBusy(bool busy) {
    m_progressBar->setVisible(busy);
    m_cancelButton->setVisible(busy);
    if (!busy) {
        m_progressBar->setValue(0);
    }
}

void MainWindow::showError(const QString& title, const QString& message) {
    m_statusLabel->setText(message);
    if (qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
        return;
    }
    QMessageBox::warning(this, title, message);
}

bool MainWindow::saveProject(const QString& path, QString* error) {
    QString modelPath = m_workbench.modelPath();
    if (modelPath.isEmpty() || m_workbench.model().calibration || m_workbench.model().hasResidualModels()) {
        // The session's model as it is now, beside the project.
        // The session writes it (atomically) on the engine thread, queued before anything else the
        // user starts; a project whose model file is missing opens with the data alone.
        modelPath = path + QStringLiteral(".model.json");
        m_workbench.saveModel(modelPath);
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
    o[QStringLiteral("tab")] = QString::fromLatin1(kTabKeys[std::max(0, m_tabs->currentIndex())]);
    QJsonArray batches;
    for (const auto& r : m_data->batchTable()->selectionModel()->selectedRows()) {
        batches.append(r.row());
    }
    o[QStringLiteral("selected_batches")] = batches;
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
    m_projectPath = path;
    rememberRecent(path);
    m_statusLabel->setText(tr("Project saved to %1").arg(path));
    return true;
}

bool MainWindow::openProject(const QString& path, QString* error) {
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
    m_projectPath = path;
    rememberRecent(path);
    if (!model.isEmpty() && QFileInfo::exists(base.filePath(model))) {
        m_pendingModel = base.filePath(model);
    }
    const QString mapping = o.value(QStringLiteral("mapping_path")).toString();
    if (!data.isEmpty()) {
        m_workbench.openData(base.filePath(data), mapping.isEmpty() ? QString() : base.filePath(mapping));
    } else if (!m_pendingModel.isEmpty()) {
        m_workbench.openModel(m_pendingModel);
        m_pendingModel.clear();
    }
    return true;
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
        if (m_tabs->widget(i) == m_training) { // the instructor's view of the same moment
            m_training->setInstructorView(true);
            for (int k = 0; k < 5; ++k) {
                QApplication::processEvents();
            }
            const QString instructor = QDir(folder).filePath(
                QStringLiteral("%1-training-instructor.png").arg(i + 2, 2, 10, QLatin1Char('0')));
            if (grab().save(instructor)) {
                files << instructor;
            }
            m_training->setInstructorView(false);
        }
    }
    return files;
}

} // namespace drytwin::widgets
