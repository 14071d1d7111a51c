#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
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
    /// Removes the temporary file the editor's scenario ran from.
    ~MpcPanel() override;
    /// @brief The temporary file the last run's scenario was written to (empty before a run).
    QString temporaryScenarioPath() const { return m_tempScenario; }
    PlotStack* plots() const { return m_plots; }
    QTableWidget* table() const { return m_table; }
    QPlainTextEdit* editor() const { return m_editor; }
    /// @brief The scenario as a form (the first tab; the JSON editor is the second).
    ScenarioForm* form() const { return m_form; }
    QTabWidget* scenarioTabs() const { return m_scenarioTabs; }
    QComboBox* scenarios() const { return m_scenario; }
    /// @brief Runs the scenario; refused (the reason shown beside Run) while it has a problem.
    void run();
    /// @brief The bundled scenario chosen last (the text may have been edited since).
    QString scenarioName() const;
    /// @brief The scenario as it stands in the editor (a project keeps it).
    QString scenarioText() const;
    /// @brief Puts back a scenario a project kept: @p name chosen in the list, @p text in the editor.
    void setScenario(const QString& name, const QString& text);
    QPushButton* runButton() const { return m_run; }
    /// @brief What stops the scenario from running, worded for the user (the form's first problem,
    /// else the scenario parser's on the JSON text); empty when it can run.
    QString scenarioProblem() const;
    /// @brief The line under Run: what a run is doing, how it ended, or why it failed.
    QLabel* note() const { return m_note; }
    /// @brief The reason Run is off, beside it (hidden while the scenario can run).
    QLabel* runBlockedMessage() const { return m_blocked; }
    /// @brief The controller tick boxes, one per controller, enabled where its model exists.
    QCheckBox* controllerBox(int i) const { return m_controllers[i]; }
    ModelStateBar* modelState() const { return m_state; }
    /// @brief Why a controller whose model's steady gain is @p ratio times the plant's
    /// (control::mismatchedGainRatio) controls as it does, in a sentence.
    static QString gainMismatchText(const QString& controller, double ratio);

Q_SIGNALS:
    /// @brief The user changed the scenario (the form, the JSON, another bundled one or a file).
    void scenarioEdited();

private:
    void show();
    void offerControllers();
    /// The latest run: the decisions to show predictions at, then the plots and table.
    void showRun();
    /// Enables Run when no run is queued and the scenario has no problem; says why not.
    void updateRunState();

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
    QPushButton* m_run = nullptr;
    QLabel* m_blocked = nullptr;
    QString m_tempScenario;
    bool m_awaitingRun = false;     ///< run() started a job whose ending the note has not shown yet
    bool m_settingScenario = false; ///< the editor's text is being set by the program, not the user
};

} // namespace drytwin::widgets
