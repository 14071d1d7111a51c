// The Discover tab's words: a finding's evidence, specificity and notes, the rejections' and
// signatures' sentences, in the window's language (DiscoverPanel.cpp keeps the tab's layout and
// wiring).
#include "common/EngineText.h"
#include "discovery/DiscoverPanel.h"
#include "discovery/FindingWords.h"

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

namespace finding_words {

/// What to look for on the plots, per cause. The engine has the same sentences in English for the
/// CLI's evidence sentence (lookFor in engine/discovery/Discovery.cpp, which has no Qt); they are
/// worded here again because the GUI translates them.
/// A parameter's unit after its value (" 1/h"), nothing for a dimensionless one ("-").
QString paramUnitSuffix(properties::Param p) {
    return unitSuffix(properties::info(p).unit);
}

QString lookForText(properties::Param p) {
    using properties::Param;
    switch (p) {
    case Param::theta_wall:
        return DiscoverPanel::tr("the outlet-temperature error grows with the hot-air excess over ambient "
                                 "(bias by T_amb and T_hot)");
    case Param::theta_gas:
        return DiscoverPanel::tr(
            "the errors grow with feed rate and inlet moisture (bias by feed rate and by inlet moisture)");
    case Param::theta_foul:
        return DiscoverPanel::tr(
            "the error drifts over each batch, or over the recording from the fouling's onset, "
            "and starts afresh with each new batch");
    case Param::tau_meter:
        return DiscoverPanel::tr(
            "the outlet-moisture error follows the rate of change of the simulated outlet "
            "moisture, and the tube-outlet error does not");
    case Param::X_meter_offset:
        return DiscoverPanel::tr(
            "a steady outlet-moisture bias that the tube-outlet moisture does not share");
    case Param::dtau_conv:
        return DiscoverPanel::tr("the outlet error correlates with tube-outlet changes at a shifted lag");
    case Param::theta_fall:
        return DiscoverPanel::tr(
            "the tube-outlet and outlet moisture are wetter than simulated, most where the "
            "tube dries furthest");
    case Param::theta_reabs:
        return DiscoverPanel::tr(
            "the outlet-moisture error grows with ambient humidity while the tube-outlet "
            "error does not");
    case Param::X_in_offset:
        return DiscoverPanel::tr(
            "a steady bias of the tube-outlet and outlet moisture alike, larger where the tube dries less");
    case Param::tau_hot_sensor:
        return DiscoverPanel::tr("after each hot-air setpoint step the outlet temperature and moisture move "
                                 "before the simulation, which follows the slow reading");
    case Param::phi_X_in_scatter:
        return DiscoverPanel::tr("the inlet-moisture reading scatters from second to second while the outlet "
                                 "does not follow it, and the simulated outlet does");
    default:
        return QString();
    }
}

/// The measurement that tells a look-alike group's members apart, in the GUI's language.
QString tellApartText(const std::string& group) {
    if (group == "outlet_response_time") {
        return DiscoverPanel::tr(
            "a step of the hot-air setpoint logged at 1 s: a transport-time error delays the outlet "
            "temperature's response as much as the moisture's, a meter lag delays the moisture reading "
            "alone; "
            "or grab samples timed against the meter");
    }
    if (group == "moisture_offset") {
        return DiscoverPanel::tr(
            "oven-dry laboratory samples at the outlet against the meter and at the inlet against the gauge; "
            "or a tube-outlet moisture channel (X_hdt), which an inlet-gauge offset moves and an "
            "outlet-meter "
            "offset does not");
    }
    if (group == "gas_temperature") {
        return DiscoverPanel::tr("a gas-temperature reading at the tube's outlet end at two feed rates: wall "
                                 "loss does not change with the feed, gas-phase cooling grows with it");
    }
    return QString::fromStdString(group);
}

/// Why a candidate that predicted better was not named, in the GUI's language (the engine's
/// sentence follows in the details).
/// The outcome column's words for a candidate not named (rejectionText() says it in full).
QString rejectionShortText(const std::string& code) {
    static const std::map<std::string, const char*> shortTexts{
        {"compensation", QT_TRANSLATE_NOOP("DiscoverPanel", "compensation")},
        {"inconsistent", QT_TRANSLATE_NOOP("DiscoverPanel", "inconsistent")},
        {"not_constant", QT_TRANSLATE_NOOP("DiscoverPanel", "not constant")},
        {"within_normal_spread", QT_TRANSLATE_NOOP("DiscoverPanel", "within normal range")},
        {"not_on_every_output", QT_TRANSLATE_NOOP("DiscoverPanel", "not on every output")},
        {"below_floor", QT_TRANSLATE_NOOP("DiscoverPanel", "below the floor")},
        {"no_held_out_gain", QT_TRANSLATE_NOOP("DiscoverPanel", "no held-out gain")},
        {"channels", QT_TRANSLATE_NOOP("DiscoverPanel", "its look-alike")},
        {"line_dynamics", QT_TRANSLATE_NOOP("DiscoverPanel", "line dynamics")}};
    const auto it = shortTexts.find(code);
    return it == shortTexts.end() ? DiscoverPanel::tr("not named")
                                  : QCoreApplication::translate("DiscoverPanel", it->second);
}

QString rejectionText(const std::string& code) {
    if (code == "compensation") {
        return DiscoverPanel::tr("it lowers one output's error by raising another's (compensation)");
    }
    if (code == "inconsistent") {
        return DiscoverPanel::tr("its size is not consistent across batches or operating regions");
    }
    if (code == "not_constant") {
        return DiscoverPanel::tr(
            "it does not change within a batch (an offset, the tube's wall or gas phase), "
            "but this error grows or shrinks within the batch (fouling, a drifting reading)");
    }
    if (code == "within_normal_spread") {
        return DiscoverPanel::tr("its value lies within the reference period's normal range: not a change");
    }
    if (code == "not_on_every_output") {
        return DiscoverPanel::tr(
            "named after another cause, it must lower the error of every output it acts on, "
            "and on one it does not: what is left there is not this cause's");
    }
    if (code == "below_floor") {
        return DiscoverPanel::tr("it is below what the instruments can tell (practical floor)");
    }
    if (code == "no_held_out_gain") {
        return DiscoverPanel::tr("it does not predict the held-out part clearly better (too small a share of "
                                 "the error, or not significant)");
    }
    if (code == "channels") {
        return DiscoverPanel::tr(
            "the outlet channels' timing points to its look-alike (the moisture answers later "
            "than the temperature: a meter, not the transport)");
    }
    if (code == "line_dynamics") {
        return DiscoverPanel::tr("the outlet temperature lags the model as much: the line is slower than the "
                                 "model, not the meter");
    }
    return DiscoverPanel::tr("no clear held-out gain");
}

/// A signature no cause explains (Signature::type), in the GUI's language.
QString signatureText(const discovery::Signature& u) {
    if (u.type == "periodic") {
        return DiscoverPanel::tr("a periodic error of %1 s period (power %2 times its background)")
            .arg(u.periodS, 0, 'f', 0)
            .arg(u.strength, 0, 'g', 3);
    }
    if (u.type == "lagged_input") {
        return DiscoverPanel::tr("the error follows %1 %2 s later (correlation %3)")
            .arg(columnDisplayName(u.column))
            .arg(u.lagS, 0, 'f', 0)
            .arg(u.strength, 0, 'f', 2);
    }
    if (u.type == "batch_shift") {
        QStringList batches;
        for (const auto& b : u.batches) {
            batches << QString::fromStdString(b);
        }
        return DiscoverPanel::tr("batches %1 are shifted by %2 against the others")
            .arg(batches.join(QStringLiteral(", ")))
            .arg(u.strength, 0, 'g', 3);
    }
    if (u.type == "drift") {
        return DiscoverPanel::tr("the error drifts by %1 per hour within the batches")
            .arg(u.strength, 0, 'g', 3);
    }
    return QString::fromStdString(u.type);
}

/// Why a round stopped, worded here from the round's numbers (the engine's sentence is English).
QString roundReasonText(const discovery::Round& rd) {
    if (rd.named) {
        return DiscoverPanel::tr("named");
    }
    if (rd.best.empty()) {
        return DiscoverPanel::tr("no candidate passes the screening test");
    }
    for (const auto& x : rd.rejected) {
        if (x.cause == rd.best) {
            return rejectionText(x.code);
        }
    }
    return DiscoverPanel::tr("no fitted candidate lowers the training loss");
}

} // namespace finding_words

using namespace finding_words;

/// Discovery's notes, worded in the GUI's language from their forms in
/// engine/discovery/DiscoveryNotes.h (TestMainWindow's everyDiscoveryNoteIsWordedInChinese builds
/// each form there and checks it is worded here).
QString DiscoverPanel::noteText(const std::string& note) {
    const QString n = QString::fromStdString(note);
    const auto starts = [&](const char* prefix) { return n.startsWith(QLatin1String(prefix)); };
    const auto numbers = [&] {
        static const QRegularExpression number(QStringLiteral("[-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?"));
        QStringList found;
        for (auto it = number.globalMatch(n); it.hasNext();) {
            found << it.next().captured(0);
        }
        return found;
    };
    if (starts("X_hdt_pct is not measured")) {
        return tr("X_hdt_pct is not measured: without the tube-outlet moisture, meter and conveyor "
                  "causes cannot be told from tube causes; only the outlet channels are used.");
    }
    if (starts("T_hdt_C is not measured")) {
        return tr("T_hdt_C is not measured: the tube-outlet temperature is not used.");
    }
    if (starts("air_speed_m_s is constant")) {
        return tr("air_speed_m_s is constant (not measured?): the air cooling along the tube is "
                  "fitted with that one value.");
    }
    if (starts("the line's outlet mixing") && !numbers().isEmpty()) {
        return tr("The line's outlet mixing (belt and winnower): a first-order lag of %1 s fitted "
                  "with h_HDT and k_HDT (0: plug flow).")
            .arg(numbers().first());
    }
    if (starts("the inlet gauge's normal scatter") && numbers().size() >= 2) {
        return tr("The inlet gauge's normal scatter: %1 % of X_in's fast variation (%2 % wb) is taken "
                  "as gauge scatter, not moisture, in the starting model.")
            .arg(numbers().at(0), numbers().at(1));
    }
    // ReferenceDiscovery.cpp's withdrawTakenUp and its note on a short reference.
    static const QRegularExpression withdrawn(QStringLiteral(
        "^(\\S+): named first, then withdrawn: refitted with the causes named after it, it is (.*); it had "
        "taken up what they explain$"));
    if (const auto m = withdrawn.match(n); m.hasMatch()) {
        return tr("%1 was named first, then withdrawn: refitted together with the causes named "
                  "after it, it is no change of the line (it had taken up what they explain). "
                  "In detail: %2.")
            .arg(causeDisplayName(m.captured(1).toStdString()), m.captured(2));
    }
    // ReferenceDiscovery.cpp: the batches wholly before the change point left out of the causes' judgement.
    static const QRegularExpression fromChange(QStringLiteral(
        "^the causes are judged on the batches from (.+) on, where the change began; (.+) before it ran as "
        "the reference did$"));
    if (const auto m = fromChange.match(n); m.hasMatch()) {
        return tr("The causes are judged on the batches from %1 on, where the change began; %2 before it "
                  "ran as the reference did.")
            .arg(m.captured(1), m.captured(2));
    }
    // ReferenceDiscovery.cpp: the batches a change that began mid-batch goes on into.
    static const QRegularExpression goesOn(QStringLiteral(
        "^the change goes on from the start of (.+) \\(the monitor reads them changed before the onset time "
        "too\\): the causes act there from the batch's start$"));
    if (const auto m = goesOn.match(n); m.hasMatch()) {
        return tr("The change goes on from the start of %1 (the monitor reads them changed before the "
                  "onset time too): the causes act there from the batch's start.")
            .arg(m.captured(1));
    }
    if (starts("the reference holds ") && !numbers().isEmpty()) {
        return tr("The reference holds %1 batch(es): a period's normal spread comes from thirds of "
                  "them, which share their day and weather; a change named here may be a "
                  "difference of conditions the reference never showed. A reference of several "
                  "batches over the conditions the line runs in (weeks, seasons) judges better.")
            .arg(numbers().first());
    }
    // ReferenceDiscovery.cpp: "the reference period itself drifts: the model's X_out error changes by
    // 2.7 % wb within a mean batch (...)".
    static const QRegularExpression drifts(
        QStringLiteral("^the reference period itself drifts: the model's (\\S+) error changes by (\\S+) (.+) "
                       "within a mean batch"));
    if (const auto m = drifts.match(n); m.hasMatch()) {
        return tr("The reference period itself drifts: the model's %1 error changes by %2 %3 "
                  "within a mean batch. A reference should be a period when the line ran "
                  "well; against this one a change since may read as none.")
            .arg(m.captured(1), m.captured(2), m.captured(3));
    }
    // A batch's inputs outside a range seen elsewhere, one note a batch (DiscoveryNotes.cpp's
    // inputsOutside): "T_amb_C is typically 31.6 °C, outside what the reference saw (11 to 23 °C);
    // RH_pct is typically …". Each input worded, then joined.
    const auto inputsOutside = [](const QString& list, bool otherReferenceBatches) {
        static const QRegularExpression item(
            QStringLiteral("(\\S+) is typically (\\S+) ([^,;]+), outside what the (?:other reference batches|"
                           "reference) saw \\((\\S+) to (\\S+) [^)]*\\)"));
        QStringList worded;
        for (auto it = item.globalMatch(list); it.hasNext();) {
            const auto m = it.next();
            const QString column = columnDisplayName(m.captured(1).toStdString());
            worded << (otherReferenceBatches
                           ? tr("%1 is typically %2 %3, outside what the other reference batches saw (%4 to "
                                "%5 %3)")
                           : tr("%1 is typically %2 %3, outside what the reference saw (%4 to %5 %3)"))
                          .arg(column, m.captured(2), m.captured(3), m.captured(4), m.captured(5));
        }
        return worded.join(tr("; "));
    };
    // ReferenceDiscovery.cpp: "reference batch R03: T_amb_C is typically 30.4 °C, outside what the
    // other reference batches saw (12.1 to 19.4 °C)[; …]: the line's structure there …"
    static const QRegularExpression beyondOthers(
        QStringLiteral("^reference batch (.+?): (\\S+ is typically .+): the line's structure there is the "
                       "map's extrapolation"));
    if (const auto m = beyondOthers.match(n); m.hasMatch()) {
        return tr("Reference batch %1: %2: the line's structure there is the map's extrapolation, so the "
                  "batch is left out of the causes' normal spread.")
            .arg(m.captured(1), inputsOutside(m.captured(2), true));
    }
    // ReferenceDiscovery.cpp's operatingRangeNotes: "B04: T_amb_C is typically 31.6 °C, outside what
    // the reference saw (11 to 23 °C)[; …]: …"
    static const QRegularExpression outside(QStringLiteral(
        "^(.+?): (\\S+ is typically .+ outside what the reference saw \\([^)]*\\)): (?:the reference has|the "
        "model's error)"));
    if (const auto m = outside.match(n); m.hasMatch()) {
        // Whether the detectors judged the batch's level
        // (DiscoveryOptions::judgeOnlyChangesBeyondReferenceConditions).
        const QString text =
            n.contains(QStringLiteral("only changes within"))
                ? tr("%1: %2: the reference has no normal level for these conditions, so the detectors judge "
                     "only changes within this batch, not its level.")
                : tr("%1: %2: the model's error there is judged beyond the reference's conditions, and an "
                     "alarm "
                     "there may be that condition rather than a change of the line.");
        return text.arg(m.captured(1), inputsOutside(m.captured(2), false));
    }
    if (n.startsWith(QLatin1String(discovery::notes::kOnlyCausesAsked))) {
        QStringList causes;
        for (const auto& c : n.mid(static_cast<int>(std::strlen(discovery::notes::kOnlyCausesAsked)))
                                 .split(QStringLiteral(", "), Qt::SkipEmptyParts)) {
            causes << causeDisplayName(c.toStdString());
        }
        return tr("Only the causes asked were tried: %1. That the others are not named says nothing about "
                  "them.")
            .arg(causes.join(tr(", ")));
    }
    // ReferenceDiscovery.cpp: "commissioned on the reference period (6 batch(es), 45000 rows): h_HDT
    // 71.98 W/(m²·K), k_HDT 0.02392 m/s, held fixed on the data judged".
    static const QRegularExpression commissioned(QStringLiteral(
        "^commissioned on the reference period \\((\\d+) batch\\(es\\), (\\d+) rows\\): h_HDT (\\S+) "
        "W/\\(m²·K\\), k_HDT (\\S+) m/s"));
    if (const auto m = commissioned.match(n); m.hasMatch()) {
        return tr("Commissioned on the reference period (%1 batch(es), %2 rows): h_HDT %3 W/(m²·K) and "
                  "k_HDT %4 m/s, held fixed on the data judged.")
            .arg(m.captured(1), m.captured(2), m.captured(3), m.captured(4));
    }
    static const QRegularExpression structure(QStringLiteral(
        "^the line's own structure \\(what the model always gets wrong, a ridge regression on the inputs and "
        "the model's outputs, penalty (\\S+)\\)"));
    if (const auto m = structure.match(n); m.hasMatch()) {
        return tr("The line's own structure (what the model always gets wrong: a ridge regression on the "
                  "inputs and the model's outputs, penalty %1) was learnt on the reference and taken off "
                  "the measurements; the residuals shown are what is left.")
            .arg(m.captured(1));
    }
    // SessionDiscover.cpp: an output only one of the two periods measures.
    static const QRegularExpression onePeriod(
        QStringLiteral("^(\\S+) is measured in the (data|reference period) "
                       "but not in every batch of the"));
    if (const auto m = onePeriod.match(n); m.hasMatch()) {
        const QString column = columnDisplayName(m.captured(1).toStdString());
        return m.captured(2) == QLatin1String("data")
                   ? tr("%1 is measured in the data but not in every batch of the reference period: the "
                        "periods are compared on the outputs both measure, without it.")
                         .arg(column)
                   : tr("%1 is measured in the reference period but not in every batch of the data: the "
                        "periods are compared on the outputs both measure, without it.")
                         .arg(column);
    }
    // SessionData.cpp: the data checks' note on the reference's own files (the note itself is the
    // Data tab's, shown as the checks word it).
    if (n.startsWith(QLatin1String(discovery::notes::kAboutReferenceFiles))) {
        return tr("The reference period's files: %1")
            .arg(n.mid(static_cast<int>(std::strlen(discovery::notes::kAboutReferenceFiles))));
    }
    return n;
}

QString DiscoverPanel::specificityText(const discovery::Finding& f) {
    const auto& info = properties::info(f.parameter);
    const QString unit = QString::fromUtf8(info.unit.data(), static_cast<int>(info.unit.size()));
    QStringList parts;
    if (!f.perPart.empty()) {
        // Held within the parameter's range, as the CLI's text: a part that hardly informs the
        // estimate can step outside it (its uncertainty, not a value the line can have).
        double lo = std::clamp(f.perPart.front().value, info.lower, info.upper), hi = lo;
        bool held = false;
        for (const auto& e : f.perPart) {
            const double v = std::clamp(e.value, info.lower, info.upper);
            held = held || v != e.value;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        parts << tr("Fitted part by part (%1 parts) it lies between %2 and %3 %4: %5.")
                         .arg(f.perPart.size())
                         .arg(lo, 0, 'g', 3)
                         .arg(hi, 0, 'g', 3)
                         .arg(unit)
                         .arg(f.consistent ? tr("consistent") : tr("not consistent")) +
                     (held ? QStringLiteral(" ") +
                                 tr("A part whose estimate left the parameter's range is held at its bound.")
                           : QString());
    }
    if (f.transferChecked) {
        parts << tr("Fitted on the cooler half of the data it removes %1 % of the warmer half's error.")
                     .arg(100 * f.transferReduction, 0, 'f', 0);
    }
    if (f.hasOnset) {
        parts << tr("It starts %1 min into the batch (95 % interval %2–%3 min).")
                     .arg(f.onsetS / 60, 0, 'f', 0)
                     .arg(f.onsetLowS / 60, 0, 'f', 0)
                     .arg(f.onsetHighS / 60, 0, 'f', 0);
        if (!f.actsFromStartOf.empty()) {
            QStringList batches;
            for (const auto& b : f.actsFromStartOf) {
                batches << QString::fromStdString(b);
            }
            parts << tr("It goes on from the start of %1.").arg(batches.join(QStringLiteral(", ")));
        }
    }
    for (const auto& l : f.lookAlikes) {
        if (l.namedAfter) {
            parts << tr("%1 was named on top of it (a further %2 % of the held-out error): alone it predicts "
                        "worse (%3 times the held-out error), but the change needs both forms, so the data "
                        "cannot say which of them it is.")
                         .arg(causeDisplayName(l.cause))
                         .arg(100 * l.explainedAfter, 0, 'f', 0)
                         .arg(l.heldOutLossRatio, 0, 'g', 2);
            continue;
        }
        if (l.byChannels) {
            parts
                << (l.ruledOut
                        ? tr("Not %1: the moisture answers %2 s later than the model and the outlet "
                             "temperature "
                             "%3 s (each fitted alone, p = %4); a transport time delays both alike.")
                              .arg(causeDisplayName(l.cause))
                              .arg(l.moistureDelayS, 0, 'g', 3)
                              .arg(l.temperatureDelayS, 0, 'g', 3)
                        : tr("%1 fits too: the moisture answers %2 s later than the model and the outlet "
                             "temperature %3 s (each fitted alone, p = %4); the channels' timing cannot tell "
                             "them apart (the temperature has dynamics of its own, or the difference is "
                             "within "
                             "the noise).")
                              .arg(causeDisplayName(l.cause))
                              .arg(l.moistureDelayS, 0, 'g', 3)
                              .arg(l.temperatureDelayS, 0, 'g', 3))
                       .arg(l.pValue, 0, 'g', 2);
            continue;
        }
        if (!l.ruledOut && !l.worseOutput.empty()) {
            parts
                << tr("%1 fits too: overall it leaves %2 times the held-out error (p = %3), but it predicts "
                      "%4 better; which output a cause favours is the model's structure, so the data cannot "
                      "tell them apart.")
                       .arg(causeDisplayName(l.cause))
                       .arg(l.heldOutLossRatio, 0, 'g', 2)
                       .arg(l.pValue, 0, 'g', 2)
                       .arg(l.worseOutput == "X_out"   ? tr("the outlet moisture")
                            : l.worseOutput == "T_out" ? tr("the outlet temperature")
                            : l.worseOutput == "X_hdt" ? tr("the tube-outlet moisture")
                                                       : tr("the tube-outlet temperature"));
            continue;
        }
        parts << (l.ruledOut
                      ? tr("Not %1: fitted in its place it leaves %2 times the held-out error (p = %3).")
                      : tr("%1 fits these data about as well (held-out error %2 times, p = %3): the data "
                           "cannot tell them apart."))
                     .arg(causeDisplayName(l.cause))
                     .arg(l.heldOutLossRatio, 0, 'g', 2)
                     .arg(l.pValue, 0, 'g', 2);
    }
    if (!f.group.empty()) {
        parts << tr("To tell them apart: %1.").arg(tellApartText(f.group));
    }
    return parts.join(QLatin1Char(' '));
}

QString DiscoverPanel::evidenceText(const discovery::Finding& f) {
    const bool moisture = f.output == "X_out";
    const QString unit = moisture ? tr("% wb") : tr("°C");
    const auto& info = properties::info(f.parameter);
    const auto& g = f.gain;
    const QString share =
        f.onItsChannelsCounted
            ? (f.parameter == properties::Param::tau_meter
                   ? tr("it removes %1 % of the held-out squared error, and of the outlet moisture's, the "
                        "only "
                        "measured output it acts on, %2 % (%3 % of its fast part)")
                   : tr("it removes %1 % of the held-out squared error, and of the outlet moisture's and "
                        "temperature's, the only measured outputs it acts on, %2 % (%3 % of its fast part)"))
                  .arg(100 * f.explainedFraction, 0, 'f', 0)
                  .arg(100 * f.explainedFractionOnItsChannels, 0, 'f', 0)
                  .arg(100 * f.explainedFractionOnItsChannelsFast, 0, 'f', 0)
        : f.fastPartCounted
            ? tr("it removes %1 % of the held-out squared error and %2 % of its fast part (the error about "
                 "its moving average, where slow drift does not hide it)")
                  .arg(100 * f.explainedFraction, 0, 'f', 0)
                  .arg(100 * f.explainedFractionFast, 0, 'f', 0)
            : tr("it removes %1 % of the held-out squared error").arg(100 * f.explainedFraction, 0, 'f', 0);
    const QString commissioned = f.hasReference ? tr("h_HDT, k_HDT as commissioned on the reference period")
                                                : tr("h_HDT, k_HDT refitted");
    // Against a reference the finding is a change: the value it had there, and its normal range.
    const QString changed =
        f.hasReference
            ? tr(" On the reference period it was %1 %2 (a period's normal range %3 to %4): it changed.")
                  .arg(f.referenceValue, 0, 'g', 4)
                  .arg(QString::fromUtf8(info.unit.data(), static_cast<int>(info.unit.size())))
                  .arg(f.referenceCi95Low, 0, 'g', 3)
                  .arg(f.referenceCi95High, 0, 'g', 3)
            : QString();
    return tr("%1 error before: bias %2 %3, within-batch trend %4 %3/h. With %5 (%6 = %7%8, 95 % CI [%9, "
              "%10]) "
              "and %18, the held-out MAE of X_out goes from %11 to %12 % wb and of T_out "
              "from %13 to %14 °C (the chance that a gain this large is luck: %15); "
              "%16. Check on the plots: %17.")
               .arg(moisture ? tr("Outlet-moisture") : tr("Outlet-temperature"))
               .arg(f.biasBefore, 0, 'g', 3)
               .arg(unit)
               .arg(f.trendPerHourBefore, 0, 'g', 3)
               .arg(causeDisplayName(f.cause))
               .arg(QString::fromUtf8(info.symbol.data(), static_cast<int>(info.symbol.size())))
               .arg(f.restated ? f.valueWhenNamed : f.value, 0, 'g', 4)
               .arg(paramUnitSuffix(f.parameter))
               .arg(f.restated ? f.ci95LowWhenNamed : f.ci95Low, 0, 'g', 3)
               .arg(f.restated ? f.ci95HighWhenNamed : f.ci95High, 0, 'g', 3)
               .arg(g.maeMoistureBefore, 0, 'f', 3)
               .arg(g.maeMoistureAfter, 0, 'f', 3)
               .arg(g.maeTemperatureBefore, 0, 'f', 2)
               .arg(g.maeTemperatureAfter, 0, 'f', 2)
               .arg(g.pValue, 0, 'g', 2)
               .arg(share)
               .arg(lookForText(f.parameter))
               .arg(commissioned) +
           changed + responseSizeText(f);
}

QString DiscoverPanel::responseSizeText(const discovery::Finding& f) {
    // Against a reference a cause is judged by the direction of its effect on each output; where
    // the line moved by a different amount than the model form says, the engineer is told.
    QString text;
    static const char* const kChannels[] = {"X_out", "T_out", "X_hdt", "T_hdt"};
    for (int c : discovery::outputsMovedOtherThanModelled(f)) {
        const double scale = f.responseScale[static_cast<std::size_t>(c)];
        text +=
            (scale < 0 ? tr(" %1 moved against this cause's effect (%2 times what its model form says), by "
                            "less than that output's noise can tell from none: it counts neither for the "
                            "cause nor against it.")
                       : tr(" %1 moved %2 times as much as this cause's model form says: the direction "
                            "agrees, the size is the model's to answer."))
                .arg(QLatin1String(kChannels[c]))
                .arg(scale, 0, 'g', 2);
    }
    return text;
}

} // namespace drytwin::widgets
