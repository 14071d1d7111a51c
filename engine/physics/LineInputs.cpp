#include "physics/LineInputs.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace drytwin::physics {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

/// One input series as the batch file has it: its column, unit and range, in file units.
struct InputCheck {
    const std::vector<double>* values;
    data::Column column;
    double (*toFileUnit)(double);
    double low, high; ///< the model's range in file units
    bool lowOpen, highOpen;
};

} // namespace

Status LineInputs::validate() const {
    const std::size_t n = timeS.size();
    if (n < 2) {
        return Error{ErrorKind::BadInput, "line inputs", "need at least 2 samples"};
    }
    const std::vector<double>* all[] = {&tHotK, &xInDb, &tInK, &tAmbK, &rhAmb, &feedKgPerS, &airSpeedMPerS};
    for (const auto* v : all) {
        if (v->size() != n) {
            return Error{ErrorKind::BadInput, "line inputs", "series lengths differ"};
        }
    }
    const auto kelvin = [](double k) { return units::kelvinToCelsius(k); };
    const auto wet = [](double x) { return units::dryToWetPct(x); };
    const auto percent = [](double f) { return units::fractionToPercent(f); };
    const auto perHour = [](double kgPerS) { return units::kgPerSToKgPerHour(kgPerS); };
    const auto same = [](double v) { return v; };
    const double inf = std::numeric_limits<double>::infinity();
    // The ranges the line model takes (SI limits written in the file's units for the message).
    const InputCheck checks[] = {
        {&tHotK, data::Column::THot, kelvin, kelvin(200), kelvin(800), true, true},
        {&xInDb, data::Column::XIn, wet, 0, wet(10), false, true},
        {&tInK, data::Column::TIn, kelvin, kelvin(200), kelvin(500), true, true},
        {&tAmbK, data::Column::TAmb, kelvin, kelvin(200), kelvin(400), true, true},
        {&rhAmb, data::Column::RHAmb, percent, 0, 100, false, false},
        {&feedKgPerS, data::Column::Feed, perHour, -inf, inf, true, true},
        {&airSpeedMPerS, data::Column::AirSpeed, same, -inf, inf, true, true},
    };
    const auto place = [&](std::size_t i) {
        std::string where = batchId.empty() ? "line inputs" : "batch " + batchId;
        if (i < lineOfRow.size() && !sourcePath.empty()) {
            where += " (" + sourcePath + ":" + std::to_string(lineOfRow[i]) + ")";
        }
        return where + ", row " + std::to_string(i + 1) + ", t = " + number(timeS[i]) + " s";
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(timeS[i])) {
            return Error{ErrorKind::BadInput, place(i), "the time is missing"};
        }
        if (i > 0 && !(timeS[i] > timeS[i - 1])) {
            return Error{ErrorKind::BadInput, place(i), "time must increase strictly"};
        }
        for (const auto& c : checks) {
            const double si = (*c.values)[i];
            const double v = c.toFileUnit(si);
            const bool aboveLow = c.lowOpen ? v > c.low : v >= c.low;
            const bool belowHigh = c.highOpen ? v < c.high : v <= c.high;
            if (std::isfinite(v) && aboveLow && belowHigh) {
                continue;
            }
            const auto& spec = data::spec(c.column);
            const std::string name(spec.name), unit(spec.unit);
            if (std::isnan(v)) {
                return Error{
                    ErrorKind::BadInput, place(i),
                    "input " + name + " [" + unit + ", " + std::string(spec.meaning) +
                        "] is missing here and in every row around it (an empty column, or one "
                        "whose values are all impossible); fill the column or map it to another tag"};
            }
            return Error{ErrorKind::BadInput, place(i),
                         "input " + name + " = " + number(v) + " " + unit +
                             " lies outside the range the line "
                             "model takes (" +
                             number(c.low) + " to " + number(c.high) + " " + unit +
                             "); fix the cell, or the column's unit in the column mapping"};
        }
    }
    return {};
}

double interpolate(const std::vector<double>& timeS, const std::vector<double>& values, double t) {
    if (t <= timeS.front()) {
        return values.front();
    }
    if (t >= timeS.back()) {
        return values.back();
    }
    const auto it = std::upper_bound(timeS.begin(), timeS.end(), t);
    const std::size_t j = static_cast<std::size_t>(it - timeS.begin());
    const double w = (t - timeS[j - 1]) / (timeS[j] - timeS[j - 1]);
    return values[j - 1] + w * (values[j] - values[j - 1]);
}

SamplePoint locateFrom(const std::vector<double>& timeS, double t, std::size_t& hint) {
    const std::size_t n = timeS.size();
    if (t <= timeS.front()) {
        hint = 0;
        return {0, 0.0};
    }
    if (t >= timeS.back()) {
        hint = n - 2;
        return {n - 2, 1.0};
    }
    std::size_t j = std::min(hint, n - 2);
    while (j > 0 && timeS[j] > t) {
        --j;
    }
    while (j + 1 < n - 1 && timeS[j + 1] <= t) {
        ++j;
    }
    hint = j;
    return {j, (t - timeS[j]) / (timeS[j + 1] - timeS[j])};
}

std::vector<double> firstOrderResponse(const std::vector<double>& timeS, const std::vector<double>& setpoint,
                                       double tauS, double initial) {
    std::vector<double> y(setpoint.size());
    if (y.empty()) {
        return y;
    }
    y[0] = initial;
    for (std::size_t i = 1; i < y.size(); ++i) {
        const double a = std::exp(-(timeS[i] - timeS[i - 1]) / tauS);
        y[i] = a * y[i - 1] + (1.0 - a) * setpoint[i - 1];
    }
    return y;
}

LineInputs toLineInputs(const data::SiBatch& b) {
    return {b.timeS,      b.tHotK,         b.xInDb, b.tInK,       b.tAmbK,    b.rhAmb,
            b.feedKgPerS, b.airSpeedMPerS, b.id,    b.sourcePath, b.lineOfRow};
}

} // namespace drytwin::physics
