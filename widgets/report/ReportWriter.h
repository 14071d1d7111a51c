#pragma once

#include "common/Error.h"
#include "workflow/Session.h"

#include <QString>
#include <QStringList>

namespace drytwin::widgets {

/// @brief What the report says about how it was made (its reproducibility block).
struct ReportContext {
    QString command;                    ///< the exact command line
    std::vector<std::string> dataFiles; ///< batch files read (hashed in the report)
    /// A saved project's results file the report re-draws (`drytwin report`), named and hashed in
    /// the report; empty when the results were made by the run that writes it.
    QString resultsFile;
};

/// @brief The pipeline's report as `report.html` (self-contained, figures as inline SVG) and
/// `report.pdf`, built from the result structs of the run (not read back from files), with the
/// figures drawn by the GUI's own plot code (PlotStack) offscreen, so they look the same. Needs a
/// QApplication (the offscreen platform is enough). Returns the two paths.
Expected<QStringList> writeHtmlPdfReport(const workflow::PipelineResult& result,
                                         const std::vector<data::SiBatch>& batches,
                                         const ReportContext& context, const QString& folder);

} // namespace drytwin::widgets
