// Plots without data and tables' headers (issue #43, items 12 and 17): an empty plot shows its
// quantity's range or says it has no data, never Qwt's made-up 0–1000; the export takes its format
// from the filter chosen in the dialog; every column is as wide as its header.
#include "MainWindow.h"
#include "calibration/CalibrationPanel.h"
#include "common/PlotStack.h"
#include "common/Translations.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "training/TrainingPanel.h"
#include "workflow/Session.h"

#include <QApplication>
#include <QFileDialog>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <qwt_legend.h>
#include <qwt_legend_label.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_scale_div.h>

using namespace drytwin;
using namespace drytwin::widgets;

namespace {

double yUpper(const QwtPlot* plot) {
    return plot->axisScaleDiv(QwtPlot::yLeft).upperBound();
}
double xUpper(const QwtPlot* plot) {
    return plot->axisScaleDiv(QwtPlot::xBottom).upperBound();
}

/// The width a header's text needs, as QHeaderView measures it (bold), its widest line.
int headerTextWidth(const QHeaderView* header, const QString& text) {
    QFont font = header->font();
    font.setBold(true);
    const QFontMetrics fm(font);
    int w = 0;
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        w = std::max(w, fm.horizontalAdvance(line));
    }
    return w;
}

/// Every column of every table under @p root whose header is cut: "table/column: width < need".
QStringList cutHeaders(QWidget* root) {
    QStringList cut;
    for (auto* table : root->findChildren<QTableWidget*>()) {
        if (!table->isVisibleTo(root)) {
            continue;
        }
        const QHeaderView* header = table->horizontalHeader();
        for (int c = 0; c < table->columnCount(); ++c) {
            const auto* item = table->horizontalHeaderItem(c);
            if (!item || header->isSectionHidden(c)) {
                continue;
            }
            const int need = headerTextWidth(header, item->text());
            // Cut by its own width, or by the table's edge (a table not at its widest shows all
            // its columns; only one that asked for kMaxFittedTableWidth may scroll). What a table
            // asks for is its preferred width (a FittedTable's size hint; it may be squeezed on a
            // small screen), or its least width (another table).
            const int asked =
                dynamic_cast<const FittedTable*>(table) ? table->sizeHint().width() : table->minimumWidth();
            const bool pastTheEdge =
                asked < kMaxFittedTableWidth &&
                header->sectionViewportPosition(c) + header->sectionSize(c) > table->viewport()->width();
            if (header->sectionSize(c) < need || pastTheEdge) {
                cut << QStringLiteral("%1/%2: %3 < %4")
                           .arg(table->horizontalHeaderItem(0) ? table->horizontalHeaderItem(0)->text()
                                                               : QString())
                           .arg(item->text())
                           .arg(header->sectionSize(c))
                           .arg(need);
            }
        }
    }
    return cut;
}

} // namespace

class TestPlotStack : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // Item 12: the Training tab before a session runs: each plot shows its quantity's range.
    void emptyTrainingPlotsShowTheirQuantitysRange() {
        Workbench wb;
        TrainingPanel panel(wb);
        panel.resize(1200, 800);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        PlotStack* plots = panel.plots();
        QVERIFY(plots->plot(0)->axisEnabled(QwtPlot::yLeft));
        QVERIFY2(yUpper(plots->plot(0)) < 100 && yUpper(plots->plot(0)) > 5,
                 qPrintable(QString::number(yUpper(plots->plot(0))))); // X_out [% wb]
        QVERIFY(yUpper(plots->plot(1)) < 400);                         // T_hot [°C]
        for (int i = 0; i < plots->plotCount(); ++i) {
            QVERIFY2(yUpper(plots->plot(i)) != 1000.0, qPrintable(QString::number(i)));
        }
        QVERIFY(xUpper(plots->plot(plots->plotCount() - 1)) <= 60); // minutes of the window
        QCOMPARE(plots->plot(plots->plotCount() - 1)->axisTitle(QwtPlot::xBottom).text(),
                 QString("session time [min]"));
        QVERIFY(plots->showsEmptyText());
        QVERIFY(yUpper(panel.truthPlots()->plot(0)) < 100);
    }

    // Item 12: while Calibrate runs only the loss comes in; the parameters' plot keeps a sensible
    // axis and says when its points come.
    void calibrationParameterPlotWhileItRuns() {
        Workbench wb;
        CalibrationPanel panel(wb);
        panel.resize(1200, 800);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        Q_EMIT wb.calibrationProgress(0.1, 3.0);
        Q_EMIT wb.calibrationProgress(0.3, 2.0);
        PlotStack* loss = panel.lossPlot();
        QCOMPARE(loss->curveCount(0), 1);
        QCOMPARE(loss->curveCount(1), 0);
        QVERIFY2(yUpper(loss->plot(1)) <= 2.5, qPrintable(QString::number(yUpper(loss->plot(1)))));
        QVERIFY(loss->noteShown(1).contains("calibration ends"));
        QVERIFY(loss->noteShown(0).isEmpty());
        // The bottom plot labels the shared time axis: the loss's, not 0–1000.
        QVERIFY2(xUpper(loss->plot(1)) <= 1.5, qPrintable(QString::number(xUpper(loss->plot(1)))));
    }

    // A legend's key is the curve's line (a setpoint dashed, its band dotted, a prediction
    // dash-dot), and every entry's text starts after its key: the last entry added kept an indent
    // of 2 px and wrote its text over the key (the Training tab's "T² of the model's error").
    void legendKeysShowTheLineAndTextFollowsThem() {
        PlotStack s;
        s.addPlot("a [-]");
        s.addPlot("b [-]");
        s.resize(700, 400);
        s.show();
        s.addCurve(0, "setpoint", {0, 10}, {1, 1}, Qt::black, Qt::DashLine);
        s.addCurve(0, "band", {0, 10}, {2, 2}, Qt::black, Qt::DotLine);
        s.addCurve(1, "only on the lower plot, a long name", {0, 10}, {5, 6}, Qt::blue);
        auto* legend = qobject_cast<QwtLegend*>(s.plot(0)->legend());
        QVERIFY(legend);
        const auto labels = legend->findChildren<QwtLegendLabel*>();
        QCOMPARE(labels.size(), 3);
        for (const auto* label : labels) {
            QVERIFY2(label->indent() >= 22,
                     qPrintable(label->text().text() + ": indent " + QString::number(label->indent())));
        }
        for (auto* item : s.plot(0)->itemList(QwtPlotItem::Rtti_PlotCurve)) {
            QVERIFY(static_cast<QwtPlotCurve*>(item)->testLegendAttribute(QwtPlotCurve::LegendShowLine));
        }
    }

    // Item 12: a plot without data and without a known range hides its y-axis and says so.
    void anEmptyPlotSaysSo() {
        PlotStack s;
        s.addPlot("a [-]");
        s.addPlot("b [-]");
        s.resize(600, 400);
        s.show();
        s.addCurve(0, "a", {0, 10, 20}, {1, 2, 3}, Qt::red);
        s.rescale();
        QVERIFY(!s.plot(1)->axisEnabled(QwtPlot::yLeft));
        QCOMPARE(s.noteShown(1), QString("No data yet"));
        QVERIFY(xUpper(s.plot(1)) <= 25); // the time axis of the plot with data
        s.setEmptyRange(1, -1, 1);
        QVERIFY(s.plot(1)->axisEnabled(QwtPlot::yLeft));
        QCOMPARE(yUpper(s.plot(1)), 1.0);
        s.addCurve(1, "b", {0, 10}, {5, 6}, Qt::blue);
        s.rescale();
        QVERIFY(s.noteShown(1).isEmpty());
        QVERIFY(yUpper(s.plot(1)) >= 6);
        // The stack's own text, while no plot has data, is said once, on the first plot.
        PlotStack none;
        none.addPlot("a [-]");
        none.addPlot("b [-]");
        none.setEmptyText("Open a data set");
        none.show();
        QCOMPARE(none.noteShown(0), QString("Open a data set"));
        QVERIFY(none.noteShown(1).isEmpty());
        // Data on the second plot alone takes the stack's text away from the first.
        none.addCurve(1, "b", {0, 1}, {1, 2}, Qt::blue);
        QVERIFY2(none.noteShown(0) != QString("Open a data set"), qPrintable(none.noteShown(0)));
    }

    void filterSuffix_data() {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("filter");
        QTest::addColumn<QString>("expected");
        const QString all = "PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf);;Data as CSV (*.csv)";
        QTest::newRow("no extension, CSV") << "/x/foo"
                                           << "Data as CSV (*.csv)"
                                           << "/x/foo.csv";
        QTest::newRow("no extension, PDF") << "/x/foo"
                                           << "PDF (*.pdf)"
                                           << "/x/foo.pdf";
        QTest::newRow("extension typed") << "/x/foo.svg"
                                         << "Data as CSV (*.csv)"
                                         << "/x/foo.svg";
        QTest::newRow("upper case") << "/x/foo.PNG"
                                    << "PDF (*.pdf)"
                                    << "/x/foo.PNG";
        QTest::newRow("a dot in the name") << "/x/run.2"
                                           << "Data as CSV (*.csv)"
                                           << "/x/run.2.csv";
        Q_UNUSED(all);
    }
    void filterSuffix() {
        QFETCH(QString, typed);
        QFETCH(QString, filter);
        QFETCH(QString, expected);
        const QString all = "PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf);;Data as CSV (*.csv)";
        QCOMPARE(withFilterSuffix(typed, filter, all), expected);
    }

    // Item 17: "Data as CSV" chosen in the export dialog, "foo" typed: foo.csv is written.
    void exportWithTheCsvFilterAndNoExtension() {
        QTemporaryDir dir;
        PlotStack s;
        s.addPlot("X_out [% wb]");
        s.addCurve(0, "measured", {0, 1, 2}, {12.0, 12.5, 13.0}, Qt::red);
        s.rescale();
        s.show();
        QPushButton* exportButton = nullptr;
        for (auto* b : s.findChildren<QPushButton*>()) {
            if (b->text().startsWith("Export")) {
                exportButton = b;
            }
        }
        QVERIFY(exportButton);
        bool answered = false;
        QTimer::singleShot(300, [&] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!dialog) {
                return;
            }
            // As a user does: choose the filter, then type a name without an extension.
            dialog->selectNameFilter("Data as CSV (*.csv)");
            dialog->setDirectory(dir.path());
            auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
            if (!name) {
                return;
            }
            name->setText("foo");
            answered = true;
            static_cast<QDialog*>(dialog)->accept(); // QFileDialog::accept(), through the public slot
        });
        QTest::mouseClick(exportButton, Qt::LeftButton);
        QVERIFY(answered);
        QVERIFY2(QFileInfo::exists(dir.filePath("foo.csv")), qPrintable(s.readout()));
        QFile f(dir.filePath("foo.csv"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readLine().startsWith("plot,curve,"));
        QVERIFY(s.readout().contains("foo.csv"));
    }

    // Bars drawn beside their lag (two correlates at one lag, side by side) are exported at the
    // lag itself: the CSV holds the data, not the drawing's nudge.
    void aCurveDrawnBesideItsDataIsExportedAtItsData() {
        QTemporaryDir dir;
        PlotStack s;
        s.addPlot("ccf [-]");
        auto* bar = s.addCurve(0, "inlet moisture", {10.6, 10.6}, {0.0, 0.3}, Qt::red);
        s.setDrawnXOffset(bar, 0.6);
        s.addCurve(0, "hot air", {9.4, 9.4}, {0.0, -0.2}, Qt::blue);
        QVERIFY(s.exportTo(dir.filePath("ccf.csv")));
        QFile f(dir.filePath("ccf.csv"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains("\"inlet moisture\",10,0.3"), qPrintable(text));
        QVERIFY2(text.contains("\"hot air\",9.4,-0.2"), qPrintable(text));
        s.clearCurves(); // the nudge goes with its curve
        auto* again = s.addCurve(0, "inlet moisture", {10.6, 10.6}, {0.0, 0.3}, Qt::red);
        Q_UNUSED(again);
        QVERIFY(s.exportTo(dir.filePath("again.csv")));
        QFile g(dir.filePath("again.csv"));
        QVERIFY(g.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(g.readAll()).contains("\"inlet moisture\",10.6,0.3"));
    }

    // A results table narrower than its columns gives up the width of its first column (the
    // names), down to that column's header, before it scrolls: the numbers beside the names show
    // (at 1280 x 800 the What-if table's solve times lay beyond the edge). A name cut short keeps
    // its whole text as a tooltip; with room again the column is as wide as its names.
    void aNarrowTableShortensItsNamesBeforeItScrolls() {
        QWidget host;
        auto* table = makeResultTable(
            {"Controller", "IAE [% wb·s]", "Effort [K²]", "Violations [%]", "Solve median [ms]"});
        table->setParent(&host);
        const QStringList names{"Physics model", "Physics + input-only correction", "LSTM (black box)",
                                "Physics + learnt correction (PGRL-CC)", "PI loop (the plant's own)"};
        table->setRowCount(static_cast<int>(names.size()));
        for (int r = 0; r < names.size(); ++r) {
            setTableRow(table, r, {names[r], "303.2", "1102.4", "14.9", "3.02"});
        }
        fitTableWidth(table);
        host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&host));
        const QHeaderView* header = table->horizontalHeader();

        // With room, the names are whole.
        table->resize(1600, 260);
        QCoreApplication::processEvents();
        const int natural = header->sectionSize(0);
        const int wide = header->length() + table->width() - table->viewport()->width(); // every column whole
        QVERIFY2(natural >= table->fontMetrics().horizontalAdvance(names[3]),
                 qPrintable(QString::number(natural)));
        QVERIFY(natural > header->sectionSizeHint(0) + 40);

        table->resize(wide - 120, 260); // 120 px short of showing every column at full width
        QCoreApplication::processEvents();
        const int last = table->columnCount() - 1;
        QVERIFY2(header->sectionViewportPosition(last) + header->sectionSize(last) <=
                     table->viewport()->width(),
                 qPrintable(QStringLiteral("last column ends at %1 of %2 px")
                                .arg(header->sectionViewportPosition(last) + header->sectionSize(last))
                                .arg(table->viewport()->width())));
        QCOMPARE(table->horizontalScrollBar()->maximum(), 0);
        QVERIFY(header->sectionSize(0) < natural);
        QVERIFY(header->sectionSize(0) >= header->sectionSizeHint(0)); // its header stays whole
        QCOMPARE(table->item(3, 0)->toolTip(), names[3]);
        for (int c = 1; c <= last; ++c) { // the numbers whole: each as wide as its header and cells
            QVERIFY(header->sectionSize(c) >= header->sectionSizeHint(c));
            QVERIFY(header->sectionSize(c) >=
                    table->fontMetrics().horizontalAdvance(table->item(0, c)->text()));
        }

        table->resize(1600, 260); // and whole again with room
        QCoreApplication::processEvents();
        QCOMPARE(header->sectionSize(0), natural);

        // So narrow that the numbers would not show even beside the names' header: the table
        // scrolls and keeps its names whole (three controllers cut to "Physics …" could not be
        // told apart).
        table->resize(200, 260);
        QCoreApplication::processEvents();
        QCOMPARE(header->sectionSize(0), natural);
        QVERIFY(table->horizontalScrollBar()->maximum() > 0);
    }

    // Item 17: every table's columns are as wide as their headers, in English and in Chinese, with
    // data and results in them.
    void headersFitTheirColumns_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << "en";
        QTest::newRow("zh_CN") << "zh_CN";
    }
    void headersFitTheirColumns() {
        QFETCH(QString, language);
        QVERIFY(setLanguage(language) || language == "en");
        QTemporaryDir dir;
        workflow::GenerateOptions g;
        g.plant = plant::PlantOptions::demo(5, plant::PlantKind::Lumped);
        g.plant.batches = 2;
        g.plant.samples = 900;
        g.outFolder = dir.filePath("plant").toStdString();
        QVERIFY(workflow::Session().generate(g).ok());
        {
            MainWindow w;
            w.resize(1280, 800);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QSignalSpy loaded(&w, &MainWindow::loadFinished);
            w.openDataSet(dir.filePath("plant"));
            QVERIFY(loaded.wait(30000));
            QTRY_VERIFY_WITH_TIMEOUT(!w.jobs().busy(), 60000);
            for (int i = 0; i < w.tabs()->count(); ++i) {
                w.tabs()->setCurrentIndex(i);
                QTest::qWait(50);
                const QStringList cut = cutHeaders(w.tabs()->widget(i));
                QVERIFY2(cut.isEmpty(), qPrintable(w.tabs()->tabText(i) + ": " + cut.join("; ")));
            }
        }
        setLanguage("en");
    }
};

QTEST_MAIN(TestPlotStack)
#include "TestPlotStack.moc"
