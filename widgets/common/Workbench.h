#pragma once

#include "common/JobRunner.h"
#include "workflow/Session.h"

#include <QObject>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace drytwin::widgets {

/// @brief The GUI's side of the workflow Session: starts every action as a job on the engine
/// thread (JobRunner) and keeps, on the GUI thread, copies of what the panels show (data set,
/// model, latest results). Panels ask it for actions and listen to its signals; none of them
/// touches the Session or computes anything (ARCHITECTURE.md rules 4 and 5). A second request
/// while one runs is queued behind it (the status bar says so).
class Workbench : public QObject {
    Q_OBJECT
public:
    explicit Workbench(QObject* parent = nullptr);

    JobRunner& jobs() { return m_jobs; }
    bool hasData() const { return m_dataSet != nullptr; }
    std::shared_ptr<const data::DataSet> dataSet() const { return m_dataSet; }
    const std::vector<data::SiBatch>& siBatches() const { return m_si; }
    const data::DataSetSummary& summary() const { return m_summary; }
    const hybrid::HybridModel& model() const { return m_model; }
    const workflow::LatestResults& latest() const { return m_latest; }
    QString dataPath() const { return m_dataPath; }
    QString modelPath() const { return m_modelPath; }
    QString mappingPath() const { return m_mappingPath; }

    /// @brief Loads data; @p mappingPath: a column mapping file (empty: the contract's names).
    void openData(const QString& path, const QString& mappingPath = {});
    void openModel(const QString& path);
    void saveModel(const QString& path);
    /// @brief Sets a physics parameter (checked against its bounds on the engine thread).
    void setParameter(properties::Param param, double value);
    /// @brief Replaces the session's model (undo, "extend the model").
    void setModel(const hybrid::HybridModel& model);
    void simulate();
    void calibrate(const workflow::CalibrateOptions& options);
    /// @brief Asks a running calibration to stop and keep its best parameters so far.
    void stopKeepBest();
    void train(const workflow::TrainOptions& options);
    void evaluate();
    void discover();
    void runMpc(const workflow::MpcOptions& options);
    /// @brief The ablation table (paper Table 3) on the session's model.
    void ablation();
    /// @brief Writes virtual-plant batches into a folder and opens them.
    void generate(const workflow::GenerateOptions& options);
    /// @brief Cancels everything queued or running.
    void cancelAll() { m_jobs.cancelAll(); }

Q_SIGNALS:
    void dataChanged();
    void modelChanged();
    void simulated();
    void calibrated();
    /// @brief A calibration progress report: evaluations so far and the best loss.
    void calibrationProgress(double fraction, double bestLoss);
    void trained();
    void evaluated();
    void discovered();
    void mpcFinished();
    void ablationFinished();
    /// @brief An action failed or was cancelled; @p message is worded for the user.
    void failed(const QString& action, const QString& message, bool cancelled);
    /// @brief Loading data failed; what was loaded before is unchanged.
    void dataLoadFailed(const QString& message);
    /// @brief A line for the status bar.
    void status(const QString& text);
    /// @brief An action finished (successfully or not), for scripts and tests.
    void actionFinished(const QString& action, bool ok);

private:
    template <class R, class Work, class Done>
    JobId start(const QString& action, Work work, Done done,
                std::function<void(const QString&)> onFailure = {});
    /// Refreshes the GUI copy of the model after an action that may change it.
    void fetchModel();

    JobRunner m_jobs;
    std::shared_ptr<const data::DataSet> m_dataSet;
    std::vector<data::SiBatch> m_si;
    data::DataSetSummary m_summary;
    hybrid::HybridModel m_model;
    workflow::LatestResults m_latest;
    QString m_dataPath, m_modelPath, m_mappingPath;
    JobId m_calibrationJob = 0;
};

} // namespace drytwin::widgets
