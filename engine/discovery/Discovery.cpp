// Question 3: which cause to name, and whether it is specific. Causes are chosen one at a time
// on the training part, confirmed on the held-out part, and named only when they are specific.
#include "discovery/DiscoveryInternal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>

namespace drytwin::discovery {

using namespace detail;

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
    auto refit = [&](const ParameterSet& start, const std::vector<Param>& free, bool global,
                     const calibration::LossWeights* weights =
                         nullptr) -> Expected<calibration::CalibrationResult> {
        calibration::CalibrationOptions co;
        co.freeParameters = free;
        co.rows = pr.subsetRefs;
        co.weights = weights ? *weights : options.weights;
        co.maxEvaluations = options.maxEvaluationsPerFit * (global ? 2 : 1);
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
    if (stop(0.02, "refitting h_HDT and k_HDT on the training part")) {
        return cancelledError("discover");
    }
    auto base = refit(model.parameters, nuisance, !model.calibration.has_value());
    if (!base) {
        return base.error();
    }
    ParameterSet current = base->parameters;
    double currentLoss = base->after.loss;
    const double mixingS = current[Param::tau_mix];

    DiscoveryResult result;
    result.baseParameters = current;
    result.notes = dataNotes(batches);
    if (options.freeOutletMixing) {
        result.notes.push_back(format("the line's outlet mixing (belt and winnower, both outlet channels): a "
                                      "first-order lag of %.1f s fitted with h_HDT and k_HDT (0: plug flow)",
                                      mixingS));
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
    if (auto scatter = inletScatterFinding(pr, current, nuisance, *currentHeld, currentResiduals, options);
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
            format("the inlet gauge's normal scatter: %.0f %% of X_in's fast variation (%.2g %% wb, "
                   "1σ about its 30 s mean) is taken as gauge scatter, not moisture, in the "
                   "starting model",
                   100 * current[Param::phi_X_in_scatter], inletFastScatterPct(pr)));
    }

    std::vector<Param> remaining;
    for (Param m : properties::mechanismParams()) {
        if (std::find(nuisance.begin(), nuisance.end(), m) == nuisance.end()) {
            remaining.push_back(m);
        }
    }
    for (int round = 0; round < options.maxCauses && !remaining.empty(); ++round) {
        const double frac0 = 0.1 + 0.8 * round / std::max(1, options.maxCauses);
        if (stop(frac0, "score tests, round " + std::to_string(round + 1))) {
            return cancelledError("discover");
        }
        std::vector<Param> sens = nuisance;
        sens.insert(sens.end(), remaining.begin(), remaining.end());
        auto st = stackAt(pr, current, sens);
        if (!st) {
            return st.error();
        }
        std::vector<int> nuisanceCols(nuisance.size());
        std::iota(nuisanceCols.begin(), nuisanceCols.end(), 0);
        const auto columnOf = [&](Param p) {
            return static_cast<int>(
                nuisance.size() + static_cast<std::size_t>(std::find(remaining.begin(), remaining.end(), p) -
                                                           remaining.begin()));
        };
        std::vector<Candidate> cands = scoreCandidates(*st, nuisanceCols, remaining);
        // Fit the leading candidates that pass the screen, largest predicted reduction first.
        std::sort(cands.begin(), cands.end(), [&](const auto& a, const auto& b) {
            const bool pa = a.pValue < options.screenAlpha;
            const bool pb = b.pValue < options.screenAlpha;
            return pa != pb ? pa : a.predictedReduction > b.predictedReduction;
        });
        struct Fit {
            ParameterSet parameters;
            double loss = 0;
            Onset onset;
        };
        std::map<Param, Fit> fits;
        const auto fitCause = [&](Candidate& c, double onsetS) -> Status {
            std::vector<Param> free = nuisance;
            free.push_back(c.parameter);
            ParameterSet start = current;
            // Start at the one-step estimate when it lies inside the range; BOBYQA refines it.
            const auto& info = properties::info(c.parameter);
            start[c.parameter] = std::clamp(c.linearEstimate, info.lower, info.upper);
            start[Param::t_onset] = onsetS; // the cause acts from its onset on (0: throughout)
            auto fit = refit(start, free, false);
            if (!fit) {
                return fit.error();
            }
            c.fitted = true;
            c.fitLossBefore = currentLoss;
            c.fitLossAfter = fit->after.loss;
            fits[c.parameter] = Fit{fit->parameters, fit->after.loss, {}};
            return {};
        };
        // The cause refitted from @p onset, where it acts; none where that refit fails (no
        // evidence either way).
        const auto refitFromOnset = [&](const Candidate& cand,
                                        const Onset& onset) -> Expected<std::optional<Fit>> {
            if (stop(frac0 + 0.2, "fitting " + cand.cause + " from its onset")) {
                return cancelledError("discover");
            }
            Candidate again = cand;
            if (auto fs = fitCause(again, onset.s); !fs) {
                if (fs.error().kind == ErrorKind::Cancelled) {
                    return fs.error();
                }
                return std::optional<Fit>{};
            }
            return std::optional<Fit>{Fit{fits[cand.parameter].parameters, fits[cand.parameter].loss, onset}};
        };
        // A fitted cause, refitted from its onset where it has one. One onset for the model
        // (t_onset): searched while no cause has one yet; a transport time acts from the start.
        const auto fittedFromOnset = [&](const Candidate& cand) -> Expected<Fit> {
            Fit fit = fits[cand.parameter];
            if (!options.searchOnset || current[Param::t_onset] != 0 || cand.parameter == Param::dtau_conv) {
                return fit;
            }
            fit.onset = findOnset(*st, nuisanceCols, columnOf(cand.parameter));
            if (!fit.onset.found) {
                return fit;
            }
            auto refitted = refitFromOnset(cand, fit.onset);
            if (!refitted) {
                return refitted.error();
            }
            return refitted->value_or(fit);
        };
        // A fitted cause (from its onset where it has one), the k-th tried judged at level α/k.
        struct Judged {
            Fit fit;
            Confirmation confirmation;
        };
        const auto judgeFitted = [&](const Candidate& cand, int k) -> Expected<Judged> {
            auto withOnset = fittedFromOnset(cand);
            if (!withOnset) {
                return withOnset.error();
            }
            const auto confirm = [&](const Fit& fit) {
                return confirmCandidate({pr, cand, fit.parameters, fit.onset, options.gainAlpha / k,
                                         prepared->meanBatchHours, *currentHeld, *st, nuisanceCols,
                                         columnOf(cand.parameter), nuisance, currentSims});
            };
            auto conf = confirm(*withOnset);
            if (!conf) {
                return conf.error();
            }
            // Its estimate strays part by part and no onset was found on its tangent: an effect
            // that starts mid-batch and is far from linear in its parameter (a long meter lag
            // switched on at 5 min) looks so. Its own effect at the fit tells where it starts.
            if (conf->code == "inconsistent" && options.searchOnset && current[Param::t_onset] == 0 &&
                !withOnset->onset.found && cand.parameter != Param::dtau_conv) {
                auto onset = findOnsetOfEffect(pr, *st, nuisanceCols, columnOf(cand.parameter),
                                               cand.parameter, withOnset->parameters);
                if (!onset) {
                    return onset.error();
                }
                if (onset->found) {
                    auto refitted = refitFromOnset(cand, *onset);
                    if (!refitted) {
                        return refitted.error();
                    }
                    if (*refitted) { // judged again where it acts
                        auto second = confirm(**refitted);
                        if (!second) {
                            return second.error();
                        }
                        return Judged{std::move(**refitted), std::move(*second)};
                    }
                }
            }
            return Judged{std::move(*withOnset), std::move(*conf)};
        };
        int fitted = 0;
        for (std::size_t i = 0; i < cands.size() && fitted < options.candidatesToFit; ++i) {
            if (cands[i].pValue >= options.screenAlpha) {
                break;
            }
            if (stop(frac0 + 0.05 * (fitted + 1), "fitting " + cands[i].cause)) {
                return cancelledError("discover");
            }
            ++fitted;
            if (auto fs = fitCause(cands[i], current[Param::t_onset]);
                !fs && fs.error().kind == ErrorKind::Cancelled) {
                return fs.error(); // a fit that fails otherwise counts as no evidence for this cause
            }
        }
        // The two outlet delays are fitted as a pair: a transport time that lowers the moisture's
        // error while raising the temperature's is a moisture-only delay, the meter's, and the
        // meter lag must then be there to be tried (it is fitted in its place as a look-alike
        // anyway when the transport time is named). Only one that passes the screen.
        for (const auto& [fittedOne, partner] :
             {std::pair{Param::dtau_conv, Param::tau_meter}, std::pair{Param::tau_meter, Param::dtau_conv}}) {
            auto other = std::find_if(cands.begin(), cands.end(), [&, p = partner](const auto& c) {
                return c.parameter == p && !c.fitted && c.pValue < options.screenAlpha;
            });
            if (!fits.count(fittedOne) || other == cands.end()) {
                continue;
            }
            if (stop(frac0 + 0.2, "fitting " + other->cause)) {
                return cancelledError("discover");
            }
            if (auto fs = fitCause(*other, current[Param::t_onset]);
                !fs && fs.error().kind == ErrorKind::Cancelled) {
                return fs.error();
            }
        }
        Round record;
        record.candidates = cands;
        // The ranking a user reads: fitted causes by training loss removed, then the rest by evidence.
        std::stable_sort(record.candidates.begin(), record.candidates.end(),
                         [](const auto& a, const auto& b) {
                             if (a.fitted != b.fitted) {
                                 return a.fitted;
                             }
                             if (a.fitted) {
                                 return a.fitLossAfter < b.fitLossAfter;
                             }
                             return a.pValue < b.pValue;
                         });
        if (round == 0) {
            result.ranking = record.candidates;
        }
        // Try the fitted candidates by training loss. The k-th tried is judged at level α/k
        // (Bonferroni over those tried), so that trying another after one that was not specific
        // does not raise the chance of naming an absent cause.
        std::optional<Finding> named;
        ParameterSet namedParams;
        double namedLoss = 0;
        std::optional<HeldOut> namedHeld;
        int tried = 0;
        // The outlet response time: a meter lag delays the moisture reading alone, a transport
        // time both outlet channels. A line that is not the model answers later than it in the
        // temperature too (the product's heat capacity, the pyrometer); a transport time then
        // takes a meter's lag with that and wins any comparison in its place. The delay each
        // channel asks for alone tells: the moisture later than the temperature is a meter's;
        // alike is a transport time's; the temperature later (or apart without the held-out
        // part confirming which is later) leaves both possible: a group; the temperature later
        // while the moisture asks for no delay of its own is neither (the line's own dynamics).
        // Measured once per round, when the first of the two is confirmed.
        std::optional<ChannelTiming> timing;
        bool timed = false;
        const auto isRemaining = [&](Param p) {
            return std::find(remaining.begin(), remaining.end(), p) != remaining.end();
        };
        const auto isOutletDelay = [](Param p) { return p == Param::tau_meter || p == Param::dtau_conv; };
        for (const auto& cand : record.candidates) {
            if (!cand.fitted || named) {
                continue;
            }
            if (!(cand.fitLossAfter < currentLoss)) {
                if (tried == 0 && record.reason.empty()) {
                    record.reason = "no fitted candidate lowers the training loss";
                }
                continue;
            }
            ++tried;
            if (record.best.empty()) {
                record.best = cand.cause;
            }
            auto judged = judgeFitted(cand, tried);
            if (!judged) {
                return judged.error();
            }
            const Fit& fit = judged->fit;
            auto& conf = judged->confirmation;
            if (tried == 1) {
                record.heldOutPValue = conf.pValue;
                record.explainedFraction = conf.explained;
                record.explainedFractionFast = conf.explainedFast;
            }
            if (!conf.finding) {
                if (tried == 1) {
                    record.reason = conf.why;
                }
                record.rejected.push_back({cand.cause, conf.code, conf.why});
                continue;
            }
            if (isOutletDelay(cand.parameter) && isRemaining(Param::tau_meter) &&
                isRemaining(Param::dtau_conv) && !timed) {
                timed = true;
                if (stop(frac0 + 0.25, "the delay of each outlet channel")) {
                    return cancelledError("discover");
                }
                auto t = timeOutletChannels(
                    pr, current,
                    fits.count(Param::dtau_conv) ? fits[Param::dtau_conv].parameters[Param::dtau_conv] : 0.0,
                    // Globally: one channel alone has local optima a few seconds apart (demo
                    // 2025: the moisture's best delay 14.6 s, a local one at 17.7 s beside the
                    // joint fit's 17.8 s), and which one a local fit finds decided the pattern.
                    [&](const ParameterSet& start, const calibration::LossWeights& weights) {
                        return refit(start, {Param::dtau_conv}, true, &weights);
                    });
                if (!t) {
                    if (t.error().kind == ErrorKind::Cancelled) {
                        return t.error();
                    }
                } else if (t->pattern != ChannelTiming::Pattern::Alike) {
                    timing = *t;
                }
            }
            if (timing && timing->pattern == ChannelTiming::Pattern::TemperatureOnly &&
                isOutletDelay(cand.parameter)) {
                record.rejected.push_back({cand.cause, "line_dynamics", lineDynamicsReason(*timing)});
                if (tried == 1) {
                    record.reason = record.rejected.back().reason;
                }
                continue;
            }
            record.best = cand.cause;
            named = std::move(conf.finding);
            namedParams = fit.parameters;
            namedLoss = fit.loss;
            namedHeld = std::move(conf.held);
        }
        if (!named) {
            if (record.reason.empty()) {
                record.reason = "no candidate passes the screening test (p < " +
                                format("%.2g", options.screenAlpha) + ")";
            }
            result.rounds.push_back(record);
            break;
        }
        if (timing && timing->pattern == ChannelTiming::Pattern::MoistureLater &&
            named->parameter == Param::dtau_conv) {
            // Only a meter lag makes the moisture later than the temperature: confirm it alone.
            auto meterCand = std::find_if(cands.begin(), cands.end(),
                                          [&](const auto& c) { return c.parameter == Param::tau_meter; });
            bool confirmed = false;
            if (!fits.count(Param::tau_meter)) {
                if (stop(frac0 + 0.25, "fitting " + meterCand->cause)) {
                    return cancelledError("discover");
                }
                if (auto fs = fitCause(*meterCand, current[Param::t_onset]);
                    !fs && fs.error().kind == ErrorKind::Cancelled) {
                    return fs.error();
                }
            }
            if (fits.count(Param::tau_meter)) {
                auto judged = judgeFitted(*meterCand, ++tried);
                if (!judged) {
                    return judged.error();
                }
                auto& conf = judged->confirmation;
                if (conf.finding) {
                    record.rejected.push_back({named->cause, "channels", moistureLaterReason(*timing)});
                    named = std::move(conf.finding);
                    namedParams = judged->fit.parameters;
                    namedLoss = judged->fit.loss;
                    namedHeld = std::move(conf.held);
                    record.best = meterCand->cause;
                    confirmed = true;
                } else {
                    record.rejected.push_back({meterCand->cause, conf.code, conf.why});
                }
            }
            if (!confirmed) {
                // Not a transport time, yet the lag alone does not predict clearly better: the
                // moisture channel's response time, either of the two.
                timing->pattern = ChannelTiming::Pattern::Undecided;
            }
        }
        Finding& f = *named;
        // Look-alikes: fitted in its place and judged on the same held-out part.
        const auto fitInPlace = [&](Param other) -> Expected<const ParameterSet*> {
            if (!fits.count(other)) {
                auto it = std::find_if(cands.begin(), cands.end(),
                                       [&](const auto& c) { return c.parameter == other; });
                if (stop(frac0 + 0.25, "fitting the look-alike " + it->cause)) {
                    return cancelledError("discover");
                }
                if (auto fs = fitCause(*it, current[Param::t_onset] > 0 ? current[Param::t_onset]
                                                                        : (f.hasOnset ? f.onsetS : 0));
                    !fs) {
                    if (fs.error().kind == ErrorKind::Cancelled) {
                        return fs.error();
                    }
                    return static_cast<const ParameterSet*>(nullptr);
                }
            }
            return &fits[other].parameters;
        };
        if (auto added = addLookAlikes(pr, f, remaining, fitInPlace, *namedHeld, timing); !added) {
            return added.error();
        }
        record.named = true;
        result.rounds.push_back(record);
        describeOutput(f, currentResiduals);
        f.evidence = findingEvidence(f, options);
        result.findings.push_back(f);
        auto sims = physics::simulateBatches(pr.inputs, namedParams, pr.simulation);
        if (!sims) {
            return sims.error();
        }
        currentSims = std::move(*sims);
        currentResiduals = analyse(pr, currentSims);
        current = namedParams;
        currentLoss = namedLoss;
        *currentHeld = std::move(*namedHeld);
        nuisance.push_back(f.parameter);
        remaining.erase(std::find(remaining.begin(), remaining.end(), f.parameter));
    }

    if (stop(0.95, "what is left")) {
        return cancelledError("discover");
    }
    conclude(pr, current, nuisance, currentSims, std::move(currentResiduals), result);
    reportProgress(progress, "discover", 1.0, "done");
    result.ending = {Termination::Completed,
                     std::to_string(result.findings.size()) + " cause(s) named, " +
                         std::to_string(result.unexplained.size()) + " unexplained signature(s)",
                     elapsed()};
    return result;
}

} // namespace drytwin::discovery
