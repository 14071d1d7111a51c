#pragma once

#include "data/Batch.h"
#include "data/DataSetSummary.h"

#include <QMainWindow>
#include <QThread>
#include <QVector>

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QwtPlot;
class QwtPlotCurve;
class QTreeWidget;

namespace drytwin::widgets {

class EngineWorker;

/// @brief DryTwin's main window: menus, a batch list, plots of the selected batch, a status bar.
/// Engine work runs on a worker thread; the window only shows and edits.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// @brief Starts loading a batch file or folder on the worker thread.
    void openDataSet(const QString& path);
    /// @brief The data set shown now (empty before the first successful load).
    const data::DataSet& dataSet() const { return m_data; }
    /// @brief HTML of the About box: DryTwin's version and every library's.
    static QString aboutText();

Q_SIGNALS:
    void loadRequested(const QString& path);
    void simulationRequested(const drytwin::data::DataSet& dataSet);
    /// @brief The model's predictions are shown (for tests and scripting).
    void simulationShown();
    /// @brief Emitted after a load attempt finished, successful or not (for tests and scripting).
    void loadFinished(bool ok);

private Q_SLOTS:
    void onDataLoaded(const QString& path, const drytwin::data::DataSet& dataSet,
                      const drytwin::data::DataSetSummary& summary);
    void onLoadFailed(const QString& path, const QStringList& errors);
    void onProgress(const QString& stage, double fraction, const QString& detail);
    void onBatchSelected(int row);
    void onSimulated(const QVector<QVector<double>>& xOutPct, const QVector<QVector<double>>& tOutC);
    void showAbout();
    void chooseFile();
    void chooseFolder();

private:
    void createMenus();
    void showBatch(int row);
    void setBusy(bool busy);

    QThread m_thread;
    EngineWorker* m_worker = nullptr;
    data::DataSet m_data;
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
