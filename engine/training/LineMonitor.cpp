// The live line's monitors: commissioning runs of the same scenario, the physics model calibrated
// on them, a dynamic PCA monitor of the model's error and one of the screens' signals, fed as the
// line runs.
#include "training/LineMonitor.h"

#include "calibration/Calibration.h"
#include "common/Units.h"
#include "data/Cleaning.h"
#include "data/SiBatch.h"
#include "physics/LineInputs.h"
#include "physics/LineSimulator.h"

#include <cmath>
#include <limits>

namespace drytwin::training {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Seeds of the commissioning runs: far from any scenario's own, so that the reference is the
/// same line on other days, not the session's own noise.
constexpr unsigned kCommissioningSeedOffset = 90001;

/// The model's error is fed a minute at a time: one simulation of the line per minute.
constexpr double kModelFeedS = 60;

void screenRow(const LiveSample& s, double* row) {
    row[0] = s.xOutPct;
    row[1] = s.tOutC;
    row[2] = s.hotAirSetpointC;
    row[3] = s.hotAirC;
    row[4] = s.feedKgH;
    row[5] = s.xInPct;
}

monitoring::MonitorRun screensOf(const std::string& id, const std::vector<LiveSample>& trace) {
    monitoring::MonitorRun run;
    run.id = id;
    run.values.resize(static_cast<Eigen::Index>(trace.size()), 6);
    double row[6];
    for (std::size_t k = 0; k < trace.size(); ++k) {
        run.timeS.push_back(trace[k].timeS);
        screenRow(trace[k], row);
        for (int c = 0; c < 6; ++c) {
            run.values(static_cast<Eigen::Index>(k), c) = row[c];
        }
    }
    return run;
}

data::SiBatch siOf(const data::Batch& batch) {
    data::DataSet ds;
    ds.batches.push_back(batch);
    return data::toSi(ds, data::clean(ds)).front();
}

/// The model's error on the outlet moisture [% wb] and temperature [°C] at every row of @p si,
/// with time since the session's start (the recording holds the warm-up before it).
struct ModelErrors {
    std::vector<double> timeS;
    Eigen::MatrixXd values;
};

Expected<ModelErrors> modelErrors(const data::SiBatch& si, const properties::ParameterSet& p,
                                  double sessionStartS, double fromS) {
    auto sim = physics::simulateLine(physics::toLineInputs(si), p, physics::SimulationOptions{});
    if (!sim) {
        return sim.error();
    }
    ModelErrors out;
    std::vector<std::size_t> rows;
    for (std::size_t k = 0; k < si.rows(); ++k) {
        const double t = si.timeS[k] - sessionStartS;
        if (t >= 0 && t > fromS) {
            rows.push_back(k);
        }
    }
    out.values.resize(static_cast<Eigen::Index>(rows.size()), 2);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::size_t k = rows[i];
        out.timeS.push_back(si.timeS[k] - sessionStartS);
        const bool ok = si.keep[k] != 0;
        out.values(static_cast<Eigen::Index>(i), 0) =
            ok ? units::dryToWetPct(si.xOutDb[k]) - units::dryToWetPct(sim->xOutDb[k]) : kNaN;
        out.values(static_cast<Eigen::Index>(i), 1) = ok ? si.tOutK[k] - sim->tOutK[k] : kNaN;
    }
    return out;
}

void record(const monitoring::StreamingWindow& w, double thresholdSpe, LineDetectorState& d) {
    d.timeS.push_back(w.timeS);
    d.t2.push_back(w.t2);
    d.spe.push_back(w.spe);
    if (w.alarmed && !d.alarmed) {
        d.alarmed = true;
        d.alarmAtS = w.timeS;
        d.statistic = w.cusumSpe > thresholdSpe ? "SPE" : "T2";
    }
    if (w.hasOnset) {
        d.hasOnset = true;
        d.onsetS = w.onsetS;
    }
}

} // namespace

const std::vector<std::string>& LineMonitor::screenColumns() {
    static const std::vector<std::string> names{"X_out_pct", "T_out_C",   "T_hot_sp_C",
                                                "T_hot_C",   "feed_kg_h", "X_in_pct"};
    return names;
}

Expected<LineMonitor> LineMonitor::commission(const control::Scenario& scenario, int runs,
                                              double falseAlarmRate) {
    if (runs < 1) {
        return invalidOption("commissioning runs", "at least one");
    }
    LineMonitor out;
    std::vector<monitoring::MonitorRun> screens;
    std::vector<data::SiBatch> si;
    std::vector<double> sessionStarts;
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
        screens.push_back(screensOf(id, session->trace()));
        out.m_runs.push_back(session->recording(id));
        si.push_back(siOf(out.m_runs.back()));
        sessionStarts.push_back(si.back().timeS.back() - session->trace().back().timeS);
    }
    monitoring::MonitorOptions mo;
    mo.falseAlarmRate = falseAlarmRate;
    auto screenMonitor = monitoring::Monitor::fit(screens, screenColumns(), mo);
    if (!screenMonitor) {
        return screenMonitor.error();
    }
    // The physics model commissioned on the same runs (h_HDT, k_HDT), then its error on each.
    calibration::CalibrationOptions co;
    co.maxEvaluations = 300;
    co.intervals = false;
    auto calibrated = calibration::calibrate(si, properties::ParameterSet{}, co);
    if (!calibrated) {
        return calibrated.error();
    }
    out.m_parameters = calibrated->parameters;
    std::vector<monitoring::MonitorRun> errors;
    for (std::size_t r = 0; r < si.size(); ++r) {
        auto e = modelErrors(si[r], out.m_parameters, sessionStarts[r], -1);
        if (!e) {
            return e.error();
        }
        errors.push_back({si[r].id, std::move(e->timeS), std::move(e->values)});
    }
    auto modelMonitor = monitoring::Monitor::fit(errors, {"error_X_out_pct", "error_T_out_C"}, mo);
    if (!modelMonitor) {
        return modelMonitor.error();
    }
    out.m_screens = std::make_shared<const monitoring::Monitor>(std::move(*screenMonitor));
    out.m_model = std::make_shared<const monitoring::Monitor>(std::move(*modelMonitor));
    out.m_durationS = scenario.lengthS;
    if (auto st = out.restart(); !st) {
        return st.error();
    }
    return out;
}

Status LineMonitor::restart() {
    for (auto* pair : {&m_screensStream, &m_modelStream}) {
        auto stream = monitoring::StreamingMonitor::create(pair == &m_screensStream ? *m_screens : *m_model,
                                                           {m_durationS});
        if (!stream) {
            return stream.error();
        }
        pair->emplace(std::move(*stream));
        (*pair)->startRun("live");
    }
    m_screensFed = 0;
    m_modelFedToS = -1;
    m_state = {};
    m_state.ready = true;
    m_state.pca.t2Limit = m_screens->limits().t2Window;
    m_state.pca.speLimit = m_screens->limits().speWindow;
    m_state.drytwin.t2Limit = m_model->limits().t2Window;
    m_state.drytwin.speLimit = m_model->limits().speWindow;
    return {};
}

Status LineMonitor::feed(const TrainingSession& session) {
    if (!m_screensStream) {
        return Error{ErrorKind::Usage, "line monitor", "not commissioned"};
    }
    const auto& trace = session.trace();
    if (trace.size() < m_screensFed) { // a restore: the line went back, and the monitors with it
        if (auto st = restart(); !st) {
            return st;
        }
    }
    if (auto st = feedScreens(trace); !st) {
        return st;
    }
    if (!trace.empty() && trace.back().timeS >= m_modelFedToS + kModelFeedS) {
        return feedModelError(session);
    }
    return {};
}

Status LineMonitor::feedScreens(const std::vector<LiveSample>& trace) {
    double row[6];
    for (std::size_t k = m_screensFed; k < trace.size(); ++k) {
        screenRow(trace[k], row);
        auto windows = m_screensStream->push(trace[k].timeS, row);
        if (!windows) {
            return windows.error();
        }
        for (const auto& w : *windows) {
            record(w, m_screensStream->speThreshold(), m_state.pca);
        }
    }
    m_screensFed = trace.size();
    return {};
}

Status LineMonitor::feedModelError(const TrainingSession& session) {
    const data::SiBatch si = siOf(session.recording("live"));
    const double sessionStartS = si.timeS.back() - session.trace().back().timeS;
    auto e = modelErrors(si, m_parameters, sessionStartS, m_modelFedToS);
    if (!e) {
        return e.error();
    }
    for (std::size_t k = 0; k < e->timeS.size(); ++k) {
        const auto i = static_cast<Eigen::Index>(k);
        const double row[2] = {e->values(i, 0), e->values(i, 1)}; // a matrix row is not contiguous
        auto windows = m_modelStream->push(e->timeS[k], row);
        if (!windows) {
            return windows.error();
        }
        for (const auto& w : *windows) {
            record(w, m_modelStream->speThreshold(), m_state.drytwin);
        }
        m_modelFedToS = e->timeS[k];
    }
    return {};
}

} // namespace drytwin::training
