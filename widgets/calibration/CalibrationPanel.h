#pragma once

#include <QVector>

#include "workflow/Session.h"

#include <QWidget>
#include <optional>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace drytwin::widgets {

class PlotStack;
class Workbench;

/// @brief The Calibrate panel: free parameters and their bounds, a live loss curve, progress,
/// Stop (keeping the best so far) and Cancel, then the estimates with their intervals and the fit
/// before and after.
class CalibrationPanel : public QWidget {
    Q_OBJECT
public:
    explicit CalibrationPanel(Workbench& workbench, QWidget* parent = nullptr);
    QPushButton* runButton() const { return m_run; }
    QPushButton* stopButton() const { return m_stop; }
    QTableWidget* estimates() const { return m_estimates; }
    /// @brief The summary under the plots: how the calibration ended, its MAEs on its own rows and,
    /// once simulated, on every kept row (the status bar's figure).
    QLabel* summary() const { return m_fit; }
    QTableWidget* freeParameters() const { return m_free; }
    PlotStack* lossPlot() const { return m_loss; }
    /// @brief Measured outlet moisture with the simulation before and after the last calibration.
    PlotStack* fitPlot() const { return m_fitPlot; }
    /// @brief Sets the evaluation budget (tests use a small one).
    void setBudget(int evaluations);
    void run();

private:
    void showResult();
    void showBeforeAfter();

    Workbench& m_workbench;
    QTableWidget* m_free = nullptr;
    QSpinBox* m_budget = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_stop = nullptr;
    QTableWidget* m_estimates = nullptr;
    QLabel* m_fit = nullptr;
    QString m_fitSummary; ///< the calibration's own sentence, before the all-rows one is added
    PlotStack* m_loss = nullptr;
    PlotStack* m_fitPlot = nullptr;
    QVector<double> m_lossX, m_lossY;
};

} // namespace drytwin::widgets
