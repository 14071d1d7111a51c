#pragma once
// What every widget test waits on: the engine's queue of a window or a workbench empty.
#include <QElapsedTimer>
#include <QtTest>

namespace drytwin::widgets::test {

/// Waits until @p owner's job queue (MainWindow::jobs(), Workbench::jobs()) has been idle for four
/// polls in a row (200 ms: an action's follow-ups are queued from its end), at most @p ms.
template <class Owner> bool waitUntilIdle(Owner& owner, int ms) {
    QElapsedTimer t;
    t.start();
    int idle = 0;
    while (t.elapsed() < ms) {
        QTest::qWait(50);
        idle = owner.jobs().busy() ? 0 : idle + 1;
        if (idle >= 4) {
            return true;
        }
    }
    return false;
}

} // namespace drytwin::widgets::test
