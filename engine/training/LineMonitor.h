#pragma once

#include "common/Error.h"
#include "control/Scenario.h"
#include "monitoring/Monitor.h"
#include "monitoring/StreamingMonitor.h"
#include "training/TrainingSession.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::training {

/// @brief What the live line's monitor says now.
struct LineMonitorState {
    bool ready = false;   ///< commissioned and fed
    bool alarmed = false; ///< the line has left its normal (a CUSUM crossed its threshold)
    double alarmAtS = 0;  ///< session time of the first alarm [s]
    bool hasOnset = false;
    double onsetS = 0;           ///< where the change began, by the GLR over what was seen [session s]
    std::string statistic;       ///< "T2" or "SPE": the one that alarmed first
    double t2Limit = 0, speLimit = 0; ///< the windows' 99 % limits on the commissioning runs
    /// One point per completed minute: session time [s], T², SPE (NaN where too few valid seconds).
    std::vector<double> timeS, t2, spe;
};

/// @brief The live line watched against its commissioning (issue #41): a dynamic PCA monitor of
/// what the operator's screens show (outlet moisture and temperature, hot air and its setpoint,
/// feed, inlet moisture), fitted on healthy runs of the same scenario under its PI loop with
/// other seeds and no fault, and fed one second at a time. Its false-alarm rate holds over the
/// scenario's length. A restore sends it back with the line. A copy watches on its own (the
/// fitted monitor is shared, the streaming state is not). Not thread-safe: one thread drives it.
class LineMonitor {
public:
    /// @brief Commissions the monitor on @p runs healthy runs of @p scenario (its mechanisms and
    /// the instructor's faults left out), each the scenario's length; also returns those runs'
    /// recordings (batch ids C01, C02, …) for a discovery against them.
    static Expected<LineMonitor> commission(const control::Scenario& scenario, int runs = 3,
                                            double falseAlarmRate = 0.01);
    /// @brief Feeds the session's trace from where it was fed last (the whole trace again when it
    /// is shorter than what was fed: a restore).
    Status feed(const std::vector<LiveSample>& trace);
    const LineMonitorState& state() const { return m_state; }
    /// @brief The commissioning runs as batches (the reference period of a diagnosis).
    const std::vector<data::Batch>& commissioningRuns() const { return m_runs; }
    /// @brief The monitored columns, in order.
    static const std::vector<std::string>& columns();

private:
    Status restart();

    std::shared_ptr<const monitoring::Monitor> m_monitor;
    std::optional<monitoring::StreamingMonitor> m_stream; ///< a value: a copy watches on its own
    double m_durationS = 0;
    std::size_t m_fed = 0;
    LineMonitorState m_state;
    std::vector<data::Batch> m_runs;
};

} // namespace drytwin::training
