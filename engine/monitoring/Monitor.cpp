#include "monitoring/Monitor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace drytwin::monitoring {

namespace {

/// NotEnoughData with its arguments {what, count}.
Error notEnoughData(const std::string& place, const std::string& reason, const std::string& what,
                    std::size_t count) {
    return Error{ErrorKind::BadInput, place, reason, ErrorCode::NotEnoughData, {what, std::to_string(count)}};
}

NullModel nullModelOf(const LongRunNull& null, const std::vector<int>& runWindows,
                      const std::vector<char>& levelFree) {
    NullModel m;
    m.runLengths = runWindows;
    if (std::find(levelFree.begin(), levelFree.end(), char{1}) != levelFree.end()) {
        m.levelFree = levelFree; // else empty: the same cached null as every fully judged series
    }
    m.runEffectVariance = null.runEffectVariance;
    m.offsetVariance = null.offsetVariance;
    return m;
}

Status checkRuns(const std::vector<MonitorRun>& runs, std::size_t columns, const std::string& place) {
    for (const auto& run : runs) {
        const std::string where = place + ": run '" + run.id + "'";
        if (static_cast<std::size_t>(run.values.cols()) != columns) {
            return Error{ErrorKind::BadInput, where,
                         "has " + std::to_string(run.values.cols()) + " columns; the monitor has " +
                             std::to_string(columns) + " column names"};
        }
        if (run.timeS.size() != static_cast<std::size_t>(run.values.rows()) || run.timeS.empty()) {
            return Error{ErrorKind::BadInput, where,
                         "has " + std::to_string(run.timeS.size()) + " times for " +
                             std::to_string(run.values.rows()) +
                             " rows (need one time per row, at least one row)"};
        }
        for (std::size_t i = 0; i < run.timeS.size(); ++i) {
            if (!std::isfinite(run.timeS[i]) || (i > 0 && !(run.timeS[i] > run.timeS[i - 1]))) {
                return Error{ErrorKind::BadInput,
                             where,
                             "time is not finite and strictly increasing at row " + std::to_string(i + 1),
                             ErrorCode::TimeNotIncreasing,
                             {run.id, std::to_string(i + 1), "timeS"}};
            }
        }
    }
    return {};
}

/// Linear-interpolation quantile (type 7) of finite values.
double quantile(std::vector<double> v, double q) {
    if (v.empty()) {
        return kNaN;
    }
    std::sort(v.begin(), v.end());
    const double pos = q * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const auto hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

std::string formatNumber(double v, const char* format) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

} // namespace

Status MonitorOptions::validate() const {
    if (Status s = pcaOptions().validate(); !s) {
        return s;
    }
    if (!(windowS >= blockS) || !std::isfinite(windowS)) {
        return invalidOption("windowS", "the window must be at least one block long");
    }
    if (!(falseAlarmRate > 0 && falseAlarmRate < 0.5)) {
        return invalidOption("falseAlarmRate", "the false-alarm rate must be in (0, 0.5)");
    }
    if (!(minSegmentS > 0) || !std::isfinite(minSegmentS)) {
        return invalidOption("minSegmentS",
                             "the shortest shifted stretch must be a positive number of seconds");
    }
    return changePointOptions().validate();
}

DynamicPcaOptions MonitorOptions::pcaOptions() const {
    return DynamicPcaOptions{blockS, lags, varianceExplained, confidence};
}

int MonitorOptions::blocksPerWindow() const {
    return std::max(1, static_cast<int>(std::lround(windowS / blockS)));
}

ChangePointOptions MonitorOptions::changePointOptions() const {
    ChangePointOptions o;
    o.falseAlarmRate = falseAlarmRate / 2;
    o.minSegment = std::max(1, static_cast<int>(std::lround(minSegmentS / (blocksPerWindow() * blockS))));
    o.simulations = simulations;
    o.seed = seed;
    return o;
}

Expected<Monitor> Monitor::fit(const std::vector<MonitorRun>& reference,
                               const std::vector<std::string>& columns, const MonitorOptions& options) {
    const std::string place = "monitor.fit";
    if (Status s = options.validate(); !s) {
        return s.error();
    }
    if (columns.empty()) {
        return Error{ErrorKind::BadInput, place, "no columns to monitor"};
    }
    if (reference.empty()) {
        return notEnoughData(place, "no reference runs: give at least one healthy run", "reference runs", 0);
    }
    if (Status s = checkRuns(reference, columns.size(), place); !s) {
        return s.error();
    }
    const int p = static_cast<int>(columns.size());
    const int bpw = options.blocksPerWindow();
    const DynamicPcaOptions pcaOptions = options.pcaOptions();
    const int minWindows = std::max(2, options.changePointOptions().minSegment);

    // With one run, its thirds stand in for independent runs in the leave-one-out null.
    const bool thirds = reference.size() == 1;
    std::vector<MonitorRun> split;
    if (thirds) {
        const MonitorRun& run = reference.front();
        const Eigen::Index rows = run.values.rows();
        for (int k = 0; k < 3; ++k) {
            const Eigen::Index begin = rows * k / 3, end = rows * (k + 1) / 3;
            MonitorRun part{run.id + " (third " + std::to_string(k + 1) + ")",
                            std::vector<double>(run.timeS.begin() + begin, run.timeS.begin() + end),
                            run.values.middleRows(begin, end - begin)};
            split.push_back(std::move(part));
        }
    }
    const std::vector<MonitorRun>& parts = thirds ? split : reference;
    std::vector<Eigen::MatrixXd> lagged;
    std::vector<LaggedMoments> moments;
    for (const auto& part : parts) {
        lagged.push_back(part.timeS.empty()
                             ? Eigen::MatrixXd(0, p * options.lags)
                             : lagBlocks(part.timeS, part.values, options.blockS, options.lags));
        moments.push_back(LaggedMoments::of(lagged.back()));
    }
    // Windows in the words of the line: minutes of data.
    const double windowMinutes = options.blocksPerWindow() * options.blockS / 60;
    const auto minutesOf = [windowMinutes](int windows) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f min", windows * windowMinutes);
        return std::string(text);
    };
    const auto tooShort = [&](const std::string& why) {
        const MonitorRun& run = reference.front();
        return notEnoughData(place + ": reference run '" + run.id + "'",
                             "a single reference run of " + std::to_string(run.values.rows()) +
                                 " rows is too short to split in three parts for the monitor's null (" + why +
                                 "); give a longer run or more runs",
                             "reference rows", static_cast<std::size_t>(run.values.rows()));
    };

    auto full = thirds
                    ? DynamicPca::fit(std::vector<Eigen::MatrixXd>{lagBlocks(reference.front().timeS,
                                                                             reference.front().values,
                                                                             options.blockS, options.lags)},
                                      p, pcaOptions, place)
                    : DynamicPca::fit(moments, p, pcaOptions, place);
    if (!full) {
        return full.error();
    }

    std::vector<DynamicPca> leaveOneOut;
    std::vector<double> blockT2, blockSpe, windowT2, windowSpe;
    std::vector<std::vector<double>> seriesT2, seriesSpe;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        std::vector<LaggedMoments> others;
        for (std::size_t j = 0; j < parts.size(); ++j) {
            if (j != k) {
                others.push_back(moments[j]);
            }
        }
        auto loo =
            DynamicPca::fit(others, p, pcaOptions, place + ": leave-one-out without '" + parts[k].id + "'");
        if (!loo) {
            return thirds ? tooShort(loo.error().reason) : loo.error();
        }
        const Eigen::Index rows = lagged[k].rows();
        Eigen::VectorXd blockLogT2(rows), blockLogSpe(rows);
        for (Eigen::Index r = 0; r < rows; ++r) {
            double t2 = kNaN, spe = kNaN;
            loo->scoreRow(lagged[k].row(r).transpose(), t2, spe);
            blockLogT2[r] = std::isfinite(t2) ? logStatistic(t2) : kNaN;
            blockLogSpe[r] = std::isfinite(spe) ? logStatistic(spe) : kNaN;
            if (std::isfinite(t2)) {
                blockT2.push_back(t2);
                blockSpe.push_back(spe);
            }
        }
        leaveOneOut.push_back(std::move(*loo));
        std::vector<double> logT2, logSpe;
        windowLogMeans(blockLogT2, blockLogSpe, bpw, logT2, logSpe);
        seriesT2.emplace_back();
        seriesSpe.emplace_back();
        for (std::size_t w = 0; w < logT2.size(); ++w) {
            if (std::isfinite(logT2[w])) {
                seriesT2.back().push_back(logT2[w]);
                seriesSpe.back().push_back(logSpe[w]);
                windowT2.push_back(std::exp(logT2[w]));
                windowSpe.push_back(std::exp(logSpe[w]));
            }
        }
        // A part shorter than the shortest shifted stretch could not show the wander the GLR
        // is judged against, and the null would rest on too few windows.
        if (thirds && static_cast<int>(seriesT2.back().size()) < minWindows) {
            return tooShort("each third needs at least " + minutesOf(minWindows) +
                            " of valid data, the shortest change the monitor looks for");
        }
    }
    if (static_cast<int>(windowT2.size()) < 3 * minWindows) {
        return notEnoughData(place,
                             "the reference holds only " + minutesOf(static_cast<int>(windowT2.size())) +
                                 " of valid data; the monitor's null needs at least " +
                                 minutesOf(3 * minWindows) +
                                 " (three times the shortest change it looks for): give a longer reference "
                                 "period or more runs",
                             "reference windows", windowT2.size());
    }
    auto t2Null = longRunNull(seriesT2, place + ": T2 null");
    auto speNull = longRunNull(seriesSpe, place + ": SPE null");
    if (!t2Null) {
        return t2Null.error();
    }
    if (!speNull) {
        return speNull.error();
    }

    Monitor monitor;
    monitor.m_options = options;
    monitor.m_columns = columns;
    monitor.m_pca = std::move(*full);
    monitor.m_leaveOneOut = std::move(leaveOneOut);
    monitor.m_t2Null = *t2Null;
    monitor.m_speNull = *speNull;
    monitor.m_limits.t2Theoretical = monitor.m_pca.t2Limit();
    monitor.m_limits.speTheoretical = monitor.m_pca.speLimit();
    monitor.m_limits.t2Empirical = quantile(blockT2, options.confidence);
    monitor.m_limits.speEmpirical = quantile(blockSpe, options.confidence);
    monitor.m_limits.t2Window = quantile(windowT2, options.confidence);
    monitor.m_limits.speWindow = quantile(windowSpe, options.confidence);
    return monitor;
}

void Monitor::scoreBlock(const Eigen::Ref<const Eigen::VectorXd>& lagged, double& logT2,
                         double& logSpe) const {
    logT2 = logSpe = 0;
    for (const DynamicPca& fit : m_leaveOneOut) {
        double t2 = kNaN, spe = kNaN;
        fit.scoreRow(lagged, t2, spe);
        if (!std::isfinite(t2)) {
            logT2 = logSpe = kNaN;
            return;
        }
        logT2 += logStatistic(t2);
        logSpe += logStatistic(spe);
    }
    logT2 /= static_cast<double>(m_leaveOneOut.size());
    logSpe /= static_cast<double>(m_leaveOneOut.size());
}

NullModel Monitor::t2NullModel(const std::vector<int>& runWindows, const std::vector<char>& levelFree) const {
    return nullModelOf(m_t2Null, runWindows, levelFree);
}

NullModel Monitor::speNullModel(const std::vector<int>& runWindows,
                                const std::vector<char>& levelFree) const {
    return nullModelOf(m_speNull, runWindows, levelFree);
}

Expected<Detection> Monitor::judge(const std::vector<MonitorRun>& runs) const {
    const auto started = std::chrono::steady_clock::now();
    const std::string place = "monitor.judge";
    if (runs.empty()) {
        return notEnoughData(place, "no runs to judge", "runs", 0);
    }
    if (Status s = checkRuns(runs, m_columns.size(), place); !s) {
        return s.error();
    }
    const int bpw = m_options.blocksPerWindow();
    const double windowLen = windowLengthS();
    Detection d;
    d.falseAlarmRate = m_options.falseAlarmRate;
    d.limits = m_limits;
    d.components = m_pca.components();
    d.varianceExplainedActual = m_pca.varianceExplained();

    std::vector<PcaScores> scores;
    std::vector<double> zT2, zSpe;
    std::vector<int> zWhere;     // series index of each z
    std::vector<int> runWindows; // valid windows per run
    std::vector<char> levelFree; // per run: its level is not judged
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const Eigen::MatrixXd lagged =
            lagBlocks(runs[r].timeS, runs[r].values, m_options.blockS, m_options.lags);
        scores.push_back(m_pca.score(lagged));
        Eigen::VectorXd blockLogT2(lagged.rows()), blockLogSpe(lagged.rows());
        for (Eigen::Index b = 0; b < lagged.rows(); ++b) {
            scoreBlock(lagged.row(b).transpose(), blockLogT2[b], blockLogSpe[b]);
        }
        std::vector<double> logT2, logSpe;
        windowLogMeans(blockLogT2, blockLogSpe, bpw, logT2, logSpe);
        d.runStarts.push_back(static_cast<int>(d.series.size()));
        runWindows.push_back(0);
        for (std::size_t w = 0; w < logT2.size(); ++w) {
            const WindowPoint pt{runs[r].id,
                                 static_cast<int>(r),
                                 static_cast<double>(w + 1) * windowLen,
                                 std::exp(logT2[w]),
                                 std::exp(logSpe[w]),
                                 m_limits.t2Window,
                                 m_limits.speWindow,
                                 (logT2[w] - m_t2Null.mean) / m_t2Null.longRunSd,
                                 (logSpe[w] - m_speNull.mean) / m_speNull.longRunSd,
                                 kNaN,
                                 kNaN,
                                 false};
            if (std::isfinite(logT2[w])) {
                zT2.push_back(pt.zT2);
                zSpe.push_back(pt.zSpe);
                zWhere.push_back(static_cast<int>(d.series.size()));
                ++runWindows.back();
            }
            d.series.push_back(pt);
        }
        levelFree.push_back(runs[r].levelJudged ? 0 : 1);
        if (!runs[r].levelJudged && runWindows.back() > 0) { // only changes within the run count
            const int n = runWindows.back();
            const auto takeOffRunMean = [n](std::vector<double>& z) { // the run's values are z's last n
                const auto first = z.end() - n;
                const double mean = std::accumulate(first, z.end(), 0.0) / n;
                std::for_each(first, z.end(), [mean](double& v) { v -= mean; });
                return mean;
            };
            const double meanT2 = takeOffRunMean(zT2), meanSpe = takeOffRunMean(zSpe);
            for (auto it = zWhere.end() - n; it != zWhere.end(); ++it) {
                d.series[static_cast<std::size_t>(*it)].zT2 -= meanT2;
                d.series[static_cast<std::size_t>(*it)].zSpe -= meanSpe;
            }
            d.levelNotJudged.push_back(runs[r].id);
        }
    }

    const ChangePointOptions cp = m_options.changePointOptions();
    const NullModel t2Model = t2NullModel(runWindows, levelFree),
                    speModel = speNullModel(runWindows, levelFree);
    nullDistributions({t2Model, speModel}, cp); // one simulation for both
    auto t2 = detectChangePoint(zT2, t2Model, cp);
    auto spe = detectChangePoint(zSpe, speModel, cp);
    if (!t2 || !spe) {
        return (!t2 ? t2 : spe).error();
    }
    const auto toSeries = [&](int zIndex) {
        return zIndex < 0 ? -1 : zWhere[static_cast<std::size_t>(zIndex)];
    };
    for (std::size_t i = 0; i < zWhere.size(); ++i) {
        WindowPoint& pt = d.series[static_cast<std::size_t>(zWhere[i])];
        pt.cusumT2 = t2->cusum[i];
        pt.cusumSpe = spe->cusum[i];
        pt.alarm = pt.cusumT2 > t2->cusumThreshold || pt.cusumSpe > spe->cusumThreshold;
    }
    const auto judgement = [&](const ChangePointResult& c) {
        const GlrScan& g = c.scan;
        return StatisticJudgement{c.changed,         c.pValue,         c.glr,
                                  c.glrThreshold,    c.cusumThreshold, toSeries(c.firstAlarm),
                                  toSeries(g.onset), toSeries(g.low),  toSeries(g.high)};
    };
    d.t2 = judgement(*t2);
    d.spe = judgement(*spe);

    // The deciding statistic: the one beyond its threshold, or the smaller p (then the larger
    // margin) when both or neither are.
    const bool bySpe =
        d.spe.changed != d.t2.changed
            ? d.spe.changed
            : (d.spe.pValue != d.t2.pValue ? d.spe.pValue < d.t2.pValue
                                           : d.spe.glr - d.spe.glrThreshold >= d.t2.glr - d.t2.glrThreshold);
    const StatisticJudgement& decider = bySpe ? d.spe : d.t2;
    d.statistic = bySpe ? "SPE" : "T2";
    d.changed = d.t2.changed || d.spe.changed;
    d.pValue = std::min(1.0, 2 * decider.pValue);

    if (d.changed && decider.onsetWindow >= 0) {
        d.hasOnset = true;
        d.onsetWindow = decider.onsetWindow;
        d.onsetLowWindow = decider.onsetLowWindow;
        d.onsetHighWindow = decider.onsetHighWindow;
        const WindowPoint& at = d.series[static_cast<std::size_t>(d.onsetWindow)];
        const WindowPoint& low = d.series[static_cast<std::size_t>(d.onsetLowWindow)];
        const WindowPoint& high = d.series[static_cast<std::size_t>(d.onsetHighWindow)];
        const auto runEnd = static_cast<std::size_t>(at.runIndex + 1 < static_cast<int>(d.runStarts.size())
                                                         ? d.runStarts[at.runIndex + 1]
                                                         : d.series.size());
        // A change at the first window judged after a stretch no window judges (the run's first
        // minutes, the model's start-up; frozen or cleaned-out readings) may have come anywhere in
        // that stretch, at the batch change (a cleaning, a maintenance) too: the interval reaches
        // back to the end of the last window judged before it, or to the run's start. It read
        // "15 to 16 min" for a fouling whose windows from 8 to 15 min were not judged.
        const auto stretchStart = [&](int w) {
            const int run = d.series[static_cast<std::size_t>(w)].runIndex;
            for (int s = w - 1; s >= 0 && d.series[static_cast<std::size_t>(s)].runIndex == run; --s) {
                if (std::isfinite(d.series[static_cast<std::size_t>(s)].zT2)) {
                    return d.series[static_cast<std::size_t>(s)].timeS;
                }
            }
            return 0.0;
        };
        d.onsetRun = at.run;
        d.onsetS = at.timeS - windowLen;
        d.onsetLowS = low.runIndex == at.runIndex ? stretchStart(d.onsetLowWindow) : 0.0;
        d.onsetHighS = high.runIndex == at.runIndex ? high.timeS : d.series[runEnd - 1].timeS;
    }
    const int firstT2 = d.t2.firstAlarmWindow, firstSpe = d.spe.firstAlarmWindow;
    d.firstAlarmWindow = firstT2 < 0 ? firstSpe : (firstSpe < 0 ? firstT2 : std::min(firstT2, firstSpe));
    if (d.firstAlarmWindow >= 0) {
        d.hasFirstAlarm = true;
        d.firstAlarmRun = d.series[static_cast<std::size_t>(d.firstAlarmWindow)].run;
        d.firstAlarmTimeS = d.series[static_cast<std::size_t>(d.firstAlarmWindow)].timeS;
    }

    // Shares rather than raw contributions: a block with a huge statistic would otherwise
    // decide the ranking alone.
    const int p = static_cast<int>(m_columns.size());
    Eigen::MatrixXd shares = Eigen::MatrixXd::Zero(p, 4); // SPE, T², SPE reconstruction, T² reconstruction
    double counted = 0;
    for (std::size_t s = d.hasOnset ? static_cast<std::size_t>(d.onsetWindow) : 0; s < d.series.size(); ++s) {
        const auto r = static_cast<std::size_t>(d.series[s].runIndex);
        const Eigen::Index w = static_cast<Eigen::Index>(s) - d.runStarts[r];
        const PcaScores& sc = scores[r];
        for (Eigen::Index b = w * bpw; b < (w + 1) * bpw; ++b) {
            const double speRbc = std::isfinite(sc.t2[b]) ? sc.speReconstruction.row(b).sum() : 0.0;
            const double t2Rbc = std::isfinite(sc.t2[b]) ? sc.t2Reconstruction.row(b).sum() : 0.0;
            if (sc.t2[b] > 0 && sc.spe[b] > 0 && speRbc > 0 && t2Rbc > 0) {
                shares.col(0) += sc.speContributions.row(b).transpose() / sc.spe[b];
                shares.col(1) += sc.t2Contributions.row(b).transpose() / sc.t2[b];
                shares.col(2) += sc.speReconstruction.row(b).transpose() / speRbc;
                shares.col(3) += sc.t2Reconstruction.row(b).transpose() / t2Rbc;
                counted += 1;
            }
        }
    }
    if (counted > 0) {
        shares /= counted;
    }
    for (int j = 0; j < p; ++j) {
        d.contributions.push_back(
            {m_columns[static_cast<std::size_t>(j)], shares(j, 0), shares(j, 1), shares(j, 2), shares(j, 3)});
    }
    std::stable_sort(d.contributions.begin(), d.contributions.end(),
                     [bySpe](const Contribution& a, const Contribution& b) {
                         return bySpe ? a.speReconstructionShare > b.speReconstructionShare
                                      : a.t2ReconstructionShare > b.t2ReconstructionShare;
                     });

    d.ending.termination = Termination::Completed;
    const std::string pText = formatNumber(d.pValue, "%.3g");
    if (d.changed) {
        d.ending.message = d.statistic + " differs from the reference (p = " + pText + ") from run '" +
                           d.onsetRun + "' at " + formatNumber(d.onsetS, "%.0f") +
                           " s; largest share: " + d.contributions.front().column;
    } else {
        d.ending.message = "no change against the reference (p = " + pText + " for " + d.statistic + ")";
    }
    if (zT2.size() < static_cast<std::size_t>(cp.minSegment)) {
        d.ending.message += "; only " + std::to_string(zT2.size()) + " valid windows, fewer than the " +
                            std::to_string(cp.minSegment) + " a shifted stretch needs";
    }
    d.ending.elapsedSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return d;
}

} // namespace drytwin::monitoring
