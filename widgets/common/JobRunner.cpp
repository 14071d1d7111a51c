#include "common/JobRunner.h"

#include "common/DisplayNames.h"

#include <QMetaObject>

namespace drytwin::widgets {

JobRunner::JobRunner(QObject* parent) : QObject(parent) {
    qRegisterMetaType<drytwin::widgets::JobId>("drytwin::widgets::JobId");
    qRegisterMetaType<drytwin::widgets::JobStatus>("drytwin::widgets::JobStatus");
    m_worker = new detail::JobWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &detail::JobWorker::started, this, &JobRunner::started);
    connect(m_worker, &detail::JobWorker::progress, this, &JobRunner::progress);
    connect(m_worker, &detail::JobWorker::finished, this, &JobRunner::onJobFinished);
    m_thread.setObjectName(QStringLiteral("DryTwin engine"));
    m_thread.start();
}

JobRunner::~JobRunner() {
    cancelAll();
    m_thread.quit();
    m_thread.wait();
}

JobId JobRunner::enqueue(const QString& name, std::shared_ptr<detail::Job> job) {
    job->id = m_nextId++;
    job->name = name;
    const bool wasBusy = busy();
    m_jobs[job->id] = job;
    m_worker->push(job);
    auto* worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker] { worker->runNext(); }, Qt::QueuedConnection);
    if (!wasBusy) {
        Q_EMIT busyChanged(true);
    }
    return job->id;
}

void JobRunner::cancel(JobId id) {
    if (const auto it = m_jobs.find(id); it != m_jobs.end()) {
        it->second->cancel = true;
    }
}

void JobRunner::stopKeepBest(JobId id) {
    if (const auto it = m_jobs.find(id); it != m_jobs.end()) {
        it->second->keepBest = true;
    }
}

void JobRunner::cancelAll() {
    for (auto& [id, job] : m_jobs) {
        job->cancel = true;
    }
}

void JobRunner::onJobFinished(JobId id, JobStatus status) {
    const auto it = m_jobs.find(id);
    if (it == m_jobs.end()) {
        return;
    }
    const auto job = it->second;
    m_jobs.erase(it);
    if (!job->hasContext || job->context) {
        job->deliver();
    }
    Q_EMIT finished(id, status);
    if (!busy()) {
        Q_EMIT busyChanged(false);
    }
}

namespace detail {

void JobWorker::push(std::shared_ptr<Job> job) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_queue.push_back(std::move(job));
}

void JobWorker::runNext() {
    std::shared_ptr<Job> job;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_queue.empty()) {
            return;
        }
        job = m_queue.front();
        m_queue.pop_front();
    }
    if (job->cancel || job->keepBest) { // stopped while queued: it never runs
        Q_EMIT finished(job->id, JobStatus::Cancelled);
        return;
    }
    Q_EMIT started(job->id, job->name);
    const JobId id = job->id;
    Job* raw = job.get();
    const Progress progressCb = [this, id, raw](const ProgressInfo& info) {
        Q_EMIT progress(id, QString::fromStdString(info.stage), info.fraction,
                        progressDetailText(info.stage, info.detail));
        if (raw->cancel) {
            return ProgressAction::Stop;
        }
        return raw->keepBest ? ProgressAction::StopKeepBest : ProgressAction::Continue;
    };
    const JobStatus status = job->run(m_session, progressCb);
    Q_EMIT finished(id, status);
}

} // namespace detail

} // namespace drytwin::widgets
