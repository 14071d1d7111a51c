// The Training tab's frames: what the line, the score and the monitor show at each frame, the
// scrolling plots and the instructor's marks of faults and answers.
#include "training/TrainingPanel.h"

#include "common/DisplayNames.h"
#include "common/PlotStack.h"
#include "common/WidgetHelpers.h"
#include "common/Workbench.h"
#include "control/BundledScenarios.h"
#include "control/ClosedLoop.h"
#include "training/FaultWords.h"
#include "training/TrainingPanelInternal.h"
#include "training/TrainingRunner.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <qwt_plot.h>
#include <qwt_plot_curve.h>
#include <qwt_plot_marker.h>
#include <qwt_text.h>
#include <utility>

namespace drytwin::widgets {

using namespace training_panel;

void TrainingPanel::showFrame() {
    const TrainingFrame& f = m_runner->frame();
    if (!f.started) {
        return;
    }
    setLongWork(false);
    if (m_opening && f.opened) {
        m_opening = false;
        QString text =
            tr("Session reopened at %1, frozen: the instructor resumes it.").arg(clockText(f.timeS));
        if (!f.openNote.isEmpty()) {
            text += QLatin1Char(' ') + modelDiffersText(f.openNote);
        }
        m_note->setText(text);
        Q_EMIT sessionOpenFinished(m_openingFile, true, {});
    }
    QString state = f.finished ? tr("finished") : f.frozen ? tr("FROZEN") : tr("running %1×").arg(f.speed);
    m_clock->setText(
        tr("%1  t = %2 / %3  (%4)").arg(f.scenarioName, clockText(f.timeS), clockText(f.endS), state));
    m_freeze->setText(f.frozen ? tr("Resume") : tr("Freeze"));
    m_pause->setText(f.frozen ? tr("Continue") : tr("Pause"));
    if (!m_setpoint->hasFocus()) {
        m_setpoint->setValue(f.setpointPct);
    }
    const int ci = m_controller->findData(static_cast<int>(f.controller));
    if (ci >= 0 && !m_controller->view()->isVisible()) {
        m_controller->setCurrentIndex(ci);
    }
    m_controllerNote->setText(
        f.controllerNote.isEmpty()
            ? tr("Setpoint %1 % wb, band ±%2 % wb").arg(f.setpointPct, 0, 'f', 2).arg(f.bandPct)
            : tr("MPC fell back: %1").arg(f.controllerNote));
    m_answers->clear();
    for (const auto& a : f.answers) {
        const auto m = plant::mechanismByName(a.cause);
        m_answers->addItem(tr("%1  %2").arg(clockText(a.atS), m ? mechanismLabel(*m) : tr("No fault")));
    }
    const QString selected =
        m_snapshots->currentItem() ? m_snapshots->currentItem()->data(Qt::UserRole).toString() : QString();
    m_snapshots->clear();
    for (const auto& s : f.snapshots) {
        auto* item =
            new QListWidgetItem(tr("%1 (at %2)").arg(QString::fromStdString(s.label), clockText(s.atS)));
        item->setData(Qt::UserRole, QString::fromStdString(s.label));
        m_snapshots->addItem(item);
        if (item->data(Qt::UserRole).toString() == selected) {
            m_snapshots->setCurrentItem(item);
        }
    }
    m_faults->setRowCount(static_cast<int>(f.faults.size()));
    for (std::size_t i = 0; i < f.faults.size(); ++i) {
        const auto& fault = f.faults[i];
        const auto scored = std::find_if(f.score.faults.begin(), f.score.faults.end(), [&](const auto& fs) {
            return fs.fault.mechanism == fault.mechanism && fs.fault.onsetS == fault.onsetS;
        });
        const QString state =
            faultStateText(scored == f.score.faults.end() ? nullptr : &*scored, fault.onsetS <= f.timeS);
        setTableRow(m_faults, static_cast<int>(i),
                    {mechanismLabel(fault.mechanism), faultStrengthText(fault.mechanism, fault.strength),
                     clockText(fault.onsetS), state});
        m_faults->item(static_cast<int>(i), 1)->setToolTip(faultStrengthToolTip(fault.mechanism));
    }
    fitTableWidth(m_faults);
    m_score->setText(scoreText(f.score));
    const auto& m = f.monitor;
    if (!m.ready && f.monitorCommissioning) {
        m_monitorLabel->setText(tr("Line monitor: commissioning on healthy runs of this scenario (a few "
                                   "seconds); it then catches up with the line."));
    } else if (!m.ready) {
        m_monitorLabel->setText(
            f.monitorNote.isEmpty() ? QString() : tr("Line monitor unavailable: %1").arg(f.monitorNote));
    } else if (!m.alarmed()) {
        m_monitorLabel->setText(tr("Line monitor: normal (as on its commissioning runs)."));
    } else {
        // The earlier of the two detectors' alarms, and who raised it.
        const auto& d = m.firstAlarm();
        const QString who = m.drytwinFirst() ? tr("the model's error") : tr("the screens' signals (PCA)");
        m_monitorLabel->setText(
            d.hasOnset
                ? tr("<b>Line monitor: ALARM</b> at %1 (%2) — the line has left its normal; the change "
                     "began at about %3. Diagnose the recording to name the cause.")
                      .arg(clockText(d.alarmAtS), who, clockText(d.onsetS))
                : tr("<b>Line monitor: ALARM</b> at %1 (%2) — the line has left its normal. Diagnose the "
                     "recording to name the cause.")
                      .arg(clockText(d.alarmAtS), who));
    }
    redrawPlots();
}

void TrainingPanel::markFaultsAndAnswers(const TrainingFrame& f, double fromS, double toS) {
    // What the trainee's screen cannot show: when each fault began to act and when the trainee
    // answered, so that the instructor reads the time to find it, and the moisture lost meanwhile,
    // off the plot. Few of them (a session's faults and answers): redrawn whole.
    for (auto* m : m_truthMarkers) {
        m->detach();
        delete m;
    }
    m_truthMarkers.clear();
    // Each label runs into the plot from its line, at the plot's foot or head: the first row and
    // side (rightwards first) where it stays inside the plot and clear of the labels placed before
    // it, else where there is more room (a label at 35 of 40 min was cut at the plot's edge, two
    // answers' labels ran into each other).
    const QwtPlot* plot = m_truthPlots->plot(0);
    const double secondsPerPixel = (toS - fromS) / std::max(1, plot->canvas()->width());
    std::vector<std::pair<double, double>> taken[2]; // per row: the spans its labels cover [s]
    const Qt::Alignment rowAlignment[2] = {Qt::AlignBottom, Qt::AlignTop};
    const auto add = [&](double atS, const QString& label, const QColor& colour, int firstRow) {
        auto* m = new QwtPlotMarker(label);
        m->setLineStyle(QwtPlotMarker::VLine);
        m->setLinePen(colour, 1.5, Qt::DashLine);
        QwtText text(label);
        text.setColor(colour);
        m->setLabel(text);
        const double widthS = (text.textSize(plot->font()).width() + 12) * secondsPerPixel;
        const auto clear = [&](int row, double a, double b) {
            return a >= fromS && b <= toS &&
                   std::none_of(taken[row].begin(), taken[row].end(),
                                [&](const auto& t) { return a < t.second && t.first < b; });
        };
        int row = firstRow;
        bool right = toS - atS >= atS - fromS;
        for (int r : {firstRow, 1 - firstRow}) {
            if (clear(r, atS, atS + widthS) || clear(r, atS - widthS, atS)) {
                row = r;
                right = clear(r, atS, atS + widthS);
                break;
            }
        }
        taken[row].emplace_back(right ? atS : atS - widthS, right ? atS + widthS : atS);
        m->setLabelAlignment((right ? Qt::AlignRight : Qt::AlignLeft) | rowAlignment[row]);
        m->setXValue(atS / 60.0);
        m->attach(m_truthPlots->plot(0));
        m_truthMarkers.push_back(m);
    };
    for (const auto& fault : f.faults) {
        add(fault.onsetS, mechanismLabel(fault.mechanism), kFaultColour, 0);
    }
    for (const auto& a : f.answers) {
        const auto m = plant::mechanismByName(a.cause);
        add(a.atS, m ? mechanismLabel(*m) : tr("No fault"), kAnswerColour, 1);
    }
}

void TrainingPanel::redrawPlots() {
    const auto& trace = m_runner->trace();
    const TrainingFrame& f = m_runner->frame();
    // The plots scroll: the last kWindowS seconds, time in minutes; once the monitor has alarmed,
    // from two minutes before the change began, so that its start and the alarm stay in view.
    const auto& m = f.monitor;
    const auto& alarmed = m.firstAlarm();
    const bool showAlarm = m.ready && m.alarmed();
    const double changeStartS =
        alarmed.hasOnset ? std::min(alarmed.onsetS, alarmed.alarmAtS) : alarmed.alarmAtS;
    const double from = showAlarm ? std::min(f.timeS - kWindowS, changeStartS - 120.0) : f.timeS - kWindowS;
    // The instructor's plot reaches back to two minutes before the earliest fault that acts, so
    // that its start, the trainee's answers and the moisture between stay in one view.
    double truthFrom = from;
    for (const auto& fault : f.faults) {
        if (fault.onsetS <= f.timeS) {
            truthFrom = std::min(truthFrom, fault.onsetS - 120.0);
        }
    }
    MoistureSeries trainee, truth; // the trainee's plot from `from`, the instructor's from `truthFrom`
    QVector<double> hsp, h, feed, xin;
    for (const auto& s : trace) {
        if (s.timeS >= truthFrom) {
            truth.add(s, f.bandPct);
        }
        if (s.timeS < from) {
            continue;
        }
        trainee.add(s, f.bandPct);
        hsp << s.hotAirSetpointC;
        h << s.hotAirC;
        feed << s.feedKgH;
        xin << s.xInPct;
    }
    const QVector<double>& t = trainee.minutes;
    m_xMeasured->setSamples(t, trainee.measured);
    m_xSetpoint->setSamples(t, trainee.setpoint);
    m_bandHigh->setSamples(t, trainee.bandHigh);
    m_bandLow->setSamples(t, trainee.bandLow);
    m_truthMeasured->setSamples(truth.minutes, truth.measured);
    m_xTrue->setSamples(truth.minutes, truth.truth);
    m_truthSetpoint->setSamples(truth.minutes, truth.setpoint);
    m_truthBandHigh->setSamples(truth.minutes, truth.bandHigh);
    m_truthBandLow->setSamples(truth.minutes, truth.bandLow);
    // The earlier detector's alarm and change start, as the monitor's sentence says them.
    m_alarmMarker->setVisible(showAlarm);
    m_alarmMarker->setXValue(alarmed.alarmAtS / 60.0);
    m_onsetMarker->setVisible(showAlarm && alarmed.hasOnset);
    m_onsetMarker->setXValue(alarmed.onsetS / 60.0);
    m_hotSetpoint->setSamples(t, hsp);
    m_hot->setSamples(t, h);
    m_feed->setSamples(t, feed);
    m_xIn->setSamples(t, xin);
    // DryTwin's detector: the model's error, its T² per minute against its 99 % limit.
    const auto& d = f.monitor.drytwin;
    QVector<double> mt, mt2, limit;
    for (std::size_t i = 0; i < d.timeS.size(); ++i) {
        if (d.timeS[i] >= from && std::isfinite(d.t2[i])) {
            mt << d.timeS[i] / 60.0;
            mt2 << d.t2[i];
            limit << d.t2Limit;
        }
    }
    m_monitorT2->setSamples(mt, mt2);
    m_monitorLimit->setSamples(mt, limit);
    m_plots->rescale();
    m_plots->setXRange(std::max(0.0, from) / 60.0, std::max(kWindowS, f.timeS) / 60.0);
    if (m_instructorWindow->isVisible() && !m_instructorWindow->isMinimized()) {
        const double truthTo = std::max(kWindowS, f.timeS);
        markFaultsAndAnswers(f, std::max(0.0, truthFrom), truthTo);
        m_truthPlots->rescale();
        m_truthPlots->setXRange(std::max(0.0, truthFrom) / 60.0, truthTo / 60.0);
    }
}

} // namespace drytwin::widgets
