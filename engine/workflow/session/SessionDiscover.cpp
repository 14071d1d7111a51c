// What discover() does: the causes found on the loaded data (alone, or against a reference
// period), the extended model built from them, PGRL-CC retrained on the starting and the extended
// physics model and scored on the held-out part beside the trivial forecasts, and the rule that
// the model offered for forecasting never gets worse (issue #23).

#include "workflow/Session.h"

#include "common/Parallel.h"
#include "discovery/DiscoveryNotes.h"
#include "hybrid/Evaluation.h"
#include "workflow/session/SessionInternal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

namespace drytwin::workflow {

Expected<DiscoverResult> Session::discover(const DiscoverOptions& options, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = ready(options, "discover"); !st) {
        return st.error();
    }
    // Discovery's own stages fill the bar to 95 % when PGRL-CC is retrained after it: the bar
    // went from "100 % done" back to 97 % "retraining" before.
    const double discoveryShare = options.retrainResidual ? 0.95 : 1.0;
    const Progress discoveryProgress = !progress ? Progress{} : [&](const ProgressInfo& info) {
        ProgressInfo scaled = info;
        if (scaled.stage == "discover") {
            scaled.fraction *= discoveryShare;
        }
        return progress(scaled);
    };
    Expected<discovery::DiscoveryResult> found = Error{};
    if (options.referencePath.empty()) {
        found = discovery::discover(m_si, m_model, options.discovery, discoveryProgress);
    } else {
        std::vector<std::string> referenceNotes;
        auto reference =
            loadReference(options.referencePath, options.referenceMappingPath, progress, referenceNotes);
        if (!reference) {
            return reference.error();
        }
        // Both periods are compared on the outputs both measure: an output only the data measure
        // has no normal to be judged against (a reference without the tube-outlet readings once
        // let a cause that doubled the outlet temperature's error be named on them).
        const auto measuredIn = [](const std::vector<data::SiBatch>& set, bool data::SiBatch::*has) {
            return !set.empty() && std::all_of(set.begin(), set.end(), [&](const auto& b) { return b.*has; });
        };
        // A copy of the data only where an output must be left out (a month of data is large).
        std::optional<std::vector<data::SiBatch>> narrowed;
        for (const auto& [has, name] : {std::pair{&data::SiBatch::hasXHdt, "X_hdt_pct"},
                                        std::pair{&data::SiBatch::hasTHdt, "T_hdt_C"}}) {
            const bool inReference = measuredIn(*reference, has), inData = measuredIn(m_si, has);
            if (inReference == inData) {
                continue;
            }
            if (inData && !narrowed) {
                narrowed = m_si;
            }
            for (auto& b : inData ? *narrowed : *reference) {
                b.*has = false;
            }
            referenceNotes.push_back(discovery::notes::measuredInOnePeriodOnly(name, inData));
        }
        found = discovery::discoverChange(*reference, narrowed ? *narrowed : m_si, m_model, options.discovery,
                                          discoveryProgress);
        if (found) {
            found->referencePath = options.referencePath;
            found->notes.insert(found->notes.begin(), referenceNotes.begin(), referenceNotes.end());
        }
    }
    if (!found) {
        // A stop inside discovery's own calibrations is the discovery's ("discover: cancelled"),
        // not a calibration the user did not start.
        return found.error().kind == ErrorKind::Cancelled ? cancelledError("discover") : found.error();
    }
    DiscoverResult result;
    result.extendedModel = m_model;
    auto& ext = result.extendedModel;
    ext.parameters = found->parameters;
    for (const auto& f : found->findings) {
        ext.mechanisms[f.cause] = {f.value, std::string(properties::info(f.parameter).unit), f.ci95Low,
                                   f.ci95High};
    }
    hybrid::CalibrationRecord rec;
    rec.algorithm = "discovery: h_HDT, k_HDT and the named mechanisms refitted on the training part (BOBYQA)";
    for (properties::Param p : {properties::Param::h_HDT, properties::Param::k_HDT}) {
        const double v = ext.parameters[p];
        // Refitted jointly with the causes; their own intervals are not computed here.
        rec.estimates.push_back({std::string(properties::info(p).symbol), v, v, v, false});
    }
    ext.calibration = rec;
    // The residual models were learnt on the old physics model: retrain on the extended one.
    ext.pgrlCc.reset();
    ext.extInput.reset();
    if (options.retrainResidual) {
        // PGRL-CC trained on a physics model and scored one step ahead on the held-out part,
        // with the PBM-with-its-last-error-held reference on the same rows (and persistence,
        // which does not depend on the model, where asked).
        const auto pgrlHeldOut = [&](const hybrid::HybridModel& m,
                                     std::shared_ptr<const residual::ResidualModel>& out, double& maeX,
                                     double& maeT, double& holdX, double& holdT, double* persistenceX,
                                     double* persistenceT) -> Status {
            auto sims = hybrid::simulatePbm(m_si, m, m.switches);
            if (!sims) {
                return sims.error();
            }
            // The settings the session's PGRL-CC was trained with (chosen by validation there).
            residual::ResidualOptions settings =
                m_model.pgrlCc ? m_model.pgrlCc->options() : residual::ResidualOptions{};
            // ... and the input-driven basis it chose there (not chosen again on each model).
            if (m_model.pgrlCc && m_model.pgrlCc->inputDriven()) {
                settings.inputDrivenOptions.basis = m_model.pgrlCc->inputDriven()->options().basis;
            }
            auto trained = residual::ResidualModel::train(hybrid::splitViews(m_si, *sims, false), settings);
            if (!trained) {
                return trained.error();
            }
            const auto heldOutViews = hybrid::splitViews(m_si, *sims, true);
            const auto scored = evaluation::scorePredictions(
                heldOutViews, [&](const residual::BatchView& v) { return trained->predictOneStep(v); }, 20);
            maeX = scored.moisture.mae;
            maeT = scored.temperature.mae;
            const auto reference = [&](bool holdPbmError) {
                return evaluation::scorePredictions(
                    heldOutViews,
                    [&](const residual::BatchView& v) {
                        return evaluation::referencePrediction(v, 1, holdPbmError);
                    },
                    20);
            };
            const auto held = reference(true);
            holdX = held.moisture.mae;
            holdT = held.temperature.mae;
            if (persistenceX && persistenceT) {
                const auto persistence = reference(false);
                *persistenceX = persistence.moisture.mae;
                *persistenceT = persistence.temperature.mae;
            }
            out = std::make_shared<const residual::ResidualModel>(std::move(*trained));
            return {};
        };
        if (reportProgress(progress, "discover", 0.97, "retraining PGRL-CC on both models")) {
            return cancelledError("discover");
        }
        std::shared_ptr<const residual::ResidualModel> before;
        hybrid::HybridModel start = m_model;
        start.parameters = found->baseParameters; // the same refit, without the causes
        // The two trainings are independent and mostly on one core each: side by side they take
        // the time of one (demo seed 2025: 11 s one after the other on 2 cores).
        std::array<Status, 2> trainedStatus;
        auto& ref = result.references;
        parallelFor(2, [&](std::size_t i) {
            trainedStatus[i] = i == 0
                                   ? pgrlHeldOut(start, before, result.hybridMaeMoistureBefore,
                                                 result.hybridMaeTemperatureBefore, ref.pbmHoldMoistureBefore,
                                                 ref.pbmHoldTemperatureBefore, &ref.persistenceMoisture,
                                                 &ref.persistenceTemperature)
                                   : pgrlHeldOut(ext, ext.pgrlCc, result.hybridMaeMoistureAfter,
                                                 result.hybridMaeTemperatureAfter, ref.pbmHoldMoistureAfter,
                                                 ref.pbmHoldTemperatureAfter, nullptr, nullptr);
        });
        for (const auto& st : trainedStatus) {
            if (!st) {
                return st.error();
            }
        }
        // The trainings take no progress callback: a cancel asked for during them is honoured
        // here, before anything is returned to be written (it was ignored, and the files written).
        if (reportProgress(progress, "discover", 0.995, "comparing PGRL-CC on both models")) {
            return cancelledError("discover");
        }
        result.hasHybrid = true;
        // Never make the hybrid worse (issue #23): where PGRL-CC on the extended physics model
        // loses to PGRL-CC on the starting one on the held-out part (moisture and temperature
        // weighed as in calibration), the findings stand as findings but the model offered for
        // forecasting stays the starting one with its residual model.
        const auto& w = options.discovery.weights;
        const auto combined = [&](double maeX, double maeT) {
            return std::sqrt(w.xOut) * maeX + std::sqrt(w.tOut) * maeT;
        };
        if (combined(result.hybridMaeMoistureAfter, result.hybridMaeTemperatureAfter) >
            combined(result.hybridMaeMoistureBefore, result.hybridMaeTemperatureBefore)) {
            result.keptStartingModel = true;
            ext = std::move(start);
            ext.pgrlCc = before;
        }
    }
    result.ending = found->ending;
    result.ending.elapsedSeconds = secondsSince(t0);
    result.discovery = std::move(*found);
    m_latest.discover = result;
    return result;
}

} // namespace drytwin::workflow
