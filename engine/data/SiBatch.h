#pragma once

#include "common/Error.h"
#include "data/Batch.h"
#include "data/Cleaning.h"

#include <cstdint>
#include <string>
#include <vector>

namespace drytwin::data {

/// @brief One batch in SI units and dry-basis moisture, the engine's internal form.
/// Series absent from the file hold the column default, or NaN when "not measured".
struct SiBatch {
    std::string id;
    std::vector<double> timeS;
    std::vector<double> tHotSpK;       ///< hot-air setpoint [K]
    std::vector<double> tHotK;         ///< measured hot-air temperature [K]
    std::vector<double> airSpeedMPerS; ///< [m/s]
    std::vector<double> feedKgPerS;    ///< wet feed [kg/s]
    std::vector<double> xInDb;         ///< inlet moisture, dry basis [kg/kg]
    std::vector<double> tInK;          ///< inlet material temperature [K]
    std::vector<double> tAmbK;         ///< ambient temperature [K]
    std::vector<double> rhAmb;         ///< ambient relative humidity [0..1]
    std::vector<double> xHdtDb;        ///< tube-outlet moisture, dry basis (NaN when not measured)
    std::vector<double> tHdtK;         ///< tube-outlet material temperature [K] (NaN when not measured)
    std::vector<double> xOutDb;        ///< final outlet moisture, dry basis
    std::vector<double> tOutK;         ///< final outlet temperature [K]
    std::vector<std::uint8_t> keep;    ///< rows the cleaning rules keep (1) for fitting and metrics
    bool hasXHdt = false;
    bool hasTHdt = false;
    std::string sourcePath;     ///< the batch's file, for messages ("" when made in code)
    std::vector<int> lineOfRow; ///< the file line of each row, for messages (empty when not known)
    std::size_t rows() const { return timeS.size(); }
};

/// @brief Converts to SI / dry basis. A missing input cell is bridged by linear interpolation
/// between its neighbours (inputs must be continuous for simulation) and its row is masked
/// out of fitting and metrics; missing outputs stay NaN and masked.
std::vector<SiBatch> toSi(const DataSet& data, const CleaningReport& cleaning);

/// @brief Row range [begin, end) of one batch.
struct RowRange {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
};

/// @brief The chronological split of paper §IV.A: the first @p trainFraction of all rows
/// (batches in order) train, the rest test. Per batch, its train and test ranges.
struct ChronologicalSplit {
    std::vector<RowRange> train;
    std::vector<RowRange> test;
    std::string name; ///< e.g. "chronological_70_30"
};
ChronologicalSplit chronologicalSplit(const std::vector<std::size_t>& rowsPerBatch,
                                      double trainFraction = 0.7);

/// @brief A row of a data set.
struct RowRef {
    std::size_t batch = 0;
    std::size_t row = 0;
};

/// @brief The calibration subset of paper §IV.A: every @p stride-th kept row of the data set,
/// the first @p count of them (1 in 10, first 300).
std::vector<RowRef> calibrationSubset(const std::vector<SiBatch>& batches, std::size_t stride = 10,
                                      std::size_t count = 300);

} // namespace drytwin::data
