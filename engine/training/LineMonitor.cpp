// The live line's monitor: commissioning runs of the same scenario, a dynamic PCA monitor fitted
// on them, and the streaming judgement fed second by second.
#include "training/LineMonitor.h"

#include <cmath>
#include <limits>

namespace drytwin::training {

namespace {

/// Seeds of the commissioning runs: far from any scenario's own, so that the reference is the
/// same line on other days, not the session's own noise.
constexpr unsigned kCommissioningSeedOffset = 90001;

void rowOf(const LiveSample& s, double* row) {
    row[0] = s.xOutPct;
    row[1] = s.tOutC;
    row[2] = s.hotAirSetpointC;
    row[3] = s.hotAirC;
    row[4] = s.feedKgH;
    row[5] = s.xInPct;
}

monitoring::MonitorRun runOf(const std::string& id, const std::vector<LiveSample>& trace) {
    monitoring::MonitorRun run;
    run.id = id;
    run.values.resize(static_cast<Eigen::Index>(trace.size()), static_cast<Eigen::Index>(LineMonitor::columns().size()));
    double row[6];
    for (std::size_t k = 0; k < trace.size(); ++k) {
        run.timeS.push_back(trace[k].timeS);
        rowOf(trace[k], row);
        for (int c = 0; c < 6; ++c) {
            run.values(static_cast<Eigen::Index>(k), c) = row[c];
        }
    }
    return run;
}

} // namespace

const std::vector<std::string>& LineMonitor::columns() {
    static const std::vector<std::string> names{"X_out_pct", "T_out_C",  "T_hot_sp_C",
                                                "T_hot_C",   "feed_kg_h", "X_in_pct"};
    return names;
}

Expected<LineMonitor> LineMonitor::commission(const control::Scenario& scenario, int runs, double falseAlarmRate) {
    if (runs < 1) {
        return invalidOption("commissioning runs", "at least one");
    }
    LineMonitor out;
    std::vector<monitoring::MonitorRun> reference;
    const auto physicsOnly = std::make_shared<const hybrid::HybridModel>();
    for (int r = 0; r < runs; ++r) {
        control::Scenario healthy = scenario;
        healthy.mechanisms.clear();
        healthy.seed = scenario.seed + kCommissioningSeedOffset + static_cast<unsigned>(r);
        auto session = TrainingSession::start(healthy, physicsOnly);
        if (!session) {
            return session.error();
        }
        session->advance(static_cast<std::size_t>(std::ceil(session->endS() - session->timeS())));
        const std::string id = "C" + std::string(r + 1 < 10 ? "0" : "") + std::to_string(r + 1);
        reference.push_back(runOf(id, session->trace()));
        out.m_runs.push_back(session->recording(id));
    }
    monitoring::MonitorOptions mo;
    mo.falseAlarmRate = falseAlarmRate;
    auto monitor = monitoring::Monitor::fit(reference, columns(), mo);
    if (!monitor) {
        return monitor.error();
    }
    out.m_monitor = std::make_shared<const monitoring::Monitor>(std::move(*monitor));
    out.m_durationS = scenario.lengthS;
    out.m_state.t2Limit = out.m_monitor->limits().t2Window;
    out.m_state.speLimit = out.m_monitor->limits().speWindow;
    if (auto st = out.restart(); !st) {
        return st.error();
    }
    return out;
}

Status LineMonitor::restart() {
    auto stream = monitoring::StreamingMonitor::create(*m_monitor, {m_durationS});
    if (!stream) {
        return stream.error();
    }
    m_stream.emplace(std::move(*stream));
    m_stream->startRun("live");
    m_fed = 0;
    const double t2Limit = m_state.t2Limit, speLimit = m_state.speLimit;
    m_state = {};
    m_state.t2Limit = t2Limit;
    m_state.speLimit = speLimit;
    m_state.ready = true;
    return {};
}

Status LineMonitor::feed(const std::vector<LiveSample>& trace) {
    if (!m_stream) {
        return Error{ErrorKind::Usage, "line monitor", "not commissioned"};
    }
    if (trace.size() < m_fed) { // a restore: the line went back, and the monitor with it
        if (auto st = restart(); !st) {
            return st;
        }
    }
    double row[6];
    for (std::size_t k = m_fed; k < trace.size(); ++k) {
        rowOf(trace[k], row);
        auto windows = m_stream->push(trace[k].timeS, row);
        if (!windows) {
            return windows.error();
        }
        for (const auto& w : *windows) {
            m_state.timeS.push_back(w.timeS);
            m_state.t2.push_back(w.t2);
            m_state.spe.push_back(w.spe);
            if (w.alarmed && !m_state.alarmed) {
                m_state.alarmed = true;
                m_state.alarmAtS = w.timeS;
                m_state.statistic = w.cusumSpe > m_stream->speThreshold() ? "SPE" : "T2";
            }
            if (w.hasOnset) {
                m_state.hasOnset = true;
                m_state.onsetS = w.onsetS;
            }
        }
    }
    m_fed = trace.size();
    return {};
}

} // namespace drytwin::training
