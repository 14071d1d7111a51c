#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QSpinBox;
class QTableWidget;
class QTabWidget;

namespace drytwin::widgets {

class ModelStateBar;
class ScenarioForm;
class PlotStack;
class Workbench;

/// @brief The What-if MPC panel: a scenario (bundled, from a file, or edited here as JSON with
/// its schema checked), the controllers to compare, Run; every controller's trajectory together
/// with the horizon it predicted at a chosen decision; the Table 2 metrics.
class MpcPanel : public QWidget {
    Q_OBJECT
public:
    explicit MpcPanel(Workbench& workbench, QWidget* parent = nullptr);
    PlotStack* plots() const { return m_plots; }
    QTableWidget* table() const { return m_table; }
    QPlainTextEdit* editor() const { return m_editor; }
    /// @brief The scenario as a form (the first tab; the JSON editor is the second).
    ScenarioForm* form() const { return m_form; }
    QTabWidget* scenarioTabs() const { return m_scenarioTabs; }
    QComboBox* scenarios() const { return m_scenario; }
    void run();
    /// @brief The controller tick boxes, one per controller, enabled where its model exists.
    QCheckBox* controllerBox(int i) const { return m_controllers[i]; }
    ModelStateBar* modelState() const { return m_state; }

private:
    void show();
    void offerControllers();
    /// The latest run: the decisions to show predictions at, then the plots and table.
    void showRun();

    Workbench& m_workbench;
    QComboBox* m_scenario = nullptr;
    QPlainTextEdit* m_editor = nullptr;
    ScenarioForm* m_form = nullptr;
    QTabWidget* m_scenarioTabs = nullptr;
    QCheckBox* m_controllers[5] = {};
    bool m_wanted[5] = {true, true, true, true, true};
    ModelStateBar* m_state = nullptr;
    QComboBox* m_prediction = nullptr;
    QTableWidget* m_table = nullptr;
    PlotStack* m_plots = nullptr;
    QLabel* m_note = nullptr;
    QString m_tempScenario;
};

} // namespace drytwin::widgets
