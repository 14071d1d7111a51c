// The GUI's engine-thread job runner: order, results on the GUI thread, cancel of queued and
// running jobs (never lost), stop-and-keep-best, errors, and jobs whose receiver is gone.
#include "common/JobRunner.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>
#include <atomic>
#include <memory>

using namespace drytwin;
using drytwin::widgets::JobId;
using drytwin::widgets::JobRunner;
using drytwin::widgets::JobStatus;

namespace {

/// A job that reports progress every millisecond until told to stop, or @p steps are done.
std::function<Expected<int>(workflow::Session&, const Progress&)>
countingJob(int steps, std::atomic<bool>* ran, QThread** thread) {
    return [=](workflow::Session&, const Progress& progress) -> Expected<int> {
        *ran = true;
        *thread = QThread::currentThread();
        for (int i = 0; i < steps; ++i) {
            const auto action = progressAction(progress, "count", double(i) / steps, std::to_string(i));
            if (action == ProgressAction::Stop) {
                return cancelledError("count");
            }
            if (action == ProgressAction::StopKeepBest) {
                return i; // the best so far
            }
            QThread::msleep(1);
        }
        return steps;
    };
}

} // namespace

class TestJobRunner : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void runsOnTheEngineThreadAndDeliversOnTheGuiThread() {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        QSignalSpy progress(&runner, &JobRunner::progress);
        std::atomic<bool> ran{false};
        QThread* engineThread = nullptr;
        int value = -1;
        QThread* deliveredOn = nullptr;
        runner.submit<int>(QStringLiteral("count"), countingJob(20, &ran, &engineThread), this,
                           [&](const Expected<int>& r) {
                               value = r.ok() ? *r : -2;
                               deliveredOn = QThread::currentThread();
                           });
        QVERIFY(runner.busy());
        QVERIFY(finished.wait(10000));
        QCOMPARE(value, 20);
        QVERIFY(engineThread != nullptr && engineThread != QThread::currentThread());
        QCOMPARE(deliveredOn, QThread::currentThread());
        QCOMPARE(finished.first().at(1).value<JobStatus>(), JobStatus::Done);
        QVERIFY(progress.count() >= 20);
        QVERIFY(!runner.busy());
    }

    void cancelOfAQueuedJobIsNotLost() {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        std::atomic<bool> firstRan{false}, secondRan{false};
        QThread *t1 = nullptr, *t2 = nullptr;
        Expected<int> second = 0;
        const JobId a = runner.submit<int>(QStringLiteral("first"), countingJob(200, &firstRan, &t1), this,
                                           [](const Expected<int>&) {});
        const JobId b = runner.submit<int>(QStringLiteral("second"), countingJob(5, &secondRan, &t2), this,
                                           [&](const Expected<int>& r) { second = r; });
        QCOMPARE(runner.pending(), 2);
        runner.cancel(b); // while it waits behind the first
        QTRY_VERIFY_WITH_TIMEOUT(firstRan, 10000);
        runner.cancel(a); // while it runs
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 10000);
        QCOMPARE(finished.at(0).at(0).value<JobId>(), a);
        QCOMPARE(finished.at(0).at(1).value<JobStatus>(), JobStatus::Cancelled);
        QCOMPARE(finished.at(1).at(0).value<JobId>(), b);
        QCOMPARE(finished.at(1).at(1).value<JobStatus>(), JobStatus::Cancelled);
        QVERIFY(!secondRan); // it never started
        QVERIFY(!second.ok());
        QCOMPARE(second.error().code, ErrorCode::Cancelled);
        // The runner goes on with new work after cancels.
        std::atomic<bool> thirdRan{false};
        QThread* t3 = nullptr;
        int third = 0;
        runner.submit<int>(QStringLiteral("third"), countingJob(3, &thirdRan, &t3), this,
                           [&](const Expected<int>& r) { third = r.ok() ? *r : -1; });
        QTRY_COMPARE_WITH_TIMEOUT(third, 3, 10000);
    }

    void stopKeepBestReturnsTheResultSoFar() {
        JobRunner runner;
        std::atomic<bool> ran{false};
        QThread* t = nullptr;
        int value = -1;
        bool delivered = false;
        const JobId id = runner.submit<int>(QStringLiteral("count"), countingJob(100000, &ran, &t), this,
                                            [&](const Expected<int>& r) {
                                                value = r.ok() ? *r : -2;
                                                delivered = true;
                                            });
        QTRY_VERIFY_WITH_TIMEOUT(ran, 10000);
        QTest::qWait(20);
        runner.stopKeepBest(id);
        QTRY_VERIFY_WITH_TIMEOUT(delivered, 10000);
        QVERIFY(value > 0 && value < 100000);
    }

    void engineErrorsArriveAsValues() {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        Error got;
        runner.submit<workflow::SimulateResult>(
            QStringLiteral("simulate"),
            [](workflow::Session& s, const Progress& p) { return s.simulate({}, p); }, this,
            [&](const Expected<workflow::SimulateResult>& r) { got = r.error(); });
        QVERIFY(finished.wait(10000));
        QCOMPARE(finished.first().at(1).value<JobStatus>(), JobStatus::Failed);
        QCOMPARE(got.code, ErrorCode::NoDataLoaded);
    }

    void aGoneReceiverIsNotCalled() {
        JobRunner runner;
        QSignalSpy finished(&runner, &JobRunner::finished);
        bool called = false;
        std::atomic<bool> ran{false};
        QThread* t = nullptr;
        auto receiver = std::make_unique<QObject>();
        runner.submit<int>(QStringLiteral("count"), countingJob(30, &ran, &t), receiver.get(),
                           [&](const Expected<int>&) { called = true; });
        receiver.reset();
        QVERIFY(finished.wait(10000));
        QVERIFY(!called);
    }

    void destroyingTheRunnerStopsTheRunningJob() {
        std::atomic<bool> ran{false};
        QThread* t = nullptr;
        QElapsedTimer timer;
        {
            JobRunner runner;
            runner.submit<int>(QStringLiteral("long"), countingJob(1000000, &ran, &t), this,
                               [](const Expected<int>&) {});
            QTRY_VERIFY_WITH_TIMEOUT(ran, 10000);
            timer.start();
        } // cancels and joins the engine thread
        QVERIFY(timer.elapsed() < 5000);
    }
};

QTEST_MAIN(TestJobRunner)
#include "TestJobRunner.moc"
