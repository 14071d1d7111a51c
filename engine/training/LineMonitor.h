#pragma once

#include "common/Error.h"
#include "control/Scenario.h"
#include "monitoring/Monitor.h"
#include "monitoring/StreamingMonitor.h"
#include "properties/Parameters.h"
#include "training/TrainingSession.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::training {

/// @brief What one of the live line's detectors says now.
struct LineDetectorState {
    bool alarmed = false; ///< the line has left its normal (a CUSUM crossed its threshold)
    double alarmAtS = 0;  ///< session time of the first alarm [s]
    bool hasOnset = false;
    double onsetS = 0;                ///< where the change began, by the GLR over what was seen [session s]
    std::string statistic;            ///< "T2" or "SPE": the one that alarmed first
    double t2Limit = 0, speLimit = 0; ///< the windows' 99 % limits on the commissioning runs
    /// One point per completed minute: session time [s], T², SPE (NaN where too few valid seconds).
    std::vector<double> timeS, t2, spe;
};

/// @brief What the live line's monitor says now: DryTwin's detector (the model's error) and the
/// dynamic PCA monitor of the operator's screens, side by side.
struct LineMonitorState {
    bool ready = false; ///< commissioned and fed
    LineDetectorState drytwin, pca;
    bool alarmed() const { return drytwin.alarmed || pca.alarmed; }
    /// DryTwin's detector if it alarmed no later than the PCA monitor, else the PCA monitor:
    /// the alarm the trainee is told of and shown (meaningful once alarmed()).
    bool drytwinFirst() const {
        return drytwin.alarmed && (!pca.alarmed || drytwin.alarmAtS <= pca.alarmAtS);
    }
    const LineDetectorState& firstAlarm() const { return drytwinFirst() ? drytwin : pca; }
};

/// @brief The live line watched against its commissioning (issue #41). Two detectors, each at
/// the stated false-alarm rate over the scenario's length, fitted on healthy runs of the same
/// scenario under its PI loop with other seeds and no fault:
/// - DryTwin's: the physics model (h_HDT, k_HDT calibrated on those runs) run over the live
///   line's inputs, and its error on each measured output monitored; under closed loop the PI
///   hides a change in the outlet moisture by moving the hot air, which the model's error shows;
/// - a dynamic PCA monitor of what the operator's screens show (outlet moisture and temperature,
///   hot air and its setpoint, feed, inlet moisture).
/// A restore sends both back with the line. A copy watches on its own (the fitted monitors are
/// shared, the streaming states are not). Not thread-safe: one thread drives it.
class LineMonitor {
public:
    /// @brief Commissions the monitors on @p runs healthy runs of @p scenario (its mechanisms left
    /// out), each the scenario's length; the runs' recordings (batch ids C01, C02, …) are kept for
    /// a discovery against them. Six by default: a reference's normal spread between 3 runs has
    /// 2 degrees of freedom, and a recording judged against it named the right fault in 12 of 24
    /// hours (6 runs: 16; 10 runs: 16; scripts/training-discoverability.sh, docs/training.md).
    static constexpr int kDefaultCommissioningRuns = 6;
    static Expected<LineMonitor> commission(const control::Scenario& scenario,
                                            int runs = kDefaultCommissioningRuns,
                                            double falseAlarmRate = 0.01);
    /// @brief Feeds the session from where it was fed last (all of it again after a restore).
    /// The model's error is fed a minute at a time (one simulation of the line per minute).
    Status feed(const TrainingSession& session);
    const LineMonitorState& state() const { return m_state; }
    /// @brief The commissioning runs as batches (the reference period of a diagnosis).
    const std::vector<data::Batch>& commissioningRuns() const { return m_runs; }
    /// @brief The physics parameters commissioned on those runs.
    const properties::ParameterSet& parameters() const { return m_parameters; }
    /// @brief The screens' columns the PCA monitor watches, in order.
    static const std::vector<std::string>& screenColumns();

private:
    Status restart();
    Status feedScreens(const std::vector<LiveSample>& trace);
    Status feedModelError(const TrainingSession& session);

    std::shared_ptr<const monitoring::Monitor> m_screens, m_model;
    std::optional<monitoring::StreamingMonitor> m_screensStream, m_modelStream;
    properties::ParameterSet m_parameters;
    double m_durationS = 0;
    std::size_t m_screensFed = 0;
    double m_modelFedToS = -1; ///< session time of the last model-error row fed
    LineMonitorState m_state;
    std::vector<data::Batch> m_runs;
};

} // namespace drytwin::training
