#pragma once

#include "common/Error.h"
#include "data/SiBatch.h"

#include <cstddef>
#include <string>
#include <vector>

namespace drytwin::physics {

/// @brief Input series of one batch in SI units and dry basis, as the line model needs them.
/// Before the first sample the line is taken to have run steadily at the first values; after
/// the last, at the last values.
struct LineInputs {
    std::vector<double> timeS;
    std::vector<double> tHotK;         ///< hot-air temperature at the tube inlet [K]
    std::vector<double> xInDb;         ///< inlet moisture, dry basis
    std::vector<double> tInK;          ///< inlet material temperature [K]
    std::vector<double> tAmbK;         ///< ambient air [K]
    std::vector<double> rhAmb;         ///< ambient relative humidity [0..1]
    std::vector<double> feedKgPerS;    ///< wet feed [kg/s] (not used by the paper's PBM; by the plant)
    std::vector<double> airSpeedMPerS; ///< [m/s] (not used by the paper's PBM; by the plant)
    std::string batchId;        ///< for messages: the batch the series come from ("" when made in code)
    std::string sourcePath;     ///< its file
    std::vector<int> lineOfRow; ///< the file line of each sample (empty when not known)
    /// The model's mechanisms act from this batch's start whatever t_onset says: a later batch of
    /// a change that began during an earlier one and went on (discovery against a reference sets
    /// it where the monitor sees the batch changed from its start). t_onset is counted from each
    /// batch's start, so without it a fault that began 20 min into B03 would be taken to start
    /// 20 min into B04 as well.
    bool mechanismsFromStart = false;
    /// @brief t_onset as this batch's mechanisms see it [s since its start]: 0 when they act from its start.
    double onsetS(double tOnsetS) const { return mechanismsFromStart ? 0.0 : tOnsetS; }

    std::size_t size() const { return timeS.size(); }
    /// @brief Equal lengths, ≥ 2 samples, strictly increasing time, finite physical values. An
    /// error names the batch, its file and line, the time, the input's column and its value.
    Status validate() const;
};

/// @brief The model's input series of an SI batch.
LineInputs toLineInputs(const data::SiBatch& b);

/// @brief Linear interpolation in a sampled series, held constant outside its time range.
/// Thread-safe (no state).
double interpolate(const std::vector<double>& timeS, const std::vector<double>& values, double t);

/// @brief Where a time falls in a sampled series: value = v[j] + w (v[j+1] − v[j]), with w in
/// [0, 1] (held constant outside the time range). One look-up serves every series of a batch.
struct SamplePoint {
    std::size_t j = 0;
    double w = 0;
    double of(const std::vector<double>& values) const { return values[j] + w * (values[j + 1] - values[j]); }
};

/// @brief Locates @p t starting the search at @p hint (updated), which makes the many nearby
/// look-ups of an integration O(1) instead of O(log n). Needs ≥ 2 samples.
SamplePoint locateFrom(const std::vector<double>& timeS, double t, std::size_t& hint);

/// @brief Response of a first-order actuator with time constant @p tauS to a setpoint series
/// (exact for a setpoint held between samples). Used when T_hot follows T_hot_sp (MPC).
std::vector<double> firstOrderResponse(const std::vector<double>& timeS, const std::vector<double>& setpoint,
                                       double tauS, double initial);

} // namespace drytwin::physics
