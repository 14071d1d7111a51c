#pragma once

#include "common/Workbench.h"
#include "data/Batch.h"

#include <QMainWindow>
#include <QStringList>
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTextBrowser;

namespace drytwin::widgets {

class CalibrationPanel;
class DataPanel;
class DiagnosticsPanel;
class DiscoverPanel;
class LineView3D;
class ModelPanel;
class MpcPanel;
class ResidualPanel;
class TrainingPanel;

/// @brief DryTwin's workbench: one tab per task (Data, Model, Calibrate, Residual model,
/// Diagnostics, Discover, What-if MPC, 3D line, Training), menus, projects, a status bar with progress
/// and cancel. Engine work runs on the engine thread through the Workbench; the window only shows
/// and edits. Closing it mid-run cancels cleanly.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// @brief Starts loading a batch file or folder; the physics model is simulated after it.
    /// @p mappingPath: a column mapping for a historian export (empty: the contract's columns).
    void openDataSet(const QString& path, const QString& mappingPath = {});
    /// @brief Opens the bundled demo data set (writes it first, once).
    void openBundledDemo();
    /// @brief Opens a project file: data, model and view (errors go to the status bar and a box).
    /// @p remember: make it the window's project and list it under Recent projects.
    bool openProject(const QString& path, QString* error = nullptr, bool remember = true);
    /// @brief Writes the project atomically: the model beside it when it has no file yet, the latest
    /// results (PATH.results.json) and the learnt parts' states; reopened, all of it is shown again.
    bool saveProject(const QString& path, QString* error = nullptr, bool remember = true);
    /// @brief The same work in another language, without restarting DryTwin: the state goes into a
    /// temporary project, a new window opens it in @p language and this one closes. Refused (null,
    /// @p error says why) while a job runs.
    MainWindow* reopenInLanguage(const QString& language, QString* error = nullptr);
    /// @brief The data set shown now (empty before the first successful load).
    const data::DataSet& dataSet() const { return m_workbench.dataSet() ? *m_workbench.dataSet() : m_noData; }
    Workbench& workbench() { return m_workbench; }
    JobRunner& jobs() { return m_workbench.jobs(); }
    QTabWidget* tabs() const { return m_tabs; }
    /// @brief The status bar's way to the column mapping after a file was not recognised.
    QPushButton* mapColumnsButton() const { return m_mapButton; }
    /// @brief The data-set list at the tabs' top right.
    QComboBox* dataSetChooser() const { return m_dataSetChooser; }
    DataPanel* dataPanel() const { return m_data; }
    /// @brief The user guide's window (null until Help ▸ User guide was opened).
    QTextBrowser* userGuide() const { return m_guide; }
    ModelPanel* modelPanel() const { return m_model; }
    CalibrationPanel* calibrationPanel() const { return m_calibration; }
    ResidualPanel* residualPanel() const { return m_residual; }
    DiagnosticsPanel* diagnosticsPanel() const { return m_diagnostics; }
    DiscoverPanel* discoverPanel() const { return m_discover; }
    MpcPanel* mpcPanel() const { return m_mpc; }
    TrainingPanel* trainingPanel() const { return m_training; }
    /// @brief Shows the Training tab and reopens a saved session there (replayed, frozen).
    void openTrainingSession(const QString& sessionFile);
    LineView3D* lineView() const { return m_view3d; }
    /// @brief Runs actions once the data is loaded, in order, as if their buttons were pressed:
    /// "calibrate", "train", "evaluate", "discover", "extend", "mpc" (demos, screenshots, training).
    void runAfterLoad(const QStringList& actions);
    bool hasPendingActions() const;
    /// @brief Saves one PNG per tab into @p folder (NN-name.png); returns the files written.
    QStringList saveTabScreenshots(const QString& folder);
    /// @brief HTML of the About box: DryTwin's version and every library's.
    static QString aboutText();
    /// @brief The status line with no data: where to open data, and the bundled demo.
    static QString noDataHint();
    /// @brief The steps still to run before File ▸ Export report… can write the report (empty: ready).
    QStringList reportMissingSteps() const;
    /// @brief Writes the pipeline's report (HTML and PDF) from this window's results into @p folder.
    Expected<QStringList> exportReport(const QString& folder) const;
    /// @brief What opening the last project warned of (its data changed since it was saved), or empty.
    QString projectWarning() const { return m_projectWarning; }
    /// @brief What was done in this window since the project was last saved or opened ("the
    /// calibration", "the edited scenario" …); empty when nothing would be lost by closing.
    QStringList unsavedWork() const { return m_unsavedWork; }
    /// @brief Closing with unsaved work asks Save / Discard / Cancel; false when the user cancels
    /// (or saving failed), and the window stays open.
    bool askToSaveBeforeClosing();
    /// @brief An engine progress stage ("calibrate") in the user's language ("Calibrating").
    static QString stageText(const QString& stage);
    /// @brief Help ▸ User guide: the workflow, shipped as a resource, in the window's language.
    void showUserGuide();
    /// @brief The user guide's HTML for @p language (en, zh_CN; English when there is none).
    static QString userGuideHtml(const QString& language);

Q_SIGNALS:
    /// @brief The model's predictions are shown (for tests and scripting).
    void simulationShown();
    /// @brief Emitted after a load attempt finished, successful or not (for tests and scripting).
    void loadFinished(bool ok);
    /// @brief A project finished opening (data loaded and simulated, model opened).
    void projectReady(bool ok);
    /// @brief A training session asked for by openTrainingSession() could not be opened.
    void trainingSessionFailed(const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    /// The data-set list at the tabs' top right (mainwindow/MainWindowData.cpp).
    void createDataSetChooser();
    /// The status line, the progress bar, Cancel and the column-mapping button
    /// (mainwindow/MainWindowStatus.cpp).
    void createStatusBar();
    void createMenus();
    /// Jobs' progress, the Workbench's status and errors onto the status bar.
    void connectProgress();
    /// What follows a load, successful or not (mainwindow/MainWindowData.cpp).
    void connectDataLoading();
    void startActions();
    /// Runs `then` once the engine thread has no job queued or running: at once when it is idle,
    /// else when JobRunner says it has become idle (checked again on the next turn of the event
    /// loop, since a finished job's result may queue the next job).
    void whenEngineIdle(std::function<void()> then);
    void setBusy(bool busy);
    void rememberRecent(const QString& path);
    void fillRecent();
    void askAndExportReport();
    void showError(const QString& title, const QString& message);
    /// Puts back a reopened project's results and learnt parts' states.
    void restorePending();
    /// Notes what the user does that a project keeps, for the question on closing
    /// (mainwindow/MainWindowUnsaved.cpp).
    void trackUnsavedWork();
    void noteUnsaved(const QString& what);

    Workbench m_workbench;
    data::DataSet m_noData;
    QTabWidget* m_tabs = nullptr;
    DataPanel* m_data = nullptr;
    ModelPanel* m_model = nullptr;
    CalibrationPanel* m_calibration = nullptr;
    ResidualPanel* m_residual = nullptr;
    DiagnosticsPanel* m_diagnostics = nullptr;
    DiscoverPanel* m_discover = nullptr;
    MpcPanel* m_mpc = nullptr;
    TrainingPanel* m_training = nullptr;
    LineView3D* m_view3d = nullptr;
    QMenu* m_recent = nullptr;
    QLabel* m_statusLabel = nullptr;
    QComboBox* m_dataSetChooser = nullptr;
    QTextBrowser* m_guide = nullptr;
    QProgressBar* m_progressBar = nullptr;
    QPushButton* m_cancelButton = nullptr;
    QPushButton* m_mapButton = nullptr;
    QString m_mapFile;
    QString m_projectPath;
    /// The temporary project this window was opened from when the language changed (its model
    /// and results beside it): removed with the window, which reads them until it is closed.
    QString m_languageTempProject;
    JobId m_progressJob = 0;
    QString m_lastStatus;            ///< the Workbench's last status line
    bool m_statusIsProgress = false; ///< the status line shows a job's progress
    QString m_progressStage;
    QString m_pendingModel; ///< a project's model, opened once its data is in
    QStringList m_pendingActions;
    int m_pendingTab = -1;
    std::optional<workflow::LatestResults> m_pendingResults;
    /// The results of a reopened project's other data sets, by path (put back with the rest).
    std::map<QString, workflow::LatestResults> m_pendingOtherResults;
    QStringList m_unsavedWork; ///< see unsavedWork()
    std::optional<std::array<LearntPart, 3>> m_pendingParts;
    /// What the project's data held when it was saved ("B01:3000 B02:3000 …"), compared once the
    /// data are in again: a batch file removed or changed since then makes the restored results
    /// and learnt parts stale, and the user is told (empty: no project being opened).
    QString m_pendingDataFingerprint;
    QString m_projectWarning; ///< what opening the last project warned of (its data changed), or empty
    QString dataFingerprint() const;
};

} // namespace drytwin::widgets
