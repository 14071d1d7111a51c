// What a project would lose if the window closed now, and the question asked before it does
// (issue #72 item 3: Ctrl+Q after a fresh run quit without asking). Work counts as unsaved from
// the action that made it until the project is saved or another one is opened; what the window
// recomputes by itself on opening (the simulation, the held-out evaluation) does not count.

#include "MainWindow.h"

#include "common/WidgetHelpers.h"
#include "mpc/MpcPanel.h"

#include <QCloseEvent>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace drytwin::widgets {

void MainWindow::noteUnsaved(const QString& what) {
    if (!m_unsavedWork.contains(what)) {
        m_unsavedWork << what;
    }
}

void MainWindow::trackUnsavedWork() {
    const auto note = [this](const char* what) { return [this, what] { noteUnsaved(tr(what)); }; };
    connect(&m_workbench, &Workbench::calibrated, this, note(QT_TR_NOOP("the calibration")));
    connect(&m_workbench, &Workbench::trained, this, note(QT_TR_NOOP("the learnt correction models")));
    connect(&m_workbench, &Workbench::discovered, this, note(QT_TR_NOOP("the discovery")));
    connect(&m_workbench, &Workbench::mpcFinished, this, note(QT_TR_NOOP("the what-if run")));
    connect(&m_workbench, &Workbench::ablationFinished, this, note(QT_TR_NOOP("the ablation")));
    connect(&m_workbench, &Workbench::modelEdited, this, note(QT_TR_NOOP("the changes to the model")));
    connect(m_mpc, &MpcPanel::scenarioEdited, this, note(QT_TR_NOOP("the edited scenario")));
}

bool MainWindow::askToSaveBeforeClosing() {
    QMessageBox box(QMessageBox::Question, tr("Save the project?"),
                    tr("Not saved in a project yet: %1. Save the project before closing?")
                        .arg(m_unsavedWork.join(tr(", "))),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setDefaultButton(QMessageBox::Save);
    const int answer = box.exec();
    if (answer == QMessageBox::Discard) {
        return true;
    }
    if (answer != QMessageBox::Save) {
        return false;
    }
    QString path = m_projectPath;
    if (path.isEmpty()) {
        path = askSaveFile(this, tr("Save project"), QStringLiteral("project.drytwin"),
                           tr("DryTwin projects (*.drytwin)"));
        if (path.isEmpty()) {
            return false; // no file chosen: nothing saved, so the window stays
        }
    }
    // Closing stops the work under way anyway; what is done is saved, and the model file is
    // written by a job of its own that must end before the window goes.
    m_workbench.cancelAll();
    const auto waitForEngine = [this] {
        QElapsedTimer waited;
        waited.start();
        while (m_workbench.jobs().busy() && waited.elapsed() < 60000) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
        }
    };
    waitForEngine();
    QString error;
    if (!saveProject(path, &error)) {
        showError(tr("Save project"), error);
        return false;
    }
    waitForEngine();
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_unsavedWork.isEmpty() && !askToSaveBeforeClosing()) {
        event->ignore();
        return;
    }
    // Closing mid-run cancels cleanly: the running job is told to stop, queued ones never start.
    m_workbench.cancelAll();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    event->accept();
}

} // namespace drytwin::widgets
