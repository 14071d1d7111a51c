#pragma once

#include <QDialog>
#include <QStringList>

class QLabel;
class QTableWidget;

namespace drytwin::widgets {

/// @brief Maps a plant's own column headers onto the contract's columns (CONTRACT.md §1): one row
/// per contract column with its unit and meaning, a choice among the file's headers and of the
/// unit the file uses (°F, % dry basis, t/h …: converted when read). Saves the mapping as the JSON
/// file `--mapping` reads.
class ColumnMappingDialog : public QDialog {
    Q_OBJECT
public:
    /// @brief A dialog for the headers of @p batchFile.
    explicit ColumnMappingDialog(const QString& batchFile, QWidget* parent = nullptr);
    /// @brief The headers read from the file (empty when it could not be read).
    const QStringList& headers() const { return m_headers; }
    /// @brief Chooses @p header for contract column @p contractName (for tests and scripts).
    bool choose(const QString& contractName, const QString& header);
    /// @brief Chooses the unit the file uses for @p contractName (one of data::unitsFor).
    bool chooseUnit(const QString& contractName, const QString& unit);
    /// @brief The mapping as JSON {"contract name": "file header"} (only columns whose name differs).
    QByteArray mappingJson() const;
    /// @brief Writes the mapping atomically; false with @p error on failure.
    bool save(const QString& path, QString* error = nullptr) const;

private:
    QStringList m_headers;
    QTableWidget* m_table = nullptr;
    QLabel* m_note = nullptr;
};

} // namespace drytwin::widgets
