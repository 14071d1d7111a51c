#pragma once
// What the Training tab's layout (TrainingPanel.cpp) and its frames' drawing
// (TrainingPanelFrame.cpp) share: the plots' window, the controllers offered, their labels and
// the clock's format.
#include "common/DisplayNames.h"
#include "control/ClosedLoop.h"
#include "plant/Mechanisms.h"
#include "training/TrainingSession.h"

#include <QColor>
#include <QCoreApplication>
#include <QRegularExpression>
#include <QString>
#include <QVector>
#include <algorithm>
#include <string>

namespace drytwin::widgets::training_panel {

/// Minutes of session shown in the scrolling plots.
inline constexpr double kWindowS = 900;
inline constexpr const char* kDefaultTrainingScenario = "training_shift";

inline const control::ControllerKind kControllers[] = {
    control::ControllerKind::Pi, control::ControllerKind::Pbm, control::ControllerKind::PgrlCc,
    control::ControllerKind::ExtInputResidual, control::ControllerKind::Lstm};

inline QString controllerLabel(control::ControllerKind k) {
    // The models' names are the ones every tab uses (DisplayNames); an MPC runs on each.
    return k == control::ControllerKind::Pi
               ? controllerDisplayName(k)
               : QCoreApplication::translate("TrainingPanel", "MPC on: %1").arg(controllerDisplayName(k));
}

/// The outlet moisture's curves of one plot over the samples given to add(): time [min], the
/// measured and the true moisture, the setpoint and its band [% wb].
struct MoistureSeries {
    QVector<double> minutes, measured, truth, setpoint, bandHigh, bandLow;
    void add(const training::LiveSample& s, double bandPct) {
        minutes << s.timeS / 60.0;
        measured << s.xOutPct;
        truth << s.xOutTruePct;
        setpoint << s.setpointPct;
        bandHigh << s.setpointPct + bandPct;
        bandLow << s.setpointPct - bandPct;
    }
};

/// The instructor's plot: when a fault began, when the trainee answered.
inline const QColor kFaultColour(230, 120, 0);
inline const QColor kAnswerColour(40, 140, 40);

/// A mechanism by the one name every tab gives its cause (DisplayNames): the trainee names on
/// Training the cause Discover found under the same words.
inline QString mechanismLabel(plant::Mechanism m) {
    return causeDisplayName(std::string(plant::info(m).name));
}

inline QString clockText(double s) {
    const auto t = static_cast<long>(std::max(0.0, s));
    return QStringLiteral("%1:%2:%3")
        .arg(t / 3600, 2, 10, QLatin1Char('0'))
        .arg((t / 60) % 60, 2, 10, QLatin1Char('0'))
        .arg(t % 60, 2, 10, QLatin1Char('0'));
}

/// training::modelDiffersNote in the GUI's language, the controllers by their display names.
inline QString modelDiffersText(const QString& note) {
    static const QRegularExpression form(QStringLiteral(
        "fingerprint (\\S+), this one (\\S+)\\): its MPC controllers \\((.+)\\) run on this one"));
    const auto m = form.match(note);
    if (!m.hasMatch()) {
        return note;
    }
    QStringList controllers;
    for (const auto& name : m.captured(3).split(QStringLiteral(", "), Qt::SkipEmptyParts)) {
        const auto kind = control::controllerByName(name.toStdString());
        controllers << (kind ? controllerLabel(*kind) : name);
    }
    return QCoreApplication::translate(
               "TrainingPanel", "It was saved with another model (fingerprint %1, this one %2): its MPC "
                                "controllers (%3) run on this one, so the recording may differ from the "
                                "saved one. Open the project or model file it was run with to replay it "
                                "exactly.")
        .arg(m.captured(1), m.captured(2), controllers.join(QStringLiteral(", ")));
}

} // namespace drytwin::widgets::training_panel
