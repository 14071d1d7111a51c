#include "common/ErrorText.h"

#include <QCoreApplication>

namespace drytwin::widgets {

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
                .arg(a[0], a[1], a[2], a[3]);
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
    return QString::fromStdString(e.message());
}

} // namespace drytwin::widgets
