#pragma once

#include <QJsonObject>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;

namespace drytwin::widgets {

/// @brief A what-if scenario as a form: the plant, its length, the initial setpoint and band, and
/// three tables (setpoint steps, input changes, hidden mechanisms). It edits the scenario's JSON
/// (docs/mpc.md), which stays one tab away: keys the form has no field for (noise, fluctuation, the
/// initial input levels) are kept as they are. The form checks its own values as they are edited
/// (a step after the scored length, a value outside its range) and says what is wrong beside the
/// field; the engine's parser checks the whole text again before a run.
class ScenarioForm : public QWidget {
    Q_OBJECT
public:
    explicit ScenarioForm(QWidget* parent = nullptr);
    /// @brief Fills the form from scenario JSON; false (form unchanged, a note says why) when the
    /// text is not a JSON object.
    bool setJson(const QString& text);
    /// @brief The scenario as JSON: what setJson() read, with the form's values in place.
    QString json() const;

    QTableWidget* setpointSteps() const { return m_steps; }
    QTableWidget* inputChanges() const { return m_inputs; }
    QTableWidget* mechanisms() const { return m_mechanisms; }
    /// @brief Appends a row to a table (the form's "Add" buttons), with these cells.
    void addSetpointStep(double atS, double toPct);
    void addInputChange(const QString& input, double atS, double durationS, double to);
    void addMechanism(const QString& mechanism, double strength, double atS);
    QSpinBox* scoredLength() const { return m_length; }
    /// @brief The specification band's box (± % wb around the setpoint).
    QDoubleSpinBox* band() const { return m_band; }

    /// @brief What is wrong with the form's values, worded for the user; empty when nothing is.
    QStringList problems() const { return m_problems; }
    bool isValid() const { return m_problems.isEmpty(); }
    /// @brief The inline message under the scored length and under each table (hidden when empty).
    QLabel* lengthMessage() const { return m_lengthError; }
    QLabel* setpointStepsMessage() const { return m_stepsError; }
    QLabel* inputChangesMessage() const { return m_inputsError; }
    QLabel* mechanismsMessage() const { return m_mechanismsError; }

Q_SIGNALS:
    /// @brief The user changed a value (not emitted by setJson()).
    void edited();
    /// @brief The form became valid or invalid (problems() changed from or to empty).
    void validityChanged(bool valid);

private:
    QTableWidget* makeTable(const QStringList& headers);
    /// The time for a row the Add button appends to @p table (its times in @p timeColumn).
    double timeForNewRow(const QTableWidget* table, int timeColumn) const;
    void emitEdited();
    /// Checks the values again, fills the inline messages, marks the cells at fault.
    void revalidate();

    QJsonObject m_base;
    bool m_filling = false;
    QLabel* m_note = nullptr;
    QLineEdit* m_name = nullptr;
    QComboBox* m_plant = nullptr;
    QComboBox* m_sensors = nullptr;
    QSpinBox* m_seed = nullptr;
    QSpinBox* m_length = nullptr;
    QDoubleSpinBox* m_setpoint = nullptr;
    QDoubleSpinBox* m_band = nullptr;
    QTableWidget* m_steps = nullptr;
    QTableWidget* m_inputs = nullptr;
    QTableWidget* m_mechanisms = nullptr;
    QLabel* m_lengthError = nullptr;
    QLabel* m_stepsError = nullptr;
    QLabel* m_inputsError = nullptr;
    QLabel* m_mechanismsError = nullptr;
    QStringList m_problems;
};

} // namespace drytwin::widgets
