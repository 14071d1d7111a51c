// Detection against a reference period: does the new data differ from the time the line ran
// well, and from when? Two monitors fitted on the same reference at the same false-alarm rate:
// the dynamic PCA monitor every process engineer knows (the measured columns), and DryTwin's own
// (the commissioned model's error on each measured output, the line's own structure taken off). The model
// takes out what the inputs explain, so a change in how the line answers its inputs stands out
// against a much smaller normal spread than the outputs themselves have.
#include "discovery/DiscoveryInternal.h"

#include "common/Units.h"

#include <cmath>
#include <limits>

namespace drytwin::discovery::detail {

const std::array<InputColumn, 8>& inputColumns() {
    static const std::array<InputColumn, 8> columns{{
        {"T_hot_sp_C", "°C",
         [](const data::SiBatch& b, std::size_t k) { return units::kelvinToCelsius(b.tHotSpK[k]); }},
        {"T_hot_C", "°C",
         [](const data::SiBatch& b, std::size_t k) { return units::kelvinToCelsius(b.tHotK[k]); }},
        {"air_speed_m_s", "m/s", [](const data::SiBatch& b, std::size_t k) { return b.airSpeedMPerS[k]; }},
        {"feed_kg_h", "kg/h", [](const data::SiBatch& b, std::size_t k) { return 3600 * b.feedKgPerS[k]; }},
        {"X_in_pct", "% wb",
         [](const data::SiBatch& b, std::size_t k) { return units::dryToWetPct(b.xInDb[k]); }},
        {"T_in_C", "°C",
         [](const data::SiBatch& b, std::size_t k) { return units::kelvinToCelsius(b.tInK[k]); }},
        {"T_amb_C", "°C",
         [](const data::SiBatch& b, std::size_t k) { return units::kelvinToCelsius(b.tAmbK[k]); }},
        {"RH_amb_pct", "%", [](const data::SiBatch& b, std::size_t k) { return 100 * b.rhAmb[k]; }},
    }};
    return columns;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const char* const kMeasuredOutputs[] = {"X_out_pct", "T_out_C", "X_hdt_pct", "T_hdt_C"};
const char* const kResidualNames[] = {"error_X_out_pct", "error_T_out_C", "error_X_hdt_pct", "error_T_hdt_C"};

/// Whether every batch of both sets measures output channel @p c.
bool measuredEverywhere(const std::vector<data::SiBatch>& a, const std::vector<data::SiBatch>& b, int c) {
    const auto has = [c](const data::SiBatch& x) {
        return c == kXOut || c == kTOut || (c == kXHdt ? x.hasXHdt : x.hasTHdt);
    };
    for (const auto* set : {&a, &b}) {
        for (const auto& x : *set) {
            if (!has(x)) {
                return false;
            }
        }
    }
    return true;
}

/// The monitored rows of one batch: the inputs and the measured outputs (PCA), or the model's
/// error on each measured output alone (DryTwin: the inputs' own variation between periods, a
/// new operating point, is not a change of the line, and the model already answers it). Rows the cleaning
/// rules drop are missing, so a spike or a dropout is not read as a change.
monitoring::MonitorRun runOf(const data::SiBatch& b, const physics::SimulationResult& sim,
                             const std::vector<int>& channels, bool residuals) {
    monitoring::MonitorRun run;
    run.id = b.id;
    run.timeS = b.timeS;
    const auto& kInputs = inputColumns();
    const std::size_t inputs = residuals ? 0 : kInputs.size();
    const auto cols = static_cast<Eigen::Index>(inputs + channels.size());
    run.values.resize(static_cast<Eigen::Index>(b.rows()), cols);
    for (std::size_t k = 0; k < b.rows(); ++k) {
        const auto row = static_cast<Eigen::Index>(k);
        Eigen::Index c = 0;
        for (std::size_t i = 0; i < inputs; ++i) {
            run.values(row, c++) = b.keep[k] ? kInputs[i].at(b, k) : kNaN;
        }
        for (int ch : channels) {
            double obs = 0, pred = 0, toFile = 1;
            const bool ok = channelAt(b, sim, k, k, ch, obs, pred, toFile);
            run.values(row, c++) = ok ? (residuals ? obs - pred : obs) : kNaN;
        }
    }
    return run;
}

Expected<monitoring::Detection>
judgeWith(const std::vector<data::SiBatch>& reference, const std::vector<physics::SimulationResult>& refSims,
          const std::vector<data::SiBatch>& batches, const std::vector<physics::SimulationResult>& sims,
          const std::vector<int>& channels, bool residuals, const monitoring::MonitorOptions& mo,
          const std::vector<bool>& levelJudged, std::vector<std::string>& columns) {
    columns.clear();
    if (!residuals) {
        for (const auto& in : inputColumns()) {
            columns.emplace_back(in.name);
        }
    }
    for (int ch : channels) {
        columns.emplace_back(residuals ? kResidualNames[ch] : kMeasuredOutputs[ch]);
    }
    std::vector<monitoring::MonitorRun> refRuns, newRuns;
    for (std::size_t b = 0; b < reference.size(); ++b) {
        refRuns.push_back(runOf(reference[b], refSims[b], channels, residuals));
    }
    for (std::size_t b = 0; b < batches.size(); ++b) {
        newRuns.push_back(runOf(batches[b], sims[b], channels, residuals));
        newRuns.back().levelJudged = levelJudged[b];
    }
    auto monitor = monitoring::Monitor::fit(refRuns, columns, mo);
    if (!monitor) {
        Error e = monitor.error();
        // The monitor's own name ("monitor.fit: reference run 'B01'") tells a user nothing; the run does.
        const std::string internal = "monitor.fit";
        e.place = "the reference period" +
                  (e.place.rfind(internal, 0) == 0 ? e.place.substr(internal.size()) : ": " + e.place);
        return e;
    }
    return monitor->judge(newRuns);
}

} // namespace

Expected<ChangeDetection>
detectChange(const std::vector<data::SiBatch>& reference, const std::vector<data::SiBatch>& referenceForModel,
             const std::vector<physics::SimulationResult>& refSims, const std::vector<data::SiBatch>& batches,
             const std::vector<data::SiBatch>& batchesForModel,
             const std::vector<physics::SimulationResult>& sims, const DiscoveryOptions& options) {
    std::vector<int> channels;
    for (int c = 0; c < 4; ++c) {
        if (measuredEverywhere(reference, batches, c)) {
            channels.push_back(c);
        }
    }
    monitoring::MonitorOptions mo;
    mo.falseAlarmRate = options.falseAlarmRate;
    std::vector<bool> levelJudged(batches.size(), true);
    if (options.judgeOnlyChangesBeyondReferenceConditions) {
        for (const auto& o : outsideReference(reference, batches)) {
            levelJudged[o.batch] = false;
        }
    }
    ChangeDetection out;
    out.falseAlarmRate = options.falseAlarmRate;
    // DryTwin's monitor shares its detector's rate with the causes' change tests (Bonferroni).
    monitoring::MonitorOptions half = mo;
    half.falseAlarmRate = options.falseAlarmRate / 2;
    auto drytwin = judgeWith(referenceForModel, refSims, batchesForModel, sims, channels, true, half,
                             levelJudged, out.drytwinColumns);
    if (!drytwin) {
        return drytwin.error();
    }
    auto pca = judgeWith(reference, refSims, batches, sims, channels, false, mo, levelJudged, out.pcaColumns);
    if (!pca) {
        return pca.error();
    }
    out.drytwin = std::move(*drytwin);
    out.pca = std::move(*pca);
    decide(out);
    return out;
}

void decide(ChangeDetection& d) {
    d.drytwinChanged = d.drytwin.changed || d.causeTest.changed;
    d.changed = d.drytwinChanged || d.pca.changed;
    d.decidedBy = d.drytwinChanged && d.pca.changed ? "both"
                  : d.drytwinChanged                ? "drytwin"
                  : d.pca.changed                   ? "pca"
                                                    : "";
}

void testCauses(const std::vector<Candidate>& ranking, ChangeDetection& d) {
    double best = 1;
    for (const auto& c : ranking) {
        // score holds the change z (scoreAgainstReference), also for a timing cause whose screen
        // took its own score: the detector asks only whether the parameter moved.
        const double p = changeP(c.parameter, c.score);
        if (p < best) {
            best = p;
            d.causeTest.cause = c.cause;
        }
    }
    d.causeTest.pValue = std::min(1.0, best * static_cast<double>(std::max<std::size_t>(1, ranking.size())));
    d.causeTest.changed = !ranking.empty() && d.causeTest.pValue <= d.falseAlarmRate / 2;
    decide(d);
}

} // namespace drytwin::discovery::detail
