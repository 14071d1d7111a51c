#include "MainWindow.h"

#include "common/ErrorText.h"
#include "common/LibraryVersions.h"
#include "common/Units.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <qwt_global.h>
#include <qwt_legend.h>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_grid.h>
#include <vtkVersion.h>

// The widgets are a static library: its resources (window icon) must be registered by hand,
// and Q_INIT_RESOURCE must be called outside any namespace.
static void initDryTwinResources() {
    Q_INIT_RESOURCE(drytwin);
}

namespace drytwin::widgets {

namespace {

QwtPlotCurve* addModelCurve(QwtPlot* plot, const QString& title, const QColor& colour) {
    auto* curve = new QwtPlotCurve(title);
    curve->setPen(colour, 1.6, Qt::DashLine);
    curve->setRenderHint(QwtPlotItem::RenderAntialiased);
    curve->attach(plot);
    return curve;
}

QwtPlot* makePlot(const QString& yTitle, QwtPlotCurve*& curve, const QColor& colour, QWidget* parent) {
    auto* plot = new QwtPlot(parent);
    plot->setCanvasBackground(Qt::white);
    plot->setAxisTitle(QwtPlot::xBottom, QObject::tr("time [s]"));
    plot->setAxisTitle(QwtPlot::yLeft, yTitle);
    auto* grid = new QwtPlotGrid;
    grid->setMajorPen(QColor(220, 220, 220), 0, Qt::DotLine);
    grid->attach(plot);
    curve = new QwtPlotCurve(QObject::tr("measured"));
    curve->setPen(colour, 1.2);
    curve->setRenderHint(QwtPlotItem::RenderAntialiased);
    curve->attach(plot);
    return plot;
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("DryTwin"));
    initDryTwinResources();
    setWindowIcon(QIcon(QStringLiteral(":/icons/drytwin.svg")));
    resize(1200, 760);

    m_batchList = new QListWidget;
    m_batchList->setMinimumWidth(180);
    m_columnTable = new QTreeWidget;
    m_columnTable->setHeaderLabels(
        {tr("Column"), tr("Unit"), tr("Min"), tr("Max"), tr("Mean"), tr("Missing")});
    m_columnTable->setRootIsDecorated(false);

    auto* plots = new QWidget;
    auto* plotLayout = new QVBoxLayout(plots);
    m_moisturePlot =
        makePlot(tr("outlet moisture X_out [% wb]"), m_moistureCurve, QColor(31, 119, 180), plots);
    m_temperaturePlot =
        makePlot(tr("outlet temperature T_out [°C]"), m_temperatureCurve, QColor(214, 39, 40), plots);
    m_moistureModelCurve = addModelCurve(m_moisturePlot, tr("physics model (default parameters)"), Qt::black);
    m_temperatureModelCurve =
        addModelCurve(m_temperaturePlot, tr("physics model (default parameters)"), Qt::black);
    for (auto* plot : {m_moisturePlot, m_temperaturePlot}) {
        plot->insertLegend(new QwtLegend, QwtPlot::TopLegend);
    }
    plotLayout->addWidget(m_moisturePlot);
    plotLayout->addWidget(m_temperaturePlot);

    auto* tabs = new QTabWidget;
    tabs->addTab(plots, tr("Batch plots"));
    tabs->addTab(m_columnTable, tr("Columns"));

    auto* splitter = new QSplitter;
    splitter->addWidget(m_batchList);
    splitter->addWidget(tabs);
    splitter->setStretchFactor(1, 1);
    setCentralWidget(splitter);

    m_statusLabel = new QLabel(tr("No data loaded. File ▸ Open data set…"));
    m_progressBar = new QProgressBar;
    m_progressBar->setMaximumWidth(200);
    m_progressBar->setRange(0, 100);
    m_cancelButton = new QPushButton(tr("Cancel"));
    statusBar()->addWidget(m_statusLabel, 1);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    setBusy(false);

    createMenus();

    connect(&m_jobs, &JobRunner::progress, this, &MainWindow::onProgress);
    connect(&m_jobs, &JobRunner::busyChanged, this, &MainWindow::setBusy);
    connect(m_cancelButton, &QPushButton::clicked, this, [this] { m_jobs.cancelAll(); });
    connect(m_batchList, &QListWidget::currentRowChanged, this, &MainWindow::onBatchSelected);
}

// The job runner's destructor cancels every job and waits for the engine thread.
MainWindow::~MainWindow() = default;

void MainWindow::createMenus() {
    auto* file = menuBar()->addMenu(tr("&File"));
    auto* openFile = file->addAction(tr("&Open batch file…"), this, &MainWindow::chooseFile);
    openFile->setShortcut(QKeySequence::Open);
    file->addAction(tr("Open data set &folder…"), this, &MainWindow::chooseFolder);
    file->addSeparator();
    auto* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    auto* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About DryTwin"), this, &MainWindow::showAbout);
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

QString MainWindow::aboutText() {
    QString html = tr("<h3>DryTwin %1</h3><p>Digital-twin workbench for pneumatic drying lines, "
                      "implementing the PGRL-CC method.</p><table>")
                       .arg(QString::fromStdString(dryTwinVersion()));
    auto row = [&](const QString& name, const QString& version) {
        html += QStringLiteral("<tr><td>%1</td><td>&nbsp;%2</td></tr>")
                    .arg(name.toHtmlEscaped(), version.toHtmlEscaped());
    };
    row(QStringLiteral("Qt"), QString::fromLatin1(qVersion()));
    row(QStringLiteral("Qwt"), QStringLiteral(QWT_VERSION_STR));
    row(QStringLiteral("VTK"), QString::fromLatin1(vtkVersion::GetVTKVersion()));
    for (const auto& [name, version] : engineLibraryVersions()) {
        row(QString::fromStdString(name), QString::fromStdString(version));
    }
    html += QStringLiteral("</table>");
    return html;
}

void MainWindow::showAbout() {
    QMessageBox::about(this, tr("About DryTwin"), aboutText());
}

void MainWindow::chooseFile() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open batch file"), {}, tr("Batch files (*.csv)"));
    if (!path.isEmpty()) {
        openDataSet(path);
    }
}

void MainWindow::chooseFolder() {
    const QString path = QFileDialog::getExistingDirectory(this, tr("Open data set folder"));
    if (!path.isEmpty()) {
        openDataSet(path);
    }
}

void MainWindow::openDataSet(const QString& path) {
    m_statusLabel->setText(tr("Loading %1…").arg(path));
    workflow::OpenOptions options;
    options.dataPath = path.toStdString();
    m_jobs.submit<workflow::OpenResult>(
        tr("Load %1").arg(path),
        [options](workflow::Session& session, const Progress& progress) {
            return session.open(options, progress);
        },
        this,
        [this, path](const Expected<workflow::OpenResult>& result) {
            if (result) {
                onDataLoaded(path, *result);
            } else {
                onLoadFailed(path, result.error());
            }
        });
}

void MainWindow::setBusy(bool busy) {
    m_progressBar->setVisible(busy);
    m_cancelButton->setVisible(busy);
    if (!busy) {
        m_progressBar->setValue(0);
    }
}

void MainWindow::onProgress(JobId, const QString& stage, double fraction, const QString& detail) {
    m_progressBar->setValue(static_cast<int>(fraction * 100));
    if (!detail.isEmpty()) {
        const QString what = stage == QLatin1String("simulate") ? tr("Simulating %1…") : tr("Loading %1…");
        m_statusLabel->setText(what.arg(detail));
    }
}

void MainWindow::onDataLoaded(const QString& path, const workflow::OpenResult& result) {
    const auto& summary = result.summary;
    m_data = result.dataSet;
    m_batchList->clear();
    for (const auto& b : summary.batches) {
        m_batchList->addItem(tr("%1  (%2 rows)").arg(QString::fromStdString(b.id)).arg(b.rows));
    }
    m_columnTable->clear();
    for (const auto& c : summary.columns) {
        auto* item = new QTreeWidgetItem(m_columnTable);
        item->setText(0, QString::fromStdString(c.name));
        item->setText(1, QString::fromStdString(c.unit));
        if (c.present) {
            item->setText(2, QString::number(c.min, 'g', 5));
            item->setText(3, QString::number(c.max, 'g', 5));
            item->setText(4, QString::number(c.mean, 'g', 5));
            item->setText(5, QString::number(c.missing));
        } else {
            item->setText(2, tr("absent"));
        }
    }
    m_columnTable->header()->resizeSections(QHeaderView::ResizeToContents);
    m_dataStatus = tr("%1: %2 batches, %3 rows, %4 missing cells; cleaning keeps %5 rows")
                       .arg(path)
                       .arg(summary.batches.size())
                       .arg(summary.rows)
                       .arg(summary.missing)
                       .arg(summary.cleaning.kept);
    m_statusLabel->setText(m_dataStatus);
    m_modelX.clear();
    m_modelT.clear();
    if (m_batchList->count() > 0) {
        m_batchList->setCurrentRow(0);
    }
    Q_EMIT loadFinished(true);
    simulate();
}

void MainWindow::onLoadFailed(const QString& path, const Error& error) {
    if (error.kind == ErrorKind::Cancelled) {
        m_statusLabel->setText(tr("Loading cancelled; the data shown before is unchanged."));
        Q_EMIT loadFinished(false);
        return;
    }
    m_statusLabel->setText(tr("Could not load %1; the data shown before is unchanged.").arg(path));
    QStringList errors;
    for (const auto& cause : error.causes) {
        errors << errorText(cause);
    }
    if (errors.isEmpty()) {
        errors << errorText(error);
    }
    QMessageBox box(QMessageBox::Warning, tr("Data set rejected"),
                    tr("%n file(s) could not be read. Nothing was loaded or changed.", nullptr,
                       static_cast<int>(errors.size())),
                    QMessageBox::Ok, this);
    box.setDetailedText(errors.join(QLatin1Char('\n')));
    box.setInformativeText(errors.value(0));
    if (!qEnvironmentVariableIsSet("DRYTWIN_NO_MODAL")) {
        box.exec();
    }
    Q_EMIT loadFinished(false);
}

void MainWindow::simulate() {
    m_jobs.submit<workflow::SimulateResult>(
        tr("Simulate"),
        [](workflow::Session& session, const Progress& progress) { return session.simulate({}, progress); },
        this,
        [this](const Expected<workflow::SimulateResult>& result) {
            if (result) {
                onSimulated(*result);
            } else if (result.error().kind == ErrorKind::Cancelled) {
                m_statusLabel->setText(m_dataStatus + tr("; simulation cancelled"));
            } else {
                m_statusLabel->setText(
                    tr("The physics model failed on this data: %1").arg(errorText(result.error())));
            }
        });
}

void MainWindow::onSimulated(const workflow::SimulateResult& result) {
    // Outlet predictions in the file units the plots show (% wb, °C).
    m_modelX.clear();
    m_modelT.clear();
    for (const auto& r : result.simulations) {
        QVector<double> xb, tb;
        xb.reserve(static_cast<int>(r.xOutDb.size()));
        tb.reserve(static_cast<int>(r.tOutK.size()));
        for (std::size_t k = 0; k < r.xOutDb.size(); ++k) {
            xb.push_back(units::dryToWetPct(r.xOutDb[k]));
            tb.push_back(units::kelvinToCelsius(r.tOutK[k]));
        }
        m_modelX.push_back(xb);
        m_modelT.push_back(tb);
    }
    m_statusLabel->setText(m_dataStatus + tr("; physics model (default parameters) shown dashed"));
    showBatch(m_batchList->currentRow());
    Q_EMIT simulationShown();
}

void MainWindow::onBatchSelected(int row) {
    showBatch(row);
}

void MainWindow::showBatch(int row) {
    if (!m_data || row < 0 || static_cast<std::size_t>(row) >= m_data->batches.size()) {
        return;
    }
    const auto& b = m_data->batches[static_cast<std::size_t>(row)];
    const auto* t = b.values(data::Column::Time);
    const auto* x = b.values(data::Column::XOut);
    const auto* temp = b.values(data::Column::TOut);
    if (t && x) {
        m_moistureCurve->setSamples(t->data(), x->data(), static_cast<int>(t->size()));
    }
    if (t && temp) {
        m_temperatureCurve->setSamples(t->data(), temp->data(), static_cast<int>(t->size()));
    }
    const auto r = static_cast<int>(row);
    if (t && r < m_modelX.size() && m_modelX[r].size() == static_cast<int>(t->size())) {
        m_moistureModelCurve->setSamples(t->data(), m_modelX[r].constData(), m_modelX[r].size());
        m_temperatureModelCurve->setSamples(t->data(), m_modelT[r].constData(), m_modelT[r].size());
    } else {
        m_moistureModelCurve->setSamples(QVector<QPointF>());
        m_temperatureModelCurve->setSamples(QVector<QPointF>());
    }
    m_moisturePlot->replot();
    m_temperaturePlot->replot();
}

} // namespace drytwin::widgets
