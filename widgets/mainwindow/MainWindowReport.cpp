// File ▸ Export report…: the pipeline's HTML and PDF report (report/ReportWriter) from what this
// window has run, so that work done in the workbench reaches a report as `drytwin pipeline` does.

#include "MainWindow.h"
#include "common/ErrorText.h"

#include "report/ReportWriter.h"
#include "workflow/ProjectFile.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMap>
#include <QStringList>

namespace drytwin::widgets {

QStringList MainWindow::reportMissingSteps() const {
    // The report has a section for each: a step not run would leave it empty, or worse, show
    // numbers of another model. Each named as its tab's button says it.
    QStringList missing;
    if (!m_workbench.hasData()) {
        missing << tr("open data");
    }
    const QMap<QString, QString> buttons{
        {QStringLiteral("calibrate"), tr("Calibrate")},
        {QStringLiteral("train"), tr("Learn the correction models (Residual model tab)")},
        {QStringLiteral("evaluate"), tr("Learn the correction models (Residual model tab)")},
        {QStringLiteral("ablation"), tr("Ablation (Residual model tab)")},
        {QStringLiteral("discover"), tr("Discover")},
        {QStringLiteral("mpc"), tr("Run scenario (What-if MPC tab)")}};
    for (const auto& step : workflow::stepsMissingForReport(m_workbench.latest())) {
        if (const QString button = buttons.value(QString::fromStdString(step)); !missing.contains(button)) {
            missing << button; // train and evaluate are one button
        }
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
    auto r = workflow::reportInputs(m_workbench.latest(), m_workbench.summary());
    if (!r) {
        return r.error();
    }
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
    return writeHtmlPdfReport(*r, m_workbench.siBatches(), context, folder);
}

void MainWindow::askAndExportReport() {
    // Before the folder is asked for: the same message exportReport() would give.
    if (!reportMissingSteps().isEmpty()) {
        showError(tr("Export report"), errorText(exportReport(QString()).error()));
        return;
    }
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export report into folder"));
    if (folder.isEmpty()) {
        return;
    }
    const auto files = exportReport(folder);
    if (!files) {
        showError(tr("Export report"), errorText(files.error()));
        return;
    }
    m_statusLabel->setText(
        tr("Report written: %1").arg(QDir::toNativeSeparators(files->join(QStringLiteral(", ")))));
}

} // namespace drytwin::widgets
