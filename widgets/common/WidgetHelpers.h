#pragma once

#include <QColor>
#include <QString>
#include <QStringList>
#include <string>
#include <string_view>

class QTableWidget;
class QWidget;

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
/// @brief The folder file dialogs start in: the last one a file was opened from or saved to, else
/// the loaded data's, else the home folder.
QString lastFolder();
/// @brief Remembers the folder of @p path (a file or a folder) for the next dialog.
void rememberFolder(const QString& path);
/// @brief File dialogs that start in lastFolder() and remember where the user went; empty when
/// cancelled. The dialogs are Qt's own, so Qt's translations word them (qtbase).
QString askOpenFile(QWidget* parent, const QString& title, const QString& filter);
QString askFolder(QWidget* parent, const QString& title);
QString askSaveFile(QWidget* parent, const QString& title, const QString& defaultName, const QString& filter);
/// @brief The i-th colour of the plots' categorical palette (batches, parameters).
QColor seriesColour(int i);

} // namespace drytwin::widgets
