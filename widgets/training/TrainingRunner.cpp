#include "training/TrainingRunner.h"
#include "common/EngineText.h"

#include "common/ErrorText.h"
#include "data/BatchWriter.h"
#include "io/ModelFile.h"
#include "training/TrainingScript.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace drytwin::widgets {

namespace detail {

/// Lives on the runner's thread and owns the session; only it touches the session.
class TrainingWorker : public QObject {
    Q_OBJECT
public:
    explicit TrainingWorker(std::atomic<bool>& cancel) : m_cancel(cancel) {
        m_tick = new QTimer(this);
        m_tick->setInterval(100); // frames at 10 Hz; the plots redraw from them
        connect(m_tick, &QTimer::timeout, this, &TrainingWorker::tick);
    }

    void start(const std::string& scenarioJson, std::shared_ptr<const hybrid::HybridModel> model) {
        auto scenario = control::parseScenario(scenarioJson, "scenario");
        if (!scenario) {
            fail(QCoreApplication::translate("TrainingRunner", "Start"), scenario.error());
            return;
        }
        auto session = training::TrainingSession::start(*scenario, model);
        if (!session) {
            fail(QCoreApplication::translate("TrainingRunner", "Start"), session.error());
            return;
        }
        adopt(std::move(*session), scenarioJson, std::move(model), {});
    }

    void open(const std::string& path, std::shared_ptr<const hybrid::HybridModel> model) {
        auto script = training::loadTrainingScript(path);
        if (!script) {
            fail(QCoreApplication::translate("TrainingRunner", "Open session"), script.error());
            return;
        }
        const std::string fingerprint = io::modelFingerprint(*model);
        auto session = training::replay(*script, model, longWork());
        m_cancel = false;
        if (!session) {
            fail(QCoreApplication::translate("TrainingRunner", "Open session"), session.error());
            return;
        }
        session->freeze();
        m_openNote = training::modelDiffersNote(*script, fingerprint);
        m_justOpened = true;
        adopt(std::move(*session), script->scenarioJson, std::move(model), fingerprint);
    }

    /// Runs a command on the session and sends a frame; errors go to failed().
    void command(const QString& action, const std::function<Status(training::TrainingSession&)>& f) {
        if (!m_session) {
            Q_EMIT failed(action, QCoreApplication::translate("TrainingRunner", "Start a session first."));
            return;
        }
        if (auto st = f(*m_session); !st) {
            fail(action, st.error());
        }
        sendFrame();
    }

    void setSpeed(double factor) {
        m_speed = std::clamp(factor, 1.0, 50.0);
        sendFrame();
    }

    void runAhead(int seconds) {
        if (m_session) {
            const bool wasFrozen = m_session->frozen();
            if (wasFrozen) {
                m_session->resume();
            }
            m_session->advance(static_cast<std::size_t>(std::max(0, seconds)), longWork());
            m_cancel = false;
            if (wasFrozen) {
                m_session->freeze();
            }
        }
        sendFrame();
    }

    void save(const QString& folder) {
        if (!m_session) {
            Q_EMIT failed(QCoreApplication::translate("TrainingRunner", "Save session"),
                          QCoreApplication::translate("TrainingRunner", "Start a session first."));
            return;
        }
        if (m_modelFingerprint.empty()) {
            m_modelFingerprint = io::modelFingerprint(*m_model);
        }
        auto r = training::saveSession(folder.toStdString(), m_scenarioJson, *m_session, m_modelFingerprint);
        if (!r) {
            fail(QCoreApplication::translate("TrainingRunner", "Save session"), r.error());
            return;
        }
        QStringList files;
        for (const auto& f : r->recordingFiles) {
            files << QString::fromStdString(f);
        }
        // The commissioning runs beside it: the period when this line ran as it should, which a
        // diagnosis of the recording compares with. A monitor still being commissioned writes
        // them there when it is ready, so that a save (and a language change's freeze after it)
        // never waits for it.
        const QString referenceFolder = QDir(folder).filePath(QStringLiteral("commissioning"));
        adoptCommissionedMonitor(false);
        if (m_monitor) {
            if (!writeCommissioningRuns(*m_monitor, referenceFolder)) {
                fail(QCoreApplication::translate("TrainingRunner", "Save session"),
                     Error{ErrorKind::BadInput, referenceFolder.toStdString(),
                           "the commissioning runs could not be written"});
            }
        } else if (!m_commissioning.isFinished()) {
            m_commissioningFolders << referenceFolder;
        }
        Q_EMIT saved(QString::fromStdString(r->sessionFile), files,
                     m_monitor || !m_commissioning.isFinished() ? referenceFolder : QString());
    }

    void stop() {
        m_tick->stop();
        m_session.reset();
    }

Q_SIGNALS:
    void progress(double fraction);
    void frame(const drytwin::widgets::TrainingFrame& frame);
    void failed(const QString& action, const QString& message);
    void saved(const QString& sessionFile, const QStringList& recordingFiles, const QString& referenceFolder);

private:
    /// @p modelFingerprint: the model's, where already known (an open); else worked out at the
    /// first save (the whole model file's text: not on a start that may never be saved).
    void adopt(training::TrainingSession session, const std::string& scenarioJson,
               std::shared_ptr<const hybrid::HybridModel> model, const std::string& modelFingerprint) {
        // The line's monitor, commissioned on healthy runs of the same scenario: ten seconds of
        // simulation and calibration, done beside the running line so that the session starts at
        // once; the monitor then catches up on the trace so far (LineMonitor::feed).
        m_monitor.reset();
        m_monitorNote.clear();
        if (!m_commissioning.isFinished() && !m_commissioningFolders.isEmpty()) {
            m_earlierCommissionings.emplace_back(m_commissioning, std::exchange(m_commissioningFolders, {}));
        }
        m_commissioningFolders.clear();
        m_commissioning = QtConcurrent::run([scenario = session.scenario()] {
            return std::make_shared<Expected<training::LineMonitor>>(
                training::LineMonitor::commission(scenario));
        });
        m_session.emplace(std::move(session));
        m_scenarioJson = scenarioJson;
        m_model = std::move(model);
        m_modelFingerprint = modelFingerprint;
        m_sent = 0;
        m_clock.start();
        m_owed = 0;
        m_tick->start();
        sendFrame();
    }

    void fail(const QString& action, const Error& error) { Q_EMIT failed(action, errorText(error)); }

    bool commissioningFinished() const {
        return m_commissioning.isFinished() && !m_commissioning.isCanceled();
    }

    /// Takes in the monitor once its commissioning has finished; @p wait: waits for it (a save,
    /// which writes the commissioning runs beside the recording).
    void adoptCommissionedMonitor(bool wait) {
        if (m_commissioning.isCanceled() || (!wait && !commissioningFinished())) {
            return; // a default QFuture (none under way) reads as cancelled
        }
        auto monitor = m_commissioning.result();
        m_commissioning = {};
        if (*monitor) {
            m_monitor.emplace(std::move(**monitor));
            writeWhenCommissioned(*m_monitor, std::exchange(m_commissioningFolders, {}));
        } else {
            m_monitorNote = errorText(monitor->error());
            m_commissioningFolders.clear();
        }
    }

    /// Sessions saved, then replaced by another, before their monitor was commissioned: their
    /// commissioning runs are written once it is.
    void writeEarlierSessionsRuns() {
        for (auto it = m_earlierCommissionings.begin(); it != m_earlierCommissionings.end();) {
            if (!it->first.isFinished()) {
                ++it;
                continue;
            }
            if (auto monitor = it->first.result(); *monitor) {
                writeWhenCommissioned(**monitor, it->second);
            }
            it = m_earlierCommissionings.erase(it);
        }
    }

    void writeWhenCommissioned(const training::LineMonitor& monitor, const QStringList& folders) {
        for (const auto& folder : folders) {
            if (!writeCommissioningRuns(monitor, folder)) {
                fail(QCoreApplication::translate("TrainingRunner", "Save session"),
                     Error{ErrorKind::BadInput, folder.toStdString(),
                           "the commissioning runs could not be written"});
            }
        }
    }

    /// The monitor's commissioning runs as batch files in @p dir (created); false on a failed write.
    static bool writeCommissioningRuns(const training::LineMonitor& monitor, const QString& dir) {
        QDir().mkpath(dir);
        bool ok = true;
        for (const auto& run : monitor.commissioningRuns()) {
            ok = ok && data::writeBatchFile(
                           run, QDir(dir)
                                    .filePath(QString::fromStdString(run.id) + QStringLiteral(".csv"))
                                    .toStdString());
        }
        return ok;
    }

    /// Progress and cancel of a replay or a run ahead (minutes of MPC at full speed take seconds).
    Progress longWork() {
        return [this](const ProgressInfo& info) {
            Q_EMIT progress(info.fraction);
            return m_cancel ? ProgressAction::Stop : ProgressAction::Continue;
        };
    }

    void tick() {
        if (!m_session) {
            return;
        }
        // Session time follows the wall clock times the speed; what a slow step leaves owing is
        // run on the next tick, at most two seconds' worth so that a stall does not snowball.
        const double elapsedS = static_cast<double>(m_clock.restart()) / 1000.0;
        if (!m_session->frozen() && !m_session->finished()) {
            m_owed = std::min(m_owed + elapsedS * m_speed, 2.0 * m_speed);
            const auto whole = static_cast<std::size_t>(std::floor(m_owed));
            m_owed -= static_cast<double>(m_session->advance(whole));
            sendFrame();
        } else {
            m_owed = 0; // a frozen or finished line has nothing new to show; commands send their own frames
            if (commissioningFinished()) {
                sendFrame(); // ... but the monitor commissioned meanwhile has: its verdict on the trace
            }
        }
    }

    void sendFrame() {
        TrainingFrame f;
        f.speed = m_speed;
        if (m_session) {
            const auto& s = *m_session;
            f.started = true;
            f.frozen = s.frozen();
            f.finished = s.finished();
            f.timeS = s.timeS();
            f.endS = s.endS();
            f.bandPct = s.scenario().bandPct;
            f.setpointPct = s.setpointPct();
            f.controller = s.controller();
            f.controllerNote = fallbackReasonText(s.controllerNote()); // the MPC's reason to hold its plan
            f.opened = std::exchange(m_justOpened, false);
            f.openNote = QString::fromStdString(std::exchange(m_openNote, {}));
            f.scenarioName = QString::fromStdString(s.scenario().name);
            const auto& trace = s.trace();
            // A restore shortens the trace (and a later run may lengthen it past the count
            // sent): every restore or start sends it whole.
            const std::size_t restores =
                std::count_if(s.events().begin(), s.events().end(),
                              [](const auto& e) { return e.type == training::EventType::Restore; });
            if (restores != m_restoresSeen || m_sent > trace.size()) {
                m_restoresSeen = restores;
                m_sent = 0;
            }
            f.replaceTrace = m_sent == 0;
            f.samples.assign(trace.begin() + static_cast<long>(m_sent), trace.end());
            m_sent = trace.size();
            f.snapshots = s.snapshots();
            f.faults = s.faults();
            f.answers = s.answers();
            f.score = s.score();
            adoptCommissionedMonitor(false);
            writeEarlierSessionsRuns();
            if (m_monitor) {
                if (auto st = m_monitor->feed(s); !st) {
                    m_monitorNote = errorText(st.error());
                    m_monitor.reset();
                } else {
                    f.monitor = m_monitor->state();
                }
            }
            f.monitorNote = m_monitorNote;
            f.monitorCommissioning = !m_commissioning.isFinished();
        }
        Q_EMIT frame(f);
    }

    std::atomic<bool>& m_cancel;
    std::optional<training::TrainingSession> m_session;
    std::optional<training::LineMonitor> m_monitor;
    /// The monitor being commissioned for the current session (a shared pointer: the monitor is
    /// move-only, QFuture's results are copied).
    QFuture<std::shared_ptr<Expected<training::LineMonitor>>> m_commissioning;
    QStringList m_commissioningFolders; ///< sessions saved before it finished: their runs go there
    std::vector<std::pair<QFuture<std::shared_ptr<Expected<training::LineMonitor>>>, QStringList>>
        m_earlierCommissionings;
    QString m_monitorNote;
    std::string m_scenarioJson;
    std::shared_ptr<const hybrid::HybridModel> m_model; ///< the one the session's MPCs run on
    std::string m_modelFingerprint; ///< its io::modelFingerprint; empty until an open or a save needs it
    std::string m_openNote;         ///< the reopened session's model differs: said once, in the next frame
    bool m_justOpened = false;      ///< the next frame is the reopened session's first
    QTimer* m_tick = nullptr;
    QElapsedTimer m_clock;
    double m_speed = 10;
    double m_owed = 0;
    std::size_t m_sent = 0;
    std::size_t m_restoresSeen = 0;
};

} // namespace detail

TrainingRunner::TrainingRunner(QObject* parent) : QObject(parent) {
    qRegisterMetaType<TrainingFrame>();
    m_worker = new detail::TrainingWorker(m_cancel);
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &detail::TrainingWorker::frame, this, &TrainingRunner::receive);
    connect(m_worker, &detail::TrainingWorker::failed, this, &TrainingRunner::failed);
    connect(m_worker, &detail::TrainingWorker::saved, this, &TrainingRunner::saved);
    connect(m_worker, &detail::TrainingWorker::progress, this, &TrainingRunner::progress);
    m_thread.setObjectName(QStringLiteral("drytwin-training"));
    m_thread.start();
}

TrainingRunner::~TrainingRunner() {
    m_cancel = true; // a replay or run ahead under way stops at its next second
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker] { w->stop(); }, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
}

void TrainingRunner::post(std::function<void(detail::TrainingWorker&)> command) {
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, command = std::move(command)] { command(*w); }, Qt::QueuedConnection);
}

void TrainingRunner::receive(const TrainingFrame& frame) {
    if (frame.replaceTrace) {
        m_trace = frame.samples;
    } else {
        m_trace.insert(m_trace.end(), frame.samples.begin(), frame.samples.end());
    }
    m_frame = frame;
    m_frame.samples.clear(); // held once, in m_trace
    Q_EMIT frameReady();
}

void TrainingRunner::start(const QString& scenarioJson, const hybrid::HybridModel& model) {
    auto shared = std::make_shared<const hybrid::HybridModel>(model);
    post([text = scenarioJson.toStdString(), shared](detail::TrainingWorker& w) { w.start(text, shared); });
}

void TrainingRunner::open(const QString& sessionFile, const hybrid::HybridModel& model) {
    auto shared = std::make_shared<const hybrid::HybridModel>(model);
    post([path = sessionFile.toStdString(), shared](detail::TrainingWorker& w) { w.open(path, shared); });
}

void TrainingRunner::setSpeed(double factor) {
    post([factor](detail::TrainingWorker& w) { w.setSpeed(factor); });
}

void TrainingRunner::runAhead(int seconds) {
    post([seconds](detail::TrainingWorker& w) { w.runAhead(seconds); });
}

void TrainingRunner::setSetpoint(double pct) {
    post([pct](detail::TrainingWorker& w) {
        w.command(tr("Setpoint"), [pct](training::TrainingSession& s) { return s.setSetpoint(pct); });
    });
}

void TrainingRunner::setController(control::ControllerKind kind) {
    post([kind](detail::TrainingWorker& w) {
        w.command(tr("Controller"), [kind](training::TrainingSession& s) { return s.setController(kind); });
    });
}

void TrainingRunner::injectFault(plant::Mechanism mechanism, double strength, double delayS) {
    post([=](detail::TrainingWorker& w) {
        // "From now" means the line's time when the command arrives: the last frame may be a
        // few session seconds behind at 50×.
        w.command(tr("Inject fault"), [=](training::TrainingSession& s) {
            return s.injectFault(mechanism, strength, s.timeS() + delayS);
        });
    });
}

void TrainingRunner::freeze() {
    post([](detail::TrainingWorker& w) {
        w.command(tr("Freeze"), [](training::TrainingSession& s) {
            s.freeze();
            return Status{};
        });
    });
}

void TrainingRunner::resume() {
    post([](detail::TrainingWorker& w) {
        w.command(tr("Resume"), [](training::TrainingSession& s) {
            s.resume();
            return Status{};
        });
    });
}

void TrainingRunner::takeSnapshot(const QString& label) {
    post([l = label.toStdString()](detail::TrainingWorker& w) {
        w.command(tr("Snapshot"), [l](training::TrainingSession& s) { return s.takeSnapshot(l); });
    });
}

void TrainingRunner::restore(const QString& label) {
    post([l = label.toStdString()](detail::TrainingWorker& w) {
        w.command(tr("Restore"), [l](training::TrainingSession& s) { return s.restore(l); });
    });
}

void TrainingRunner::answer(const QString& cause) {
    post([c = cause.toStdString()](detail::TrainingWorker& w) {
        w.command(tr("Name the cause"), [c](training::TrainingSession& s) { return s.answer(c); });
    });
}

void TrainingRunner::save(const QString& folder) {
    post([folder](detail::TrainingWorker& w) { w.save(folder); });
}

} // namespace drytwin::widgets

#include "TrainingRunner.moc"
