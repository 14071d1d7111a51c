// File ▸ Export report…: the pipeline's HTML and PDF report (report/ReportWriter) from what this
// window has run, so that work done in the workbench reaches a report as `drytwin pipeline` does.

#include "MainWindow.h"

#include "report/ReportWriter.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QStringList>

namespace drytwin::widgets {

QStringList MainWindow::reportMissingSteps() const {
    // The report has a section for each: a step not run would leave it empty, or worse, show
    // numbers of another model. Each named as its tab's button says it.
    const auto& latest = m_workbench.latest();
    QStringList missing;
    if (!m_workbench.hasData()) {
        missing << tr("open data");
    }
    if (!latest.calibrate) {
        missing << tr("Calibrate");
    }
    if (!latest.evaluate) {
        missing << tr("Learn the correction models (Residual model tab)");
    }
    if (!latest.ablation) {
        missing << tr("Ablation (Residual model tab)");
    }
    if (!latest.discover) {
        missing << tr("Discover");
    }
    if (!latest.mpc) {
        missing << tr("Run scenario (What-if MPC tab)");
    }
    return missing;
}

Expected<QStringList> MainWindow::exportReport(const QString& folder) const {
    if (const QStringList missing = reportMissingSteps(); !missing.isEmpty()) {
        return Error{ErrorKind::Usage, tr("Export report").toStdString(),
                     tr("the report needs every step's result; still to run: %1")
                         .arg(missing.join(QStringLiteral(", ")))
                         .toStdString()};
    }
    if (!QDir().mkpath(folder)) {
        return Error{ErrorKind::BadInput, folder.toStdString(), tr("cannot create the folder").toStdString()};
    }
    const auto& latest = m_workbench.latest();
    workflow::PipelineResult r;
    r.inspect = m_workbench.summary();
    r.calibrate = *latest.calibrate;
    if (latest.train) {
        r.train = *latest.train;
    }
    r.evaluate = *latest.evaluate;
    r.ablation = *latest.ablation;
    r.discover = *latest.discover;
    r.mpc = *latest.mpc;
    ReportContext context;
    // What a reader needs to redo it: the data and model files the window worked on.
    context.command = tr("DryTwin workbench: data %1, model %2")
                          .arg(QDir::toNativeSeparators(QFileInfo(m_workbench.dataPath()).absoluteFilePath()),
                               m_workbench.modelPath().isEmpty()
                                   ? tr("as built in this window (save it with File ▸ Save model as…)")
                                   : QDir::toNativeSeparators(m_workbench.modelPath()));
    if (const auto data = m_workbench.dataSet()) {
        for (const auto& b : data->batches) {
            context.dataFiles.push_back(b.sourcePath);
        }
    }
    return writeHtmlPdfReport(r, m_workbench.siBatches(), context, folder);
}

void MainWindow::askAndExportReport() {
    // Before the folder is asked for: the same message exportReport() would give.
    if (!reportMissingSteps().isEmpty()) {
        showError(tr("Export report"), QString::fromStdString(exportReport(QString()).error().message()));
        return;
    }
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export report into folder"));
    if (folder.isEmpty()) {
        return;
    }
    const auto files = exportReport(folder);
    if (!files) {
        showError(tr("Export report"), QString::fromStdString(files.error().message()));
        return;
    }
    m_statusLabel->setText(
        tr("Report written: %1").arg(QDir::toNativeSeparators(files->join(QStringLiteral(", ")))));
}

} // namespace drytwin::widgets
