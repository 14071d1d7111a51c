#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "workflow/Session.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QThread>
#include <atomic>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>

namespace drytwin::widgets {

/// @brief Identifies one submitted job.
using JobId = quint64;

/// @brief How a job ended, as the GUI thread sees it.
enum class JobStatus { Done, Failed, Cancelled };

namespace detail {
class JobWorker;
/// One queued or running job. The flags are set from the GUI thread and read on the engine thread.
struct Job {
    JobId id = 0;
    QString name;
    std::atomic<bool> cancel{false};   ///< stop and give up
    std::atomic<bool> keepBest{false}; ///< stop and keep the best so far (iterative work)
    std::function<JobStatus(workflow::Session&, const Progress&)> run; ///< engine thread
    std::function<void()> deliver;                                     ///< GUI thread, after run
    QPointer<QObject> context; ///< deliver is skipped when this object is gone
    bool hasContext = false;
};
} // namespace detail

/// @brief Runs workflow::Session calls on one engine thread, in the order submitted
/// (ARCHITECTURE.md rules 3 and 4). The Session lives on that thread and only jobs touch it.
/// Every job has its own cancel token: cancelling a queued job is never lost, and it then does
/// not run at all. Results come back by value on the GUI thread. Create and use from the GUI
/// thread only.
class JobRunner : public QObject {
    Q_OBJECT
public:
    explicit JobRunner(QObject* parent = nullptr);
    ~JobRunner() override; ///< cancels every job and waits for the running one to stop

    /// @brief Queues @p work; @p done receives its result on this (the GUI) thread unless
    /// @p context has been destroyed by then. A cancelled job's @p done receives the
    /// Cancelled error.
    template <class R>
    JobId submit(const QString& name, std::function<Expected<R>(workflow::Session&, const Progress&)> work,
                 QObject* context, std::function<void(const Expected<R>&)> done) {
        auto job = std::make_shared<detail::Job>();
        auto result = std::make_shared<std::unique_ptr<Expected<R>>>();
        job->run = [work = std::move(work), result](workflow::Session& s, const Progress& p) {
            *result = std::make_unique<Expected<R>>(work(s, p));
            if (**result) {
                return JobStatus::Done;
            }
            return (*result)->error().kind == ErrorKind::Cancelled ? JobStatus::Cancelled : JobStatus::Failed;
        };
        job->deliver = [done = std::move(done), result, name] {
            if (!*result) { // cancelled before it ran
                *result = std::make_unique<Expected<R>>(cancelledError(name.toStdString()));
            }
            if (done) {
                done(**result);
            }
        };
        job->context = context;
        job->hasContext = context != nullptr;
        return enqueue(name, std::move(job));
    }

    /// @brief Asks a queued or running job to stop; a queued one will not run. Thread-safe.
    void cancel(JobId id);
    /// @brief Asks a running iterative job to stop and keep its best result so far (a queued
    /// job is cancelled).
    void stopKeepBest(JobId id);
    /// @brief Cancels every queued and running job.
    void cancelAll();
    /// @brief True while a job is queued or running.
    bool busy() const { return !m_jobs.empty(); }
    /// @brief Jobs queued or running.
    int pending() const { return static_cast<int>(m_jobs.size()); }
    /// @brief The job the engine thread runs now, or runs next when none has started yet (jobs
    /// run in the order submitted); 0 when idle.
    JobId headJob() const { return m_jobs.empty() ? 0 : m_jobs.begin()->first; }
    /// @brief The name a queued or running job was submitted with ("" when it is not).
    QString jobName(JobId id) const {
        const auto it = m_jobs.find(id);
        return it == m_jobs.end() ? QString() : it->second->name;
    }

Q_SIGNALS:
    void started(drytwin::widgets::JobId id, const QString& name);
    void progress(drytwin::widgets::JobId id, const QString& stage, double fraction, const QString& detail);
    void finished(drytwin::widgets::JobId id, drytwin::widgets::JobStatus status);
    void busyChanged(bool busy);

private:
    JobId enqueue(const QString& name, std::shared_ptr<detail::Job> job);
    void onJobFinished(JobId id, JobStatus status);

    QThread m_thread;
    detail::JobWorker* m_worker = nullptr;
    std::map<JobId, std::shared_ptr<detail::Job>> m_jobs; ///< queued or running, GUI thread only
    JobId m_nextId = 1;
};

namespace detail {

/// @brief Lives on the engine thread, owns the Session and runs queued jobs one at a time.
class JobWorker : public QObject {
    Q_OBJECT
public:
    void push(std::shared_ptr<Job> job);
    void runNext();

Q_SIGNALS:
    void started(drytwin::widgets::JobId id, const QString& name);
    void progress(drytwin::widgets::JobId id, const QString& stage, double fraction, const QString& detail);
    void finished(drytwin::widgets::JobId id, drytwin::widgets::JobStatus status);

private:
    std::mutex m_mutex;
    std::deque<std::shared_ptr<Job>> m_queue;
    workflow::Session m_session;
};

} // namespace detail

} // namespace drytwin::widgets

Q_DECLARE_METATYPE(drytwin::widgets::JobStatus)
