#include "physics/LineInputs.h"

#include <algorithm>
#include <cmath>

namespace drytwin::physics {

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
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && !(timeS[i] > timeS[i - 1])) {
            return Error{ErrorKind::BadInput, "line inputs", "time must increase strictly"};
        }
        const bool ok = std::isfinite(timeS[i]) && tHotK[i] > 200 && tHotK[i] < 800 && xInDb[i] >= 0 &&
                        xInDb[i] < 10 && tInK[i] > 200 && tInK[i] < 500 && tAmbK[i] > 200 && tAmbK[i] < 400 &&
                        rhAmb[i] >= 0 && rhAmb[i] <= 1 && std::isfinite(feedKgPerS[i]) &&
                        std::isfinite(airSpeedMPerS[i]);
        if (!ok) {
            return Error{ErrorKind::BadInput, "line inputs at t = " + std::to_string(timeS[i]) + " s",
                         "an input is missing or outside its physical range"};
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
    return {b.timeS, b.tHotK, b.xInDb, b.tInK, b.tAmbK, b.rhAmb, b.feedKgPerS, b.airSpeedMPerS};
}

} // namespace drytwin::physics
