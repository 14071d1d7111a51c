#include "mpc/ScenarioForm.h"

#include "common/DisplayNames.h"
#include "common/WidgetHelpers.h"
#include "plant/Mechanisms.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <functional>
#include <utility>

namespace drytwin::widgets {

namespace {

/// The inputs a scenario moves, by their scenario-file keys, with words and units.
struct InputKey {
    const char* key;
    const char* words;
};
const InputKey kInputs[] = {{"feed_kg_h", QT_TRANSLATE_NOOP("ScenarioForm", "feed [kg/h]")},
                            {"x_in_pct", QT_TRANSLATE_NOOP("ScenarioForm", "inlet moisture [% wb]")},
                            {"t_amb_c", QT_TRANSLATE_NOOP("ScenarioForm", "ambient temperature [°C]")},
                            {"rh_pct", QT_TRANSLATE_NOOP("ScenarioForm", "ambient humidity [% RH]")}};

double cellNumber(const QTableWidget* t, int row, int column, double fallback = 0) {
    const auto* item = t->item(row, column);
    bool ok = false;
    const double v = item ? item->text().toDouble(&ok) : 0;
    return ok ? v : fallback;
}

QString comboKey(const QTableWidget* t, int row, int column) {
    const auto* combo = qobject_cast<const QComboBox*>(t->cellWidget(row, column));
    return combo ? combo->currentData().toString() : QString();
}

} // namespace

ScenarioForm::ScenarioForm(QWidget* parent) : QWidget(parent) {
    m_note = new QLabel;
    m_note->setWordWrap(true);
    m_name = new QLineEdit;
    m_plant = new QComboBox;
    m_plant->addItem(tr("distributed (realistic line)"), QStringLiteral("distributed"));
    m_plant->addItem(tr("lumped (the model's own equations)"), QStringLiteral("lumped"));
    m_sensors = new QComboBox;
    m_sensors->addItem(tr("realistic (noise, lags, faults)"), QStringLiteral("realistic"));
    m_sensors->addItem(tr("ideal"), QStringLiteral("ideal"));
    m_seed = new QSpinBox;
    m_seed->setRange(1, 1000000);
    m_length = new QSpinBox;
    m_length->setRange(10, 100000);
    m_length->setSuffix(tr(" s"));
    m_setpoint = new QDoubleSpinBox;
    m_setpoint->setRange(5, 30);
    m_setpoint->setDecimals(2);
    m_setpoint->setSuffix(tr(" % wb"));
    m_band = new QDoubleSpinBox;
    m_band->setRange(0.01, 5);
    m_band->setDecimals(2);
    m_band->setSuffix(tr(" % wb"));
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Plant"), m_plant);
    form->addRow(tr("Instruments"), m_sensors);
    form->addRow(tr("Random seed"), m_seed);
    form->addRow(tr("Scored length"), m_length);
    form->addRow(tr("Initial X_out setpoint"), m_setpoint);
    form->addRow(tr("Specification band ±"), m_band);
    m_steps = makeTable({tr("at [s]"), tr("setpoint to [% wb]")});
    m_inputs = makeTable({tr("input"), tr("at [s]"), tr("over [s]"), tr("to")});
    m_mechanisms = makeTable({tr("hidden cause"), tr("strength"), tr("from [s]")});
    const auto section = [this](const QString& title, QTableWidget* table, std::function<void()> add) {
        auto* box = new QWidget;
        auto* l = new QVBoxLayout(box);
        l->setContentsMargins(0, 0, 0, 0);
        auto* row = new QHBoxLayout;
        row->addWidget(new QLabel(title), 1);
        auto* plus = new QPushButton(tr("Add"));
        auto* minus = new QPushButton(tr("Remove"));
        row->addWidget(plus);
        row->addWidget(minus);
        l->addLayout(row);
        l->addWidget(table);
        connect(plus, &QPushButton::clicked, this, [this, add] {
            add();
            emitEdited();
        });
        connect(minus, &QPushButton::clicked, this, [this, table] {
            table->removeRow(table->currentRow() >= 0 ? table->currentRow() : table->rowCount() - 1);
            emitEdited();
        });
        return box;
    };
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_note);
    layout->addLayout(form);
    layout->addWidget(section(tr("Setpoint steps"), m_steps, [this] { addSetpointStep(100, 13.0); }));
    layout->addWidget(section(tr("Input changes (a ramp when \"over\" > 0)"), m_inputs,
                              [this] { addInputChange(QStringLiteral("feed_kg_h"), 100, 0, 6400); }));
    layout->addWidget(section(tr("Hidden causes in the plant (no controller knows them)"), m_mechanisms,
                              [this] { addMechanism(QStringLiteral("heat_transfer_fouling"), 0.2, 0); }));
    m_note->setText(tr("The scenario as a form; the JSON tab shows the same scenario as text."));
    connect(m_name, &QLineEdit::textEdited, this, &ScenarioForm::emitEdited);
    connect(m_plant, QOverload<int>::of(&QComboBox::activated), this, &ScenarioForm::emitEdited);
    connect(m_sensors, QOverload<int>::of(&QComboBox::activated), this, &ScenarioForm::emitEdited);
    for (auto* spin : {m_seed, m_length}) {
        connect(spin, QOverload<int>::of(&QSpinBox::valueChanged), this, &ScenarioForm::emitEdited);
    }
    for (auto* spin : {m_setpoint, m_band}) {
        connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &ScenarioForm::emitEdited);
    }
    for (auto* table : {m_steps, m_inputs, m_mechanisms}) {
        connect(table, &QTableWidget::itemChanged, this, &ScenarioForm::emitEdited);
    }
}

QTableWidget* ScenarioForm::makeTable(const QStringList& headers) {
    auto* t = new QTableWidget(0, static_cast<int>(headers.size()));
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->hide();
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    t->setMinimumHeight(90);
    return t;
}

void ScenarioForm::emitEdited() {
    if (!m_filling) {
        Q_EMIT edited();
    }
}

void ScenarioForm::addSetpointStep(double atS, double toPct) {
    const bool filling = std::exchange(m_filling, true);
    const int r = m_steps->rowCount();
    m_steps->insertRow(r);
    m_steps->setItem(r, 0, new QTableWidgetItem(QString::number(atS)));
    m_steps->setItem(r, 1, new QTableWidgetItem(QString::number(toPct)));
    m_filling = filling;
}

void ScenarioForm::addInputChange(const QString& input, double atS, double durationS, double to) {
    const bool filling = std::exchange(m_filling, true);
    const int r = m_inputs->rowCount();
    m_inputs->insertRow(r);
    auto* combo = new QComboBox;
    for (const auto& k : kInputs) {
        combo->addItem(QCoreApplication::translate("ScenarioForm", k.words), QString::fromLatin1(k.key));
    }
    combo->setCurrentIndex(std::max(0, combo->findData(input)));
    connect(combo, QOverload<int>::of(&QComboBox::activated), this, &ScenarioForm::emitEdited);
    m_inputs->setCellWidget(r, 0, combo);
    m_inputs->setItem(r, 1, new QTableWidgetItem(QString::number(atS)));
    m_inputs->setItem(r, 2, new QTableWidgetItem(QString::number(durationS)));
    m_inputs->setItem(r, 3, new QTableWidgetItem(QString::number(to)));
    m_filling = filling;
}

void ScenarioForm::addMechanism(const QString& mechanism, double strength, double atS) {
    const bool filling = std::exchange(m_filling, true);
    const int r = m_mechanisms->rowCount();
    m_mechanisms->insertRow(r);
    auto* combo = new QComboBox;
    for (const auto& mi : plant::mechanisms()) {
        const std::string name(mi.name);
        combo->addItem(causeDisplayName(name), QString::fromStdString(name));
        combo->setItemData(combo->count() - 1,
                           tr("%1; strength in %2").arg(QString::fromStdString(name), fromView(mi.unit)),
                           Qt::ToolTipRole);
    }
    combo->setCurrentIndex(std::max(0, combo->findData(mechanism)));
    connect(combo, QOverload<int>::of(&QComboBox::activated), this, &ScenarioForm::emitEdited);
    m_mechanisms->setCellWidget(r, 0, combo);
    m_mechanisms->setItem(r, 1, new QTableWidgetItem(QString::number(strength)));
    m_mechanisms->setItem(r, 2, new QTableWidgetItem(QString::number(atS)));
    m_filling = filling;
}

bool ScenarioForm::setJson(const QString& text) {
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(text.toUtf8(), &error);
    if (!doc.isObject()) {
        m_note->setText(tr("The JSON tab's text is not a scenario the form can show (%1); fix it there.")
                            .arg(error.errorString()));
        setEnabled(false);
        return false;
    }
    setEnabled(true);
    m_note->setText(tr("The scenario as a form; the JSON tab shows the same scenario as text."));
    m_filling = true;
    m_base = doc.object();
    const QJsonObject initial = m_base.value(QStringLiteral("initial")).toObject();
    m_name->setText(m_base.value(QStringLiteral("name")).toString());
    m_plant->setCurrentIndex(std::max(
        0, m_plant->findData(m_base.value(QStringLiteral("plant")).toString(QStringLiteral("lumped")))));
    m_sensors->setCurrentIndex(std::max(
        0,
        m_sensors->findData(m_base.value(QStringLiteral("sensors")).toString(QStringLiteral("realistic")))));
    m_seed->setValue(m_base.value(QStringLiteral("seed")).toInt(1));
    m_length->setValue(m_base.value(QStringLiteral("length_s")).toInt(1000));
    m_setpoint->setValue(initial.value(QStringLiteral("setpoint_pct")).toDouble(13.0));
    m_band->setValue(m_base.value(QStringLiteral("band_pct")).toDouble(0.5));
    for (auto* t : {m_steps, m_inputs, m_mechanisms}) {
        t->setRowCount(0);
    }
    for (const auto& v : m_base.value(QStringLiteral("setpoint_steps")).toArray()) {
        const auto o = v.toObject();
        addSetpointStep(o.value(QStringLiteral("at_s")).toDouble(),
                        o.value(QStringLiteral("to_pct")).toDouble());
    }
    for (const auto& v : m_base.value(QStringLiteral("input_changes")).toArray()) {
        const auto o = v.toObject();
        addInputChange(
            o.value(QStringLiteral("input")).toString(), o.value(QStringLiteral("at_s")).toDouble(),
            o.value(QStringLiteral("duration_s")).toDouble(), o.value(QStringLiteral("to")).toDouble());
    }
    for (const auto& v : m_base.value(QStringLiteral("mechanisms")).toArray()) {
        const auto o = v.toObject();
        addMechanism(o.value(QStringLiteral("mechanism")).toString(),
                     o.value(QStringLiteral("strength")).toDouble(),
                     o.value(QStringLiteral("at_s")).toDouble());
    }
    m_filling = false;
    return true;
}

QString ScenarioForm::json() const {
    QJsonObject o = m_base;
    o[QStringLiteral("name")] = m_name->text();
    o[QStringLiteral("plant")] = m_plant->currentData().toString();
    o[QStringLiteral("sensors")] = m_sensors->currentData().toString();
    o[QStringLiteral("seed")] = m_seed->value();
    o[QStringLiteral("length_s")] = m_length->value();
    o[QStringLiteral("band_pct")] = m_band->value();
    QJsonObject initial = o.value(QStringLiteral("initial")).toObject();
    initial[QStringLiteral("setpoint_pct")] = m_setpoint->value();
    o[QStringLiteral("initial")] = initial;
    QJsonArray steps, inputs, mechanisms;
    for (int r = 0; r < m_steps->rowCount(); ++r) {
        steps.append(QJsonObject{{QStringLiteral("at_s"), cellNumber(m_steps, r, 0)},
                                 {QStringLiteral("to_pct"), cellNumber(m_steps, r, 1)}});
    }
    for (int r = 0; r < m_inputs->rowCount(); ++r) {
        QJsonObject change{{QStringLiteral("input"), comboKey(m_inputs, r, 0)},
                           {QStringLiteral("at_s"), cellNumber(m_inputs, r, 1)},
                           {QStringLiteral("to"), cellNumber(m_inputs, r, 3)}};
        if (cellNumber(m_inputs, r, 2) > 0) {
            change[QStringLiteral("duration_s")] = cellNumber(m_inputs, r, 2);
        }
        inputs.append(change);
    }
    for (int r = 0; r < m_mechanisms->rowCount(); ++r) {
        QJsonObject m{{QStringLiteral("mechanism"), comboKey(m_mechanisms, r, 0)},
                      {QStringLiteral("strength"), cellNumber(m_mechanisms, r, 1)}};
        if (cellNumber(m_mechanisms, r, 2) > 0) {
            m[QStringLiteral("at_s")] = cellNumber(m_mechanisms, r, 2);
        }
        mechanisms.append(m);
    }
    o[QStringLiteral("setpoint_steps")] = steps;
    o[QStringLiteral("input_changes")] = inputs;
    o[QStringLiteral("mechanisms")] = mechanisms;
    return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
}

} // namespace drytwin::widgets
