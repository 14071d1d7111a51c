#pragma once

#include <QColor>
#include <QString>
#include <QStringList>
#include <string>
#include <string_view>

class QTableWidget;

namespace drytwin::widgets {

/// @brief An engine string (UTF-8 string_view) as a QString.
QString fromView(std::string_view text);
/// @brief An empty table of results: these column headers, no row header, read-only cells.
QTableWidget* makeResultTable(const QStringList& headers);
/// @brief Fills row @p row of @p table with read-only text cells (the row must exist).
void setTableRow(QTableWidget* table, int row, const QStringList& cells);
/// @brief The colour of a model or controller by its contract key (pbm, pgrl_cc, pi …), the same
/// in every panel so that a model is recognised at a glance.
QColor modelColour(const std::string& key);
/// @brief The i-th colour of the plots' categorical palette (batches, parameters).
QColor seriesColour(int i);

} // namespace drytwin::widgets
