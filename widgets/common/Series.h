#pragma once

#include "data/SiBatch.h"

#include <QString>
#include <QVector>
#include <functional>
#include <string>
#include <vector>

namespace drytwin::widgets {

/// @brief A series of a batch as the plots show it: file units (°C, % wb, kg/h, %).
struct SeriesInfo {
    QString title; ///< axis title with its unit
    std::function<double(const data::SiBatch&, std::size_t)> value;
};

/// @brief Positions of the outputs in batchSeries().
inline constexpr std::size_t kSeriesXHdt = 5, kSeriesXOut = 6, kSeriesTOut = 7;

/// @brief Every column of a batch file the Data panel plots, in the order of the file, with titles
/// in the present language.
std::vector<SeriesInfo> batchSeries();

/// @brief Seconds since the batch start of each row.
QVector<double> timeOf(const data::SiBatch& b);
/// @brief Values of a series over every row (NaN where missing).
QVector<double> valuesOf(const data::SiBatch& b, const SeriesInfo& s);
/// @brief Discovery's residual series (every 60 s of every batch) with the batches laid one after
/// another: time [h] in @p hours, the residual in @p values.
void residualSeriesInHours(const std::vector<std::string>& batchOfPoint, const std::vector<double>& timeS,
                           const std::vector<double>& residual, QVector<double>& hours,
                           QVector<double>& values);

/// @brief A std::vector as a QVector.
QVector<double> toQVector(const std::vector<double>& v);

} // namespace drytwin::widgets
