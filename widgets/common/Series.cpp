#include "common/Series.h"

#include "common/Units.h"

#include <QCoreApplication>

namespace drytwin::widgets {

std::vector<SeriesInfo> batchSeries() {
    using namespace units;
    // The titles are translated on every call, not once: a static list keeps the language the
    // program started in, and the Chinese window would show English axis titles.
    struct Entry {
        const char* title;
        double (*value)(const data::SiBatch&, std::size_t);
    };
    static const Entry entries[] = {
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "T_hot [°C]"),
         [](const data::SiBatch& b, std::size_t k) { return kelvinToCelsius(b.tHotK[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "feed [kg/h]"),
         [](const data::SiBatch& b, std::size_t k) { return kgPerSToKgPerHour(b.feedKgPerS[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "X_in [% wb]"),
         [](const data::SiBatch& b, std::size_t k) { return dryToWetPct(b.xInDb[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "T_amb [°C]"),
         [](const data::SiBatch& b, std::size_t k) { return kelvinToCelsius(b.tAmbK[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "RH [%]"),
         [](const data::SiBatch& b, std::size_t k) { return fractionToPercent(b.rhAmb[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "X_HDT [% wb]"),
         [](const data::SiBatch& b, std::size_t k) { return dryToWetPct(b.xHdtDb[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "X_out [% wb]"),
         [](const data::SiBatch& b, std::size_t k) { return dryToWetPct(b.xOutDb[k]); }},
        {QT_TRANSLATE_NOOP("drytwin::widgets::Series", "T_out [°C]"),
         [](const data::SiBatch& b, std::size_t k) { return kelvinToCelsius(b.tOutK[k]); }},
    };
    std::vector<SeriesInfo> s;
    for (const auto& e : entries) {
        s.push_back({QCoreApplication::translate("drytwin::widgets::Series", e.title), e.value});
    }
    return s;
}

QVector<double> timeOf(const data::SiBatch& b) {
    QVector<double> t(static_cast<int>(b.rows()));
    const double t0 = b.rows() > 0 ? b.timeS.front() : 0.0;
    for (std::size_t k = 0; k < b.rows(); ++k) {
        t[static_cast<int>(k)] = b.timeS[k] - t0;
    }
    return t;
}

QVector<double> valuesOf(const data::SiBatch& b, const SeriesInfo& s) {
    QVector<double> v(static_cast<int>(b.rows()));
    for (std::size_t k = 0; k < b.rows(); ++k) {
        v[static_cast<int>(k)] = s.value(b, k);
    }
    return v;
}

void residualSeriesInHours(const std::vector<std::string>& batchOfPoint, const std::vector<double>& timeS,
                           const std::vector<double>& residual, QVector<double>& hours,
                           QVector<double>& values) {
    hours.clear();
    values.clear();
    double offset = 0, last = 0;
    for (std::size_t k = 0; k < residual.size() && k < timeS.size() && k < batchOfPoint.size(); ++k) {
        if (k > 0 && batchOfPoint[k] != batchOfPoint[k - 1]) {
            offset += last + 60; // the next batch starts a sample after the last one shown
        }
        last = timeS[k];
        hours << (offset + timeS[k]) / 3600.0;
        values << residual[k];
    }
}

QVector<double> toQVector(const std::vector<double>& v) {
    return QVector<double>(v.begin(), v.end());
}

} // namespace drytwin::widgets
