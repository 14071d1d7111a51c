#include "data/DataPanel.h"
#include "common/EngineText.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/Series.h"
#include "common/Units.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "data/ColumnMappingDialog.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <iterator>

namespace drytwin::widgets {

namespace {

/// The plots top to bottom: the product's outlet first, what an engineer opens the file to see
/// (a newcomer's review found X_out and T_out below the fold at 1280 × 800, under six inputs),
/// then the tube outlet, then the inputs in batchSeries()'s order.
constexpr std::size_t kPlotOrder[] = {kSeriesXOut, kSeriesTOut, kSeriesXHdt, 0, 1, 2, 3, 4};

} // namespace

DataPanel::DataPanel(Workbench& workbench, QWidget* parent) : QWidget(parent), m_workbench(workbench) {
    setAcceptDrops(true);
    auto* openFile = new QPushButton(tr("Open file…"));
    auto* openFolder = new QPushButton(tr("Open folder…"));
    auto* mapping = new QPushButton(tr("Column mapping…"));
    mapping->setToolTip(tr("Files with other column names: map them onto DryTwin's columns, then load"));
    m_cleaning = new QLabel;
    m_cleaning->setWordWrap(true);
    m_arrangement = new QComboBox;
    m_arrangement->addItems({tr("Batches overlaid"), tr("Batches one after another")});
    m_table = makeResultTable({tr("Batch"), tr("Rows"), tr("Kept"), tr("Length [min]"),
                               tr("Mean X_out [% wb]"), tr("Mean T_hot [°C]"), tr("Source")});
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_plots = new PlotStack;
    const auto series = batchSeries();
    static_assert(std::size(kPlotOrder) == 8, "one plot per batch series");
    for (const std::size_t s : kPlotOrder) {
        m_plots->addPlot(series[s].title);
    }
    auto* left = new QWidget;
    auto* leftLayout = new QVBoxLayout(left);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(openFile);
    buttons->addWidget(openFolder);
    leftLayout->addLayout(buttons);
    leftLayout->addWidget(new QLabel(tr("Batches (select several to overlay; drop files here):")));
    leftLayout->addWidget(m_table, 1);
    leftLayout->addWidget(m_cleaning);
    leftLayout->addWidget(mapping);
    leftLayout->addWidget(m_arrangement);
    // Eight plots one above the other: scroll rather than squeeze them.
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_plots);
    scroll->setWidgetResizable(true);
    m_plots->setMinimumHeight(8 * 125);
    auto* split = new QSplitter;
    split->addWidget(left);
    split->addWidget(scroll);
    split->setStretchFactor(1, 1);
    split->setSizes({660, 620}); // the batch table's columns whole, the plots beside them
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(split);

    connect(openFile, &QPushButton::clicked, this, [this] {
        const QString p = askOpenFile(this, tr("Open batch file"), tr("Batch files (*.csv)"));
        if (!p.isEmpty()) {
            m_workbench.openData(p);
        }
    });
    connect(openFolder, &QPushButton::clicked, this, [this] {
        const QString p = askFolder(this, tr("Open data set folder"));
        if (!p.isEmpty()) {
            m_workbench.openData(p);
        }
    });
    connect(mapping, &QPushButton::clicked, this, [this] {
        const QString file =
            askOpenFile(this, tr("A batch file with your column names"), tr("Batch files (*.csv)"));
        if (!file.isEmpty()) {
            mapAndOpen(file);
        }
    });
    connect(&m_workbench, &Workbench::dataChanged, this, &DataPanel::fill);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &DataPanel::redraw);
    connect(m_arrangement, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &DataPanel::redraw);
    m_plots->setEmptyText(
        tr("Open a data set: File ▸ Open data set folder…, or File ▸ Open the bundled demo"));
}

namespace {
/// Where a column mapping the user did not save is kept: DryTwin's own data folder, named after
/// the export's folder and the time, so that the next one does not overwrite it.
QString keptMappingPath(const QString& file) {
    const QDir dir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation));
    dir.mkpath(QStringLiteral("mappings"));
    return dir.filePath(QStringLiteral("mappings/%1-%2.json")
                            .arg(QFileInfo(file).absoluteDir().dirName(),
                                 QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
}
} // namespace

void DataPanel::mapAndOpen(const QString& file) {
    {
        ColumnMappingDialog dialog(file, this);
        if (dialog.exec() != QDialog::Accepted) {
            return;
        }
        // The user's corrections, proposed again for the next file with these headers.
        dialog.rememberForTheseHeaders();
        QString saveTo = askSaveFile(this, tr("Save the column mapping"), QStringLiteral("mapping.json"),
                                     tr("Mappings (*.json)"));
        const bool chosenByUser = !saveTo.isEmpty();
        if (!chosenByUser) {
            // Not saving it to a file of one's own must not throw the mapping away (issue #43
            // item 8): it is kept in DryTwin's data folder, the data load with it, and a saved
            // project remembers it like any other mapping.
            saveTo = keptMappingPath(file);
        }
        QString error;
        if (!dialog.save(saveTo, &error)) {
            m_cleaning->setText(
                tr("The column mapping could not be saved (%1); the data were not loaded.").arg(error));
            m_cleaning->setToolTip({}); // the notes of the data shown before do not describe this
            return;
        }
        m_keptMappingPath = chosenByUser ? QString() : saveTo;
        // The file mapped is the data set, not its folder: another CSV beside it (an export of
        // another line, a file of plots) was pulled in with it (issue #72 item 6).
        m_workbench.openData(QFileInfo(file).absoluteFilePath(), saveTo);
        if (!chosenByUser) {
            m_keptMappingNote = tr("The column mapping is kept at %1 and in the project when you save it; "
                                   "“Column mapping…” changes it.")
                                    .arg(QDir::toNativeSeparators(saveTo));
        }
    }
}

void DataPanel::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) {
        event->acceptProposedAction();
    }
}

void DataPanel::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.front().isLocalFile()) {
        m_workbench.openData(urls.front().toLocalFile());
    }
}

void DataPanel::fill() {
    const auto& si = m_workbench.siBatches();
    const auto& summary = m_workbench.summary();
    m_table->blockSignals(true);
    m_table->setRowCount(static_cast<int>(si.size()));
    std::size_t modelRows = 0;
    for (std::size_t i = 0; i < si.size(); ++i) {
        const auto& b = si[i];
        // The cleaning rules' count, as the summary below and `drytwin inspect` give it; the rows
        // the model uses besides (an input bridged across a dropout left out too) are said below.
        std::size_t kept = 0, nx = 0, nh = 0;
        double x = 0, h = 0;
        const std::vector<std::uint8_t>* cleaningKeep =
            i < summary.cleaning.keep.size() && summary.cleaning.keep[i].size() == b.rows()
                ? &summary.cleaning.keep[i]
                : nullptr;
        for (std::size_t k = 0; k < b.rows(); ++k) {
            kept += cleaningKeep ? (*cleaningKeep)[k] : b.keep[k];
            modelRows += b.keep[k];
            // Means over the cells that hold a value: a transmitter's dropout is no reading.
            if (std::isfinite(b.xOutDb[k])) {
                x += units::dryToWetPct(b.xOutDb[k]);
                ++nx;
            }
            if (std::isfinite(b.tHotK[k])) {
                h += units::kelvinToCelsius(b.tHotK[k]);
                ++nh;
            }
        }
        x = nx ? x / static_cast<double>(nx) : std::nan("");
        h = nh ? h / static_cast<double>(nh) : std::nan("");
        const double minutes = b.rows() > 1 ? (b.timeS.back() - b.timeS.front()) / 60.0 : 0.0;
        const QStringList cells{
            QString::fromStdString(i < summary.batches.size() ? summary.batches[i].id : b.id),
            QString::number(b.rows()), QString::number(kept), QString::number(minutes, 'f', 1),
            QString::number(x, 'f', 3), QString::number(h, 'f', 1),
            // A run cut from a long plant file says where it came from; a batch file is its own source.
            i < summary.batches.size() && summary.batches[i].run
                ? tr("%1, lines %2–%3, from %4, ended by %5")
                      .arg(QFileInfo(QString::fromStdString(summary.batches[i].run->file)).fileName())
                      .arg(summary.batches[i].run->firstLine)
                      .arg(summary.batches[i].run->lastLine)
                      .arg(QString::fromStdString(summary.batches[i].run->startTimestamp),
                           runEndText(summary.batches[i].run->splitReason))
                : QFileInfo(QString::fromStdString(i < summary.batches.size() ? summary.batches[i].path : ""))
                      .fileName()};
        setTableRow(m_table, static_cast<int>(i), cells);
        if (auto* item = m_table->item(static_cast<int>(i), 0)) {
            item->setToolTip(cells.back()); // the source in full, when the column is scrolled away
        }
    }
    fitTableWidth(m_table);
    m_table->blockSignals(false);
    const auto& c = summary.cleaning;
    // The chronological split of paper §IV.A over the rows in file order.
    std::vector<std::size_t> rowsPerBatch;
    for (const auto& b : si) {
        rowsPerBatch.push_back(b.rows());
    }
    const auto split = data::chronologicalSplit(rowsPerBatch);
    std::size_t train = 0, test = 0;
    for (std::size_t i = 0; i < split.train.size(); ++i) {
        train += split.train[i].size();
        test += split.test[i].size();
    }
    m_cleaning->setText(
        tr("Cleaning (paper §IV.A): %1 of %2 rows kept; dropped for X_HDT %3, T_HDT %4, feed %5, "
           "missing cells %6, impossible values %7. Split: the first %8 rows train, the last %9 "
           "test.")
            .arg(c.kept)
            .arg(c.rows)
            .arg(c.droppedXhdt)
            .arg(c.droppedThdt)
            .arg(c.droppedFeed)
            .arg(c.droppedMissing)
            .arg(c.droppedImpossible)
            .arg(train)
            .arg(test) +
        QStringLiteral(" ") +
        tr("A row may fail more than one rule. The model uses %1 rows: those kept, less the rows where "
           "an input was bridged across a dropout.")
            .arg(modelRows) +
        (c.droppedStuck == 0
             ? QString()
             : QStringLiteral(" ") +
                   tr("A transmitter hung (the same reading for a minute or more) on %1 rows: left out, an "
                      "input bridged like a dropout.")
                       .arg(c.droppedStuck)) +
        (summary.notes.empty()
             ? QString()
             : QStringLiteral("\n") + tr("Noted while reading (%1):").arg(summary.notes.size()) +
                   QStringLiteral(" ") + dataNoteText(summary.notes.front()) +
                   (summary.notes.size() > 1 ? QStringLiteral(" …") : QString())) +
        (!m_keptMappingPath.isEmpty() && m_workbench.mappingPath() == m_keptMappingPath
             ? QStringLiteral("\n") + m_keptMappingNote
             : QString()));
    // Every note in full where the line above has room for the first: a folder with a batch in
    // another unit can carry several, each naming its file.
    QStringList allNotes;
    for (const auto& note : summary.notes) {
        allNotes << dataNoteText(note);
    }
    m_cleaning->setToolTip(allNotes.isEmpty()
                               ? QString()
                               : tr("Noted while reading (%1):").arg(allNotes.size()) +
                                     QStringLiteral("\n• ") + allNotes.join(QStringLiteral("\n• ")));
    if (!si.empty()) {
        selectBatches({0});
    }
}

void DataPanel::selectBatches(const QList<int>& rows) {
    m_table->blockSignals(true);
    m_table->clearSelection();
    for (int r : rows) {
        if (r >= 0 && r < m_table->rowCount()) {
            m_table->selectionModel()->select(m_table->model()->index(r, 0),
                                              QItemSelectionModel::Select | QItemSelectionModel::Rows);
        }
    }
    m_table->blockSignals(false);
    redraw();
}

void DataPanel::redraw() {
    const auto& si = m_workbench.siBatches();
    QList<int> rows;
    for (const auto& range : m_table->selectedRanges()) {
        for (int r = range.topRow(); r <= range.bottomRow(); ++r) {
            rows << r;
        }
    }
    std::sort(rows.begin(), rows.end());
    m_plots->clearCurves();
    const bool sequential = m_arrangement->currentIndex() == 1;
    const auto series = batchSeries();
    double offset = 0;
    for (int n = 0; n < rows.size(); ++n) {
        if (rows[n] < 0 || static_cast<std::size_t>(rows[n]) >= si.size()) {
            continue;
        }
        const auto& b = si[static_cast<std::size_t>(rows[n])];
        QVector<double> t = timeOf(b);
        if (sequential) {
            for (auto& v : t) {
                v += offset;
            }
            offset = t.isEmpty() ? offset : t.back() + 1;
        }
        const QColor colour = seriesColour(n);
        for (std::size_t plot = 0; plot < std::size(kPlotOrder); ++plot) {
            m_plots->addCurve(static_cast<int>(plot), QString::fromStdString(b.id), t,
                              valuesOf(b, series[kPlotOrder[plot]]), colour);
        }
    }
    m_plots->rescale();
}

} // namespace drytwin::widgets
