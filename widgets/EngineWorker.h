#pragma once

#include "data/Batch.h"
#include "data/DataSetSummary.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QVector>
#include <atomic>

namespace drytwin::widgets {

/// @brief Runs engine calls on its own QThread and reports by queued signals (ARCHITECTURE.md rule 4).
/// Every slot runs on the worker thread; requestCancel() may be called from any thread.
class EngineWorker : public QObject {
    Q_OBJECT
public:
    explicit EngineWorker(QObject* parent = nullptr);

    /// @brief Asks the running job to stop at its next progress report. Thread-safe.
    void requestCancel() { m_cancel = true; }

public Q_SLOTS:
    /// @brief Loads a batch file or folder; emits dataLoaded or loadFailed.
    void loadDataSet(const QString& path);
    /// @brief Runs the physics model with default parameters over every batch; emits
    /// simulated (outlet predictions in % wb and °C, per batch) or simulationFailed.
    void simulateDataSet(const drytwin::data::DataSet& dataSet);

Q_SIGNALS:
    void progress(const QString& stage, double fraction, const QString& detail);
    void dataLoaded(const QString& path, const drytwin::data::DataSet& dataSet,
                    const drytwin::data::DataSetSummary& summary);
    void loadFailed(const QString& path, const QStringList& errors);
    void cancelled();
    void simulated(const QVector<QVector<double>>& xOutPct, const QVector<QVector<double>>& tOutC);
    void simulationFailed(const QString& message);

private:
    std::atomic<bool> m_cancel{false};
};

} // namespace drytwin::widgets

Q_DECLARE_METATYPE(drytwin::data::DataSet)
Q_DECLARE_METATYPE(drytwin::data::DataSetSummary)
