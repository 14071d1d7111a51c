#include "model/ModelPanel.h"

#include "model/ParameterTexts.h"

#include "common/PlotStack.h"
#include "common/Series.h"
#include "common/Units.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QUndoCommand>
#include <QUndoStack>
#include <QVBoxLayout>

namespace drytwin::widgets {

namespace {

/// One parameter edit: redo sets the new value through the Session, undo the old one.
class SetParameterCommand : public QUndoCommand {
public:
    SetParameterCommand(Workbench& w, properties::Param p, double before, double after)
        : m_w(w), m_p(p), m_before(before), m_after(after) {
        setText(QObject::tr("set %1 to %2").arg(fromView(properties::info(p).symbol)).arg(after));
    }
    void redo() override { m_w.setParameter(m_p, m_after); }
    void undo() override { m_w.setParameter(m_p, m_before); }

private:
    Workbench& m_w;
    properties::Param m_p;
    double m_before, m_after;
};

} // namespace

ModelPanel::ModelPanel(Workbench& workbench, QWidget* parent) : QWidget(parent), m_workbench(workbench) {
    m_undo = new QUndoStack(this);
    m_table = new FittedTable(0, 7);
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Value"), tr("Unit"), tr("Lower"), tr("Upper"), tr("Source"), tr("Meaning")});
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    auto* undo = new QPushButton(tr("Undo"));
    auto* redo = new QPushButton(tr("Redo"));
    undo->setEnabled(false);
    redo->setEnabled(false);
    connect(m_undo, &QUndoStack::canUndoChanged, undo, &QPushButton::setEnabled);
    connect(m_undo, &QUndoStack::canRedoChanged, redo, &QPushButton::setEnabled);
    connect(undo, &QPushButton::clicked, m_undo, &QUndoStack::undo);
    connect(redo, &QPushButton::clicked, m_undo, &QUndoStack::redo);

    auto* switches = new QGroupBox(tr("Physics switches"));
    auto* sl = new QVBoxLayout(switches);
    const QStringList names{tr("clamp water activity (Eq. 2)"), tr("bound-water latent heat (Eq. 4)"),
                            tr("moisture-dependent heat capacity (Eq. 3)"),
                            tr("consistent energy balance (Eqs. 12, 14, 19; off: as printed)")};
    for (int i = 0; i < 4; ++i) {
        m_switches[i] = new QCheckBox(names[i]);
        sl->addWidget(m_switches[i]);
        connect(m_switches[i], &QCheckBox::toggled, this, [this] {
            if (m_filling) {
                return;
            }
            hybrid::HybridModel m = m_workbench.model();
            m.switches.clampWaterActivity = m_switches[0]->isChecked();
            m.switches.latentHeatCorrection = m_switches[1]->isChecked();
            m.switches.moistureDependentCp = m_switches[2]->isChecked();
            m.switches.consistentEnergyBalance = m_switches[3]->isChecked();
            m_workbench.setModel(m);
        });
    }
    auto* simulate = new QPushButton(tr("Simulate"));
    simulate->setToolTip(tr("Run the physics model over every batch with these parameters"));
    connect(simulate, &QPushButton::clicked, &m_workbench, &Workbench::simulate);
    m_batch = new QComboBox;

    auto* left = new QWidget;
    auto* ll = new QVBoxLayout(left);
    auto* ub = new QHBoxLayout;
    auto* editHint = new QLabel(tr("Double-click a value to edit it; it is checked against its bounds."));
    editHint->setWordWrap(true); // on one line it held the window 1,034 px wide at the least
    ub->addWidget(editHint, 1);
    ub->addWidget(undo);
    ub->addWidget(redo);
    ll->addLayout(ub);
    ll->addWidget(m_table, 1);
    ll->addWidget(switches);
    auto* right = new QWidget;
    auto* rl = new QVBoxLayout(right);
    auto* top = new QHBoxLayout;
    top->addWidget(simulate);
    top->addWidget(new QLabel(tr("Batch:")));
    top->addWidget(m_batch, 1);
    rl->addLayout(top);
    m_plots = new PlotStack;
    m_plots->addPlot(tr("X_out [% wb]"));
    m_plots->addPlot(tr("T_out [°C]"));
    m_plots->addPlot(tr("X_HDT [% wb]"));
    m_plots->addPlot(tr("T_HDT [°C]"));
    rl->addWidget(m_plots, 1);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);

    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (m_filling || item->column() != 1) {
            return;
        }
        bool ok = false;
        const double v = item->text().toDouble(&ok);
        if (!ok || !editParameter(item->row(), v)) {
            fillTable(); // back to the model's value
        }
    });
    connect(&m_workbench, &Workbench::modelChanged, this, &ModelPanel::fillTable);
    connect(&m_workbench, &Workbench::simulated, this, &ModelPanel::redraw);
    connect(&m_workbench, &Workbench::dataChanged, this, [this] {
        m_batch->clear();
        for (const auto& b : m_workbench.siBatches()) {
            m_batch->addItem(QString::fromStdString(b.id));
        }
    });
    connect(m_batch, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ModelPanel::redraw);
    fillTable();
}

bool ModelPanel::editParameter(int row, double value) {
    if (row < 0 || row >= properties::kParamCount) {
        return false;
    }
    const auto& info = properties::parameterTable()[static_cast<std::size_t>(row)];
    if (!(value >= info.lower && value <= info.upper)) {
        const QString msg = tr("%1 must lie in [%2, %3] %4; it stays %5.")
                                .arg(fromView(info.symbol))
                                .arg(info.lower)
                                .arg(info.upper)
                                .arg(fromView(info.unit))
                                .arg(m_workbench.model().parameters[info.id]);
        Q_EMIT m_workbench.status(msg);
        return false;
    }
    m_undo->push(
        new SetParameterCommand(m_workbench, info.id, m_workbench.model().parameters[info.id], value));
    return true;
}

void ModelPanel::fillTable() {
    m_filling = true;
    const auto& table = properties::parameterTable();
    m_table->setRowCount(static_cast<int>(table.size()));
    const auto& p = m_workbench.model().parameters;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const auto& info = table[i];
        const QStringList cells{fromView(info.symbol),
                                QString::number(p[info.id], 'g', 6),
                                fromView(info.unit),
                                QString::number(info.lower, 'g', 4),
                                QString::number(info.upper, 'g', 4),
                                parameterSource(info),
                                parameterMeaning(info)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c != 1 || info.fixed) {
                item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            }
            m_table->setItem(static_cast<int>(i), c, item);
        }
    }
    fitTableWidth(m_table); // its long texts scroll; the first columns show
    const auto& sw = m_workbench.model().switches;
    const bool values[4] = {sw.clampWaterActivity, sw.latentHeatCorrection, sw.moistureDependentCp,
                            sw.consistentEnergyBalance};
    for (int i = 0; i < 4; ++i) {
        m_switches[i]->setChecked(values[i]);
    }
    m_filling = false;
}

void ModelPanel::redraw() {
    const auto& si = m_workbench.siBatches();
    const auto& sim = m_workbench.latest().simulate;
    const int b = m_batch->currentIndex();
    m_plots->clearCurves();
    if (b < 0 || static_cast<std::size_t>(b) >= si.size()) {
        m_plots->rescale();
        return;
    }
    const auto& batch = si[static_cast<std::size_t>(b)];
    const QVector<double> t = timeOf(batch);
    const auto& series = batchSeries();
    const int measured[4] = {kSeriesXOut, kSeriesTOut, kSeriesXHdt, -1}; // T_HDT is not a batch-file plot
    for (int i = 0; i < 4; ++i) {
        if (measured[i] >= 0) {
            m_plots->addCurve(i, tr("measured"), t,
                              valuesOf(batch, series[static_cast<std::size_t>(measured[i])]),
                              QColor(31, 119, 180));
        } else if (batch.hasTHdt) {
            QVector<double> v(static_cast<int>(batch.rows()));
            for (std::size_t k = 0; k < batch.rows(); ++k) {
                v[static_cast<int>(k)] = units::kelvinToCelsius(batch.tHdtK[k]);
            }
            m_plots->addCurve(i, tr("measured"), t, v, QColor(31, 119, 180));
        }
    }
    if (sim && static_cast<std::size_t>(b) < sim->simulations.size()) {
        const auto& r = sim->simulations[static_cast<std::size_t>(b)];
        QVector<double> x, T, xh, th;
        for (std::size_t k = 0; k < r.xOutDb.size(); ++k) {
            x << units::dryToWetPct(r.xOutDb[k]);
            T << units::kelvinToCelsius(r.tOutK[k]);
            xh << units::dryToWetPct(r.xHdtDb[k]);
            th << units::kelvinToCelsius(r.tHdtK[k]);
        }
        const QString name = tr("physics model");
        m_plots->addCurve(0, name, t, x, Qt::black, Qt::DashLine, 1.6);
        m_plots->addCurve(1, name, t, T, Qt::black, Qt::DashLine, 1.6);
        m_plots->addCurve(2, name, t, xh, Qt::black, Qt::DashLine, 1.6);
        m_plots->addCurve(3, name, t, th, Qt::black, Qt::DashLine, 1.6);
    }
    m_plots->rescale();
}

} // namespace drytwin::widgets
