// How data come into the window and which data set it shows: the data-set list at the tabs' top
// right, what follows a load (simulate, the project's model and results, the actions asked for),
// the way to the column mapping when a file was not recognised, and the bundled demo.

#include "MainWindow.h"

#include "data/DataPanel.h"
#include "workflow/ProjectFile.h"

#include <QComboBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QTabWidget>
#include <algorithm>
#include <memory>
#include <utility>

namespace drytwin::widgets {

void MainWindow::createDataSetChooser() {
    // Which data set the tabs show, and the others opened in this window.
    m_dataSetChooser = new QComboBox;
    m_dataSetChooser->setToolTip(
        tr("The data set every tab shows; the others opened in this window stay here"));
    m_dataSetChooser->setMinimumContentsLength(24);
    m_dataSetChooser->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    auto* chooserBox = new QWidget;
    auto* chooserLayout = new QHBoxLayout(chooserBox);
    chooserLayout->setContentsMargins(4, 0, 4, 0);
    chooserLayout->addWidget(new QLabel(tr("Data set:")));
    chooserLayout->addWidget(m_dataSetChooser);
    m_tabs->setCornerWidget(chooserBox, Qt::TopRightCorner);
    const auto fillChooser = [this] {
        m_dataSetChooser->blockSignals(true);
        m_dataSetChooser->clear();
        for (const auto& e : m_workbench.dataSets()) {
            m_dataSetChooser->addItem(e.labelText(), e.path);
            m_dataSetChooser->setItemData(m_dataSetChooser->count() - 1, e.path, Qt::ToolTipRole);
        }
        if (m_workbench.dataSets().empty()) {
            m_dataSetChooser->addItem(tr("none loaded"));
        }
        m_dataSetChooser->setCurrentIndex(std::max(0, m_workbench.currentDataSet()));
        m_dataSetChooser->blockSignals(false);
    };
    fillChooser();
    connect(&m_workbench, &Workbench::dataSetsChanged, this, fillChooser);
    connect(m_dataSetChooser, QOverload<int>::of(&QComboBox::activated), &m_workbench,
            &Workbench::switchDataSet);
}

void MainWindow::connectDataLoading() {
    connect(m_mapButton, &QPushButton::clicked, this, [this] {
        m_mapButton->setVisible(false);
        if (!m_mapFile.isEmpty()) {
            m_data->mapAndOpen(m_mapFile);
        }
    });
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        Q_EMIT loadFinished(true);
        m_mapButton->setVisible(false);
        m_workbench.simulate();
        // A project's data that changed since it was saved (a batch file removed, rows added): the
        // results and learnt parts restored below were made on the data as saved; say so rather
        // than show them as this data's (each learnt part still names the data it was learnt on).
        const QString saved = std::exchange(m_pendingDataFingerprint, QString());
        const auto change = workflow::dataChangeSince(saved.toStdString(), dataFingerprint().toStdString());
        if (!saved.isEmpty() && change) {
            const auto batches = [this](const std::string& list) {
                return list.empty() ? tr("nothing") : QString::fromStdString(list);
            };
            const QString how =
                change->valuesOnly
                    ? tr("the same batches and rows, %1, hold other values").arg(batches(change->batchesNow))
                    : tr("then: %1; now: %2").arg(batches(change->batchesThen), batches(change->batchesNow));
            m_projectWarning =
                tr("The project's data are not what they were when it was saved (%1). "
                   "The results shown were made on the data as saved; run the steps again to update them.")
                    .arg(how);
            showError(tr("Project data changed"), m_projectWarning);
        }
        if (!m_pendingModel.isEmpty()) {
            m_workbench.openModel(m_pendingModel, std::exchange(m_pendingParts, std::nullopt));
            m_workbench.simulate(); // again, with the project's model
            m_pendingModel.clear();
        }
        restorePending();
        startActions();
    });
    connect(&m_workbench, &Workbench::dataLoadFailed, this,
            [this](const QString&, const QString& path, bool mappingMayHelp) {
                // A file whose columns were not recognised: the way to the column mapping, at hand.
                m_mapFile = mappingMayHelp ? path : QString();
                m_mapButton->setVisible(mappingMayHelp);
                // A project whose data are gone (moved, renamed): its model and saved results still
                // open, so that nothing saved is lost from view; the failure itself is shown.
                m_pendingDataFingerprint.clear();
                // Actions asked for once the data were loaded (--run) cannot run: a scripted run
                // waited for them for ever.
                m_pendingActions.clear();
                if (!m_pendingModel.isEmpty() || m_pendingResults || m_pendingParts) {
                    const QString note = tr("The project's data could not be opened from %1: its model and "
                                            "saved results are shown. Open the data (File ▸ Open data set "
                                            "folder…) to run anything on them.")
                                             .arg(QDir::toNativeSeparators(path));
                    // Said once the failure's own message (the load's end) and, with a model, the
                    // model's opening (the next action to end) have been shown.
                    auto said = std::make_shared<QMetaObject::Connection>();
                    auto ends = std::make_shared<int>(m_pendingModel.isEmpty() ? 1 : 2);
                    *said = connect(&m_workbench, &Workbench::actionFinished, this, [this, said, ends, note] {
                        if (--*ends > 0) {
                            return;
                        }
                        disconnect(*said);
                        m_lastStatus = note;
                        m_statusLabel->setText(note);
                    });
                    if (!m_pendingModel.isEmpty()) {
                        m_workbench.openModel(m_pendingModel, std::exchange(m_pendingParts, std::nullopt));
                        m_pendingModel.clear();
                    }
                    restorePending();
                }
                Q_EMIT loadFinished(false);
            });
}

void MainWindow::openBundledDemo() {
    // The demo of scripts/run.sh (drytwin generate --demo --seed 2025), written once per user.
    const QString folder = QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                               .filePath(QStringLiteral("demo-data"));
    if (!QDir(folder).entryList({QStringLiteral("*.csv")}, QDir::Files).isEmpty()) {
        openDataSet(folder);
        return;
    }
    workflow::GenerateOptions g;
    g.plant = plant::PlantOptions::demo(2025); // distributed plant, realistic sensors
    g.outFolder = folder.toStdString();
    m_statusLabel->setText(
        tr("Writing the bundled demo (10 batches of the virtual plant) to %1…").arg(folder));
    m_workbench.generate(g);
}

void MainWindow::openDataSet(const QString& path, const QString& mappingPath) {
    m_workbench.openData(path, mappingPath);
}

} // namespace drytwin::widgets
