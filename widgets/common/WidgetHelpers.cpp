#include "common/WidgetHelpers.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QHeaderView>
#include <QLabel>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QTableWidget>
#include <QWidget>
#include <map>

namespace drytwin::widgets {

QString lastFolder() {
    const QString folder = QSettings().value(QStringLiteral("lastFolder")).toString();
    return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QDir::homePath();
}

void rememberFolder(const QString& path) {
    if (path.isEmpty()) {
        return;
    }
    const QFileInfo info(path);
    QSettings().setValue(QStringLiteral("lastFolder"),
                         info.isDir() ? info.absoluteFilePath() : info.absolutePath());
}

QString askOpenFile(QWidget* parent, const QString& title, const QString& filter) {
    const QString p = QFileDialog::getOpenFileName(parent, title, lastFolder(), filter);
    rememberFolder(p);
    return p;
}

QString askFolder(QWidget* parent, const QString& title) {
    const QString p = QFileDialog::getExistingDirectory(parent, title, lastFolder());
    rememberFolder(p);
    return p;
}

QString askSaveFile(QWidget* parent, const QString& title, const QString& defaultName,
                    const QString& filter) {
    QString selected;
    QString p = QFileDialog::getSaveFileName(parent, title, QDir(lastFolder()).filePath(defaultName), filter,
                                             &selected);
    if (!p.isEmpty()) {
        p = withFilterSuffix(p, selected.isEmpty() ? filter.section(QStringLiteral(";;"), 0, 0) : selected,
                             filter);
    }
    rememberFolder(p);
    return p;
}

namespace {
/// The extensions a filter names: "PNG image (*.png *.PNG)" gives png.
QStringList filterSuffixes(const QString& filter) {
    QStringList out;
    static const QRegularExpression pattern(QStringLiteral("\\*\\.([A-Za-z0-9_]+)"));
    for (auto it = pattern.globalMatch(filter); it.hasNext();) {
        out << it.next().captured(1).toLower();
    }
    return out;
}
} // namespace

QString withFilterSuffix(const QString& path, const QString& selectedFilter, const QString& filters) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (!suffix.isEmpty() && filterSuffixes(filters + QLatin1Char(' ') + selectedFilter).contains(suffix)) {
        return path;
    }
    const QStringList chosen = filterSuffixes(selectedFilter);
    return chosen.isEmpty() ? path : path + QLatin1Char('.') + chosen.front();
}

QString fromView(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<int>(text.size()));
}

QTableWidget* makeResultTable(const QStringList& headers) {
    auto* table = new FittedTable(0, static_cast<int>(headers.size()));
    table->setHorizontalHeaderLabels(headers);
    // Every column as wide as its header and cells: a header cut to "p (Holm" says nothing. Long
    // headers are written on two lines ("MAE X_out\n[% wb]") to keep the columns narrow.
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    fitTableWidth(table);
    return table;
}

void fitTableWidth(QTableWidget* table, int maxWidth) {
    QHeaderView* header = table->horizontalHeader();
    table->resizeColumnsToContents();
    // ResizeToContents sections are sized at the next layout; size them now to measure them.
    header->resizeSections(QHeaderView::ResizeToContents);
    if (header->stretchLastSection()) {
        return; // it takes what room there is
    }
    const int width = header->length() + 2 * table->frameWidth() +
                      (table->verticalHeader()->isVisible() ? table->verticalHeader()->width() : 0) +
                      table->verticalScrollBar()->sizeHint().width();
    if (auto* fitted = dynamic_cast<FittedTable*>(table)) {
        fitted->setPreferredWidth(std::min(maxWidth, width));
        table->setMinimumWidth(std::min(kLeastFittedTableWidth, width));
        fitted->fitFirstColumn();
    } else {
        table->setMinimumWidth(std::min(maxWidth, width));
    }
}

namespace {
int heightForRows(const QTableWidget* table, int rows) {
    return table->horizontalHeader()->sizeHint().height() +
           rows * table->verticalHeader()->defaultSectionSize() +
           table->horizontalScrollBar()->sizeHint().height() + 2 * table->frameWidth();
}
} // namespace

void FittedTable::fitFirstColumn() {
    QHeaderView* header = horizontalHeader();
    if (columnCount() < 2 || header->stretchLastSection()) {
        return; // a stretched last column takes what room there is
    }
    const int natural = std::max(header->sectionSizeHint(0), sizeHintForColumn(0));
    int others = 0;
    for (int c = 1; c < columnCount(); ++c) {
        others += header->isSectionHidden(c) ? 0 : header->sectionSize(c);
    }
    // Shortened only where that shows every column: a table that scrolls anyway keeps its names
    // whole (three controllers cut to "Physics …" could not be told apart).
    const int room = viewport()->width() - others;
    const int width = room >= header->sectionSizeHint(0) ? std::min(natural, room) : natural;
    if (header->sectionResizeMode(0) != QHeaderView::Interactive) {
        header->setSectionResizeMode(0, QHeaderView::Interactive);
    }
    if (header->sectionSize(0) != width) {
        header->resizeSection(0, width);
    }
    if (width < natural) {
        for (int r = 0; r < rowCount(); ++r) {
            if (QTableWidgetItem* cell = item(r, 0); cell && cell->toolTip().isEmpty()) {
                cell->setToolTip(cell->text());
            }
        }
        // A name narrower than its text goes on two lines rather than being cut: "drying air
        // cooling along th…" left the engineer guessing (issue #72 item 11).
        if (!wordWrap() || textElideMode() != Qt::ElideNone) {
            setWordWrap(true);
            setTextElideMode(Qt::ElideNone);
        }
        m_namesWrapped = true;
    }
    if (m_namesWrapped) {
        resizeRowsToContents(); // one line again where the names fit once more
        m_namesWrapped = width < natural;
    }
}

void FittedTable::resizeEvent(QResizeEvent* event) {
    QTableWidget::resizeEvent(event);
    fitFirstColumn();
}

QSize FittedTable::minimumSizeHint() const {
    QSize least = QTableWidget::minimumSizeHint();
    if (m_minimumRows > 0) {
        least.setHeight(std::max(least.height(), heightForRows(this, m_minimumRows)));
    }
    return least;
}

void fitTableHeight(QTableWidget* table, int rows) {
    Q_ASSERT(table);
    if (auto* fitted = dynamic_cast<FittedTable*>(table)) {
        fitted->setMinimumRows(rows);
    } else {
        table->setMinimumHeight(heightForRows(table, rows));
    }
}

void setHeaderToolTips(QTableWidget* table, const QStringList& tips) {
    Q_ASSERT(table);
    for (int c = 0; c < tips.size() && c < table->columnCount(); ++c) {
        if (auto* item = table->horizontalHeaderItem(c); item && !tips[c].isEmpty()) {
            item->setToolTip(tips[c]);
        }
    }
}

void setTableRow(QTableWidget* table, int row, const QStringList& cells) {
    for (int c = 0; c < cells.size() && c < table->columnCount(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        item->setFlags(item->flags() & ~Qt::ItemIsEditable);
        table->setItem(row, c, item);
    }
}

QColor modelColour(const std::string& key) {
    // The two reference predictors in muted tones, the learnt models in stronger ones, PGRL-CC red.
    static const std::map<std::string, QColor> colours{
        {"pbm", QColor(127, 127, 127)},
        {"persistence", QColor(128, 128, 0)}, // olive: a light yellow dash was hard to see
        {"pbm_residual_hold", QColor(140, 86, 75)},
        {"lstm", QColor(148, 103, 189)},
        {"ext_input_residual", QColor(44, 160, 44)},
        {"pgrl_cc", QColor(214, 39, 40)},
        {"pi", QColor(31, 119, 180)}};
    const auto it = colours.find(key);
    return it == colours.end() ? QColor(23, 190, 207) : it->second;
}

QLabel* makeInlineError() {
    auto* label = new QLabel;
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #a40000;"));
    label->setTextFormat(Qt::PlainText);
    label->hide();
    return label;
}

QColor seriesColour(int i) {
    static const QColor palette[] = {QColor(31, 119, 180),  QColor(214, 39, 40),   QColor(44, 160, 44),
                                     QColor(148, 103, 189), QColor(255, 127, 14),  QColor(140, 86, 75),
                                     QColor(227, 119, 194), QColor(127, 127, 127), QColor(188, 189, 34),
                                     QColor(23, 190, 207)};
    return palette[((i % 10) + 10) % 10];
}

bool keepOnScreen(QWidget* window) {
    const QRect frame = window->frameGeometry();
    for (const QScreen* screen : QGuiApplication::screens()) {
        const QRect seen = frame.intersected(screen->availableGeometry());
        if (seen.width() >= 120 && seen.height() >= 60) {
            return false;
        }
    }
    const QScreen* primary = QGuiApplication::primaryScreen();
    if (!primary) {
        return false;
    }
    const QRect area = primary->availableGeometry();
    window->resize(window->size().boundedTo(area.size()));
    QRect placed(QPoint(0, 0), window->frameGeometry().size().boundedTo(area.size()));
    placed.moveCenter(area.center());
    window->move(placed.topLeft());
    return true;
}

} // namespace drytwin::widgets
