#include "data/SiBatch.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drytwin::data {

namespace {

/// Bridges NaN gaps linearly; leading/trailing gaps hold the nearest value.
/// Returns true for every row that was filled.
std::vector<bool> bridgeGaps(std::vector<double>& v) {
    std::vector<bool> filled(v.size(), false);
    const std::size_t n = v.size();
    std::size_t lastGood = n;
    for (std::size_t i = 0; i < n; ++i) {
        if (std::isnan(v[i])) {
            continue;
        }
        if (lastGood == n) {
            for (std::size_t j = 0; j < i; ++j) {
                v[j] = v[i];
                filled[j] = true;
            }
        } else if (i > lastGood + 1) {
            for (std::size_t j = lastGood + 1; j < i; ++j) {
                const double w = static_cast<double>(j - lastGood) / static_cast<double>(i - lastGood);
                v[j] = (1 - w) * v[lastGood] + w * v[i];
                filled[j] = true;
            }
        }
        lastGood = i;
    }
    if (lastGood != n) {
        for (std::size_t j = lastGood + 1; j < n; ++j) {
            v[j] = v[lastGood];
            filled[j] = true;
        }
    }
    return filled;
}

} // namespace

std::vector<SiBatch> toSi(const DataSet& data, const CleaningReport& cleaning) {
    std::vector<SiBatch> out;
    out.reserve(data.batches.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t bi = 0; bi < data.batches.size(); ++bi) {
        const Batch& b = data.batches[bi];
        const std::size_t n = b.rows();
        SiBatch s;
        s.id = b.id;
        s.sourcePath = b.sourcePath;
        s.lineOfRow = b.lineOfRow;
        s.keep = bi < cleaning.keep.size() ? cleaning.keep[bi] : std::vector<std::uint8_t>(n, 1);
        auto column = [&](Column c) {
            if (const auto* v = b.values(c)) {
                auto values = *v;
                // A frozen reading is no reading: bridged like a dropout for an input, missing
                // for an output (its rows are masked by the cleaning).
                for (const auto& span : cleaning.stuck) {
                    if (span.batch == bi && span.column == c) {
                        std::fill(values.begin() + static_cast<std::ptrdiff_t>(span.begin),
                                  values.begin() + static_cast<std::ptrdiff_t>(span.end), nan);
                    }
                }
                return values;
            }
            return std::vector<double>(n, spec(c).defaultValue);
        };
        auto input = [&](Column c, auto convert) {
            std::vector<double> v = column(c);
            for (auto& x : v) {
                if (impossibleValue(c, x)) {
                    x = nan; // never simulated: bridged like a missing cell, its row masked
                }
            }
            const auto filled = bridgeGaps(v);
            for (std::size_t r = 0; r < n; ++r) {
                if (filled[r]) {
                    s.keep[r] = 0;
                }
                v[r] = convert(v[r]);
            }
            return v;
        };
        auto output = [&](Column c, auto convert) {
            std::vector<double> v = column(c);
            for (auto& x : v) {
                x = std::isnan(x) || impossibleValue(c, x) ? nan : convert(x);
            }
            return v;
        };
        const auto kelvin = units::celsiusToKelvin;
        const auto same = [](double x) { return x; };
        s.timeS = column(Column::Time);
        s.tHotK = input(Column::THot, kelvin);
        if (b.has(Column::THotSp)) {
            s.tHotSpK = input(Column::THotSp, kelvin);
        } else {
            s.tHotSpK = s.tHotK;
        }
        s.airSpeedMPerS = input(Column::AirSpeed, same);
        s.feedKgPerS = input(Column::Feed, units::kgPerHourToKgPerS);
        s.xInDb = input(Column::XIn, units::wetPctToDry);
        s.tInK = input(Column::TIn, kelvin);
        s.tAmbK = input(Column::TAmb, kelvin);
        s.rhAmb = input(Column::RHAmb, units::percentToFraction);
        s.xHdtDb = output(Column::XHdt, units::wetPctToDry);
        s.tHdtK = output(Column::THdt, kelvin);
        s.xOutDb = output(Column::XOut, units::wetPctToDry);
        s.tOutK = output(Column::TOut, kelvin);
        s.hasXHdt = b.has(Column::XHdt);
        s.hasTHdt = b.has(Column::THdt);
        for (std::size_t r = 0; r < n; ++r) {
            if (std::isnan(s.xOutDb[r]) || std::isnan(s.tOutK[r])) {
                s.keep[r] = 0;
            }
        }
        out.push_back(std::move(s));
    }
    return out;
}

ChronologicalSplit chronologicalSplit(const std::vector<std::size_t>& rowsPerBatch, double trainFraction) {
    ChronologicalSplit split;
    std::size_t total = 0;
    for (auto n : rowsPerBatch) {
        total += n;
    }
    const auto cut = static_cast<std::size_t>(std::floor(trainFraction * static_cast<double>(total)));
    std::size_t offset = 0;
    for (auto n : rowsPerBatch) {
        const std::size_t localCut = cut <= offset ? 0 : std::min(n, cut - offset);
        split.train.push_back({0, localCut});
        split.test.push_back({localCut, n});
        offset += n;
    }
    const int pct = static_cast<int>(std::lround(trainFraction * 100));
    split.name = "chronological_" + std::to_string(pct) + "_" + std::to_string(100 - pct);
    return split;
}

std::vector<RowRef> calibrationSubset(const std::vector<SiBatch>& batches, std::size_t stride,
                                      std::size_t count) {
    std::vector<RowRef> subset;
    std::size_t seen = 0;
    for (std::size_t b = 0; b < batches.size() && subset.size() < count; ++b) {
        for (std::size_t r = 0; r < batches[b].rows() && subset.size() < count; ++r) {
            if (!batches[b].keep[r]) {
                continue;
            }
            if (seen % stride == 0) {
                subset.push_back({b, r});
            }
            ++seen;
        }
    }
    return subset;
}

} // namespace drytwin::data
