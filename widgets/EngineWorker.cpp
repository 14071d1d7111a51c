#include "EngineWorker.h"

#include "data/BatchReader.h"

namespace drytwin::widgets {

EngineWorker::EngineWorker(QObject* parent) : QObject(parent) {
    qRegisterMetaType<drytwin::data::DataSet>();
    qRegisterMetaType<drytwin::data::DataSetSummary>();
}

void EngineWorker::loadDataSet(const QString& path) {
    m_cancel = false;
    const auto progressCb = [this](const ProgressInfo& info) {
        Q_EMIT progress(QString::fromStdString(info.stage), info.fraction,
                        QString::fromStdString(info.detail));
        return m_cancel ? ProgressAction::Stop : ProgressAction::Continue;
    };
    auto result = data::loadDataSet(path.toStdString(), {}, progressCb);
    if (result.cancelled) {
        Q_EMIT cancelled();
        return;
    }
    if (!result.ok()) {
        QStringList errors;
        for (const auto& e : result.errors) {
            errors << QString::fromStdString(e.message());
        }
        Q_EMIT loadFailed(path, errors);
        return;
    }
    const auto summary = data::summarize(result.dataSet);
    Q_EMIT dataLoaded(path, result.dataSet, summary);
}

} // namespace drytwin::widgets
