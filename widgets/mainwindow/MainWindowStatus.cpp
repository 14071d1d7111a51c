// What the status bar says while DryTwin works: the status line (the Workbench's last word, or a
// job's stage and share in the user's language), one progress bar per action, Cancel, and errors
// (on the status line, and in a box unless DRYTWIN_NO_MODAL is set).

#include "MainWindow.h"

#include "common/Translations.h"

#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <algorithm>
#include <map>

namespace drytwin::widgets {

void MainWindow::createStatusBar() {
    m_statusLabel = new QLabel(noDataHint());
    m_progressBar = new QProgressBar;
    m_progressBar->setMaximumWidth(200);
    m_progressBar->setRange(0, 100);
    m_cancelButton = new QPushButton(tr("Cancel"));
    statusBar()->addWidget(m_statusLabel, 1);
    m_mapButton = new QPushButton(tr("Column mapping…")); // the Data tab's button has the same name
    m_mapButton->setToolTip(tr("Open the column-mapping dialog for the file that was not recognised"));
    m_mapButton->setVisible(false);
    statusBar()->addPermanentWidget(m_mapButton);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    setBusy(false);
}

void MainWindow::connectProgress() {
    auto& jobs = m_workbench.jobs();
    connect(&jobs, &JobRunner::busyChanged, this, &MainWindow::setBusy);
    // One bar per action across its stages: the action's own stage ("evaluate" for Evaluate) moves
    // the bar, never back; a stage inside it (simulate, lstm …) is named after the action's share,
    // so that the bar and the status line never tell two different numbers.
    connect(&jobs, &JobRunner::started, this, [this](JobId id, const QString& name) {
        m_progressJob = id;
        m_progressStage.clear();
        m_progressBar->setValue(0);
        const QString format = QStringLiteral("%1 %p%").arg(name);
        m_progressBar->setFormat(format);
        // Wide enough for the action's name ("Learn the correction models 40%") and no wider
        // than half the window.
        const int wanted = m_progressBar->fontMetrics().horizontalAdvance(format) + 40;
        m_progressBar->setFixedWidth(std::clamp(wanted, 160, std::max(160, width() / 2)));
    });
    connect(&jobs, &JobRunner::progress, this,
            [this](JobId id, const QString& stage, double fraction, const QString& detail) {
                if (id != m_progressJob) {
                    return;
                }
                if (m_progressStage.isEmpty()) {
                    m_progressStage = progressStageOf(m_workbench.actionOf(id));
                    if (m_progressStage.isEmpty()) {
                        m_progressStage = stage; // a job of no named action: its first stage
                    }
                }
                if (stage == m_progressStage) {
                    m_progressBar->setValue(
                        std::max(m_progressBar->value(), static_cast<int>(fraction * 100)));
                }
                // The action's share is the bar's; a stage inside it follows in brackets. The engine's
                // detail is English (the CLI prints it): shown in the English window only.
                const QString said = detail.isEmpty() || currentLanguage() != QLatin1String("en")
                                         ? QString()
                                         : QStringLiteral(" — %1").arg(detail);
                QString line = tr("%1: %2 %").arg(stageText(m_progressStage)).arg(m_progressBar->value());
                if (stage != m_progressStage) {
                    line += QStringLiteral(" (%1)").arg(
                        tr("%1: %2 %").arg(stageText(stage)).arg(fraction * 100, 0, 'f', 0) + said);
                } else {
                    line += said;
                }
                m_statusLabel->setText(line);
                m_statusIsProgress = true;
            });
    connect(m_cancelButton, &QPushButton::clicked, &m_workbench, &Workbench::cancelAll);
    connect(&m_workbench, &Workbench::queued, this, [this](const QString& text) {
        m_statusLabel->setText(text);
        m_statusIsProgress = true;
    });
    connect(&m_workbench, &Workbench::status, this, [this](const QString& text) {
        m_lastStatus = text;
        m_statusIsProgress = false;
        m_statusLabel->setText(text);
    });
    connect(&m_workbench, &Workbench::failed, this,
            [this](const QString& action, const QString& message, bool cancelled) {
                if (!cancelled) {
                    showError(action, message);
                }
            });
}

void MainWindow::setBusy(bool busy) {
    m_progressBar->setVisible(busy);
    m_cancelButton->setVisible(busy);
    if (!busy) {
        m_progressBar->setValue(0);
        // A progress line of a job that has ended ("Simulating: 0 %") would say it still runs.
        if (m_statusIsProgress) {
            m_statusLabel->setText(m_lastStatus.isEmpty() ? tr("Ready.") : m_lastStatus);
            m_statusIsProgress = false;
        }
    }
}

void MainWindow::showError(const QString& title, const QString& message) {
    m_statusLabel->setText(message);
    if (qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
        return;
    }
    // Window-modal but not blocking: the job that failed finishes its cleanup first (a blocking
    // dialog held its progress bar at 100 % with Cancel enabled behind it), and a scripted run's
    // idle check goes on.
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

QString MainWindow::noDataHint() {
    return tr("No data loaded. File ▸ Open data set folder… (or File ▸ Open the bundled demo)");
}

QString MainWindow::stageText(const QString& stage) {
    // The engine's stage keys, in the user's language.
    static const std::map<QString, const char*> words{
        {QStringLiteral("load"), QT_TR_NOOP("Loading")},
        {QStringLiteral("simulate"), QT_TR_NOOP("Simulating")},
        {QStringLiteral("calibrate"), QT_TR_NOOP("Calibrating")},
        {QStringLiteral("train"), QT_TR_NOOP("Learning the correction models")},
        {QStringLiteral("lstm"), QT_TR_NOOP("Training the LSTM")},
        {QStringLiteral("evaluate"), QT_TR_NOOP("Scoring on the held-out part")},
        {QStringLiteral("discover"), QT_TR_NOOP("Discovering")},
        {QStringLiteral("ablation"), QT_TR_NOOP("Ablation")},
        {QStringLiteral("mpc"), QT_TR_NOOP("What-if scenario")},
        {QStringLiteral("generate"), QT_TR_NOOP("Generating plant data")},
        {QStringLiteral("training"), QT_TR_NOOP("Training session")}};
    const auto it = words.find(stage);
    return it == words.end() ? stage : tr(it->second);
}

} // namespace drytwin::widgets
