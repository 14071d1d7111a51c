#include "plant/PlantExport.h"

#include "common/Units.h"

#include <cmath>

namespace drytwin::plant {

namespace {
/// Rounds to @p decimals places; dividing by an exact power of ten gives the double nearest
/// the decimal value, so the file shows "13.809", not "13.809000000000001".
double round(double v, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(v * scale) / scale;
}
} // namespace

data::Batch toBatch(const PlantBatch& pb, unsigned seed) {
    using data::Column;
    data::Batch b;
    b.id = pb.id;
    b.metadataLines = {"# batch: " + pb.id, "# source: DryTwin virtual plant, seed " + std::to_string(seed),
                       "# sampling: 1 s"};
    const std::size_t n = pb.timeS.size();
    auto column = [&](Column c, const std::vector<double>& si, auto toFile, int decimals) {
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i) {
            v[i] = round(toFile(si[i]), decimals);
        }
        b.setValues(c, std::move(v));
    };
    const auto celsius = units::kelvinToCelsius;
    const auto same = [](double x) { return x; };
    column(Column::Time, pb.timeS, same, 3);
    column(Column::THotSp, pb.tHotSpK, celsius, 2);
    column(Column::THot, pb.tHotK, celsius, 2);
    column(Column::AirSpeed, pb.airSpeedMPerS, same, 3);
    column(Column::Feed, pb.feedKgPerS, units::kgPerSToKgPerHour, 1);
    column(Column::XIn, pb.xInDb, units::dryToWetPct, 3);
    column(Column::TIn, pb.tInK, celsius, 2);
    column(Column::TAmb, pb.tAmbK, celsius, 2);
    column(Column::RHAmb, pb.rhAmb, units::fractionToPercent, 2);
    column(Column::XHdt, pb.xHdtDb, units::dryToWetPct, 3);
    column(Column::THdt, pb.tHdtK, celsius, 2);
    column(Column::XOut, pb.xOutDb, units::dryToWetPct, 3);
    column(Column::TOut, pb.tOutK, celsius, 3);
    b.lineOfRow.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        b.lineOfRow[i] = static_cast<int>(i) + 5; // 3 metadata lines and the header
    }
    return b;
}

std::vector<data::SiBatch> toSiBatches(const PlantResult& result, unsigned seed) {
    data::DataSet ds;
    for (const auto& b : result.batches) {
        ds.batches.push_back(toBatch(b, seed));
    }
    return data::toSi(ds, data::clean(ds));
}

physics::LineInputs toLineInputs(const PlantBatch& pb) {
    return {pb.timeS,      pb.tHotK,         pb.xInDb, pb.tInK, pb.tAmbK, pb.rhAmb,
            pb.feedKgPerS, pb.airSpeedMPerS, pb.id,    {},      {}};
}

} // namespace drytwin::plant
