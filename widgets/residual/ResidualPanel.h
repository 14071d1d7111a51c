#pragma once

#include "control/ClosedLoop.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QTabWidget;
class QTableWidget;

namespace drytwin::widgets {

class ModelStateBar;
class PlotStack;
class Workbench;

/// @brief The Residual model panel: PGRL-CC settings and Train; the eigenvalues of A in the
/// complex plane with the unit circle, before and after the stability constraint (paper Fig. 6);
/// the held-out metrics of every model; the horizon/skill curve beside the reference predictors.
class ResidualPanel : public QWidget {
    Q_OBJECT
public:
    explicit ResidualPanel(Workbench& workbench, QWidget* parent = nullptr);
    QTableWidget* metrics() const { return m_metrics; }
    QTableWidget* ablation() const { return m_ablation; }
    QTabWidget* tables() const { return m_tables; }
    PlotStack* eigenvalues() const { return m_eigen; }
    PlotStack* skill() const { return m_skill; }
    /// @brief The line under Learn: what the learning is doing, queued, or how it ended.
    QLabel* note() const { return m_note; }
    void train();
    /// @brief A quick training for tests (2 LSTM epochs, small grid).
    void setQuick(bool quick) { m_quick = quick; }

private:
    /// Where learning stands (queued, training, learnt and waiting for its scores), said alike by
    /// the note and the empty plots (issue #72 item 8: "Learnt. Scoring…" beside plots asking to learn).
    enum class Learning { Idle, Training, Scoring };
    void showLearningState();
    void setDefaultEmptyTexts();
    void showEvaluation();
    void showAblation();
    /// The steady gains of X_out to the hot air from the last What-if MPC run, the plant's beside them.
    void showGains();
    /// The sentence showGains() writes for a closed-loop result (static: tested in both languages).
    static QString gainsText(const control::ClosedLoopResult& result);

    Workbench& m_workbench;
    QComboBox* m_lags = nullptr;
    QComboBox* m_stability = nullptr;
    QCheckBox* m_projection = nullptr;
    QTableWidget* m_metrics = nullptr;
    QTableWidget* m_ablation = nullptr;
    QTabWidget* m_tables = nullptr; ///< the held-out table and the ablation, a tab each
    PlotStack* m_eigen = nullptr;
    PlotStack* m_skill = nullptr;
    QLabel* m_note = nullptr;
    QLabel* m_gains = nullptr;
    ModelStateBar* m_state = nullptr;
    bool m_quick = false;
    Learning m_learning = Learning::Idle;
};

} // namespace drytwin::widgets
