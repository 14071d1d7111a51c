#pragma once

#include "common/JobRunner.h"
#include "data/Batch.h"
#include "data/DataSetSummary.h"

#include <QMainWindow>
#include <QVector>
#include <memory>

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QwtPlot;
class QwtPlotCurve;
class QTreeWidget;

namespace drytwin::widgets {

/// @brief DryTwin's main window: menus, a batch list, plots of the selected batch, a status bar.
/// Engine work runs on a worker thread; the window only shows and edits.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// @brief Starts loading a batch file or folder on the engine thread.
    void openDataSet(const QString& path);
    /// @brief The data set shown now (empty before the first successful load).
    const data::DataSet& dataSet() const { return m_data ? *m_data : m_noData; }
    /// @brief The runner of engine jobs (for tests and scripting).
    JobRunner& jobs() { return m_jobs; }
    /// @brief HTML of the About box: DryTwin's version and every library's.
    static QString aboutText();

Q_SIGNALS:
    /// @brief The model's predictions are shown (for tests and scripting).
    void simulationShown();
    /// @brief Emitted after a load attempt finished, successful or not (for tests and scripting).
    void loadFinished(bool ok);

private Q_SLOTS:
    void onProgress(drytwin::widgets::JobId id, const QString& stage, double fraction, const QString& detail);
    void onBatchSelected(int row);
    void showAbout();
    void chooseFile();
    void chooseFolder();

private:
    void createMenus();
    void showBatch(int row);
    void setBusy(bool busy);
    void onDataLoaded(const QString& path, const workflow::OpenResult& result);
    void onLoadFailed(const QString& path, const Error& error);
    void simulate();
    void onSimulated(const workflow::SimulateResult& result);

    JobRunner m_jobs;
    std::shared_ptr<const data::DataSet> m_data;
    data::DataSet m_noData;
    QListWidget* m_batchList = nullptr;
    QTreeWidget* m_columnTable = nullptr;
    QwtPlot* m_moisturePlot = nullptr;
    QwtPlot* m_temperaturePlot = nullptr;
    QwtPlotCurve* m_moistureCurve = nullptr;
    QwtPlotCurve* m_temperatureCurve = nullptr;
    QwtPlotCurve* m_moistureModelCurve = nullptr;
    QwtPlotCurve* m_temperatureModelCurve = nullptr;
    QVector<QVector<double>> m_modelX;
    QVector<QVector<double>> m_modelT;
    QString m_dataStatus; ///< what the status bar says about the loaded data
    QLabel* m_statusLabel = nullptr;
    QProgressBar* m_progressBar = nullptr;
    QPushButton* m_cancelButton = nullptr;
};

} // namespace drytwin::widgets
