#pragma once

#include <QDialog>
#include <QStringList>

class QComboBox;
class QLabel;
class QTableWidget;

namespace drytwin::widgets {

/// @brief Maps a plant's own column headers onto the contract's columns (CONTRACT.md §1): one row
/// per contract column with its unit and meaning, a choice among the file's headers and of the
/// unit the file uses (°F, % dry basis, t/h …: converted when read). For a historian export it
/// proposes the mapping from tag names and value ranges (with the reason beside each), names the
/// time stamps' format and a batch column, and previews the production runs the file would give.
/// Saves the mapping as the JSON file `--mapping` reads.
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
    /// @brief The header chosen for @p contractName ("" when none).
    QString chosen(const QString& contractName) const;
    /// @brief Chooses the column that names the production run ("" for none).
    bool chooseBatchColumn(const QString& header);
    /// @brief Recomputes the preview of the runs with the mapping as chosen now.
    void updatePreview();
    /// @brief The preview's table (one row per run) and the line above it.
    QTableWidget* previewTable() const { return m_preview; }
    /// @brief The mapping table: one row per DryTwin column (name, unit, header, unit, why, meaning).
    QTableWidget* mappingTable() const { return m_table; }
    QLabel* previewNote() const { return m_previewNote; }
    /// @brief Remembers the choices as they stand for files with these headers: the next file
    /// with the same header row is proposed them instead of the guess (issue #72 item 6).
    void rememberForTheseHeaders() const;
    /// @brief True when the proposal came from a mapping remembered for these headers.
    bool proposedFromMemory() const { return m_fromMemory; }
    /// @brief The settings key under which the choices for @p headers are remembered.
    static QString memoryKey(const QStringList& headers);

private:
    /// Puts back the choices remembered for these headers; false when there are none.
    bool applyRemembered();

    QString m_file;
    bool m_fromMemory = false;
    QStringList m_headers;
    QString m_timeFormat; ///< the mapping file's name of the time stamps' format ("" = seconds)
    QTableWidget* m_table = nullptr;
    QComboBox* m_batchColumn = nullptr;
    QTableWidget* m_preview = nullptr;
    QLabel* m_previewNote = nullptr;
    QLabel* m_note = nullptr;
};

} // namespace drytwin::widgets
