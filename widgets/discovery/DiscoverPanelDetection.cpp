// The Discover tab's reference period and detection against it: both detectors' verdicts, the
// monitor's T² and SPE with their limits, each column's contribution after the onset.
#include "common/EngineText.h"
#include "discovery/DiscoverPanel.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/QueuedNote.h"
#include "common/Series.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "discovery/DiscoveryNotes.h"
#include "discovery/RankingWords.h"
#include "discovery/ReferenceMenu.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

namespace drytwin::widgets {

void DiscoverPanel::showReference() {
    const QString path = m_workbench.referencePath();
    m_referenceLabel->setText(path.isEmpty() ? tr("No reference period: the data are judged alone.")
                                             : tr("Reference period: %1").arg(QFileInfo(path).fileName()));
    m_referenceLabel->setToolTip(path);
}

void DiscoverPanel::showDetection() {
    const auto& r = m_workbench.latest().discover;
    m_monitorPlots->clearCurves();
    m_contributions->setRowCount(0);
    if (!r || !r->discovery.hasReference) {
        m_detection->clear();
        m_detection->setVisible(false);
        m_monitorPlots->rescale();
        return;
    }
    const auto& det = r->discovery.detection;
    const auto describe = [&](const QString& name, const monitoring::Detection& d) {
        QString line = d.changed ? tr("%1: <b>changed</b> (p = %2)").arg(name).arg(d.pValue, 0, 'g', 2)
                                 : tr("%1: no change (p = %2)").arg(name).arg(d.pValue, 0, 'g', 2);
        if (d.changed && d.hasFirstAlarm) {
            line += tr(", first alarm in %1 at %2 min")
                        .arg(QString::fromStdString(d.firstAlarmRun).toHtmlEscaped())
                        .arg(d.firstAlarmTimeS / 60, 0, 'f', 0);
        }
        if (d.changed && d.hasOnset) {
            line += tr(", from %1 at %2 min (95 %: %3 to %4 min)")
                        .arg(QString::fromStdString(d.onsetRun).toHtmlEscaped())
                        .arg(d.onsetS / 60, 0, 'f', 0)
                        .arg(d.onsetLowS / 60, 0, 'f', 0)
                        .arg(d.onsetHighS / 60, 0, 'f', 0);
        }
        return line;
    };
    // DryTwin's detector: its monitor of the model's error, or a cause's parameter beyond its spread.
    // A p below what a double tells from 0 reads "< 1e-15", not "p = 0".
    const QString causeP = det.causeTest.pValue < 1e-15
                               ? QStringLiteral("&lt; 1e-15") /* rich text: a bare "<" opens a tag */
                               : QStringLiteral("= %1").arg(det.causeTest.pValue, 0, 'g', 2);
    const QString movedCause = causeDisplayName(det.causeTest.cause).toHtmlEscaped();
    const std::string look = det.causeTest.look();
    const QString causes =
        !det.causeTest.changed
            ? tr("DryTwin (the causes' estimates): none moved beyond its normal spread (p %1)").arg(causeP)
        : look == "screen"
            ? tr("DryTwin (the causes' one-step estimates): <b>changed</b> (p %1): %2 moved beyond its "
                 "normal spread")
                  .arg(causeP, movedCause)
        : look == "gauge_scatter"
            ? tr("DryTwin (the inlet gauge's own scatter): <b>changed</b> (p %1): %2 rose beyond the "
                 "reference's")
                  .arg(causeP, movedCause)
            : tr("DryTwin (a named cause's fitted value): <b>changed</b> (p %1): %2 moved beyond its normal "
                 "spread")
                  .arg(causeP, movedCause);
    // Conditions the reference never saw, beside the verdict they may explain.
    QString unseenConditions;
    for (const auto& n : r->discovery.notes) {
        // ... and what puts the reference itself in doubt: its own drift, a unit its files seem to
        // have wrong, an output only one period measures (Session::discover's notes).
        if (n.find("outside what the reference saw") != std::string::npos ||
            n.find("the reference period itself drifts") != std::string::npos ||
            n.rfind("the reference period: ", 0) == 0 || n.find("is measured in ") != std::string::npos) {
            unseenConditions += QStringLiteral("<br><span style=\"color:#a05a00\">%1</span>")
                                    .arg(noteText(n).toHtmlEscaped());
        }
    }
    // A cause named beyond its normal spread is a change even where the detectors, judging the
    // data set as a whole, stayed below their limits: the headline must not say "no change" beside it.
    QString namedCauses;
    for (const auto& c : det.namedCauses) {
        namedCauses += (namedCauses.isEmpty() ? QString() : tr(", ")) + causeDisplayName(c);
    }
    m_detection->setText(
        (det.changed ? tr("<b>The line has changed since the reference period.</b>")
         : det.namedChange()
             ? tr("<b>A cause has changed since the reference period: %1.</b> The detectors, judging the "
                  "data "
                  "set as a whole, stayed below their limits; fitting the causes found it beyond its normal "
                  "spread with a gain on held-out data (below). Check it on the plots.")
                   .arg(namedCauses.toHtmlEscaped())
             : tr("<b>No change against the reference period.</b>")) +
        tr(" Each detector's false-alarm rate: %1 % per data set.").arg(100 * det.falseAlarmRate, 0, 'g', 2) +
        QStringLiteral("<br>") + describe(tr("DryTwin (the model's error)"), det.drytwin) +
        QStringLiteral("<br>") + causes + QStringLiteral("<br>") +
        describe(tr("Dynamic PCA (the measured columns)"), det.pca) + unseenConditions);
    m_detection->setVisible(true);
    // The windows of both monitors, batches one after another, each statistic over its limit's
    // scale so that both detectors share one axis: above 1 is beyond the reference's 99 %.
    const auto hoursOf = [](const monitoring::Detection& d, QVector<double>& x) {
        double offset = 0, last = 0;
        std::string run;
        for (const auto& w : d.series) {
            if (w.run != run) {
                offset += last;
                run = w.run;
            }
            last = w.timeS;
            x << (offset + w.timeS) / 3600.0;
        }
    };
    for (const auto* d : {&det.drytwin, &det.pca}) {
        const bool ours = d == &det.drytwin;
        QVector<double> x, t2, spe, t2Limit, speLimit;
        hoursOf(*d, x);
        for (const auto& w : d->series) {
            t2 << w.t2;
            spe << w.spe;
        }
        const QColor colour = ours ? QColor(214, 39, 40) : QColor(31, 119, 180);
        const QString name = ours ? tr("DryTwin") : tr("dynamic PCA");
        if (ours && !x.isEmpty()) { // the limits belong to one monitor: the one the plot is named after
            m_monitorPlots->addCurve(0, tr("99 % limit"), {x.front(), x.back()},
                                     {d->limits.t2Window, d->limits.t2Window}, Qt::black, Qt::DashLine);
            m_monitorPlots->addCurve(1, tr("99 % limit"), {x.front(), x.back()},
                                     {d->limits.speWindow, d->limits.speWindow}, Qt::black, Qt::DashLine);
        }
        if (ours) {
            m_monitorPlots->addCurve(0, name, x, t2, colour);
            m_monitorPlots->addCurve(1, name, x, spe, colour);
        }
    }
    for (const auto* d : {&det.drytwin, &det.pca}) {
        if (!d->changed) {
            continue;
        }
        const QString name = d == &det.drytwin ? tr("DryTwin") : tr("dynamic PCA");
        for (std::size_t i = 0; i < d->contributions.size() && i < 6; ++i) {
            const auto& c = d->contributions[i];
            const double share = d->statistic == "SPE" ? c.speReconstructionShare : c.t2ReconstructionShare;
            const int row = m_contributions->rowCount();
            m_contributions->insertRow(row);
            setTableRow(
                m_contributions, row,
                {columnDisplayName(c.column), QStringLiteral("%1 %").arg(100 * share, 0, 'f', 0), name});
        }
    }
    fitTableWidth(m_contributions);
    m_monitorPlots->rescale();
    m_views->setCurrentIndex(det.changed ? 1 : 0);
}

} // namespace drytwin::widgets
