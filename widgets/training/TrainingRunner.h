#pragma once

#include "hybrid/HybridModel.h"
#include "training/LineMonitor.h"
#include "training/TrainingSession.h"

#include <QMetaType>
#include <QObject>
#include <QString>
#include <QThread>
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

namespace drytwin::widgets {

/// @brief What the training screens show, copied off the session's thread about ten times a
/// second. Samples come as increments; after a start or a restore the whole trace comes again.
struct TrainingFrame {
    bool started = false;
    bool frozen = false;
    bool finished = false;
    double timeS = 0;
    double endS = 0;
    double speed = 1;
    double bandPct = 0.5;
    double setpointPct = 13;
    control::ControllerKind controller = control::ControllerKind::Pi;
    QString controllerNote;
    /// The first frame of a reopened session (frames of the session before it may still be queued
    /// when the GUI asks to open one), and why its replay may differ from the saved recording
    /// (training::modelDiffersNote, engine English; else empty).
    bool opened = false;
    QString openNote;
    QString scenarioName;
    bool replaceTrace = false;
    std::vector<training::LiveSample> samples;
    std::vector<training::SnapshotInfo> snapshots;
    std::vector<training::InjectedFault> faults;
    std::vector<training::TraineeAnswer> answers;
    training::TrainingScore score;
    /// The live line watched against its commissioning runs (issue #41); not ready when it could
    /// not be commissioned (monitorNote says why).
    training::LineMonitorState monitor;
    QString monitorNote;
    bool monitorCommissioning = false; ///< the monitor is still being commissioned (seconds)
};

namespace detail {
class TrainingWorker;
}

/// @brief Runs a training session live on its own thread (ARCHITECTURE.md rule 4: the line steps
/// and MPC decisions never block the GUI), in real time or accelerated. Commands from the
/// operator, the instructor and the trainee are queued to that thread in the order given; the
/// GUI learns the result from frames and from failed(). Not a Workbench job: the session has its
/// own clock and must run on while a Discover job holds the engine thread (docs/architecture.md).
/// Create and use from the GUI thread.
class TrainingRunner : public QObject {
    Q_OBJECT
public:
    explicit TrainingRunner(QObject* parent = nullptr);
    ~TrainingRunner() override; ///< stops the line and waits for its thread

    /// @brief Starts a session on the scenario's JSON text (checked by the engine's parser), with
    /// @p model for the MPC controllers; runs at once at the current speed.
    void start(const QString& scenarioJson, const hybrid::HybridModel& model);
    /// @brief Replays a saved session file up to where it ended and goes on from there, frozen.
    void open(const QString& sessionFile, const hybrid::HybridModel& model);
    /// @brief Session seconds per wall second (1 … 50).
    void setSpeed(double factor);
    /// @brief Runs @p seconds of session time as fast as the machine can (the instructor's
    /// fast-forward; tests use it to stay independent of the wall clock).
    void runAhead(int seconds);
    void setSetpoint(double pct);
    void setController(control::ControllerKind kind);
    /// @brief A fault acting @p delayS session seconds after the command reaches the line.
    void injectFault(plant::Mechanism mechanism, double strength, double delayS);
    void freeze();
    void resume();
    void takeSnapshot(const QString& label);
    void restore(const QString& label);
    void answer(const QString& cause);
    /// @brief Writes the session (session.json, recording/*.csv) into @p folder; saved() or failed().
    void save(const QString& folder);
    /// @brief Stops a replay or a run ahead under way (the line stays where it got to; a replay
    /// that is stopped leaves the session as it was). Thread-safe.
    void cancelLongWork() { m_cancel = true; }
    /// @brief The last frame received.
    const TrainingFrame& frame() const { return m_frame; }
    /// @brief The whole trace so far as the GUI holds it.
    const std::vector<training::LiveSample>& trace() const { return m_trace; }

Q_SIGNALS:
    void frameReady();
    /// @brief How far a replay or a run ahead has got (0…1).
    void progress(double fraction);
    /// @brief A command failed; @p message is worded for the user.
    void failed(const QString& action, const QString& message);
    /// @p referenceFolder: the line's commissioning runs as batch files beside the recording (the
    /// reference period of a diagnosis), empty when the monitor could not be commissioned.
    void saved(const QString& sessionFile, const QStringList& recordingFiles, const QString& referenceFolder);

private:
    void post(std::function<void(detail::TrainingWorker&)> command);
    void receive(const TrainingFrame& frame);

    std::atomic<bool> m_cancel{false};
    QThread m_thread;
    detail::TrainingWorker* m_worker = nullptr;
    TrainingFrame m_frame;
    std::vector<training::LiveSample> m_trace;
};

} // namespace drytwin::widgets

Q_DECLARE_METATYPE(drytwin::widgets::TrainingFrame)
