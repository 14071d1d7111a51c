#include "data/ColumnMappingDialog.h"
#include "common/EngineText.h"

#include "common/DisplayNames.h"
#include "common/ErrorText.h"
#include "common/WheelGuard.h"
#include "common/WidgetHelpers.h"
#include "data/ColumnMapping.h"
#include "data/Columns.h"
#include "data/MappingGuess.h"
#include "workflow/Session.h"

#include <QComboBox>
#include <QCryptographicHash>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSaveFile>
#include <QSettings>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTextStream>
#include <QVBoxLayout>
#include <algorithm>

namespace drytwin::widgets {

ColumnMappingDialog::ColumnMappingDialog(const QString& batchFile, QWidget* parent)
    : QDialog(parent), m_file(batchFile) {
    setWindowTitle(tr("Column mapping"));
    // The engine reads the file's first rows: delimiter, time stamps, units row, and a proposal.
    const auto guess = workflow::Session::guessMapping(batchFile.toStdString());
    if (guess) {
        for (const auto& h : guess->shape.headers) {
            m_headers << QString::fromStdString(h);
        }
        if (guess->shape.timeFormat != data::TimeFormat::Seconds) {
            m_timeFormat = QString::fromStdString(data::timeFormatName(guess->shape.timeFormat));
        }
    }
    QString shape;
    if (guess) {
        const auto& sh = guess->shape;
        shape = tr("Delimiter %1, %2, time stamps in column '%3' (%4)%5.")
                    .arg(sh.delimiter == '\t' ? tr("tab") : QStringLiteral("'%1'").arg(QChar(sh.delimiter)),
                         sh.decimalComma ? tr("decimal commas") : tr("decimal points"),
                         QString::fromStdString(sh.timeHeader),
                         timeFormatText(data::timeFormatName(sh.timeFormat)),
                         sh.unitsRow ? tr(", a units row under the header") : QString());
    }
    m_note = new QLabel(
        !guess ? tr("Could not read %1: %2").arg(batchFile, errorText(guess.error()))
               : tr("Choose, for each column DryTwin needs, the header your files use and the unit its "
                    "values are "
                    "in (converted when read); required columns are marked *. The proposal comes from the "
                    "headers' words and tag letters and the ranges of the first rows' values: check it.") +
                     QStringLiteral("\n") + shape);
    m_note->setWordWrap(true);
    const auto& specs = data::columnSpecs();
    m_table = new QTableWidget(static_cast<int>(specs.size()), 6);
    m_table->setHorizontalHeaderLabels({tr("DryTwin column"), tr("Unit"), tr("Header in your file"),
                                        tr("Unit in your file"), tr("Why proposed"), tr("Meaning")});
    m_table->verticalHeader()->hide();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const auto& s = specs[i];
        const int row = static_cast<int>(i);
        auto* name = new QTableWidgetItem(fromView(s.name) + (s.required ? QStringLiteral(" *") : QString()));
        name->setData(Qt::UserRole, fromView(s.name));
        name->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 0, name);
        auto* unit = new QTableWidgetItem(mappingUnitText(std::string(s.unit)));
        unit->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 1, unit);
        auto* combo = new QComboBox;
        combo->addItem(tr("(not in the file)"), QString());
        for (const auto& h : m_headers) {
            combo->addItem(h, h);
        }
        QString why;
        if (guess) {
            const auto it = guess->mapping.contractToFile.find(std::string(s.name));
            if (it != guess->mapping.contractToFile.end()) {
                combo->setCurrentIndex(combo->findData(QString::fromStdString(it->second)));
                why = mappingReasonText(guess->reasons.at(std::string(s.name)));
            }
        }
        m_table->setCellWidget(row, 2, combo);
        auto* unitCombo = new QComboBox;
        // The unit in the user's words ("°F", "% 干基"), the mapping file's name kept as its data.
        for (const auto& u : data::unitsFor(s.id)) {
            unitCombo->addItem(mappingUnitText(u), QString::fromStdString(u));
        }
        m_table->setCellWidget(row, 3, unitCombo);
        auto* reason = new QTableWidgetItem(why);
        reason->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 4, reason);
        auto* meaning = new QTableWidgetItem(columnMeaningText(s.meaning));
        meaning->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 5, meaning);
        connect(combo, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, combo] {
            // A header feeds one column: choosing it here takes it from any other.
            const QString header = combo->currentData().toString();
            for (int r = 0; r < m_table->rowCount() && !header.isEmpty(); ++r) {
                auto* other = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2));
                if (other && other != combo && other->currentData().toString() == header) {
                    const QSignalBlocker block(other);
                    other->setCurrentIndex(0);
                    m_table->item(r, 4)->setText(QString());
                }
            }
            updatePreview();
        });
        connect(unitCombo, qOverload<int>(&QComboBox::currentIndexChanged), this,
                [this] { updatePreview(); });
    }
    m_table->resizeColumnsToContents();
    m_batchColumn = new QComboBox;
    m_batchColumn->addItem(tr("(none: cut runs at line stops and gaps)"), QString());
    for (const auto& h : m_headers) {
        m_batchColumn->addItem(h, h);
    }
    connect(m_batchColumn, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this] { updatePreview(); });
    auto* batchRow = new QHBoxLayout;
    batchRow->addWidget(new QLabel(tr("Column that names the production run:")));
    batchRow->addWidget(m_batchColumn, 1);
    m_previewNote = new QLabel;
    m_previewNote->setWordWrap(true);
    m_preview = makeResultTable(
        {tr("Run"), tr("Start"), tr("File lines"), tr("Rows"), tr("Interpolated cells"), tr("Ended by")});
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_note);
    layout->addWidget(m_table, 3);
    layout->addLayout(batchRow);
    layout->addWidget(m_previewNote);
    layout->addWidget(m_preview, 2);
    layout->addWidget(buttons);
    resize(1000, 720);
    if (applyRemembered()) {
        m_note->setText(m_note->text() + QStringLiteral("\n") +
                        tr("Proposed as you mapped a file with these same headers before; check it."));
    }
    // A wheel turned over the table scrolls it; it does not change a choice the pointer passes.
    ignoreWheelUnlessFocused(this);
    updatePreview();
}

QString ColumnMappingDialog::memoryKey(const QStringList& headers) {
    // The header row as it is, hashed: a file with exactly these columns in this order.
    const QByteArray digest =
        QCryptographicHash::hash(headers.join(QLatin1Char('\n')).toUtf8(), QCryptographicHash::Sha1);
    return QStringLiteral("columnMappings/%1").arg(QString::fromLatin1(digest.toHex()));
}

void ColumnMappingDialog::rememberForTheseHeaders() const {
    if (m_headers.isEmpty()) {
        return;
    }
    // Every row's choice, "not in the file" included: a column the user took away from the guess
    // must stay away.
    QVariantMap headerOf, unitOf;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QString name = m_table->item(r, 0)->data(Qt::UserRole).toString();
        headerOf[name] = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2))->currentData().toString();
        unitOf[name] = qobject_cast<QComboBox*>(m_table->cellWidget(r, 3))->currentData().toString();
    }
    QSettings().setValue(memoryKey(m_headers), QVariantMap{{QStringLiteral("headers"), headerOf},
                                                           {QStringLiteral("units"), unitOf},
                                                           {QStringLiteral("batch_column"),
                                                            m_batchColumn->currentData().toString()}});
}

bool ColumnMappingDialog::applyRemembered() {
    if (m_headers.isEmpty()) {
        return false;
    }
    const QVariantMap remembered = QSettings().value(memoryKey(m_headers)).toMap();
    if (remembered.isEmpty()) {
        return false;
    }
    const QVariantMap headerOf = remembered.value(QStringLiteral("headers")).toMap();
    const QVariantMap unitOf = remembered.value(QStringLiteral("units")).toMap();
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QString name = m_table->item(r, 0)->data(Qt::UserRole).toString();
        if (!headerOf.contains(name)) {
            continue;
        }
        auto* header = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2));
        auto* unit = qobject_cast<QComboBox*>(m_table->cellWidget(r, 3));
        const QSignalBlocker blockHeader(header), blockUnit(unit);
        header->setCurrentIndex(std::max(0, header->findData(headerOf.value(name).toString())));
        unit->setCurrentIndex(std::max(0, unit->findData(unitOf.value(name).toString())));
        const bool mapped = header->currentIndex() > 0;
        m_table->item(r, 4)->setText(mapped ? tr("as you mapped these headers before") : QString());
    }
    const QSignalBlocker blockBatch(m_batchColumn);
    m_batchColumn->setCurrentIndex(
        std::max(0, m_batchColumn->findData(remembered.value(QStringLiteral("batch_column")).toString())));
    m_fromMemory = true;
    return true;
}

namespace {
constexpr std::size_t kPreviewBytes = 8u << 20; // the runs of the first 8 MB (about 60,000 rows)
}

void ColumnMappingDialog::updatePreview() {
    if (!m_preview) {
        return;
    }
    m_preview->setRowCount(0);
    auto mapping = data::readColumnMappingText(mappingJson().toStdString(), "mapping");
    if (!mapping) {
        m_previewNote->setText(tr("The mapping is not complete: %1").arg(errorText(mapping.error())));
        return;
    }
    const auto runs = workflow::Session::previewRuns(m_file.toStdString(), *mapping, kPreviewBytes);
    if (!runs) {
        m_previewNote->setText(
            tr("With this mapping the file does not load: %1").arg(errorText(runs.error())));
        return;
    }
    QFileInfo info(m_file);
    m_previewNote->setText(
        (info.size() > static_cast<qint64>(kPreviewBytes)
             ? tr("The first %1 MB of the file give these production runs:").arg(kPreviewBytes >> 20)
             : tr("The file gives these production runs:")) +
        (runs->notes.empty() ? QString()
                             : QStringLiteral(" ") + tr("Notes while reading: %1; the first: %2")
                                                         .arg(runs->notes.size())
                                                         .arg(dataNoteText(runs->notes.front()))));
    for (const auto& b : runs->runs) {
        const int r = m_preview->rowCount();
        m_preview->insertRow(r);
        const bool cut = b.run.has_value();
        const QStringList cells{QString::fromStdString(b.id),
                                cut ? QString::fromStdString(b.run->startTimestamp) : QString(),
                                cut ? QStringLiteral("%1–%2").arg(b.run->firstLine).arg(b.run->lastLine)
                                    : QString(),
                                QString::number(b.rows()),
                                cut ? QString::number(b.run->interpolatedCells) : QString(),
                                cut ? runEndText(b.run->splitReason) : tr("one batch")};
        for (int c = 0; c < cells.size(); ++c) {
            m_preview->setItem(r, c, new QTableWidgetItem(cells[c]));
        }
    }
    m_preview->resizeColumnsToContents();
}

QString ColumnMappingDialog::chosen(const QString& contractName) const {
    for (int r = 0; r < m_table->rowCount(); ++r) {
        if (m_table->item(r, 0)->data(Qt::UserRole).toString() == contractName) {
            return qobject_cast<QComboBox*>(m_table->cellWidget(r, 2))->currentData().toString();
        }
    }
    return {};
}

bool ColumnMappingDialog::chooseBatchColumn(const QString& header) {
    const int k = m_batchColumn->findData(header);
    if (k < 0) {
        return false;
    }
    m_batchColumn->setCurrentIndex(k);
    return true;
}

bool ColumnMappingDialog::choose(const QString& contractName, const QString& header) {
    for (int r = 0; r < m_table->rowCount(); ++r) {
        if (m_table->item(r, 0)->data(Qt::UserRole).toString() == contractName) {
            auto* combo = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2));
            const int k = combo->findData(header);
            if (k >= 0) {
                combo->setCurrentIndex(k);
                return true;
            }
        }
    }
    return false;
}

bool ColumnMappingDialog::chooseUnit(const QString& contractName, const QString& unit) {
    for (int r = 0; r < m_table->rowCount(); ++r) {
        if (m_table->item(r, 0)->data(Qt::UserRole).toString() == contractName) {
            auto* combo = qobject_cast<QComboBox*>(m_table->cellWidget(r, 3));
            const int k = combo->findData(unit);
            if (k >= 0) {
                combo->setCurrentIndex(k);
                return true;
            }
        }
    }
    return false;
}

QByteArray ColumnMappingDialog::mappingJson() const {
    data::ColumnMapping m;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QString name = m_table->item(r, 0)->data(Qt::UserRole).toString();
        const QString header = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2))->currentData().toString();
        const auto* unit = qobject_cast<QComboBox*>(m_table->cellWidget(r, 3));
        if (header.isEmpty()) {
            continue;
        }
        if (unit->currentIndex() > 0) { // not the contract's own unit: converted when read
            m.contractToUnit[name.toStdString()] = unit->currentData().toString().toStdString();
        }
        if (header != name || unit->currentIndex() > 0 ||
            (name == QLatin1String("time_s") && !m_timeFormat.isEmpty())) {
            m.contractToFile[name.toStdString()] = header.toStdString();
        }
    }
    if (m.contractToFile.count("time_s")) {
        m.timeFormat = m_timeFormat.toStdString();
    }
    if (m_batchColumn) {
        m.batchIdHeader = m_batchColumn->currentData().toString().toStdString();
    }
    return QByteArray::fromStdString(data::mappingJson(m));
}

bool ColumnMappingDialog::save(const QString& path, QString* error) const {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(mappingJson()) < 0 || !f.commit()) {
        if (error) {
            *error = tr("cannot write %1: %2").arg(path, f.errorString());
        }
        return false;
    }
    return true;
}

} // namespace drytwin::widgets
