#pragma once

#include <QTableWidget>

#include <QColor>
#include <QString>
#include <QStringList>
#include <string>
#include <string_view>

class QWidget;

class QLabel;
class QWidget;

namespace drytwin::widgets {

/// @brief An engine string (UTF-8 string_view) as a QString.
QString fromView(std::string_view text);
/// @brief The widest a table asks to be to show all its columns (fitTableWidth()).
inline constexpr int kMaxFittedTableWidth = 640;
/// @brief The narrowest a fitted table may be squeezed to; below its full width it scrolls. 300 px
/// keeps the window's least width within a 1024-pixel laptop screen (with the full width as the
/// least, it was 1,345 px).
inline constexpr int kLeastFittedTableWidth = 300;

/// @brief A table whose preferred width fitTableWidth() sets (a QTableWidget's own size hint does
/// not follow its columns), so that layouts give it its columns where there is room and may still
/// squeeze it on a small screen.
class FittedTable : public QTableWidget {
public:
    using QTableWidget::QTableWidget;
    void setPreferredWidth(int width) {
        m_preferredWidth = width;
        updateGeometry();
    }
    QSize sizeHint() const override {
        QSize hint = QTableWidget::sizeHint();
        if (m_preferredWidth > 0) {
            hint.setWidth(m_preferredWidth);
        }
        return hint;
    }
    /// The least height shows @p rows rows below the header (fitTableHeight()).
    void setMinimumRows(int rows) {
        m_minimumRows = rows;
        updateGeometry();
    }
    /// Measured when the layout asks, after the style and fonts are applied: measured when the
    /// table is made, the header was a few pixels short and a row of five was cut.
    QSize minimumSizeHint() const override;
    /// The first column (the names: a cause, a controller, a batch) as wide as its cells where
    /// there is room, and narrower, down to its header, where that shows every other column
    /// without scrolling (at 1280 × 800 the Discover ranking's losses lay beyond the edge); a name
    /// narrower than its text is written on two lines (its row taller) and keeps its whole text in
    /// a tooltip. A table that would scroll anyway keeps its names whole. fitTableWidth() and
    /// every resize call it.
    void fitFirstColumn();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    int m_preferredWidth = 0;
    int m_minimumRows = 0;
    bool m_namesWrapped = false; ///< the names are on two lines: rows sized to them
};
/// @brief An empty table of results: these column headers, no row header, read-only cells.
QTableWidget* makeResultTable(const QStringList& headers);
/// @brief Sizes @p table's columns to their headers and cells and asks for the width that shows them
/// all (up to @p maxWidth; a wider table scrolls), so that no header is cut at the table's edge
/// where there is room: as its preferred width for a FittedTable (makeResultTable()'s), which may
/// be squeezed to kLeastFittedTableWidth on a small screen, as its least width for another table.
/// Call after filling it.
void fitTableWidth(QTableWidget* table, int maxWidth = kMaxFittedTableWidth);
/// @brief Asks for the height that shows @p rows rows of @p table below its header (and a
/// horizontal scroll bar, should its columns not fit), so that a layout short of room shrinks its
/// neighbours rather than the table: the What-if tab showed 3½ of its five controllers at 1280 × 800.
void fitTableHeight(QTableWidget* table, int rows);
/// @brief Plain-words tooltips on the column headers of @p table, in column order (an empty one:
/// none), for headers that name a statistic or a method ("Score z", "IAE [% wb·s]").
void setHeaderToolTips(QTableWidget* table, const QStringList& tips);
/// @brief Fills row @p row of @p table with read-only text cells (the row must exist).
void setTableRow(QTableWidget* table, int row, const QStringList& cells);
/// @brief The colour of a model or controller by its contract key (pbm, pgrl_cc, pi …), the same
/// in every panel so that a model is recognised at a glance.
QColor modelColour(const std::string& key);
/// @brief The folder file dialogs start in: the last one a file was opened from or saved to, else
/// the loaded data's, else the home folder.
QString lastFolder();
/// @brief Remembers the folder of @p path (a file or a folder) for the next dialog.
void rememberFolder(const QString& path);
/// @brief File dialogs that start in lastFolder() and remember where the user went; empty when
/// cancelled. The dialogs are Qt's own, so Qt's translations word them (qtbase).
QString askOpenFile(QWidget* parent, const QString& title, const QString& filter);
QString askFolder(QWidget* parent, const QString& title);
/// A name typed without an extension gets the one of the filter chosen in the dialog.
QString askSaveFile(QWidget* parent, const QString& title, const QString& defaultName, const QString& filter);
/// @brief @p path as a save dialog should return it: unchanged when its extension is one that
/// @p filters (";;"-separated, "Data as CSV (*.csv)") offer; else with the first extension of
/// @p selectedFilter appended ("foo" with "Data as CSV (*.csv)" chosen: "foo.csv").
QString withFilterSuffix(const QString& path, const QString& selectedFilter, const QString& filters);
/// @brief A label for a message beside a field that says what is wrong with it: dark red, wrapped,
/// hidden until it has text (callers show it with setVisible()).
QLabel* makeInlineError();
/// @brief The i-th colour of the plots' categorical palette (batches, parameters).
QColor seriesColour(int i);
/// @brief Moves a top-level @p window onto a screen when too little of it (less than 120 × 60
/// pixels of its frame) lies on any: a geometry saved on a monitor that is gone, or a window the
/// window manager placed off the desktop. It goes to the centre of the primary screen, no larger
/// than that screen's free area. Returns true when it was moved.
bool keepOnScreen(QWidget* window);

} // namespace drytwin::widgets
