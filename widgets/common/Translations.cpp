#include "common/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QStringList>
#include <QTranslator>
#include <memory>

namespace drytwin::widgets {

namespace {
std::unique_ptr<QTranslator> g_ours, g_qt;
QString g_language = QStringLiteral("en");
} // namespace

bool setLanguage(const QString& language) {
    for (auto* t : {&g_ours, &g_qt}) {
        if (*t) {
            QCoreApplication::removeTranslator(t->get());
            t->reset();
        }
    }
    g_language = language.isEmpty() ? QStringLiteral("en") : language;
    if (g_language == QLatin1String("en")) {
        return true;
    }
    bool found = false;
    g_ours = std::make_unique<QTranslator>();
    const QStringList places{QCoreApplication::applicationDirPath() + QStringLiteral("/../widgets"),
                             QCoreApplication::applicationDirPath() + QStringLiteral("/translations"),
                             QCoreApplication::applicationDirPath() +
                                 QStringLiteral("/../share/drytwin/translations"),
                             QStringLiteral(DRYTWIN_QM_DIR)};
    for (const auto& place : places) {
        if (g_ours->load(QStringLiteral("drytwin_") + g_language, place)) {
            QCoreApplication::installTranslator(g_ours.get());
            found = true;
            break;
        }
    }
    g_qt = std::make_unique<QTranslator>();
    if (g_qt->load(QStringLiteral("qtbase_") + g_language,
                   QLibraryInfo::location(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(g_qt.get());
    }
    return found;
}

QString currentLanguage() {
    return g_language;
}

} // namespace drytwin::widgets
