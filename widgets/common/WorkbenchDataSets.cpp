// The data sets opened in one window and the results each of them had: switching between them,
// putting back those a project had open (with their results), and what is queued behind what.
// Split from Workbench.cpp, which holds the actions.

#include "common/Workbench.h"

#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace drytwin::widgets {

QString DataSetEntry::labelText() const {
    // Worded when shown, from the file or folder's name and the count: a project saved in one
    // language reads back in the other, and a folder path never loses its name to a separator.
    const QString name = QFileInfo(QDir::cleanPath(path)).fileName();
    return batches >= 0 && !name.isEmpty() ? dataSetLabelText(name, batches) : label;
}

int Workbench::currentDataSet() const {
    for (std::size_t i = 0; i < m_dataSets.size(); ++i) {
        if (m_dataSets[i].path == m_dataPath) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

void Workbench::switchDataSet(int index) {
    if (index < 0 || index >= static_cast<int>(m_dataSets.size()) || index == currentDataSet()) {
        return;
    }
    const auto e = m_dataSets[static_cast<std::size_t>(index)];
    openData(e.path, e.mappingPath);
}

void Workbench::restoreDataSets(const std::vector<DataSetEntry>& entries) {
    bool added = false;
    for (auto e : entries) {
        e.path = QDir::cleanPath(e.path);
        const bool known = std::any_of(m_dataSets.begin(), m_dataSets.end(),
                                       [&](const DataSetEntry& d) { return d.path == e.path; });
        if (!known && QFileInfo::exists(e.path)) {
            m_dataSets.push_back(e);
            added = true;
        }
    }
    if (added) {
        Q_EMIT dataSetsChanged();
    }
}

void Workbench::restoreResults(const workflow::LatestResults& results,
                               const std::map<QString, workflow::LatestResults>& otherDataSets) {
    m_latest.calibrate = results.calibrate;
    m_calibrationStart.reset();
    m_latest.evaluate = results.evaluate;
    m_latest.ablation = results.ablation;
    m_latest.discover = results.discover;
    m_latest.mpc = results.mpc;
    // The other data sets' results wait in the stash, as if they had been switched away from
    // in this window: a switch back shows them (a reopened project showed them empty before).
    for (const auto& [path, others] : otherDataSets) {
        const QString key = QDir::cleanPath(path);
        if (key != m_dataPath) {
            m_stash[key] = {others, m_modelRevision};
        }
    }
    m_stashAwaitsProjectModel = !otherDataSets.empty();
    Q_EMIT resultsRestored();
}

std::map<QString, workflow::LatestResults> Workbench::otherDataSetResults() const {
    std::map<QString, workflow::LatestResults> others;
    for (const auto& [path, stashed] : m_stash) {
        // Only what the present model made: what switchDataSet() would show again.
        if (path != m_dataPath && stashed.modelRevision == m_modelRevision) {
            others[path] = stashed.results;
        }
    }
    return others;
}

void Workbench::suggestReference(const QString& dataPath, const QString& referencePath) {
    if (referencePath.isEmpty()) {
        m_suggestedReferences.erase(QDir::cleanPath(dataPath));
    } else {
        m_suggestedReferences[QDir::cleanPath(dataPath)] = referencePath;
    }
}

QString Workbench::suggestedReference(const QString& dataPath) const {
    const auto it = m_suggestedReferences.find(QDir::cleanPath(dataPath.isEmpty() ? m_dataPath : dataPath));
    return it == m_suggestedReferences.end() ? QString() : it->second;
}

bool Workbench::isRunningNow(Action action) const {
    return m_jobs.busy() && actionOf(m_jobs.headJob()) == action;
}

QString Workbench::queuedText(Action action) const {
    if (!isRunning(action) || isRunningNow(action)) {
        return {};
    }
    return tr("Queued — waits for “%1”").arg(m_jobs.jobName(m_jobs.headJob()));
}

} // namespace drytwin::widgets
