#pragma once
// One round of selection (question 3), shared by its two files: CandidateFits.cpp scores the
// remaining causes and fits the leading ones (from their onsets where they have one);
// Selection.cpp tries them on the held-out part and for specificity and names the first that is
// specific, with its look-alikes.

#include "discovery/DiscoveryInternal.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace drytwin::discovery::detail {

class SelectionRound {
public:
    SelectionRound(const Prepared& prepared, int round, const CauseFit& refit, const StopAt& stop,
                   ModelSoFar& model, DiscoveryResult& result)
        : m_prepared(prepared), m_pr(prepared.pr), m_options(prepared.pr.options), m_refit(refit),
          m_stop(stop), m_model(model), m_result(result),
          m_frac0(0.1 + 0.8 * round / std::max(1, prepared.pr.options.maxCauses)), m_round(round) {}

    /// The round; true when it named a cause (the model is then extended by it).
    Expected<bool> run();

private:
    /// A candidate's fit: the parameters (nuisance and the cause free), its training loss, and
    /// the onset it was fitted from (none: from each batch's start).
    struct Fit {
        ParameterSet parameters;
        double loss = 0;
        Onset onset;
    };
    /// A fitted candidate judged on the held-out part and for specificity.
    struct Judged {
        Fit fit;
        Confirmation confirmation;
    };

    // CandidateFits.cpp
    Status scoreAndFit();
    void screenFromOnsets();
    int columnOf(Param p) const;
    Expected<bool> fitCause(Candidate& c, double onsetS, double fraction, const std::string& detail);
    Expected<std::optional<Fit>> refitFromOnset(const Candidate& cand, const Onset& onset);
    Expected<Fit> fittedFromOnset(const Candidate& cand);
    Expected<Confirmation> confirm(const Candidate& cand, const Fit& fit, int k) const;
    Expected<Judged> judgeFitted(const Candidate& cand, int k);

    // Selection.cpp
    bool isRemaining(Param p) const;
    Status tryFitted();
    Status timeChannels();
    Status confirmMeterLagAlone();
    Status nameWithLookAlikes();
    bool foldIntoEarlierFinding();
    Status extendModel();

    const Prepared& m_prepared;
    const Problem& m_pr;
    const DiscoveryOptions& m_options;
    const CauseFit& m_refit;
    const StopAt& m_stop;
    ModelSoFar& m_model;
    DiscoveryResult& m_result;
    const double m_frac0; ///< the round's start, as a fraction of the whole discovery
    const int m_round;

    Stack m_stack; ///< the round's residuals and sensitivities at the model as it stands
    std::vector<int> m_nuisanceCols;
    std::vector<Candidate> m_cands; ///< by screen, then predicted reduction
    std::map<Param, Fit> m_fits;
    Round m_record;
    int m_tried = 0;
    std::optional<ChannelTiming> m_timing;
    std::optional<Finding> m_named;
    ParameterSet m_namedParams;
    double m_namedLoss = 0;
    std::optional<HeldOut> m_namedHeld;
};

} // namespace drytwin::discovery::detail
