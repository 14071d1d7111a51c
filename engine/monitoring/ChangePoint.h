#pragma once

#include "common/Error.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::monitoring {

/// @brief How a standardised statistic series is judged for an upward mean shift.
struct ChangePointOptions {
    double falseAlarmRate = 0.005; ///< chance of `changed` (and of any CUSUM alarm) on a null series
    int minSegment = 10;           ///< shortest shifted segment the GLR considers [windows]
    double cusumK = 0.5;           ///< CUSUM reference value k (half the shift it is tuned to)
    int simulations = 2000;        ///< Monte Carlo null sequences
    unsigned seed = 1;             ///< std::mt19937 seed: the thresholds are deterministic

    /// @brief An InvalidOption error naming the first bad field, or success.
    Status validate() const;
};

/// @brief What a standardised series holds under the null besides iid N(0,1) noise: a level
/// offset of its own for each run, and one offset shared by the whole series (the error of the
/// reference mean it was standardised with). Both make long stretches wander more than iid noise.
struct NullModel {
    std::vector<int> runLengths;  ///< values per run, in order; their sum is the series length
    double runEffectVariance = 0; ///< τ²: variance of each run's own offset
    double offsetVariance = 0;    ///< v: variance of the offset shared by all runs
    /// Per run (empty: none): its own mean is taken off, as the judged series' is for a run whose
    /// level is not compared with the reference (conditions the reference never saw).
    std::vector<char> levelFree;

    /// @brief iid N(0,1) values, one run of @p length.
    static NullModel iid(int length);
    /// @brief The series length, Σ runLengths.
    int length() const;
};

/// @brief Null behaviour of the GLR maximum and the CUSUM maximum, from which thresholds and
/// p-values come.
struct NullDistribution {
    int length = 0;
    std::vector<double> glrMaxima;   ///< ascending
    std::vector<double> cusumMaxima; ///< ascending
    double glrThreshold = 0;         ///< `changed` when the GLR maximum is above it
    double cusumThreshold = 0;       ///< h: alarm when S_t > h

    /// @brief Monte Carlo tail fraction (count(G_null ≥ glr) + 1) / (simulations + 1).
    double pValue(double glr) const;
};

/// @brief The Monte Carlo null of @p model. Cached by (model, options) so repeated judgements
/// and streaming cost one simulation; thread-safe.
std::shared_ptr<const NullDistribution> nullDistribution(const NullModel& model,
                                                         const ChangePointOptions& options);

/// @brief Several models at once: those of the same runs share their random numbers (one
/// simulation instead of several); each result equals what nullDistribution() gives alone.
std::vector<std::shared_ptr<const NullDistribution>> nullDistributions(const std::vector<NullModel>& models,
                                                                       const ChangePointOptions& options);

/// @brief The GLR of an upward mean shift from τ to the end, for every τ.
struct GlrScan {
    std::vector<double>
        glr; ///< G(τ) = (Σ_{t≥τ} z_t)² / (n−τ) where the sum is positive and n−τ ≥ minSegment, else 0
    double maximum = 0;
    int onset = -1; ///< argmax τ̂; −1 when no τ has a positive sum
    int low = -1;   ///< first τ of the contiguous run around τ̂ with G(τ) ≥ G_max − 3.84 (95 %)
    int high = -1;  ///< last such τ
};

/// @brief Scans τ = 0..@p lastOnset (all by default) with segment length ≥ @p minSegment.
GlrScan scanGlr(const std::vector<double>& z, int minSegment, int lastOnset = -1);

/// @brief One-sided CUSUM S_t = max(0, S_{t−1} + z_t − k) from S_{−1} = 0.
std::vector<double> cusumPath(const std::vector<double>& z, double k);

/// @brief The judgement of one standardised series.
struct ChangePointResult {
    bool changed = false;    ///< GLR maximum beyond its threshold
    double pValue = 1;       ///< Monte Carlo tail fraction of the GLR maximum
    double glr = 0;          ///< GLR maximum
    double glrThreshold = 0; ///< at falseAlarmRate
    GlrScan scan;            ///< the whole scan, onset and its interval
    std::vector<double> cusum;
    double cusumThreshold = 0; ///< h at falseAlarmRate over the series' length
    int firstAlarm = -1;       ///< first t with S_t > h; −1 when none
};

/// @brief Mean and long-run SD of a statistic under the null, to standardise a series with, and
/// what remains once standardised (in units of the long-run SD).
struct LongRunNull {
    double mean = 0;
    double longRunSd = 1;
    double runEffectVariance = 0; ///< τ²: between-run variance of run means
    double offsetVariance = 0;    ///< variance of `mean` itself: the shared offset of a judged series
    int bandwidth = 0;            ///< Bartlett lags used
    int windows = 0;              ///< values it rests on
};

/// @brief Mean and Bartlett (Newey-West) long-run SD of series from independent runs:
/// autocovariances about each run's own mean, pooled, never across a boundary; bandwidth the
/// larger of n^(1/3) and the first lag with |acf| < 0.05. Then the between-run variance of run
/// means (not reduced by their within-run part: conservative, and stable with few runs) and the
/// variance of the mean. An error names @p place when nothing varies.
Expected<LongRunNull> longRunNull(const std::vector<std::vector<double>>& runs, const std::string& place);

/// @brief GLR test, onset and CUSUM first alarm on a standardised series whose null is @p model
/// (its lengths must add up to z's). Errors for invalid options or a model of another length.
Expected<ChangePointResult> detectChangePoint(const std::vector<double>& z, const NullModel& model,
                                              const ChangePointOptions& options);

} // namespace drytwin::monitoring
