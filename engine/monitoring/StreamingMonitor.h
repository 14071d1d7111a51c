#pragma once

#include "common/Error.h"
#include "monitoring/Monitor.h"

#include <Eigen/Dense>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace drytwin::monitoring {

/// @brief One completed window of a StreamingMonitor.
struct StreamingWindow {
    std::string run;
    double timeS = 0;                          ///< end of the window since its run's first sample [s]
    double t2 = 0, spe = 0, zT2 = 0, zSpe = 0; ///< NaN when the window had too few valid blocks
    double cusumT2 = 0, cusumSpe = 0;
    bool alarm = false;    ///< either CUSUM above its threshold now
    bool alarmed = false;  ///< an alarm has been raised at this window or before
    bool hasOnset = false; ///< once alarmed: GLR onset over what was seen so far
    std::string onsetRun;
    double onsetS = 0; ///< start of the onset window since the onset run's start
};

/// @brief Sample-by-sample counterpart of Monitor::judge for live use: same blocks, windows,
/// standardisation and CUSUM threshold (for the planned runs). Not thread-safe.
class StreamingMonitor {
public:
    /// @brief A streaming monitor on @p monitor, holding the false-alarm rate over runs of the
    /// planned durations @p runDurationsS, as Monitor::judge holds it over the runs it is given.
    static Expected<StreamingMonitor> create(const Monitor& monitor,
                                             const std::vector<double>& runDurationsS);
    /// @brief Begins a run. Call endRun() first to complete the previous run's last block;
    /// otherwise that block is dropped.
    void startRun(const std::string& id);
    /// @brief One sample (columns in the monitor's order, NaN missing); the windows it completed.
    Expected<std::vector<StreamingWindow>> push(double timeS, const double* row);
    /// @brief Ends the run: completes the last block and the window it closes, if any.
    std::vector<StreamingWindow> endRun();
    /// @brief CUSUM threshold h of T².
    double t2Threshold() const { return m_hT2; }
    /// @brief CUSUM threshold h of SPE.
    double speThreshold() const { return m_hSpe; }

private:
    void resetRun();
    void completeBlock(std::vector<StreamingWindow>& out);
    void completeWindow(std::vector<StreamingWindow>& out);

    Monitor m_monitor;
    double m_hT2 = 0, m_hSpe = 0;
    int m_p = 0, m_blocksPerWindow = 1;
    std::string m_run;
    bool m_inRun = false;
    bool m_hasSample = false;
    double m_t0 = 0, m_lastT = 0;
    int m_block = 0;                                 ///< index of the block being filled
    std::vector<std::vector<double>> m_blockSamples; ///< per column, the current block's samples
    std::deque<Eigen::VectorXd> m_lagBlocks;         ///< most recent first
    double m_sumLogT2 = 0, m_sumLogSpe = 0;
    int m_validBlocks = 0;
    double m_cusumT2 = 0, m_cusumSpe = 0;
    bool m_alarmed = false;
    bool m_alarmBySpe = false;
    int m_alarmIndex = -1;
    std::vector<double> m_zT2, m_zSpe;
    std::vector<std::pair<std::string, double>> m_zWhere; ///< run and window start of each z
};

} // namespace drytwin::monitoring
