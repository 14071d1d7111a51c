#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QTableWidget;
class QUndoStack;

namespace drytwin::widgets {

class PlotStack;
class Workbench;

/// @brief The Model panel: the parameter table (value, unit, bounds, source), editable with
/// validation and undo; the physics switches; Simulate, with measured against predicted for
/// every output of the chosen batch.
class ModelPanel : public QWidget {
    Q_OBJECT
public:
    explicit ModelPanel(Workbench& workbench, QWidget* parent = nullptr);
    QTableWidget* parameterTable() const { return m_table; }
    PlotStack* plots() const { return m_plots; }
    QUndoStack* undoStack() const { return m_undo; }
    /// @brief Edits a parameter as a user would (validated, undoable). False when out of bounds.
    bool editParameter(int row, double value);

private:
    void fillTable();
    void redraw();

    Workbench& m_workbench;
    QTableWidget* m_table = nullptr;
    QUndoStack* m_undo = nullptr;
    QComboBox* m_batch = nullptr;
    QCheckBox* m_switches[4] = {};
    PlotStack* m_plots = nullptr;
    bool m_filling = false;
};

} // namespace drytwin::widgets
