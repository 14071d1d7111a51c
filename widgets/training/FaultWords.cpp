#include "training/FaultWords.h"

#include "common/DisplayNames.h"
#include "common/WidgetHelpers.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace drytwin::widgets {

namespace {
QString faultWords(const char* text) {
    return QCoreApplication::translate("FaultWords", text);
}
} // namespace

QString faultStrengthUnit(plant::Mechanism mechanism) {
    // The plant's dimensionless strengths, said as what they are a share or multiple of
    // (plant/Mechanisms.cpp's meanings).
    switch (mechanism) {
    case plant::Mechanism::TubeWallHeatLoss:
        return QLatin1Char(' ') + faultWords(QT_TRANSLATE_NOOP("FaultWords", "NTU (wall loss)"));
    case plant::Mechanism::GasPhaseCoupling:
        return QLatin1Char(' ') + faultWords(QT_TRANSLATE_NOOP("FaultWords", "× full air-side coupling"));
    case plant::Mechanism::HeatTransferFouling:
        return QLatin1Char(' ') + faultWords(QT_TRANSLATE_NOOP("FaultWords", "of h_HDT lost"));
    case plant::Mechanism::FallingRateDrying:
        return QLatin1Char(' ') + faultWords(QT_TRANSLATE_NOOP("FaultWords", "of the drying rate lost"));
    default:
        return unitSuffix(plant::info(mechanism).unit);
    }
}

QString faultStrengthText(plant::Mechanism mechanism, double strength) {
    return QString::number(strength, 'g', 3) + faultStrengthUnit(mechanism);
}

QString faultStrengthToolTip(plant::Mechanism mechanism) {
    const auto& mi = plant::info(mechanism);
    return fromView(mi.strengthMeaning) + QStringLiteral("\n") +
           faultWords(QT_TRANSLATE_NOOP(
               "FaultWords", "The virtual plant's own, richer form of this cause: Discover fits the "
                             "model's simpler form of it, with a parameter of its own (its unit may "
                             "differ, e.g. fouling in 1/h), so the two numbers are not the same "
                             "quantity."));
}

QString faultStateText(const training::FaultScore* score, bool actingYet) {
    if (!actingYet || !score) {
        return faultWords(QT_TRANSLATE_NOOP("FaultWords", "not acting yet"));
    }
    if (score->found) {
        return faultWords(QT_TRANSLATE_NOOP("FaultWords", "found after %1 s"))
            .arg(score->timeToFindS, 0, 'f', 0);
    }
    if (score->withinReactionTime) {
        return faultWords(QT_TRANSLATE_NOOP("FaultWords", "time to react: %1 min left"))
            .arg(std::ceil(score->reactionTimeLeftS / 60.0), 0, 'f', 0);
    }
    return faultWords(QT_TRANSLATE_NOOP("FaultWords", "not found"));
}

QString scoreText(const training::TrainingScore& score) {
    const auto found =
        std::count_if(score.faults.begin(), score.faults.end(), [](const auto& f) { return f.found; });
    const auto waiting = std::count_if(score.faults.begin(), score.faults.end(),
                                       [](const auto& f) { return f.withinReactionTime; });
    QString text =
        faultWords(QT_TRANSLATE_NOOP("FaultWords",
                                     "<b>Score %1 / 100</b> — faults found %2 of %3, wrong answers %4, "
                                     "product out of the band %5 % of the time (%6 kg)"))
            .arg(score.points, 0, 'f', 0)
            .arg(found)
            .arg(score.faults.size())
            .arg(score.wrongAnswers)
            .arg(score.offSpecPct, 0, 'f', 1)
            .arg(score.offSpecKg, 0, 'f', 0);
    if (waiting > 0) {
        // Said, so that an unchanged score after an injection is not read as a fault missed.
        text += faultWords(QT_TRANSLATE_NOOP(
                               "FaultWords",
                               "; %1 fault(s) within the trainee's %2 minutes to react, not scored yet"))
                    .arg(waiting)
                    .arg(training::kReactionTimeS / 60.0, 0, 'f', 0);
    }
    return text;
}

} // namespace drytwin::widgets
