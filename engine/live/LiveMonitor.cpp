#include "LiveMonitor.h"

#include "training/LineMonitor.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace drytwin::live {

Status LiveMonitorOptions::validate() const {
    if (!(falseAlarmRate > 0 && falseAlarmRate < 0.5)) {
        return invalidOption("--false-alarm-rate", "must lie in (0, 0.5)");
    }
    if (!(plannedRunS >= 0)) {
        return invalidOption("--planned-run", "must be 0 (the reference's batches) or a number of seconds");
    }
    return {};
}

const std::vector<data::Column>& LiveMonitor::columns() {
    // The training line's screens, by name (training/LineMonitor.h), so that both monitors watch
    // the same tags.
    static const std::vector<data::Column> cols = [] {
        std::vector<data::Column> c;
        for (const auto& name : training::LineMonitor::screenColumns()) {
            c.push_back(*data::columnByName(name));
        }
        return c;
    }();
    return cols;
}

Expected<LiveMonitor> LiveMonitor::commission(const data::DataSet& reference,
                                              const LiveMonitorOptions& options) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    std::vector<monitoring::MonitorRun> runs;
    double totalS = 0;
    for (const auto& b : reference.batches) {
        const auto* time = b.values(data::Column::Time);
        if (!time || b.rows() < 2) {
            continue;
        }
        monitoring::MonitorRun run;
        run.id = b.id;
        run.timeS = *time;
        run.values.resize(static_cast<Eigen::Index>(b.rows()), static_cast<Eigen::Index>(columns().size()));
        for (std::size_t c = 0; c < columns().size(); ++c) {
            const auto* v = b.values(columns()[c]);
            if (!v) {
                return Error{ErrorKind::BadInput, b.sourcePath.empty() ? b.id : b.sourcePath,
                             "the reference lacks the column '" + std::string(data::spec(columns()[c]).name) +
                                 "' the live monitor watches"};
            }
            for (std::size_t r = 0; r < b.rows(); ++r) {
                run.values(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = (*v)[r];
            }
        }
        totalS += time->back() - time->front() + 1;
        runs.push_back(std::move(run));
    }
    if (runs.empty()) {
        return Error{ErrorKind::BadInput,
                     "--reference",
                     "the reference holds no batch with rows",
                     ErrorCode::NotEnoughData,
                     {"reference batches", "0"}};
    }
    monitoring::MonitorOptions mo;
    mo.falseAlarmRate = options.falseAlarmRate;
    std::vector<std::string> names;
    for (auto c : columns()) {
        names.emplace_back(data::spec(c).name);
    }
    auto fitted = monitoring::Monitor::fit(runs, names, mo);
    if (!fitted) {
        Error e = fitted.error();
        e.place = "--reference: " + e.place;
        return e;
    }
    LiveMonitor out;
    out.m_monitor = std::make_shared<const monitoring::Monitor>(std::move(*fitted));
    out.m_plannedRunS =
        options.plannedRunS > 0 ? options.plannedRunS : totalS / static_cast<double>(runs.size());
    auto stream = monitoring::StreamingMonitor::create(*out.m_monitor, {out.m_plannedRunS});
    if (!stream) {
        return stream.error();
    }
    out.m_stream.emplace(std::move(*stream));
    return out;
}

Expected<std::vector<monitoring::StreamingWindow>>
LiveMonitor::push(const std::string& batch, double batchStartS, double timeS,
                  const std::array<double, data::kColumnCount>& values) {
    std::vector<monitoring::StreamingWindow> out;
    if (batch != m_run) {
        out = finish();
        m_stream->startRun(batch);
        m_run = batch;
        m_runStartS = batchStartS;
    }
    double row[8];
    for (std::size_t c = 0; c < columns().size(); ++c) {
        row[c] = values[static_cast<std::size_t>(columns()[c])];
    }
    auto windows = m_stream->push(timeS, row);
    if (!windows) {
        return windows.error();
    }
    out.insert(out.end(), windows->begin(), windows->end());
    return out;
}

std::vector<monitoring::StreamingWindow> LiveMonitor::finish() {
    if (m_run.empty()) {
        return {};
    }
    return m_stream->endRun();
}

std::optional<LiveAlarm> LiveMonitor::alarmOf(const monitoring::StreamingWindow& w) {
    if (!w.alarmed || m_alarmTold) {
        return std::nullopt;
    }
    m_alarmTold = true;
    LiveAlarm a;
    a.batch = w.run;
    a.timeS = w.timeS;
    a.statistic = w.cusumT2 > m_stream->t2Threshold() ? "T2" : "SPE";
    a.hasOnset = w.hasOnset;
    a.onsetBatch = w.onsetRun;
    a.onsetS = w.onsetS;
    return a;
}

namespace {

nlohmann::json numberOrNull(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

} // namespace

std::string LiveMonitor::windowPayload(const monitoring::StreamingWindow& w) const {
    nlohmann::json j;
    j["t"] = windowEndUnixS(w);
    j["batch"] = w.run;
    j["time_s"] = w.timeS;
    j["t2"] = numberOrNull(w.t2);
    j["spe"] = numberOrNull(w.spe);
    j["z_t2"] = numberOrNull(w.zT2);
    j["z_spe"] = numberOrNull(w.zSpe);
    j["cusum_t2"] = numberOrNull(w.cusumT2);
    j["cusum_spe"] = numberOrNull(w.cusumSpe);
    j["cusum_t2_limit"] = t2Threshold();
    j["cusum_spe_limit"] = speThreshold();
    j["alarm"] = w.alarm;
    j["alarmed"] = w.alarmed;
    return j.dump();
}

std::string LiveMonitor::alarmPayload(const LiveAlarm& a, const monitoring::StreamingWindow& w) const {
    nlohmann::json j;
    j["t"] = windowEndUnixS(w);
    j["batch"] = a.batch;
    j["time_s"] = a.timeS;
    j["statistic"] = a.statistic;
    if (a.hasOnset) {
        j["onset_batch"] = a.onsetBatch;
        j["onset_s"] = a.onsetS;
    }
    return j.dump();
}

} // namespace drytwin::live
