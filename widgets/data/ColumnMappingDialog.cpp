#include "data/ColumnMappingDialog.h"

#include "common/WidgetHelpers.h"
#include "data/ColumnMapping.h"
#include "data/Columns.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSaveFile>
#include <QTableWidget>
#include <QTextStream>
#include <QVBoxLayout>

namespace drytwin::widgets {

namespace {} // namespace

ColumnMappingDialog::ColumnMappingDialog(const QString& batchFile, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Column mapping"));
    QFile f(batchFile);
    if (f.open(QIODevice::ReadOnly | QIODevice::Text)) {
        QTextStream in(&f);
        // The first line that is not a "# key: value" metadata line holds the headers.
        while (!in.atEnd()) {
            const QString line = in.readLine().trimmed();
            if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) {
                continue;
            }
            for (const auto& h : line.split(QLatin1Char(','))) {
                m_headers << h.trimmed();
            }
            break;
        }
    }
    m_note =
        new QLabel(m_headers.isEmpty()
                       ? tr("Could not read the headers of %1.").arg(batchFile)
                       : tr("Choose, for each column DryTwin needs, the header your files use and the unit "
                            "its values are in (converted when read); required columns are marked *."));
    m_note->setWordWrap(true);
    const auto& specs = data::columnSpecs();
    m_table = new QTableWidget(static_cast<int>(specs.size()), 5);
    m_table->setHorizontalHeaderLabels({tr("DryTwin column"), tr("Unit"), tr("Header in your file"),
                                        tr("Unit in your file"), tr("Meaning")});
    m_table->verticalHeader()->hide();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const auto& s = specs[i];
        const int row = static_cast<int>(i);
        auto* name = new QTableWidgetItem(fromView(s.name) + (s.required ? QStringLiteral(" *") : QString()));
        name->setData(Qt::UserRole, fromView(s.name));
        name->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 0, name);
        auto* unit = new QTableWidgetItem(fromView(s.unit));
        unit->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 1, unit);
        auto* combo = new QComboBox;
        combo->addItem(tr("(not in the file)"), QString());
        for (const auto& h : m_headers) {
            combo->addItem(h, h);
        }
        // Same name or a case-insensitive match is preselected.
        for (int k = 1; k < combo->count(); ++k) {
            if (combo->itemData(k).toString().compare(fromView(s.name), Qt::CaseInsensitive) == 0) {
                combo->setCurrentIndex(k);
            }
        }
        m_table->setCellWidget(row, 2, combo);
        auto* unitCombo = new QComboBox;
        for (const auto& u : data::unitsFor(s.id)) {
            unitCombo->addItem(QString::fromStdString(u));
        }
        m_table->setCellWidget(row, 3, unitCombo);
        auto* meaning = new QTableWidgetItem(fromView(s.meaning));
        meaning->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, 4, meaning);
    }
    m_table->resizeColumnsToContents();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_note);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(900, 520);
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
            const int k = combo->findText(unit);
            if (k >= 0) {
                combo->setCurrentIndex(k);
                return true;
            }
        }
    }
    return false;
}

QByteArray ColumnMappingDialog::mappingJson() const {
    QJsonObject o;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const QString name = m_table->item(r, 0)->data(Qt::UserRole).toString();
        const QString header = qobject_cast<QComboBox*>(m_table->cellWidget(r, 2))->currentData().toString();
        const auto* unit = qobject_cast<QComboBox*>(m_table->cellWidget(r, 3));
        if (header.isEmpty()) {
            continue;
        }
        if (unit->currentIndex() > 0) { // not the contract's own unit: converted when read
            o[name] = QJsonObject{{QStringLiteral("header"), header},
                                  {QStringLiteral("unit"), unit->currentText()}};
        } else if (header != name) {
            o[name] = header;
        }
    }
    return QJsonDocument(o).toJson();
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
