// Question 3: which cause to name, and whether it is specific. Causes are chosen one at a time
// on the training part, confirmed on the held-out part, and named only when they are specific.
#include "discovery/DiscoveryInternal.h"
#include "discovery/DiscoveryNotes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace drytwin::discovery {

using namespace detail;

namespace detail {

CauseFit makeCauseFit(const std::vector<data::SiBatch>& batches, const Problem& pr, const Progress& progress,
                      const double& fraction) {
    return [&batches, &pr, progress,
            &fraction](const ParameterSet& start, const std::vector<Param>& free, bool global,
                       const calibration::LossWeights* weights) -> Expected<calibration::CalibrationResult> {
        calibration::CalibrationOptions co;
        co.freeParameters = free;
        co.rows = pr.subsetRefs;
        co.weights = weights ? *weights : pr.options.weights;
        co.maxEvaluations = pr.options.maxEvaluationsPerFit * (global ? 2 : 1);
        co.globalSearch = global;
        co.intervals = false;
        co.simulation = pr.simulation;
        // The fit's own progress reaches the user as discovery's; any stop cancels discovery.
        return calibration::calibrate(batches, start, co, [&](const ProgressInfo& info) {
            return progress && progress(ProgressInfo{"discover", fraction, "fitting: " + info.detail}) !=
                                   ProgressAction::Continue
                       ? ProgressAction::Stop
                       : ProgressAction::Continue;
        });
    };
}

} // namespace detail

Expected<DiscoveryResult> discover(const std::vector<data::SiBatch>& batches,
                                   const hybrid::HybridModel& model, const DiscoveryOptions& options,
                                   const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (batches.empty()) {
        return Error{
            ErrorKind::BadInput, "discover", "no batches", ErrorCode::NotEnoughData, {"batches", "0"}};
    }
    auto prepared = prepare(batches, model, options);
    if (!prepared) {
        return prepared.error();
    }
    const Problem& pr = prepared->pr;
    double fraction = 0; // of the whole discovery, for the fits' progress
    const auto stop = [&](double f, const std::string& detail) {
        fraction = f;
        return reportProgress(progress, "discover", f, detail);
    };
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };

    // The starting model, its h_HDT and k_HDT refitted on the training rows (locally when the
    // model was calibrated, globally and locally when not).
    // The inlet gauge's scatter share is freed with h_HDT and k_HDT: a model that carries the
    // normal scatter of a measured input into its prediction would have every candidate judged by
    // how well it smooths that scatter (a meter lag does, much as a real one). It is named as a
    // cause only above the gauge's normal scatter (below).
    // The outlet's mixing (tau_mix) likewise: a real line's belt and winnower spread a step over
    // seconds in both outlet channels, and a plug-flow model leaves that as a lag common to both,
    // which a meter lag or a transport time would otherwise absorb in the cause's place.
    std::vector<Param> nuisance{Param::h_HDT, Param::k_HDT, Param::phi_X_in_scatter};
    if (options.freeOutletMixing) {
        nuisance.push_back(Param::tau_mix);
    }
    for (Param m : properties::mechanismParams()) {
        if (model.parameters[m] != 0 && m != Param::phi_X_in_scatter) {
            nuisance.push_back(m); // extensions the model already holds stay free
        }
    }
    const CauseFit refit = makeCauseFit(batches, pr, progress, fraction);
    if (stop(0.02, "refitting h_HDT and k_HDT on the training part")) {
        return cancelledError("discover");
    }
    auto base = refit(model.parameters, nuisance, !model.calibration.has_value(), nullptr);
    if (!base) {
        return base.error();
    }
    ParameterSet current = base->parameters;
    double currentLoss = base->after.loss;
    const double mixingS = current[Param::tau_mix];

    DiscoveryResult result;
    result.baseParameters = current;
    result.notes = dataNotes(batches);
    if (!options.causes.empty()) { // a finding's absence then says nothing about the causes not asked
        result.notes.push_back(notes::onlyCausesAsked(options.causes));
    }
    if (options.freeOutletMixing) {
        result.notes.push_back(notes::outletMixing(mixingS));
    }
    result.trainingRows = prepared->keptTrain;
    result.heldOutRows = prepared->keptTest;
    auto full = physics::simulateBatches(pr.inputs, current, pr.simulation);
    if (!full) {
        return full.error();
    }
    std::vector<physics::SimulationResult> currentSims = std::move(*full);
    result.residuals = analyse(pr, currentSims);
    // The residual analysis of the model as it stands (before each round, and at the end).
    std::vector<OutputResidual> currentResiduals = result.residuals;
    auto currentHeld = heldOut(pr, current);
    if (!currentHeld) {
        return currentHeld.error();
    }
    const auto asked = [&](Param m) {
        const auto name = properties::mechanismOf(m);
        return options.causes.empty() || (name && std::find(options.causes.begin(), options.causes.end(),
                                                            *name) != options.causes.end());
    };
    if (auto scatter =
            asked(Param::phi_X_in_scatter)
                ? inletScatterFinding(pr, current, nuisance, *currentHeld, currentResiduals, options)
                : Expected<std::optional<Finding>>(std::optional<Finding>{});
        !scatter) {
        return scatter.error();
    } else if (scatter->has_value()) {
        result.findings.push_back(**scatter);
        Round record;
        record.best = (*scatter)->cause;
        record.named = true;
        record.heldOutPValue = (*scatter)->gain.pValue;
        record.explainedFraction = (*scatter)->explainedFraction;
        record.explainedFractionFast = (*scatter)->explainedFractionFast;
        result.rounds.push_back(record);
    } else {
        result.notes.push_back(
            notes::inletGaugeScatter(100 * current[Param::phi_X_in_scatter], inletFastScatterPct(pr)));
    }

    std::vector<Param> remaining;
    for (Param m : properties::mechanismParams()) {
        if (std::find(nuisance.begin(), nuisance.end(), m) == nuisance.end() && asked(m)) {
            remaining.push_back(m);
        }
    }
    ModelSoFar extended{std::move(current),     currentLoss,
                        std::move(nuisance),    std::move(remaining),
                        std::move(currentSims), std::move(currentResiduals),
                        std::move(*currentHeld)};
    if (auto st = selectCauses(*prepared, refit, stop, extended, result); !st) {
        return st.error();
    }

    if (stop(0.95, "what is left")) {
        return cancelledError("discover");
    }
    conclude(pr, extended.parameters, extended.nuisance, extended.sims, std::move(extended.residuals),
             result);
    reportProgress(progress, "discover", 1.0, "done");
    result.ending = {Termination::Completed,
                     std::to_string(result.findings.size()) + " cause(s) named, " +
                         std::to_string(result.unexplained.size()) + " unexplained signature(s)",
                     elapsed()};
    return result;
}

} // namespace drytwin::discovery
