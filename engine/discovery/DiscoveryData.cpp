// The data of a discovery run: its options checked, the chronological split, the training rows
// the tests and fits use, and what the files cannot give.
#include "discovery/DiscoveryInternal.h"
#include "discovery/DiscoveryNotes.h"

#include <algorithm>

namespace drytwin::discovery {

Status DiscoveryOptions::validate() const {
    if (!(trainFraction > 0.2 && trainFraction < 0.95)) {
        return invalidOption("train fraction", "must lie in (0.2, 0.95)");
    }
    if (!(screenAlpha > 0 && screenAlpha < 0.5) || !(gainAlpha > 0 && gainAlpha < 0.5) ||
        !(minExplainedFraction >= 0 && minExplainedFraction < 1)) {
        return invalidOption("alpha", "test levels must lie in (0, 0.5), the explained share in [0, 1)");
    }
    if (!(screenAlphaOnceDetected >= 0 && screenAlphaOnceDetected < 0.5)) {
        return invalidOption("screenAlphaOnceDetected",
                             "the screen's level once a change is detected must lie "
                             "in [0, 0.5) (0: unchanged)");
    }
    if (!(falseAlarmRate > 0 && falseAlarmRate < 0.5)) {
        return invalidOption("false-alarm rate", "must lie in (0, 0.5)");
    }
    if (!(laterCauseAlpha > 0 && laterCauseAlpha <= 1)) {
        return invalidOption("later-cause level", "must lie in (0, 1]");
    }
    if (!(unimprovedChannelAlpha > 0 && unimprovedChannelAlpha <= 1)) {
        return invalidOption("unimproved-channel level", "must lie in (0, 1]");
    }
    if (!(fastBandWindowS == 0 || (fastBandWindowS >= 10 && fastBandWindowS <= 1e5))) {
        return invalidOption("fast-band window", "must be 0 (off) or lie in [10, 1e5] s");
    }
    if (maxCauses < 0 || candidatesToFit < 1 || maxEvaluationsPerFit < 10) {
        return invalidOption("discovery limits",
                             "max causes ≥ 0, candidates to fit ≥ 1, evaluations per fit ≥ 10");
    }
    for (const auto& cause : causes) {
        if (!properties::mechanismParam(cause)) {
            return invalidOption("causes", "'" + cause + "' is not a cause of CONTRACT.md §4");
        }
    }
    return {};
}

} // namespace drytwin::discovery

namespace drytwin::discovery::detail {

Expected<Prepared> prepare(const std::vector<data::SiBatch>& batches, const hybrid::HybridModel& model,
                           const DiscoveryOptions& options, bool allRowsTrain) {
    Prepared out;
    Problem& pr = out.pr;
    pr.batches = &batches;
    pr.options = options;
    pr.simulation = model.simulationOptions();
    std::vector<std::size_t> rowsPerBatch;
    std::vector<double> steps;
    for (const auto& b : batches) {
        pr.inputs.push_back(physics::toLineInputs(b));
        rowsPerBatch.push_back(b.rows());
        if (b.rows() > 1) {
            steps.push_back((b.timeS.back() - b.timeS.front()) / static_cast<double>(b.rows() - 1));
            out.meanBatchHours +=
                (b.timeS.back() - b.timeS.front()) / 3600.0 / static_cast<double>(batches.size());
        }
    }
    if (!steps.empty()) {
        std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
        pr.samplingStepS = steps[steps.size() / 2];
    }
    if (allRowsTrain) {
        for (std::size_t b = 0; b < batches.size(); ++b) {
            pr.train.push_back({0, rowsPerBatch[b]});
            pr.test.push_back({rowsPerBatch[b], rowsPerBatch[b]});
        }
    } else {
        const auto split = data::chronologicalSplit(rowsPerBatch, options.trainFraction);
        pr.train = split.train;
        pr.test = split.test;
    }
    pr.subset.resize(batches.size());
    std::size_t stride = options.subsetStride;
    if (stride == 0) {
        std::size_t kept = 0;
        for (std::size_t b = 0; b < batches.size(); ++b) {
            for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
                kept += batches[b].keep[k];
            }
        }
        stride = std::max<std::size_t>(5, kept / 1000);
    }
    for (std::size_t b = 0; b < batches.size(); ++b) {
        std::size_t seen = 0;
        for (std::size_t k = pr.train[b].begin; k < pr.train[b].end; ++k) {
            if (batches[b].keep[k]) {
                ++out.keptTrain;
                if (seen++ % stride == 0) {
                    pr.subset[b].push_back(k);
                    pr.subsetRefs.push_back({b, k});
                }
            }
        }
        for (std::size_t k = pr.test[b].begin; k < pr.test[b].end; ++k) {
            out.keptTest += batches[b].keep[k];
        }
    }
    if (pr.subsetRefs.size() < 100 || (!allRowsTrain && out.keptTest < 100)) {
        // Say which count is short and why: the tests read every stride-th kept row (neighbouring
        // seconds say almost the same), so 300 clean rows give 60, which read as rows lost.
        std::string why = "too few rows: the tests read every " + std::to_string(stride) + "th of the " +
                          std::to_string(out.keptTrain) + " " + (allRowsTrain ? "" : "training ") +
                          "rows that pass the cleaning rules, " + std::to_string(pr.subsetRefs.size()) +
                          " in all (need 100, so at least " + std::to_string(100 * stride) + " rows)";
        if (!allRowsTrain) {
            why += ", and " + std::to_string(out.keptTest) + " held-out rows pass them (need 100)";
        }
        return Error{ErrorKind::BadInput,
                     "discover",
                     why + ": give longer batches or more of them",
                     ErrorCode::NotEnoughData,
                     {"rows", std::to_string(out.keptTrain + out.keptTest)}};
    }
    return out;
}

std::vector<std::string> dataNotes(const std::vector<data::SiBatch>& batches) {
    std::vector<std::string> notes;
    bool xHdt = false, tHdt = false, airVaries = false;
    for (const auto& b : batches) {
        xHdt = xHdt || b.hasXHdt;
        tHdt = tHdt || b.hasTHdt;
        for (double v : b.airSpeedMPerS) {
            airVaries = airVaries || v != b.airSpeedMPerS.front();
        }
    }
    if (!xHdt) {
        notes.push_back(notes::tubeOutletMoistureNotMeasured());
    }
    if (!tHdt) {
        notes.push_back(notes::tubeOutletTemperatureNotMeasured());
    }
    if (!airVaries) {
        notes.push_back(notes::airSpeedConstant());
    }
    return notes;
}

} // namespace drytwin::discovery::detail
