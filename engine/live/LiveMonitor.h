#pragma once

#include "common/Error.h"
#include "data/Batch.h"
#include "data/Columns.h"
#include "monitoring/StreamingMonitor.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::live {

/// @brief What the live monitor is fitted with.
struct LiveMonitorOptions {
    double falseAlarmRate = 0.01; ///< over one planned run, as `discover --reference` holds it
    /// The run length the false-alarm rate is held over [s]; 0: the reference batches' mean.
    double plannedRunS = 0;
    Status validate() const;
};

/// @brief The monitor's alarm: the first window whose CUSUM crossed its threshold (the monitor
/// stays alarmed from then on, across batches, as StreamingMonitor does).
struct LiveAlarm {
    std::string batch;
    double timeS = 0;      ///< end of the alarming window since the batch's start [s]
    std::string statistic; ///< "T2" or "SPE": the CUSUM that crossed its threshold
    bool hasOnset = false;
    std::string onsetBatch;
    double onsetS = 0; ///< the change's estimated start since its batch's start [s]
};

/// @brief The dynamic-PCA monitor of the line's screens (the training line's six columns:
/// outlet moisture and temperature, hot-air setpoint and temperature, feed, inlet moisture),
/// fitted on a reference period and fed the recording's final rows second by second, as
/// training/LineMonitor feeds the training line. A new batch id starts a new run. Copies are
/// independent (a copy of a freshly commissioned monitor has seen nothing). Not thread-safe.
class LiveMonitor {
public:
    /// @brief Fits on @p reference (batch files of a period when the line ran as it should); a
    /// reference without the screen columns or too short for the monitor is a BadInput error.
    static Expected<LiveMonitor> commission(const data::DataSet& reference,
                                            const LiveMonitorOptions& options);
    /// @brief One final row of the recording (values by contract column, NaN missing) at
    /// @p timeS since the start of batch @p batch, which began at Unix second @p batchStartS.
    /// Returns the windows it completed.
    Expected<std::vector<monitoring::StreamingWindow>>
    push(const std::string& batch, double batchStartS, double timeS,
         const std::array<double, data::kColumnCount>& values);
    /// @brief Ends the current run (its last block); the windows that completed.
    std::vector<monitoring::StreamingWindow> finish();
    /// @brief The alarm of @p w when it is the stream's first alarmed window, else nullopt.
    std::optional<LiveAlarm> alarmOf(const monitoring::StreamingWindow& w);
    /// @brief Unix time of the end of window @p w.
    double windowEndUnixS(const monitoring::StreamingWindow& w) const { return m_runStartS + w.timeS; }
    double t2Threshold() const { return m_stream->t2Threshold(); }
    double speThreshold() const { return m_stream->speThreshold(); }
    const monitoring::MonitorLimits& limits() const { return m_monitor->limits(); }
    double plannedRunS() const { return m_plannedRunS; }
    /// @brief `{"t": <window end, Unix s>, "batch": …, "time_s": …, "t2": …, "spe": …, "z_t2": …,
    /// "z_spe": …, "cusum_t2": …, "cusum_spe": …, "cusum_t2_limit": …, "cusum_spe_limit": …,
    /// "alarm": …, "alarmed": …}` (null where the window had too few valid blocks).
    std::string windowPayload(const monitoring::StreamingWindow& w) const;
    /// @brief `{"t": …, "batch": …, "time_s": …, "statistic": "T2"|"SPE", "onset_batch": …, "onset_s": …}`.
    std::string alarmPayload(const LiveAlarm& a, const monitoring::StreamingWindow& w) const;
    /// @brief The monitored contract columns, in the monitor's order.
    static const std::vector<data::Column>& columns();

private:
    std::shared_ptr<const monitoring::Monitor> m_monitor;
    std::optional<monitoring::StreamingMonitor>
        m_stream; ///< by value: a copy of a fresh monitor starts afresh
    double m_plannedRunS = 0;
    std::string m_run;
    double m_runStartS = 0;
    bool m_alarmTold = false;
};

} // namespace drytwin::live
