#include "common/ErrorText.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace drytwin::widgets {

namespace {

QString translated(const char* text) {
    return QCoreApplication::translate("drytwin::widgets::ErrorText", text);
}

/// The engine's English reasons that carry no code but reach users often (a data file's shape, an
/// empty folder), in the user's language; any other reason as it is. A Chinese window showed
/// "expected 13 fields as in the header, found 8" in English (a newcomer's review, 2026-11-28).
QString reasonText(const QString& reason) {
    static const QRegularExpression fields(QStringLiteral(
        "^expected (\\d+) fields as in the header, found (\\d+)( \\(wrong delimiter\\?\\))?$"));
    if (const auto m = fields.match(reason); m.hasMatch()) {
        return (m.captured(3).isEmpty()
                    ? translated(QT_TRANSLATE_NOOP("drytwin::widgets::ErrorText",
                                                   "expected %1 fields as in the header, found %2"))
                    : translated(QT_TRANSLATE_NOOP(
                          "drytwin::widgets::ErrorText",
                          "expected %1 fields as in the header, found %2 (wrong delimiter?)")))
            .arg(m.captured(1), m.captured(2));
    }
    static const QRegularExpression noCsv(QStringLiteral("^the folder holds no \\*\\.csv batch files(.*)$"));
    if (const auto m = noCsv.match(reason); m.hasMatch()) {
        return translated(QT_TRANSLATE_NOOP("drytwin::widgets::ErrorText",
                                            "the folder holds no *.csv batch files")) +
               (m.captured(1).isEmpty() ? QString() : m.captured(1));
    }
    if (reason == QLatin1String("the file has a header but no data rows")) {
        return translated(
            QT_TRANSLATE_NOOP("drytwin::widgets::ErrorText", "the file has a header but no data rows"));
    }
    if (reason == QLatin1String("missing time; the time index must be complete")) {
        return translated(QT_TRANSLATE_NOOP("drytwin::widgets::ErrorText",
                                            "missing time; the time index must be complete"));
    }
    return reason;
}

} // namespace

QString errorText(const Error& e) {
    QStringList a;
    for (const auto& arg : e.args) {
        a << QString::fromStdString(arg);
    }
    const auto has = [&](int n) { return a.size() >= n; };
    switch (e.code) {
    case ErrorCode::FileNotFound:
        if (has(1)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText", "%1: no such file or folder")
                .arg(a[0]);
        }
        break;
    case ErrorCode::MissingColumn:
        if (has(2)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText",
                                               "%1: the required column '%2' is missing")
                .arg(a[0], a[1]);
        }
        break;
    case ErrorCode::TextInNumber:
        if (has(5)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText",
                                               "%1, line %2, column %3: text '%4' in the numeric column '%5'")
                .arg(a[0], a[1], a[2], a[3], a[4]);
        }
        break;
    case ErrorCode::TimeNotIncreasing:
        if (has(3)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText",
                                               "%1, line %2, column %3: time does not increase")
                .arg(a[0], a[1], a[2]);
        }
        break;
    case ErrorCode::DataFileFormat:
        if (has(4)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText", "%1, line %2, column %3: %4")
                .arg(a[0], a[1], a[2], reasonText(a[3]));
        }
        break;
    case ErrorCode::ParameterOutOfRange:
        if (has(4)) {
            return QCoreApplication::translate("drytwin::widgets::ErrorText",
                                               "Parameter %1 = %2 lies outside its range [%3, %4]")
                .arg(a[0], a[1], a[2], a[3]);
        }
        break;
    case ErrorCode::NoDataLoaded:
        return QCoreApplication::translate("drytwin::widgets::ErrorText",
                                           "No data loaded; open a batch file or folder first.");
    case ErrorCode::Cancelled:
        return QCoreApplication::translate("drytwin::widgets::ErrorText", "Cancelled by the user.");
    default:
        break;
    }
    const QString reason = QString::fromStdString(e.reason);
    const QString worded = reasonText(reason);
    if (worded != reason) {
        return e.place.empty() ? worded : QString::fromStdString(e.place) + QStringLiteral(": ") + worded;
    }
    return QString::fromStdString(e.message());
}

} // namespace drytwin::widgets
