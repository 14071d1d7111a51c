#include "common/DisplayNames.h"

#include <QCoreApplication>
#include <map>

namespace drytwin::widgets {

namespace {

/// @p source in the workbench's language, or as written (English: the report).
QString named(const char* source, bool translated) {
    return translated ? QCoreApplication::translate("DisplayNames", source) : QString::fromUtf8(source);
}

} // namespace

QString controllerDisplayName(control::ControllerKind kind, bool translated) {
    switch (kind) {
    case control::ControllerKind::Pbm:
        return named(QT_TRANSLATE_NOOP("DisplayNames", "Physics model"), translated);
    case control::ControllerKind::PgrlCc:
        return named(QT_TRANSLATE_NOOP("DisplayNames", "Physics + learnt correction (PGRL-CC)"), translated);
    case control::ControllerKind::ExtInputResidual:
        return named(QT_TRANSLATE_NOOP("DisplayNames", "Physics + input-only correction"), translated);
    case control::ControllerKind::Lstm:
        return named(QT_TRANSLATE_NOOP("DisplayNames", "LSTM (black box)"), translated);
    case control::ControllerKind::Pi:
        return named(QT_TRANSLATE_NOOP("DisplayNames", "PI loop (the plant's own)"), translated);
    }
    return {};
}

QString modelDisplayName(const std::string& key, bool translated) {
    if (const auto kind = control::controllerByName(key)) {
        return controllerDisplayName(*kind, translated);
    }
    if (key == "persistence") {
        return named(QT_TRANSLATE_NOOP("DisplayNames", "Last measurement held"), translated);
    }
    if (key == "pbm_residual_hold") {
        return named(QT_TRANSLATE_NOOP("DisplayNames", "Physics model, last error held"), translated);
    }
    return QString::fromStdString(key);
}

QString columnDisplayName(const std::string& column) {
    static const std::map<std::string, const char*> names{
        {"T_hot_sp_C", QT_TRANSLATE_NOOP("DisplayNames", "hot-air setpoint")},
        {"T_hot_C", QT_TRANSLATE_NOOP("DisplayNames", "hot-air temperature")},
        {"air_speed_m_s", QT_TRANSLATE_NOOP("DisplayNames", "air speed")},
        {"feed_kg_h", QT_TRANSLATE_NOOP("DisplayNames", "feed rate")},
        {"X_in_pct", QT_TRANSLATE_NOOP("DisplayNames", "inlet moisture")},
        {"T_in_C", QT_TRANSLATE_NOOP("DisplayNames", "inlet material temperature")},
        {"T_amb_C", QT_TRANSLATE_NOOP("DisplayNames", "ambient temperature")},
        {"RH_amb_pct", QT_TRANSLATE_NOOP("DisplayNames", "ambient humidity")},
        {"X_out_pct", QT_TRANSLATE_NOOP("DisplayNames", "outlet moisture")},
        {"T_out_C", QT_TRANSLATE_NOOP("DisplayNames", "outlet temperature")},
        {"X_hdt_pct", QT_TRANSLATE_NOOP("DisplayNames", "tube-outlet moisture")},
        {"T_hdt_C", QT_TRANSLATE_NOOP("DisplayNames", "tube-outlet temperature")},
        // Discovery's channel names (the same quantities, without the unit suffix).
        {"X_out", QT_TRANSLATE_NOOP("DisplayNames", "outlet moisture")},
        {"T_out", QT_TRANSLATE_NOOP("DisplayNames", "outlet temperature")},
        {"X_hdt", QT_TRANSLATE_NOOP("DisplayNames", "tube-outlet moisture")},
        {"T_hdt", QT_TRANSLATE_NOOP("DisplayNames", "tube-outlet temperature")},
        {"error_X_out_pct", QT_TRANSLATE_NOOP("DisplayNames", "model error, outlet moisture")},
        {"error_T_out_C", QT_TRANSLATE_NOOP("DisplayNames", "model error, outlet temperature")},
        {"error_X_hdt_pct", QT_TRANSLATE_NOOP("DisplayNames", "model error, tube-outlet moisture")},
        {"error_T_hdt_C", QT_TRANSLATE_NOOP("DisplayNames", "model error, tube-outlet temperature")},
        // The physics model's own states that discovery correlates the error with.
        {"proxy_X_HDT", QT_TRANSLATE_NOOP("DisplayNames", "model's tube-outlet moisture")},
        {"proxy_T_HDT", QT_TRANSLATE_NOOP("DisplayNames", "model's tube-outlet temperature")},
        {"proxy_X_Conv", QT_TRANSLATE_NOOP("DisplayNames", "model's moisture on the conveyor")},
        {"proxy_T_Conv", QT_TRANSLATE_NOOP("DisplayNames", "model's temperature on the conveyor")},
    };
    const auto it = names.find(column);
    return it == names.end() ? QString::fromStdString(column)
                             : QCoreApplication::translate("DisplayNames", it->second);
}

QString causeDisplayName(const std::string& cause) {
    // QT_TRANSLATE_NOOP marks them for lupdate; translate() words them when called.
    static const std::map<std::string, const char*> names{
        {"tube_wall_heat_loss", QT_TRANSLATE_NOOP("DisplayNames", "tube-wall heat loss")},
        {"gas_phase_coupling", QT_TRANSLATE_NOOP("DisplayNames", "drying air cooling along the tube")},
        {"heat_transfer_fouling", QT_TRANSLATE_NOOP("DisplayNames", "heat-transfer fouling")},
        {"moisture_meter_lag", QT_TRANSLATE_NOOP("DisplayNames", "slow outlet moisture meter")},
        {"moisture_meter_offset", QT_TRANSLATE_NOOP("DisplayNames", "outlet moisture meter offset")},
        {"transport_delay_error", QT_TRANSLATE_NOOP("DisplayNames", "conveyor transport time off")},
        {"falling_rate_drying", QT_TRANSLATE_NOOP("DisplayNames", "slower drying below critical moisture")},
        {"ambient_reabsorption", QT_TRANSLATE_NOOP("DisplayNames", "moisture taken back on the conveyor")},
        {"inlet_moisture_sensor_offset", QT_TRANSLATE_NOOP("DisplayNames", "inlet moisture gauge offset")},
        {"hot_air_sensor_lag", QT_TRANSLATE_NOOP("DisplayNames", "slow hot-air thermocouple")},
        {"inlet_moisture_sensor_noise", QT_TRANSLATE_NOOP("DisplayNames", "noisy inlet moisture gauge")},
        {"outlet_mixing", QT_TRANSLATE_NOOP("DisplayNames", "outlet mixing")},
    };
    const auto it = names.find(cause);
    return it == names.end() ? QString::fromStdString(cause)
                             : QCoreApplication::translate("DisplayNames", it->second);
}

QString columnMeaningText(std::string_view english) {
    // data/Columns.cpp's meanings, listed for lupdate; translate() finds each by its English text.
    [[maybe_unused]] static const char* const meanings[] = {
        QT_TRANSLATE_NOOP("ColumnMeanings", "time since batch start"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "hot-air temperature setpoint"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "measured hot-air temperature at the tube inlet"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "air speed in the drying tube"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "wet feed rate entering the tube"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "inlet moisture"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "inlet material temperature"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "ambient air temperature"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "ambient relative humidity"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "moisture at the tube outlet"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "material temperature at the tube outlet"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "final outlet moisture after the winnower"),
        QT_TRANSLATE_NOOP("ColumnMeanings", "final outlet temperature after the winnower"),
    };
    const std::string text(english);
    return QCoreApplication::translate("ColumnMeanings", text.c_str());
}

QString timeFormatText(const std::string& format) {
    static const std::map<std::string, const char*> names{
        {"seconds", QT_TRANSLATE_NOOP("DisplayNames", "seconds since the start")},
        {"iso8601", QT_TRANSLATE_NOOP("DisplayNames", "date and time, ISO 8601 (2024-05-31T08:00:00)")},
        {"Y/m/d", QT_TRANSLATE_NOOP("DisplayNames", "year/month/day and time")},
        {"d.m.Y", QT_TRANSLATE_NOOP("DisplayNames", "day.month.year and time")},
        {"d/m/Y", QT_TRANSLATE_NOOP("DisplayNames", "day/month/year and time")},
        {"m/d/Y", QT_TRANSLATE_NOOP("DisplayNames", "month/day/year and time")},
        {"d-Mon-Y", QT_TRANSLATE_NOOP("DisplayNames", "day-month name-year and time")},
        {"excel_days", QT_TRANSLATE_NOOP("DisplayNames", "spreadsheet day numbers")},
        {"epoch_s", QT_TRANSLATE_NOOP("DisplayNames", "Unix time in seconds")},
        {"epoch_ms", QT_TRANSLATE_NOOP("DisplayNames", "Unix time in milliseconds")},
    };
    const auto it = names.find(format);
    return it == names.end() ? QString::fromStdString(format)
                             : QCoreApplication::translate("DisplayNames", it->second);
}

QString runEndText(const std::string& reason) {
    static const std::map<std::string, const char*> names{
        {"line stop", QT_TRANSLATE_NOOP("DisplayNames", "line stop")},
        {"gap", QT_TRANSLATE_NOOP("DisplayNames", "gap in the recording")},
        {"batch id", QT_TRANSLATE_NOOP("DisplayNames", "next batch id")},
        {"clock jump", QT_TRANSLATE_NOOP("DisplayNames", "clock jump")},
        {"end of file", QT_TRANSLATE_NOOP("DisplayNames", "end of file")},
    };
    const auto it = names.find(reason);
    return it == names.end() ? QString::fromStdString(reason)
                             : QCoreApplication::translate("DisplayNames", it->second);
}

QString mappingReasonText(const std::string& reason) {
    // The guess's reasons are English phrases of a fixed form (data/MappingGuess.cpp): read back
    // their parts and word them again.
    const QString r = QString::fromStdString(reason);
    if (r == QLatin1String("the contract's own name")) {
        return QCoreApplication::translate("DisplayNames", "DryTwin's own column name");
    }
    if (r.startsWith(QLatin1String("time stamps: "))) {
        return QCoreApplication::translate("DisplayNames", "time stamps: %1")
            .arg(timeFormatText(r.mid(13).toStdString()));
    }
    if (r.startsWith(QLatin1String("values in "))) {
        const QStringList parts = r.mid(10).split(QStringLiteral(", "));
        QStringList words;
        words << QCoreApplication::translate("DisplayNames", "values in %1").arg(parts.front());
        for (int i = 1; i < parts.size(); ++i) {
            if (parts[i] == QLatin1String("name")) {
                words << QCoreApplication::translate("DisplayNames", "words of the header");
            } else if (parts[i].startsWith(QLatin1String("tag "))) {
                words << QCoreApplication::translate("DisplayNames", "tag letters %1").arg(parts[i].mid(4));
            } else {
                words << parts[i];
            }
        }
        return words.join(QCoreApplication::translate("DisplayNames", ", "));
    }
    return r;
}

QString progressDetailText(const std::string& stage, const std::string& detail) {
    const QString d = QString::fromStdString(detail);
    if (stage == "mpc") {
        // control/ClosedLoop.cpp: "<controller key>, step <k>/<total>"
        const int comma = d.indexOf(QLatin1String(", step "));
        const int slash = d.lastIndexOf(QLatin1Char('/'));
        if (comma > 0 && slash > comma) {
            return QCoreApplication::translate("DisplayNames", "%1: second %2 of %3")
                .arg(modelDisplayName(d.left(comma).toStdString()), d.mid(comma + 7, slash - comma - 7),
                     d.mid(slash + 1));
        }
    }
    return d;
}

QString groupDisplayName(const std::string& group) {
    if (group == "outlet_response_time") {
        return QCoreApplication::translate("DisplayNames",
                                           "outlet response time (meter lag or transport time)");
    }
    if (group == "moisture_offset") {
        return QCoreApplication::translate("DisplayNames", "moisture offset (outlet meter or inlet gauge)");
    }
    if (group == "gas_temperature") {
        return QCoreApplication::translate("DisplayNames",
                                           "air temperature in the tube (wall loss or air cooling)");
    }
    return QString::fromStdString(group);
}

QString unitSuffix(std::string_view unit) {
    if (unit.empty() || unit == "-") {
        return {};
    }
    if (unit == "% wb") {
        return QLatin1Char(' ') + QCoreApplication::translate("DisplayNames", "% wb");
    }
    return QLatin1Char(' ') + QString::fromUtf8(unit.data(), static_cast<int>(unit.size()));
}

QString mappingUnitText(const std::string& unit) {
    // The mapping file's unit names are keys (CONTRACT.md §1); the dialog shows them as units read.
    if (unit == "degC") {
        return QStringLiteral("°C");
    }
    if (unit == "degF") {
        return QStringLiteral("°F");
    }
    static const std::map<std::string, const char*> words{
        {"% wb", QT_TRANSLATE_NOOP("DisplayNames", "% wb")},
        {"% db", QT_TRANSLATE_NOOP("DisplayNames", "% db")},
        {"fraction wb", QT_TRANSLATE_NOOP("DisplayNames", "fraction, wet basis")},
        {"fraction", QT_TRANSLATE_NOOP("DisplayNames", "fraction")},
        {"min", QT_TRANSLATE_NOOP("DisplayNames", "min")},
        {"%", QT_TRANSLATE_NOOP("DisplayNames", "% RH")}};
    const auto it = words.find(unit);
    return it == words.end() ? QString::fromStdString(unit)
                             : QCoreApplication::translate("DisplayNames", it->second);
}

QString verdictDisplayText(const std::string& verdict, const QString& firstCause) {
    if (verdict == "cause_found") {
        return firstCause.isEmpty()
                   ? QCoreApplication::translate("DisplayNames", "Cause found")
                   : QCoreApplication::translate("DisplayNames", "Cause found: %1").arg(firstCause);
    }
    if (verdict == "no_structural_cause") {
        // Not "within the noise": a bias the model always has (the line's own structure) or a
        // candidate that fits but fails a check leaves this verdict too.
        return QCoreApplication::translate(
            "DisplayNames", "No cause named: no candidate passed every check (the table says why each was "
                            "not named)");
    }
    if (verdict == "unexplained_structure") {
        return QCoreApplication::translate("DisplayNames", "Something is left that no known cause explains");
    }
    return QString::fromStdString(verdict);
}

QString verdictNextStep(const std::string& verdict, bool aCauseFitsButFailedACheck, bool againstReference) {
    // Compared with a reference already: the advice to compare with one would send the user in a
    // circle (issue #72 item 4); the reference's own words instead.
    if (againstReference && verdict == "no_structural_cause") {
        return QCoreApplication::translate(
            "DisplayNames",
            "Next: nothing changed since the reference period that the model needs to account "
            "for. To see smaller changes, record longer or more batches.");
    }
    if (againstReference && verdict == "unexplained_structure") {
        return QCoreApplication::translate(
            "DisplayNames",
            "Next: something changed since the reference period that no known cause explains. The evidence "
            "says which measurement the error follows; check that transmitter and the maintenance log around "
            "the time the change began. If the reference period itself was not a good time for the line, "
            "choose another one.");
    }
    if (verdict == "cause_found") {
        return QCoreApplication::translate(
            "DisplayNames", "Next: check that part of the line (the evidence says where and from when), then "
                            "“Extend the model” to add the cause and see how much the simulation improves.");
    }
    if (verdict == "no_structural_cause" && aCauseFitsButFailedACheck) {
        // Not "nothing needs changing" over a residual that plainly drifts (a newcomer's fouled
        // line): a cause fitted and predicted better, and one data set could not say it is a change.
        return QCoreApplication::translate(
            "DisplayNames",
            "Next: a cause fits these data and predicts better but failed a check (the table says which "
            "and why); one data set alone cannot tell it from the line's own structure. Compare with data "
            "from a time when the line ran well (“Compare with a reference period”), or record longer or "
            "more batches.");
    }
    if (verdict == "no_structural_cause") {
        return QCoreApplication::translate(
            "DisplayNames", "Next: nothing in the model needs changing for these data. To see smaller "
                            "effects, record longer or more batches.");
    }
    if (verdict == "unexplained_structure") {
        return QCoreApplication::translate(
            "DisplayNames",
            "Next: compare with data from a time when the line ran well (“Compare with a reference "
            "period”): what changed since then is named more surely than from one data set alone. The "
            "evidence says which measurement the error follows; check that transmitter and the maintenance "
            "log around the time it starts.");
    }
    return {};
}

QString terminationText(Termination termination) {
    switch (termination) {
    case Termination::Completed:
        return QCoreApplication::translate("DisplayNames", "Completed");
    case Termination::Converged:
        return QCoreApplication::translate("DisplayNames", "Converged");
    case Termination::BudgetExhausted:
        return QCoreApplication::translate("DisplayNames", "Evaluation budget used up");
    case Termination::StoppedKeptBest:
        return QCoreApplication::translate("DisplayNames", "Stopped by you, best so far kept");
    }
    return {};
}

QString mpcEndingText(const control::ClosedLoopResult& result) {
    if (result.ending.termination == Termination::StoppedKeptBest) {
        return QCoreApplication::translate(
            "DisplayNames", "Stopped by you; the runs so far are kept, the last one is partial");
    }
    int ran = 0;
    for (const auto& run : result.runs) {
        ran += run.ran ? 1 : 0;
    }
    return QCoreApplication::translate("DisplayNames",
                                       "Scenario %1: %2 of %3 controllers run over %4 scored seconds")
        .arg(QString::fromStdString(result.scenario.name))
        .arg(ran)
        .arg(result.runs.size())
        .arg(result.scenario.lengthS);
}

QString intervalMethodText(const std::string& method) {
    if (method.empty()) {
        return QCoreApplication::translate("DisplayNames", "none (the sensitivities could not be computed)");
    }
    if (method.find("sandwich") != std::string::npos) {
        // Plain words on screen; the estimator's names go to the tooltip (issue #72 item 10).
        return QCoreApplication::translate(
            "DisplayNames", "widened because neighbouring rows are alike and not independent evidence");
    }
    return QString::fromStdString(method);
}

QString intervalMethodDetails(const std::string& method) {
    if (method.find("sandwich") != std::string::npos) {
        return QCoreApplication::translate("DisplayNames",
                                           "Intervals: sandwich covariance with a Newey-West middle term.");
    }
    return {};
}

QString r2Explanation(double r2) {
    if (!(r2 == r2)) {
        return QCoreApplication::translate("DisplayNames", "R² could not be computed (too few rows).");
    }
    if (r2 < 0) {
        return QCoreApplication::translate(
            "DisplayNames",
            "R² below 0: the model predicts worse than the batch's mean would. Usual for the physics "
            "model alone on a short held-out part with little movement; compare MAE instead.");
    }
    return QCoreApplication::translate(
               "DisplayNames",
               "R² %1: the model explains %2 % of the variation of the measured values about their mean.")
        .arg(r2, 0, 'f', 3)
        .arg(100.0 * r2, 0, 'f', 0);
}

} // namespace drytwin::widgets
