#include "EngineWorker.h"

#include "data/BatchReader.h"
#include "data/SiBatch.h"
#include "physics/LineSimulator.h"

namespace drytwin::widgets {

EngineWorker::EngineWorker(QObject* parent) : QObject(parent) {
    qRegisterMetaType<drytwin::data::DataSet>();
    qRegisterMetaType<drytwin::data::DataSetSummary>();
    qRegisterMetaType<QVector<QVector<double>>>();
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

void EngineWorker::simulateDataSet(const drytwin::data::DataSet& dataSet) {
    m_cancel = false;
    const auto si = data::toSi(dataSet, data::clean(dataSet));
    std::vector<physics::LineInputs> inputs;
    for (const auto& b : si) {
        inputs.push_back(data::toLineInputs(b));
    }
    const auto progressCb = [this](const ProgressInfo& info) {
        Q_EMIT progress(QString::fromStdString(info.stage), info.fraction,
                        QString::fromStdString(info.detail));
        return m_cancel ? ProgressAction::Stop : ProgressAction::Continue;
    };
    auto sims = physics::simulateBatches(inputs, properties::ParameterSet{}, {}, 0, progressCb);
    if (!sims) {
        Q_EMIT simulationFailed(QString::fromStdString(sims.error().message()));
        return;
    }
    QVector<QVector<double>> x, t;
    for (const auto& r : *sims) {
        QVector<double> xb, tb;
        xb.reserve(static_cast<int>(r.xOutDb.size()));
        tb.reserve(static_cast<int>(r.tOutK.size()));
        for (std::size_t k = 0; k < r.xOutDb.size(); ++k) {
            xb.push_back(data::dryToWetPct(r.xOutDb[k]));
            tb.push_back(r.tOutK[k] - data::kKelvinOffset);
        }
        x.push_back(xb);
        t.push_back(tb);
    }
    Q_EMIT simulated(x, t);
}

} // namespace drytwin::widgets
