#pragma once

#include "plant/Mechanisms.h"

#include <QWidget>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QwtPlotCurve;
class QwtPlotMarker;

namespace drytwin::widgets {

class PlotStack;
class TrainingRunner;
struct TrainingFrame;
class Workbench;

/// @brief Training mode: the virtual plant live (1×–50×) under its PI loop or an MPC, scrolling
/// plots, and three roles on one screen. The operator moves the setpoint and switches the
/// controller; the trainee opens the recording for the Discover tab and names a cause; the
/// instructor (a role switch, no password) freezes and resumes, snapshots and restores, runs
/// ahead, injects faults of CONTRACT.md §4 hidden from the trainee's view, sees the true outlet
/// moisture and the score, and saves or reopens sessions.
class TrainingPanel : public QWidget {
    Q_OBJECT
public:
    explicit TrainingPanel(Workbench& workbench, QWidget* parent = nullptr);
    ~TrainingPanel() override;

    TrainingRunner& runner() const { return *m_runner; }
    PlotStack* plots() const { return m_plots; }
    /// @brief Shows or hides the instructor's controls, faults, truth and score.
    void setInstructorView(bool on);
    bool instructorView() const;
    QComboBox* scenarios() const { return m_scenario; }
    QPushButton* startButton() const { return m_start; }
    QComboBox* speed() const { return m_speed; }
    QDoubleSpinBox* setpoint() const { return m_setpoint; }
    QComboBox* controller() const { return m_controller; }
    QComboBox* cause() const { return m_cause; }
    QPushButton* answerButton() const { return m_answer; }
    QPushButton* diagnoseButton() const { return m_diagnose; }
    QPushButton* freezeButton() const { return m_freeze; }
    QLineEdit* snapshotLabel() const { return m_snapshotLabel; }
    QPushButton* snapshotButton() const { return m_snapshot; }
    QListWidget* snapshotList() const { return m_snapshots; }
    QPushButton* restoreButton() const { return m_restore; }
    QComboBox* faultKind() const { return m_faultKind; }
    QDoubleSpinBox* faultStrength() const { return m_faultStrength; }
    QSpinBox* faultDelay() const { return m_faultDelay; }
    QPushButton* injectButton() const { return m_inject; }
    QTableWidget* faultTable() const { return m_faults; }
    QLabel* scoreLabel() const { return m_score; }
    QLabel* clockLabel() const { return m_clock; }
    QLabel* noteLabel() const { return m_note; }
    /// @brief The live line's monitor in words: normal, or the alarm with its time and onset.
    QLabel* monitorLabel() const { return m_monitorLabel; }
    /// The T² plot's marker at the monitor's alarm (hidden while the line is normal).
    QwtPlotMarker* alarmMarker() const { return m_alarmMarker; }
    /// @brief The instructor plot's lines: each fault's start, then each answer, in that order.
    const std::vector<QwtPlotMarker*>& truthMarkers() const { return m_truthMarkers; }
    /// @brief The trainee's pause (the clock stops; the same button continues).
    QPushButton* pauseButton() const { return m_pause; }
    /// @brief The instructor's own window (faults, score, the true moisture).
    QWidget* instructorWindow() const { return m_instructorWindow; }
    PlotStack* truthPlots() const { return m_truthPlots; }
    /// @brief The hash an instructor password is kept as (QSettings "training/instructorPasswordHash").
    static QString passwordHash(const QString& password);
    /// @brief Writes the session into @p folder (asynchronous: the note says when it is done).
    void saveSession(const QString& folder);
    /// @brief Reopens a saved session (replayed to where it ended, frozen).
    void openSession(const QString& sessionFile);
    /// @brief Saves the session under way (if any) into the application's data folder before
    /// another replaces it (a new session, the window reopened in another language), so that no
    /// session is lost silently; returns the folder (empty: none).
    QString keepCurrentSession();
    /// @brief True from openSession() until its replay has arrived or failed.
    bool isOpening() const { return m_opening; }

Q_SIGNALS:
    /// @brief The trainee asked to diagnose: the recording is saved as a batch file at @p csv.
    /// @p referenceFolder: the line's commissioning runs, the reference period to compare with
    /// (empty: none; the recording is then judged alone).
    void recordingReady(const QString& csv, const QString& referenceFolder);
    /// @brief A session file asked for with openSession() is open (@p ok) or could not be
    /// (@p message says why, as the panel does).
    void sessionOpenFinished(const QString& sessionFile, bool ok, const QString& message);

protected:
    /// The instructor window: its plot is redrawn when it comes back from minimised or hidden
    /// (frames that arrived meanwhile), and its place is kept for the next time it opens.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void startSession();
    void showFrame();
    void redrawPlots();
    void updateFaultUnit();
    /// Greys out the controllers whose model does not exist (or is stale).
    void offerControllers();
    /// Shows progress and Stop while a replay or a run ahead is under way.
    void setLongWork(bool on);

    Workbench& m_workbench;
    TrainingRunner* m_runner = nullptr;
    QComboBox* m_scenario = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_instructor = nullptr;
    QWidget* m_instructorWindow = nullptr;
    PlotStack* m_truthPlots = nullptr;
    QwtPlotCurve* m_truthMeasured = nullptr;
    QPushButton* m_pause = nullptr;
    QLabel* m_clock = nullptr;
    QComboBox* m_speed = nullptr;
    QDoubleSpinBox* m_setpoint = nullptr;
    QComboBox* m_controller = nullptr;
    QLabel* m_controllerNote = nullptr;
    QPushButton* m_diagnose = nullptr;
    QComboBox* m_cause = nullptr;
    QPushButton* m_answer = nullptr;
    QListWidget* m_answers = nullptr;
    QGroupBox* m_instructorBox = nullptr;
    QPushButton* m_freeze = nullptr;
    QSpinBox* m_aheadMin = nullptr;
    QLineEdit* m_snapshotLabel = nullptr;
    QPushButton* m_snapshot = nullptr;
    QListWidget* m_snapshots = nullptr;
    QPushButton* m_restore = nullptr;
    QComboBox* m_faultKind = nullptr;
    QDoubleSpinBox* m_faultStrength = nullptr;
    QSpinBox* m_faultDelay = nullptr;
    QPushButton* m_inject = nullptr;
    QTableWidget* m_faults = nullptr;
    QLabel* m_score = nullptr;
    QLabel* m_note = nullptr;
    QLabel* m_monitorLabel = nullptr;
    QwtPlotCurve* m_monitorT2 = nullptr;
    QwtPlotCurve* m_monitorLimit = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_stop = nullptr;
    PlotStack* m_plots = nullptr;
    QwtPlotCurve* m_xMeasured = nullptr;
    QwtPlotCurve* m_xTrue = nullptr;
    QwtPlotCurve* m_xSetpoint = nullptr;
    QwtPlotCurve* m_bandHigh = nullptr;
    /// The instructor's plot: the band and setpoint the score counts the time out of.
    QwtPlotCurve *m_truthBandHigh = nullptr, *m_truthBandLow = nullptr, *m_truthSetpoint = nullptr;
    /// On the T² plot: where the monitor alarmed and where it puts the change's start.
    QwtPlotMarker *m_alarmMarker = nullptr, *m_onsetMarker = nullptr;
    /// On the instructor's plot: when each fault began acting and when the trainee answered.
    std::vector<QwtPlotMarker*> m_truthMarkers;
    /// Redraws m_truthMarkers from the frame's faults and answers on the plot's time range
    /// [@p fromS, @p toS] (labels run into the plot from their line).
    void markFaultsAndAnswers(const TrainingFrame& f, double fromS, double toS);
    QwtPlotCurve* m_bandLow = nullptr;
    QwtPlotCurve* m_hotSetpoint = nullptr;
    QwtPlotCurve* m_hot = nullptr;
    QwtPlotCurve* m_feed = nullptr;
    QwtPlotCurve* m_xIn = nullptr;
    QString m_diagnoseFolder;
    bool m_diagnosePending = false;
    bool m_opening = false;
    QString m_openingFile; ///< the session file openSession() is replaying
    std::size_t m_drawnSamples = 0;
};

} // namespace drytwin::widgets
