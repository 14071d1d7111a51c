#include "mpc/ScenarioForm.h"

#include "common/DisplayNames.h"
#include "common/WheelGuard.h"
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
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <utility>

namespace drytwin::widgets {

namespace {

/// The inputs a scenario moves, by their scenario-file keys, with words, units and the range the
/// scenario parser accepts (control/Scenario.cpp; a value outside it is refused before a run).
struct InputKey {
    const char* key;
    const char* words;
    double lo;
    double hi;
};
const InputKey kInputs[] = {{"feed_kg_h", QT_TRANSLATE_NOOP("ScenarioForm", "feed [kg/h]"), 3000, 9000},
                            {"x_in_pct", QT_TRANSLATE_NOOP("ScenarioForm", "inlet moisture [% wb]"), 15, 30},
                            {"t_amb_c", QT_TRANSLATE_NOOP("ScenarioForm", "ambient temperature [°C]"), 0, 45},
                            {"rh_pct", QT_TRANSLATE_NOOP("ScenarioForm", "ambient humidity [% RH]"), 5, 95}};
/// The setpoint range of the scenario parser [% wb].
constexpr double kSetpointLo = 8;
constexpr double kSetpointHi = 20;

/// A cell's number; nullopt when the cell holds no number (an empty cell is @p empty).
std::optional<double> cellValue(const QTableWidget* t, int row, int column,
                                std::optional<double> empty = std::nullopt) {
    const auto* item = t->item(row, column);
    const QString text = item ? item->text().trimmed() : QString();
    if (text.isEmpty()) {
        return empty;
    }
    bool ok = false;
    const double v = text.toDouble(&ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

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
    m_setpoint->setRange(kSetpointLo, kSetpointHi);
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
    m_lengthError = makeInlineError();
    form->addRow(QString(), m_lengthError);
    form->addRow(tr("Initial X_out setpoint"), m_setpoint);
    form->addRow(tr("Specification band ±"), m_band);
    m_steps = makeTable({tr("at [s]"), tr("setpoint to [% wb]")});
    m_inputs = makeTable({tr("input"), tr("at [s]"), tr("over [s]"), tr("to")});
    m_mechanisms = makeTable({tr("hidden cause"), tr("strength"), tr("from [s]")});
    m_stepsError = makeInlineError();
    m_inputsError = makeInlineError();
    m_mechanismsError = makeInlineError();
    const auto section = [this](const QString& title, QTableWidget* table, QLabel* error,
                                std::function<void()> add) {
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
        l->addWidget(error);
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
    layout->addWidget(section(tr("Setpoint steps"), m_steps, m_stepsError, [this] {
        // Appended after the last step, to the setpoint it left: inserted at 100 s before a later
        // step it made the form invalid and Run was off until it was edited (issue #72 item 7).
        const int last = m_steps->rowCount() - 1;
        addSetpointStep(timeForNewRow(m_steps, 0),
                        last >= 0 ? cellNumber(m_steps, last, 1, 13.0) : m_setpoint->value());
    }));
    layout->addWidget(
        section(tr("Input changes (a ramp when \"over\" > 0)"), m_inputs, m_inputsError, [this] {
            addInputChange(QStringLiteral("feed_kg_h"), timeForNewRow(m_inputs, 1), 0, 6400);
        }));
    layout->addWidget(section(tr("Hidden causes in the plant (no controller knows them)"), m_mechanisms,
                              m_mechanismsError,
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
    // The form scrolls: a wheel over a value scrolls it rather than changing the value.
    ignoreWheelUnlessFocused(this);
}

double ScenarioForm::timeForNewRow(const QTableWidget* table, int timeColumn) const {
    // After the latest row's time and within the scored length, so that Add never makes the form
    // invalid: halfway from the latest time to the end (100 s into an empty table, or the middle
    // of a short run).
    const int length = m_length->value();
    double latest = -1;
    for (int r = 0; r < table->rowCount(); ++r) {
        latest = std::max(latest, cellNumber(table, r, timeColumn, -1));
    }
    if (latest < 0) {
        return std::min(100, length / 2);
    }
    if (latest >= length) {
        return latest; // the form already says the table runs past the length
    }
    return std::round(latest + 0.5 * (length - latest));
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
        revalidate();
        Q_EMIT edited();
    }
}

void ScenarioForm::revalidate() {
    const bool wasValid = m_problems.isEmpty();
    const int length = m_length->value();
    QStringList steps, inputs, mechanisms;
    double latest = 0; // the latest time in the tables, when after the scored length
    // Marking a cell changes its item: no itemChanged() back into the form while we do.
    const QSignalBlocker b1(m_steps), b2(m_inputs), b3(m_mechanisms);
    for (auto* t : {m_steps, m_inputs, m_mechanisms}) {
        for (int r = 0; r < t->rowCount(); ++r) {
            for (int c = 0; c < t->columnCount(); ++c) {
                if (auto* item = t->item(r, c)) {
                    item->setBackground(QBrush());
                    item->setToolTip(QString());
                }
            }
        }
    }
    const auto mark = [](QTableWidget* t, int row, int column, QStringList& list, const QString& why) {
        if (auto* item = t->item(row, column)) {
            item->setBackground(QColor(255, 214, 214));
            item->setToolTip(why);
        }
        list << why;
    };
    const auto notANumber = [this](int row) { return tr("Row %1: enter a number.").arg(row); };
    std::optional<double> previous;
    for (int r = 0; r < m_steps->rowCount(); ++r) {
        const auto at = cellValue(m_steps, r, 0);
        const auto to = cellValue(m_steps, r, 1);
        if (!at || *at < 0) {
            mark(m_steps, r, 0, steps,
                 at ? tr("Step %1: the time cannot be negative.").arg(r + 1) : notANumber(r + 1));
        } else if (*at > length) {
            latest = std::max(latest, *at);
            mark(m_steps, r, 0, steps,
                 tr("Step %1 at %2 s comes after the scored length (%3 s): move it earlier or lengthen the "
                    "run.")
                     .arg(r + 1)
                     .arg(*at)
                     .arg(length));
        } else if (previous && *at < *previous) {
            mark(m_steps, r, 0, steps,
                 tr("Step %1 at %2 s comes before the step above it (%3 s): list the steps in time order.")
                     .arg(r + 1)
                     .arg(*at)
                     .arg(*previous));
        }
        if (at) {
            previous = *at;
        }
        if (!to) {
            mark(m_steps, r, 1, steps, notANumber(r + 1));
        } else if (*to < kSetpointLo || *to > kSetpointHi) {
            mark(m_steps, r, 1, steps,
                 tr("Step %1: a setpoint of %2 % wb lies outside %3–%4 % wb.")
                     .arg(r + 1)
                     .arg(*to)
                     .arg(kSetpointLo)
                     .arg(kSetpointHi));
        }
    }
    for (int r = 0; r < m_inputs->rowCount(); ++r) {
        const auto at = cellValue(m_inputs, r, 1);
        const auto over = cellValue(m_inputs, r, 2, 0.0);
        const auto to = cellValue(m_inputs, r, 3);
        if (!at || *at < 0) {
            mark(m_inputs, r, 1, inputs,
                 at ? tr("Change %1: the time cannot be negative.").arg(r + 1) : notANumber(r + 1));
        } else if (*at > length) {
            latest = std::max(latest, *at);
            mark(m_inputs, r, 1, inputs,
                 tr("Change %1 at %2 s comes after the scored length (%3 s): move it earlier or lengthen the "
                    "run.")
                     .arg(r + 1)
                     .arg(*at)
                     .arg(length));
        }
        if (!over || *over < 0 || *over > length) {
            mark(m_inputs, r, 2, inputs,
                 over ? tr("Change %1: a ramp lasts 0 to %2 s (the scored length).").arg(r + 1).arg(length)
                      : notANumber(r + 1));
        }
        const QString key = comboKey(m_inputs, r, 0);
        for (const auto& k : kInputs) {
            if (key != QLatin1String(k.key)) {
                continue;
            }
            if (!to) {
                mark(m_inputs, r, 3, inputs, notANumber(r + 1));
            } else if (*to < k.lo || *to > k.hi) {
                mark(m_inputs, r, 3, inputs,
                     tr("Change %1: %2 lies outside %3–%4 for %5.")
                         .arg(r + 1)
                         .arg(*to)
                         .arg(k.lo)
                         .arg(k.hi)
                         .arg(QCoreApplication::translate("ScenarioForm", k.words)));
            }
        }
    }
    std::set<QString> seen;
    for (int r = 0; r < m_mechanisms->rowCount(); ++r) {
        const QString key = comboKey(m_mechanisms, r, 0);
        const auto strength = cellValue(m_mechanisms, r, 1);
        const auto at = cellValue(m_mechanisms, r, 2, 0.0);
        const QString name = causeDisplayName(key.toStdString());
        if (!seen.insert(key).second) {
            mechanisms << tr("Hidden cause %1 (%2) is listed twice.").arg(r + 1).arg(name);
        }
        for (const auto& mi : plant::mechanisms()) {
            if (key != fromView(mi.name)) {
                continue;
            }
            if (!strength) {
                mark(m_mechanisms, r, 1, mechanisms, notANumber(r + 1));
            } else if (*strength < 0 || *strength > mi.maxStrength) {
                mark(m_mechanisms, r, 1, mechanisms,
                     tr("Hidden cause %1 (%2): a strength of %3 lies outside 0–%4 %5.")
                         .arg(r + 1)
                         .arg(name)
                         .arg(*strength)
                         .arg(mi.maxStrength)
                         .arg(fromView(mi.unit)));
            }
        }
        if (!at || *at < 0) {
            mark(m_mechanisms, r, 2, mechanisms,
                 at ? tr("Hidden cause %1: the time cannot be negative.").arg(r + 1) : notANumber(r + 1));
        } else if (*at > length) {
            latest = std::max(latest, *at);
            mark(m_mechanisms, r, 2, mechanisms,
                 tr("Hidden cause %1 from %2 s starts after the scored length (%3 s): move it earlier or "
                    "lengthen the run.")
                     .arg(r + 1)
                     .arg(*at)
                     .arg(length));
        }
    }
    const QString lengthText =
        latest > length
            ? tr("Shorter than the scenario below: something happens at %1 s. Lengthen the run to at least "
                 "%1 s, or move that entry.")
                  .arg(latest)
            : QString();
    const auto show = [](QLabel* label, const QStringList& lines) {
        label->setText(lines.join(QLatin1Char('\n')));
        label->setVisible(!lines.isEmpty());
    };
    show(m_lengthError, lengthText.isEmpty() ? QStringList() : QStringList{lengthText});
    show(m_stepsError, steps);
    show(m_inputsError, inputs);
    show(m_mechanismsError, mechanisms);
    m_problems = steps + inputs + mechanisms;
    if (wasValid != m_problems.isEmpty()) {
        Q_EMIT validityChanged(m_problems.isEmpty());
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
    ignoreWheelUnlessFocused(combo);
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
    ignoreWheelUnlessFocused(combo);
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
    revalidate();
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
