#include "monitoring/StreamingMonitor.h"

#include <cmath>
#include <limits>

namespace drytwin::monitoring {

namespace {} // namespace

Expected<StreamingMonitor> StreamingMonitor::create(const Monitor& monitor,
                                                    const std::vector<double>& runDurationsS) {
    if (monitor.columns().empty()) {
        return Error{ErrorKind::Usage,
                     "streaming.create",
                     "the monitor has not been fitted",
                     ErrorCode::ModelNotTrained,
                     {"monitor"}};
    }
    std::vector<int> runWindows;
    for (double d : runDurationsS) {
        if (!(d > 0) || !std::isfinite(d)) {
            return invalidOption("runDurationsS", "each planned run must last a positive number of seconds");
        }
        runWindows.push_back(std::max(1, static_cast<int>(std::lround(d / monitor.windowLengthS()))));
    }
    if (runWindows.empty()) {
        return invalidOption("runDurationsS", "give the planned duration of at least one run");
    }
    StreamingMonitor s;
    s.m_monitor = monitor;
    s.m_p = static_cast<int>(monitor.columns().size());
    s.m_blocksPerWindow = monitor.options().blocksPerWindow();
    const ChangePointOptions cp = monitor.options().changePointOptions();
    const auto nulls =
        nullDistributions({monitor.t2NullModel(runWindows), monitor.speNullModel(runWindows)}, cp);
    s.m_hT2 = nulls[0]->cusumThreshold;
    s.m_hSpe = nulls[1]->cusumThreshold;
    return s;
}

void StreamingMonitor::resetRun() {
    m_hasSample = false;
    m_block = 0;
    m_blockSamples.assign(static_cast<std::size_t>(m_p), {});
    m_lagBlocks.clear();
    m_sumLogT2 = m_sumLogSpe = 0;
    m_validBlocks = 0;
}

void StreamingMonitor::startRun(const std::string& id) {
    m_run = id;
    m_inRun = true;
    resetRun();
}

Expected<std::vector<StreamingWindow>> StreamingMonitor::push(double timeS, const double* row) {
    std::vector<StreamingWindow> out;
    if (!m_inRun) {
        return Error{ErrorKind::Usage, "streaming.push", "no run started: call startRun() first"};
    }
    if (!std::isfinite(timeS) || (m_hasSample && !(timeS > m_lastT))) {
        return Error{ErrorKind::BadInput,
                     "streaming.push: run '" + m_run + "'",
                     "time is not finite and strictly increasing at " + std::to_string(timeS) + " s",
                     ErrorCode::TimeNotIncreasing,
                     {m_run, "", "timeS"}};
    }
    if (!m_hasSample) {
        m_t0 = timeS;
        m_hasSample = true;
    }
    m_lastT = timeS;
    // A gap in the timestamps closes every block it skips, as missing blocks, like the batch path.
    const int block = blockIndexOf(timeS - m_t0, m_monitor.options().blockS);
    while (m_block < block) {
        completeBlock(out);
        ++m_block;
    }
    for (int j = 0; j < m_p; ++j) {
        m_blockSamples[static_cast<std::size_t>(j)].push_back(row[j]);
    }
    return out;
}

std::vector<StreamingWindow> StreamingMonitor::endRun() {
    std::vector<StreamingWindow> out;
    if (m_inRun && m_hasSample) {
        completeBlock(out);
    }
    m_inRun = false;
    resetRun();
    return out;
}

void StreamingMonitor::completeBlock(std::vector<StreamingWindow>& out) {
    Eigen::VectorXd mean(m_p);
    for (int j = 0; j < m_p; ++j) {
        auto& samples = m_blockSamples[static_cast<std::size_t>(j)];
        mean[j] = robustBlockMean(samples); // as lagBlocks, so a stream is judged as a batch is
        samples.clear();
    }
    const int lags = m_monitor.options().lags;
    m_lagBlocks.push_front(std::move(mean));
    if (static_cast<int>(m_lagBlocks.size()) > lags) {
        m_lagBlocks.pop_back();
    }
    Eigen::VectorXd lagged = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(m_p) * lags, kNaN);
    if (static_cast<int>(m_lagBlocks.size()) == lags) {
        for (int l = 0; l < lags; ++l) {
            lagged.segment(static_cast<Eigen::Index>(l) * m_p, m_p) =
                m_lagBlocks[static_cast<std::size_t>(l)];
        }
    }
    double logT2 = kNaN, logSpe = kNaN;
    m_monitor.scoreBlock(lagged, logT2, logSpe);
    if (std::isfinite(logT2) && std::isfinite(logSpe)) {
        m_sumLogT2 += logT2;
        m_sumLogSpe += logSpe;
        ++m_validBlocks;
    }
    if (m_block % m_blocksPerWindow == m_blocksPerWindow - 1) {
        completeWindow(out);
    }
}

void StreamingMonitor::completeWindow(std::vector<StreamingWindow>& out) {
    const double windowLen = m_monitor.windowLengthS();
    const double logT2 = windowLogMean(m_sumLogT2, m_validBlocks, m_blocksPerWindow);
    const double logSpe = windowLogMean(m_sumLogSpe, m_validBlocks, m_blocksPerWindow);
    m_sumLogT2 = m_sumLogSpe = 0;
    m_validBlocks = 0;

    StreamingWindow w;
    w.run = m_run;
    w.timeS = static_cast<double>(m_block / m_blocksPerWindow + 1) * windowLen;
    w.t2 = std::exp(logT2);
    w.spe = std::exp(logSpe);
    w.zT2 = (logT2 - m_monitor.t2Null().mean) / m_monitor.t2Null().longRunSd;
    w.zSpe = (logSpe - m_monitor.speNull().mean) / m_monitor.speNull().longRunSd;
    w.cusumT2 = w.cusumSpe = kNaN;
    if (std::isfinite(logT2)) {
        const double k = m_monitor.options().changePointOptions().cusumK;
        m_cusumT2 = std::max(0.0, m_cusumT2 + w.zT2 - k);
        m_cusumSpe = std::max(0.0, m_cusumSpe + w.zSpe - k);
        w.cusumT2 = m_cusumT2;
        w.cusumSpe = m_cusumSpe;
        m_zT2.push_back(w.zT2);
        m_zSpe.push_back(w.zSpe);
        m_zWhere.emplace_back(m_run, w.timeS - windowLen);
        w.alarm = m_cusumT2 > m_hT2 || m_cusumSpe > m_hSpe;
        if (w.alarm && !m_alarmed) {
            m_alarmed = true;
            m_alarmIndex = static_cast<int>(m_zT2.size()) - 1;
            m_alarmBySpe = m_cusumSpe - m_hSpe >= m_cusumT2 - m_hT2;
        }
    }
    w.alarmed = m_alarmed;
    if (m_alarmed) {
        // Any segment length: the CUSUM has already judged; the GLR only places the onset, and
        // the onset cannot come after the alarm that revealed it.
        const GlrScan scan = scanGlr(m_alarmBySpe ? m_zSpe : m_zT2, 1, m_alarmIndex);
        if (scan.onset >= 0) {
            w.hasOnset = true;
            w.onsetRun = m_zWhere[static_cast<std::size_t>(scan.onset)].first;
            w.onsetS = m_zWhere[static_cast<std::size_t>(scan.onset)].second;
        }
    }
    out.push_back(std::move(w));
}

} // namespace drytwin::monitoring
