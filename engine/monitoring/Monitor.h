#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "monitoring/ChangePoint.h"
#include "monitoring/DynamicPca.h"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace drytwin::monitoring {

/// @brief One run: time-ordered rows of the monitored columns, NaN where a value is missing.
struct MonitorRun {
    std::string id;
    std::vector<double> timeS; ///< strictly increasing; nominally 1 s apart
    Eigen::MatrixXd values;    ///< rows × columns, in the order of the monitor's column names
    /// false: the run's level is not compared with the reference's, only changes within it (its
    /// standardised statistics lose their own mean, in the null as well): a run in conditions the
    /// reference never saw has no normal level to be judged against.
    bool levelJudged = true;
};

/// @brief Everything the monitor can be told; defaults suit 1 s data and hour-long runs.
struct MonitorOptions {
    double blockS = 10;             ///< block-mean length [s]
    int lags = 3;                   ///< lagged blocks per PCA row
    double varianceExplained = 0.9; ///< share of variance the kept components reach
    double confidence = 0.99;       ///< level of the per-block limits (theoretical and empirical)
    double windowS = 60;            ///< run-level statistic window [s], rounded to whole blocks
    double falseAlarmRate = 0.01;   ///< chance that a null judgement says `changed` (split over T² and SPE)
    double minSegmentS = 600;       ///< shortest shifted stretch the GLR considers [s]
    int simulations = 2000;         ///< Monte Carlo null sequences for the thresholds
    unsigned seed = 1;              ///< seed of the Monte Carlo: judgements are deterministic

    /// @brief An InvalidOption error naming the first bad field, or success.
    Status validate() const;
    /// @brief The PCA part of these options.
    DynamicPcaOptions pcaOptions() const;
    /// @brief The change-point part, per statistic: falseAlarmRate / 2 (Bonferroni over T², SPE).
    ChangePointOptions changePointOptions() const;
    /// @brief Blocks per window, at least 1.
    int blocksPerWindow() const;
};

/// @brief One original column's mean shares of SPE and of T² per block: the complete
/// decomposition (sums to 1 over columns; T² shares may be negative) and the reconstruction-
/// based one (normalised to sum to 1), which ranks a one-column fault first where the former smears.
struct Contribution {
    std::string column;
    double speShare = 0;
    double t2Share = 0;
    double speReconstructionShare = 0;
    double t2ReconstructionShare = 0;
};

/// @brief Limits per block (theoretical and empirical) and per window (empirical).
struct MonitorLimits {
    double t2Theoretical = 0,
           speTheoretical = 0;                ///< F-based T², Box SPE; too tight for autocorrelated blocks
    double t2Empirical = 0, speEmpirical = 0; ///< `confidence` quantile of leave-one-out block values
    double t2Window = 0, speWindow = 0; ///< `confidence` quantile of leave-one-out window geometric means
};

/// @brief One window of the judged runs, for plotting.
struct WindowPoint {
    std::string run;
    int runIndex = 0;
    double timeS = 0; ///< end of the window since its run's first sample [s]
    double t2 = 0;  ///< geometric mean of block T² over the window and the leave-one-out fits (NaN: too few
                    ///< valid blocks)
    double spe = 0; ///< the same for SPE
    double t2Limit = 0, speLimit = 0; ///< MonitorLimits::t2Window, speWindow
    double zT2 = 0, zSpe = 0;         ///< standardised by the leave-one-out reference
    double cusumT2 = 0, cusumSpe = 0; ///< CUSUM states after this window
    bool alarm = false;               ///< either CUSUM above its threshold
};

/// @brief The change-point judgement of one statistic; window indices point into Detection::series.
struct StatisticJudgement {
    bool changed = false;
    double pValue = 1; ///< Monte Carlo tail fraction, to compare with falseAlarmRate / 2
    double glr = 0, glrThreshold = 0, cusumThreshold = 0;
    int firstAlarmWindow = -1;
    int onsetWindow = -1, onsetLowWindow = -1, onsetHighWindow = -1;
};

/// @brief Whether new runs differ from the reference, from when, and in which columns.
struct Detection {
    bool changed = false; ///< either statistic's GLR beyond its threshold
    double pValue =
        1; ///< Bonferroni-adjusted min(1, 2 p) of the deciding statistic: changed ⇔ ≤ falseAlarmRate
    std::string statistic; ///< "T2" or "SPE": the one that decided (smaller p when both or neither)
    double falseAlarmRate = 0;
    bool hasFirstAlarm = false; ///< a CUSUM crossed its threshold (possible without `changed`)
    std::string firstAlarmRun;
    double firstAlarmTimeS = 0; ///< end of the alarming window since its run's start
    int firstAlarmWindow = -1;
    bool hasOnset = false; ///< set when changed
    std::string onsetRun;
    double onsetS = 0;    ///< start of the first shifted window since the onset run's start
    double onsetLowS = 0; ///< 95 % interval in the onset run's times, clipped to that run
    double onsetHighS = 0;
    int onsetWindow = -1, onsetLowWindow = -1, onsetHighWindow = -1; ///< global bounds in `series`
    /// After the onset (all windows when none), largest first by the deciding statistic's
    /// reconstruction-based share.
    std::vector<Contribution> contributions;
    std::vector<WindowPoint> series;
    std::vector<int> runStarts;              ///< index in `series` of each run's first window
    std::vector<std::string> levelNotJudged; ///< runs whose level was not compared (MonitorRun::levelJudged)
    StatisticJudgement t2, spe;
    MonitorLimits limits;
    int components = 0;
    double varianceExplainedActual = 0;
    Ending ending;
};

/// @brief A dynamic PCA monitor fitted on healthy reference runs with a leave-one-out null.
/// New data are scored by the mean of the leave-one-out fits' log statistics, so that they are
/// judged exactly as the null was built (the all-run fit gives limits, components and
/// contributions). Immutable once fitted; judge() is safe to call from several threads.
class Monitor {
public:
    /// @brief Fits on @p reference (a single run is split in thirds for the leave-one-out null).
    /// NotEnoughData when the reference is empty, or too short for the leave-one-out null (each
    /// third of a single run, and every three runs' worth, must hold minSegmentS of valid windows).
    static Expected<Monitor> fit(const std::vector<MonitorRun>& reference,
                                 const std::vector<std::string>& columns, const MonitorOptions& options = {});
    /// @brief Judges @p runs, concatenated in the given order, against the reference.
    Expected<Detection> judge(const std::vector<MonitorRun>& runs) const;

    /// @brief The PCA fitted on all reference runs.
    const DynamicPca& pca() const { return m_pca; }
    /// @brief The options it was fitted with.
    const MonitorOptions& options() const { return m_options; }
    /// @brief Monitored column names.
    const std::vector<std::string>& columns() const { return m_columns; }
    /// @brief Per-block and per-window limits.
    const MonitorLimits& limits() const { return m_limits; }
    /// @brief Leave-one-out null of the window mean of log T².
    const LongRunNull& t2Null() const { return m_t2Null; }
    /// @brief Leave-one-out null of the window mean of log SPE.
    const LongRunNull& speNull() const { return m_speNull; }
    /// @brief Window length actually used: whole blocks [s].
    double windowLengthS() const { return m_options.blocksPerWindow() * m_options.blockS; }
    /// @brief log T² and log SPE of one lagged block row, each the mean over the leave-one-out
    /// fits (NaN when the row is incomplete): what the windows and the null are built from.
    void scoreBlock(const Eigen::Ref<const Eigen::VectorXd>& lagged, double& logT2, double& logSpe) const;
    /// @brief The null of the standardised T² and SPE window series for runs of @p runWindows.
    NullModel t2NullModel(const std::vector<int>& runWindows, const std::vector<char>& levelFree = {}) const;
    /// @brief As t2NullModel(), for SPE.
    NullModel speNullModel(const std::vector<int>& runWindows, const std::vector<char>& levelFree = {}) const;

private:
    MonitorOptions m_options;
    std::vector<std::string> m_columns;
    DynamicPca m_pca;
    std::vector<DynamicPca> m_leaveOneOut; ///< one fit without each reference run (or third)
    MonitorLimits m_limits;
    LongRunNull m_t2Null, m_speNull;
};

} // namespace drytwin::monitoring
