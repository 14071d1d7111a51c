// What a project file holds and how it comes back: saveProject() writes the paths (data, model,
// mapping, reference period), the tab, the selected batches, the latest results and the learnt
// parts' states; openProject() reads them and puts each back once the data and the model are in;
// reopenInLanguage() carries the whole state into a new window through a temporary project.

#include "MainWindow.h"

#include "common/ErrorText.h"
#include "common/Translations.h"
#include "data/DataPanel.h"
#include "mainwindow/MainWindowInternal.h"
#include "mpc/MpcPanel.h"
#include "training/TrainingPanel.h"
#include "training/TrainingRunner.h"
#include "workflow/ProjectFile.h"
#include "workflow/ResultArchive.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <algorithm>
#include <map>
#include <utility>

namespace drytwin::widgets {

bool MainWindow::saveProject(const QString& path, QString* error, bool remember) {
    // The results beside the project, typed (workflow/ResultArchive.h): a reopened project shows
    // its calibration, evaluation, ablation, discovery and what-if run without re-running them.
    const QString resultsPath = path + QStringLiteral(".results.json");
    // A folder typed into the save dialog that does not exist yet is made, as an engineer expects.
    const QString folder = QFileInfo(path).absolutePath();
    if (!QDir().mkpath(folder)) {
        if (error) {
            *error = tr("cannot create the folder %1 for the project").arg(folder);
        }
        return false;
    }
    const auto writeResults = [error](const QString& file, const workflow::LatestResults& latest) {
        QSaveFile results(file);
        if (!results.open(QIODevice::WriteOnly) ||
            results.write(QByteArray::fromStdString(workflow::latestResultsJson(latest))) < 0 ||
            !results.commit()) {
            if (error) {
                *error = tr("cannot write %1: %2").arg(file, results.errorString());
            }
            return false;
        }
        return true;
    };
    if (!writeResults(resultsPath, m_workbench.latest())) {
        return false;
    }
    // The other data sets' results too, each in a file of its own: results made on the plant's
    // data and kept while a historian export was looked at came back empty (issue #72 item 3).
    const auto otherResults = m_workbench.otherDataSetResults();
    std::map<QString, QString> otherResultFiles;
    for (const auto& [dataPath, latest] : otherResults) {
        const QString file =
            path + QStringLiteral(".results.%1.json").arg(static_cast<int>(otherResultFiles.size()) + 1);
        if (!writeResults(file, latest)) {
            return false;
        }
        otherResultFiles[dataPath] = file;
    }
    const QString savedMessage = tr("Project saved to %1 (model, results and view)").arg(path);
    QString modelPath = m_workbench.modelPath();
    bool modelQueued = false;
    // A model read from the language change's temporary project goes with that project: copied too.
    const bool fromLanguageTemp = !m_languageTempProject.isEmpty() &&
                                  modelPath == m_languageTempProject + QStringLiteral(".model.json");
    if (modelPath.isEmpty() || fromLanguageTemp || m_workbench.model().calibration ||
        m_workbench.model().hasResidualModels()) {
        // The session's model as it is now, beside the project.
        // The session writes it (atomically) on the engine thread, queued before anything else the
        // user starts; a project whose model file is missing opens with the data alone.
        modelPath = path + QStringLiteral(".model.json");
        m_workbench.saveModel(modelPath, savedMessage);
        modelQueued = true;
    }
    QJsonObject o;
    o[QStringLiteral("format")] = QStringLiteral("drytwin-project");
    o[QStringLiteral("format_version")] = 1;
    const QDir base = QFileInfo(path).absoluteDir();
    // Paths relative to the project file, which reopening resolves against its folder: a path
    // given relative to the working directory (`drytwin --data lag`) is made absolute first, or a
    // project saved elsewhere would look for "lag" beside itself.
    const auto fromProject = [&base](const QString& p) {
        return p.isEmpty() ? QString() : base.relativeFilePath(QFileInfo(p).absoluteFilePath());
    };
    // Each path also absolute: a project file copied away from its data (mailed, moved into an
    // archive folder) still finds them where they were.
    const auto withAbsolute = [&](QJsonObject& into, const QString& key, const QString& p) {
        into[key] = fromProject(p);
        into[key + QStringLiteral("_absolute")] = p.isEmpty() ? QString() : QFileInfo(p).absoluteFilePath();
    };
    withAbsolute(o, QStringLiteral("data_path"), m_workbench.dataPath());
    withAbsolute(o, QStringLiteral("model_path"), modelPath);
    withAbsolute(o, QStringLiteral("mapping_path"), m_workbench.mappingPath());
    // The reference period discovery compares with: the project remembers it (issue #41).
    withAbsolute(o, QStringLiteral("reference_path"), m_workbench.referencePath());
    o[QStringLiteral("data_fingerprint")] = dataFingerprint();
    // Every data set opened in the window (a historian export with its mapping, a training
    // recording beside the plant's data), so that a reopened project can switch to them again.
    QJsonArray dataSets;
    for (const auto& e : m_workbench.dataSets()) {
        QJsonObject entry{{QStringLiteral("label"), e.label}, {QStringLiteral("batches"), e.batches}};
        withAbsolute(entry, QStringLiteral("path"), e.path);
        withAbsolute(entry, QStringLiteral("mapping_path"), e.mappingPath);
        if (const QString offered = m_workbench.suggestedReference(e.path); !offered.isEmpty()) {
            withAbsolute(entry, QStringLiteral("suggested_reference"), offered);
        }
        if (const auto it = otherResultFiles.find(e.path); it != otherResultFiles.end()) {
            withAbsolute(entry, QStringLiteral("results_path"), it->second);
        }
        dataSets.append(entry);
    }
    o[QStringLiteral("data_sets")] = dataSets;
    // The what-if scenario as it stands in the editor, edits and all (it reverted to the bundled
    // one on reopening).
    o[QStringLiteral("scenario")] = QJsonObject{{QStringLiteral("name"), m_mpc->scenarioName()},
                                                {QStringLiteral("text"), m_mpc->scenarioText()}};
    o[QStringLiteral("tab")] = QString::fromLatin1(kTabKeys[std::max(0, m_tabs->currentIndex())]);
    QJsonArray batches;
    for (const auto& r : m_data->batchTable()->selectionModel()->selectedRows()) {
        batches.append(r.row());
    }
    o[QStringLiteral("selected_batches")] = batches;
    withAbsolute(o, QStringLiteral("results_path"), resultsPath);
    QJsonArray parts;
    for (const auto& part : m_workbench.learntParts()) {
        parts.append(
            QJsonObject{{QStringLiteral("kind"), QString::fromLatin1(control::controllerName(part.kind))},
                        {QStringLiteral("state"), static_cast<int>(part.state)},
                        {QStringLiteral("learnt_on"), part.learntOn},
                        {QStringLiteral("learnt_on_data_set"), part.learntOnName},
                        {QStringLiteral("learnt_on_batches"), part.learntOnBatches},
                        {QStringLiteral("stale_because"), part.staleBecause}});
    }
    o[QStringLiteral("learnt_parts")] = parts;
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) {
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    f.write(QJsonDocument(o).toJson());
    if (!f.commit()) {
        if (error) {
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    if (remember) {
        m_projectPath = path;
        rememberRecent(path);
        m_unsavedWork.clear(); // a language change's temporary project saves nothing for the user
    }
    // With a model to write, the status says "saved" once the model file is written too.
    m_statusLabel->setText(modelQueued ? tr("Saving the project to %1…").arg(path) : savedMessage);
    return true;
}

bool MainWindow::openProject(const QString& path, QString* error, bool remember) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) {
            *error = tr("cannot open %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &parseError);
    if (doc.isNull() || !doc.isObject() ||
        doc.object().value(QStringLiteral("format")).toString() != QLatin1String("drytwin-project")) {
        if (error) {
            *error = tr("%1 is not a DryTwin project (%2)").arg(path, parseError.errorString());
        }
        return false;
    }
    const QJsonObject o = doc.object();
    // Every path resolved as `drytwin report` resolves it (workflow/ProjectFile.h).
    const auto paths = workflow::readProjectPaths(path.toStdString());
    if (!paths) {
        if (error) {
            *error = errorText(paths.error());
        }
        return false;
    }
    const auto q = [](const std::string& p) { return QString::fromStdString(p); };
    const QString data = q(paths->data);
    const QString model = q(paths->model);
    m_pendingDataFingerprint = o.value(QStringLiteral("data_fingerprint")).toString();
    m_projectWarning.clear(); // a warning of the project opened before does not carry over
    m_pendingTab = -1;
    const QString tab = o.value(QStringLiteral("tab")).toString();
    for (int i = 0; i < 8; ++i) {
        if (tab == QLatin1String(kTabKeys[i])) {
            m_pendingTab = i;
        }
    }
    if (remember) {
        m_projectPath = path;
        rememberRecent(path);
    }
    // Results and the learnt parts' states, put back once the data and the model are in.
    m_pendingResults.reset();
    const QString resultsFile = q(paths->results);
    if (!resultsFile.isEmpty() && QFileInfo::exists(resultsFile)) {
        QFile rf(resultsFile);
        if (rf.open(QIODevice::ReadOnly)) {
            auto parsed = workflow::parseLatestResults(rf.readAll().toStdString(), resultsFile.toStdString());
            if (parsed) {
                m_pendingResults = std::move(*parsed);
            } else {
                m_statusLabel->setText(
                    tr("The project's results could not be read (%1); it opens without them.")
                        .arg(errorText(parsed.error())));
            }
        }
    }
    // Each other data set's results, put back with the rest so that switching to it shows them.
    m_pendingOtherResults.clear();
    for (const auto& e : paths->dataSets) {
        const QString file = q(e.results);
        QFile rf(file);
        if (file.isEmpty() || !rf.open(QIODevice::ReadOnly)) {
            continue;
        }
        if (auto parsed = workflow::parseLatestResults(rf.readAll().toStdString(), e.results)) {
            m_pendingOtherResults[QDir::cleanPath(q(e.path))] = std::move(*parsed);
        }
    }
    m_pendingParts.reset();
    const QJsonArray parts = o.value(QStringLiteral("learnt_parts")).toArray();
    if (parts.size() == 3) {
        std::array<LearntPart, 3> restored;
        for (int i = 0; i < 3; ++i) {
            const QJsonObject p = parts[i].toObject();
            const auto kind =
                control::controllerByName(p.value(QStringLiteral("kind")).toString().toStdString());
            auto& part = restored[static_cast<std::size_t>(i)];
            part.kind = kind.value_or(control::ControllerKind::Pi);
            part.state = static_cast<PartState>(std::clamp(p.value(QStringLiteral("state")).toInt(), 0, 2));
            part.learntOn = p.value(QStringLiteral("learnt_on")).toString();
            part.learntOnName = p.value(QStringLiteral("learnt_on_data_set")).toString();
            part.learntOnBatches = p.value(QStringLiteral("learnt_on_batches")).toInt(-1);
            part.staleBecause = p.value(QStringLiteral("stale_because")).toString();
        }
        m_pendingParts = restored;
    }
    if (!model.isEmpty() && QFileInfo::exists(model)) {
        m_pendingModel = model;
    }
    const QString mapping = q(paths->mapping);
    m_workbench.setReferencePath(q(paths->reference));
    std::vector<DataSetEntry> dataSets;
    for (const auto& e : paths->dataSets) {
        dataSets.push_back({q(e.path), q(e.mapping), q(e.label), e.batches});
        m_workbench.suggestReference(q(e.path), q(e.suggestedReference));
    }
    m_workbench.restoreDataSets(dataSets);
    const QJsonObject scenario = o.value(QStringLiteral("scenario")).toObject();
    if (scenario.contains(QStringLiteral("text"))) {
        m_mpc->setScenario(scenario.value(QStringLiteral("name")).toString(),
                           scenario.value(QStringLiteral("text")).toString());
    }
    m_unsavedWork.clear(); // what the window held before is replaced by the project
    if (!data.isEmpty()) {
        m_workbench.openData(data, mapping);
    } else {
        if (!m_pendingModel.isEmpty()) {
            m_workbench.openModel(m_pendingModel, std::exchange(m_pendingParts, std::nullopt));
            m_pendingModel.clear();
        }
        restorePending(); // no data: the results (an MPC run needs none) come back at once
    }
    return true;
}

QString MainWindow::dataFingerprint() const {
    return m_workbench.hasData() ? QString::fromStdString(workflow::dataFingerprint(m_workbench.summary()))
                                 : QString();
}

void MainWindow::restorePending() {
    if (m_pendingResults) {
        m_workbench.restoreResults(*m_pendingResults, std::exchange(m_pendingOtherResults, {}));
        m_pendingResults.reset();
    }
    if (m_pendingParts) { // a project without a model file: the states as saved, at once
        m_workbench.restoreLearntParts(*m_pendingParts);
        m_pendingParts.reset();
    }
}

MainWindow* MainWindow::reopenInLanguage(const QString& language, QString* error) {
    if (m_workbench.jobs().busy()) {
        if (error) {
            *error = tr("Wait until the running job has finished (or cancel it), then switch the language.");
        }
        return nullptr;
    }
    // One name per change: the window opened from it removes it when it closes (each window
    // its own, so that a second change cannot remove what the window before still reads).
    static int changes = 0;
    const QString temp = QDir(QStandardPaths::writableLocation(QStandardPaths::TempLocation))
                             .filePath(QStringLiteral("drytwin-language-%1-%2.drytwin")
                                           .arg(QCoreApplication::applicationPid())
                                           .arg(++changes));
    if (!saveProject(temp, error, false)) {
        return nullptr;
    }
    // The model file is written on the engine thread: wait for it before the new window reads it.
    QElapsedTimer waited;
    waited.start();
    while (m_workbench.jobs().busy() && waited.elapsed() < 60000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    QSettings().setValue(QStringLiteral("language"), language);
    setLanguage(language);
    auto* next = new MainWindow;
    next->setAttribute(Qt::WA_DeleteOnClose);
    next->restoreGeometry(saveGeometry());
    next->m_projectPath = m_projectPath;
    next->m_languageTempProject = temp;
    if (!next->openProject(temp, error, false)) {
        delete next;
        return nullptr;
    }
    next->m_tabs->setCurrentIndex(m_tabs->currentIndex());
    next->m_unsavedWork = m_unsavedWork; // not saved by the language change: still to ask about
    // This window stays alive until it is closed (the first one lives as long as the program): a
    // live training line in it must not run on hidden.
    if (m_training->runner().frame().started) {
        const QString kept = m_training->keepCurrentSession();
        m_training->runner().freeze();
        next->m_training->noteLabel()->setText(
            tr("The training session under way was saved in %1 when the language changed: the instructor "
               "window's Session file ▸ Open session… continues it.")
                .arg(QDir::toNativeSeparators(kept)));
    }
    hide();
    if (testAttribute(Qt::WA_DeleteOnClose)) {
        deleteLater();
    }
    return next;
}

} // namespace drytwin::widgets
