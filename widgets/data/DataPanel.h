#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QTableWidget;

namespace drytwin::widgets {

class PlotStack;
class Workbench;

/// @brief The Data panel: open files or folders (also by drag and drop), the batches with their
/// counts, and every column plotted with the selected batches overlaid or one after another.
class DataPanel : public QWidget {
    Q_OBJECT
public:
    explicit DataPanel(Workbench& workbench, QWidget* parent = nullptr);
    /// @brief The column-mapping dialog for @p file (its guess and preview), then loads it with
    /// the mapping the user saved.
    void mapAndOpen(const QString& file);
    PlotStack* plots() const { return m_plots; }
    QTableWidget* batchTable() const { return m_table; }
    /// @brief The cleaning rules' counts and the split under the table.
    QLabel* cleaningSummary() const { return m_cleaning; }
    /// @brief Selects batches by row (for tests and projects) and redraws.
    void selectBatches(const QList<int>& rows);

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void fill();
    void redraw();

    Workbench& m_workbench;
    QTableWidget* m_table = nullptr;
    QComboBox* m_arrangement = nullptr;
    QLabel* m_cleaning = nullptr;
    PlotStack* m_plots = nullptr;
    /// A mapping the user did not save to a file of their own, and what the panel says of it.
    QString m_keptMappingPath, m_keptMappingNote;
};

} // namespace drytwin::widgets
