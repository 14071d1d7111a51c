#include "common/EngineText.h"

#include "common/Translations.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <vector>

namespace drytwin::widgets {

namespace {

QString engineWords(const char* text) {
    return QCoreApplication::translate("EngineText", text);
}

/// One form of an engine sentence: the pattern that reads its parts back, and the translatable
/// template that takes them in order (%1, %2, …).
struct EngineForm {
    QRegularExpression pattern;
    const char* words;
};

QString wordedByForm(const QString& text, const std::vector<EngineForm>& forms) {
    for (const auto& f : forms) {
        if (const auto m = f.pattern.match(text); m.hasMatch()) {
            QString out = engineWords(f.words);
            for (int i = 1; i <= m.lastCapturedIndex(); ++i) {
                out = out.arg(m.captured(i));
            }
            return out;
        }
    }
    return text;
}

QRegularExpression enginePattern(const char* pattern) {
    return QRegularExpression(QString::fromUtf8(pattern));
}

} // namespace

QString dataNoteText(const std::string& note) {
    // engine/data/historian/ and engine/data/DataSetSummary.cpp: the notes a historian export or
    // a folder of batch files gives most often.
    static const std::vector<EngineForm> forms{
        {enginePattern("^(.+): column '(.+)' holds text; it is not kept in the runs$"),
         QT_TRANSLATE_NOOP("EngineText", "%1: column '%2' holds text; it is not kept in the runs")},
        {enginePattern("^(.+): a run of (\\d+) s is shorter than the minimum of (\\d+) s; left out$"),
         QT_TRANSLATE_NOOP("EngineText", "%1: a run of %2 s is shorter than the minimum of %3 s; left out")},
        {enginePattern(
             "^(.+): rows are typically (\\S+) s apart, not the 1 s the model and the learnt layer's lags "
             "assume; the physics follows the time stamps, the lags and horizons count rows$"),
         QT_TRANSLATE_NOOP(
             "EngineText",
             "%1: rows are typically %2 s apart, not the 1 s the model and the learnt layer's "
             "lags assume; the physics follows the time stamps, the lags and horizons count rows")},
        {enginePattern("^(.+):(\\d+): a gap of (\\d+) s in time \\(rows typically (\\S+) s apart\\): the "
                       "model runs across "
                       "it as if the line had run on; a stop is better cut into two batches$"),
         QT_TRANSLATE_NOOP(
             "EngineText",
             "%1, line %2: a gap of %3 s in time (rows typically %4 s apart): the model runs across "
             "it as if the line had run on; a stop is better cut into two batches")},
        {enginePattern("^(.+): column (.+): (\\d+) cell\\(s\\) hold PI digital states \\((.+)\\), the first "
                       "here; read as "
                       "missing values$"),
         QT_TRANSLATE_NOOP("EngineText",
                           "%1: column %2: %3 cell(s) hold PI digital states (%4), the first here; read as "
                           "missing values")},
        {enginePattern("^(.+): lines end in a carriage return alone \\(classic Mac OS\\); read as lines$"),
         QT_TRANSLATE_NOOP("EngineText",
                           "%1: lines end in a carriage return alone (classic Mac OS); read as lines")},
        {enginePattern("^(.+): a tag/value export \\(one row per tag and time stamp: columns '(.+)', '(.+)', "
                       "'(.+)'\\), read "
                       "as one column per tag: (\\d+) tags over (\\d+) time stamps; (\\d+) cells where a tag "
                       "has no sample at "
                       "a stamp hold its last sample \\(at most (\\d+) s back\\), (\\d+) are left empty; "
                       "places in later "
                       "messages count rows of that table$"),
         QT_TRANSLATE_NOOP(
             "EngineText",
             "%1: a tag/value export (one row per tag and time stamp: columns '%2', '%3', '%4'), "
             "read as one column per tag: %5 tags over %6 time stamps; %7 cells where a tag has no "
             "sample at a stamp hold its last sample (at most %8 s back), %9 are left empty; places "
             "in later messages count rows of that table")},
        {enginePattern(
             "^(.+): (\\d+) rows repeat a tag at a time stamp already read; the later value is kept$"),
         QT_TRANSLATE_NOOP("EngineText",
                           "%1: %2 rows repeat a tag at a time stamp already read; the later value is kept")},
        {enginePattern("^(.+): (\\S+) reads (\\S+) (.+) on average, the other batches about (\\S+) \\(their "
                       "median\\): this "
                       "batch in another unit \\(°F, K, a fraction, t/h\\) or another column\\? Check it$"),
         QT_TRANSLATE_NOOP(
             "EngineText",
             "%1: %2 reads %3 %4 on average, the other batches about %5 (their median): this batch "
             "in another unit (°F, K, a fraction, t/h) or another column? Check it")},
    };
    return wordedByForm(QString::fromStdString(note), forms);
}

QString engineDetailText(const std::string& english, const QString& worded) {
    const QString language = currentLanguage();
    return language.isEmpty() || language == QLatin1String("en") ? QString::fromStdString(english) : worded;
}

QString fallbackReasonText(const std::string& reason) {
    // engine/control/Mpc.cpp's reasons for holding the plan.
    static const std::vector<EngineForm> forms{
        {enginePattern("^no measurement of the outlet moisture at this step$"),
         QT_TRANSLATE_NOOP("EngineText", "no measurement of the outlet moisture at this step")},
        {enginePattern("^forecast too short$"),
         QT_TRANSLATE_NOOP("EngineText", "the forecast was too short")},
        {enginePattern("^forecast not finite \\(missing history or inputs\\)$"),
         QT_TRANSLATE_NOOP("EngineText", "the forecast was not finite (missing history or inputs)")},
        {enginePattern("^the model shows no effect of the hot air on the outlet moisture$"),
         QT_TRANSLATE_NOOP("EngineText", "the model shows no effect of the hot air on the outlet moisture")},
        {enginePattern("^forecast failed: (.+)$"),
         QT_TRANSLATE_NOOP("EngineText", "the forecast failed: %1")},
        {enginePattern("^Ipopt: (.+)$"),
         QT_TRANSLATE_NOOP("EngineText", "the optimiser (Ipopt) stopped: %1")},
    };
    return wordedByForm(QString::fromStdString(reason), forms);
}

} // namespace drytwin::widgets
