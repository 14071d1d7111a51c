// What a demo, a screenshot run or the training command drives from outside: actions run once
// the data is loaded, as if their buttons were pressed; a saved training session reopened on its
// tab; one PNG per tab.

#include "MainWindow.h"

#include "calibration/CalibrationPanel.h"
#include "mainwindow/MainWindowInternal.h"
#include "mpc/MpcPanel.h"
#include "residual/ResidualPanel.h"
#include "training/TrainingPanel.h"
#include "training/TrainingRunner.h"

#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTimer>
#include <utility>

namespace drytwin::widgets {

void MainWindow::runAfterLoad(const QStringList& actions) {
    m_pendingActions = actions;
    if (m_workbench.hasData()) {
        startActions();
    }
}

void MainWindow::startActions() {
    // Each is queued on the engine thread behind the one before; the panels show the results.
    // The what-if run takes its controllers from what the panel offers when it starts: with a
    // model still being opened (--model, a project) or learnt, it waits until the engine is idle,
    // and the actions after it with it (`--model M --run mpc` ran the physics model and the PI
    // loop alone: the learnt ones were not in yet).
    const QStringList actions = std::exchange(m_pendingActions, {});
    for (int i = 0; i < actions.size(); ++i) {
        const QString& a = actions[i];
        if (a == QLatin1String("mpc") && m_workbench.jobs().busy()) {
            m_pendingActions = actions.mid(i);
            whenEngineIdle([this] {
                if (m_workbench.hasData()) {
                    startActions();
                }
            });
            return;
        }
        if (a == QLatin1String("calibrate")) {
            m_calibration->run(); // the panel simulates with the new parameters when it ends
        } else if (a == QLatin1String("train")) {
            m_residual->train();
        } else if (a == QLatin1String("evaluate")) {
            m_workbench.evaluate();
        } else if (a == QLatin1String("ablation")) {
            m_workbench.ablation();
        } else if (a == QLatin1String("discover")) {
            m_workbench.discover();
        } else if (a == QLatin1String("mpc")) {
            m_mpc->run();
        }
    }
}

void MainWindow::whenEngineIdle(std::function<void()> then) {
    JobRunner& jobs = m_workbench.jobs();
    if (!jobs.busy()) {
        then();
        return;
    }
    auto* once = new QObject(this);
    connect(&jobs, &JobRunner::busyChanged, once, [this, &jobs, once, then = std::move(then)](bool busy) {
        if (busy) {
            return;
        }
        QObject::disconnect(&jobs, nullptr, once, nullptr);
        once->deleteLater();
        QTimer::singleShot(0, this, [this, then] { whenEngineIdle(then); });
    });
}

bool MainWindow::hasPendingActions() const {
    // A training session's monitor is commissioned beside the running line: a screenshot waits
    // for its verdict rather than catching "commissioning…".
    return !m_pendingActions.isEmpty() || m_training->isOpening() ||
           m_training->runner().frame().monitorCommissioning;
}

void MainWindow::openTrainingSession(const QString& sessionFile) {
    // A model or project opened beside it (--model, --project) is read by a job: the session is
    // replayed with the learnt controllers once they are in (its pgrl_cc was "not in the model
    // file" when replayed at once).
    if (m_workbench.jobs().busy()) {
        whenEngineIdle([this, sessionFile] { openTrainingSession(sessionFile); });
        return;
    }
    m_tabs->setCurrentWidget(m_training);
    m_statusLabel->setText(tr("Opening the training session %1…").arg(QDir::toNativeSeparators(sessionFile)));
    auto* once = new QObject(this);
    connect(m_training, &TrainingPanel::sessionOpenFinished, once,
            [this, once, sessionFile](const QString& file, bool ok, const QString& message) {
                if (file != sessionFile) {
                    return;
                }
                once->deleteLater();
                // The recording is the training session's own: the status line says so rather
                // than "no data"; a session that could not be opened says that instead.
                if (ok) {
                    m_statusLabel->setText(tr("Training session %1 (its recording is on the Training tab; "
                                              "no data set is loaded for the other tabs)")
                                               .arg(QDir::toNativeSeparators(sessionFile)));
                } else {
                    m_statusLabel->setText(tr("The training session %1 could not be opened: %2")
                                               .arg(QDir::toNativeSeparators(sessionFile), message));
                    Q_EMIT trainingSessionFailed(m_statusLabel->text());
                }
            });
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
            // Its faults page too: the faults with their units and the time left to react.
            QWidget* page = m_training->faultTable();
            while (page && !qobject_cast<QTabWidget*>(
                               page->parentWidget() ? page->parentWidget()->parentWidget() : nullptr)) {
                page = page->parentWidget();
            }
            if (auto* pages =
                    page ? qobject_cast<QTabWidget*>(page->parentWidget()->parentWidget()) : nullptr) {
                QWidget* shown = pages->currentWidget();
                pages->setCurrentWidget(page);
                for (int k = 0; k < 5; ++k) {
                    QApplication::processEvents();
                }
                const QString faults = QDir(folder).filePath(
                    QStringLiteral("%1-training-instructor-faults.png").arg(i + 2, 2, 10, QLatin1Char('0')));
                if (m_training->instructorWindow()->grab().save(faults)) {
                    files << faults;
                }
                pages->setCurrentWidget(shown);
            }
            m_training->setInstructorView(false);
        }
    }
    return files;
}

} // namespace drytwin::widgets
