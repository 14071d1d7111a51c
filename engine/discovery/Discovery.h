#pragma once

#include "calibration/Calibration.h"
#include "common/Error.h"
#include "common/Progress.h"
#include "data/SiBatch.h"
#include "hybrid/HybridModel.h"
#include "monitoring/Monitor.h"
#include "properties/Parameters.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace drytwin::discovery {

/// @brief Options of a discovery run. Every choice is made on the training part of the
/// chronological split; the held-out part only judges the gain.
struct DiscoveryOptions {
    double trainFraction = 0.7; ///< chronological split (paper §IV.A)
    /// Every STRIDE-th kept training row enters the tests and fits; 0: chosen so that about
    /// 1,000 rows do (the fits' cost grows with them, the tests' power hardly beyond that).
    std::size_t subsetStride = 0;
    /// Screening: a candidate is fitted when its score test (HAC variance) has p below this in the
    /// direction that helps. Deliberately liberal; the confirmatory decision is the held-out test.
    double screenAlpha = 0.05;
    /// Against a reference, once a detector has flagged a change: the screen's level for the
    /// causes' change tests. A change is then established at the detectors' stated rate, and the
    /// screen only ranks the candidates; each one fitted is still judged by the held-out test, the
    /// direction on every output, consistency, floors, look-alikes and its normal spread. A
    /// single recording against a few reference runs gives its change tests little power (one
    /// hour of fouling at twice its default: z 1.4 on every cause alike), and the screen at 0.05
    /// then fitted none of them. 0: the screen stays at screenAlpha.
    double screenAlphaOnceDetected = 0.49;
    /// Level of the one-sided held-out Diebold-Mariano test that names a cause. The rounds form a
    /// fixed sequence: the candidate of each round is chosen on the training part alone, and the
    /// selection stops at the first round whose held-out test fails, which keeps the chance of
    /// naming any absent cause at this level (fixed-sequence testing) without dividing it.
    double gainAlpha = 0.05;
    /// A named cause must remove at least this share of the held-out squared error left, either
    /// of the whole error or of its fast part (below).
    double minExplainedFraction = 0.15;
    /// The fast part of the held-out error: each channel's weighted error minus its centred
    /// moving average over this window, per batch. Unmeasured slow drift (hours) can dominate the
    /// whole error and hide a real fast mechanism (a meter's lag, a transport time) behind it;
    /// the window is five times the line's slowest own dynamic (conveyor 60 s + actuator 20 s +
    /// a meter's lag of tens of seconds) and far below the hours of drift and fouling.
    /// 0: judge the whole error only.
    double fastBandWindowS = 600;
    /// Compensation: a cause that raises any measured channel's held-out squared error by more
    /// than this share (and significantly, one-sided p < 0.05) while lowering another's is not named.
    double maxChannelWorsening = 0.05;
    /// A channel the cause acts on whose held-out error does not fall counts against it when the
    /// fall its own effect predicts is missed significantly: one-sided p below this. 1: any such
    /// channel turns it down, however noisy (the rule before 2026-11-25).
    double unimprovedChannelAlpha = 0.05;
    /// Per-batch consistency: a batch's estimate may differ from the pooled value by its 95 %
    /// interval plus this share of the pooled value (the plant's forms are not the model's).
    double consistencyTolerance = 0.5;
    /// Free the outlet's mixing (tau_mix) with h_HDT and k_HDT in the starting refit: the line's
    /// own spread of a step in both outlet channels is the model's structure, not a cause. Off by
    /// default: on the distributed plant it made a transport-time error consistent in a null
    /// (docs/mechanisms.md, measured 2026-11-24); false keeps the paper's plug flow.
    bool freeOutletMixing = false;
    /// Search an onset for each cause (an effect that starts mid-batch) and report it.
    bool searchOnset = true;
    /// Practical floors in physical units: below them a cause is not worth a maintenance order,
    /// whatever its p-value. Defaults are typical data-sheet values; enter your instruments'.
    struct Floors {
        double outletMeterAccuracyPct = 0.15; ///< moisture_meter_offset [% wb]
        double inletGaugeAccuracyPct = 0.3;   ///< inlet_moisture_sensor_offset [% wb]
        double hotAirSensorLagS = 10;         ///< a thermocouple in a clean thermowell [s]
        /// The inlet gauge's fast scatter (1σ of X_in about its 30 s mean) that is still normal;
        /// inlet_moisture_sensor_noise needs the measured scatter above it [% wb].
        double inletGaugeScatterPct = 0.3;
        double foulingShare = 0.02; ///< h_HDT lost over a mean batch
        double transportTimeS = 3;  ///< transport_delay_error [s] (and at least 2 sampling steps)
        /// The outlet moisture's own response that is still normal (a meter's output filter, the
        /// product's spread on the belt) [s]: where the outlet temperature answers later than the
        /// model, the moisture must ask for more delay than this before a transport time or a
        /// meter lag is named (chosen on nulls of seeds 301-320, docs/discovery-study.md).
        double moistureResponseS = 5;
        double moistureEffectPct = 0.03;  ///< a cause must move X_out (rms, held-out) by this [% wb] ...
        double temperatureEffectK = 0.05; ///< ... or T_out by this [K]
    } floors;
    int maxCauses = 3;       ///< causes added one at a time, at most this many
    int candidatesToFit = 3; ///< significant candidates fitted per round, best score first
    int maxEvaluationsPerFit = 120;
    /// Only these causes (CONTRACT.md §4 names) are candidates; empty: all. For an engineer who
    /// asks about one suspect, and for the study's bound on what the judgement rules allow
    /// (bench/StudyDiscovery.cpp --oracle: the hidden cause alone).
    std::vector<std::string> causes;
    calibration::LossWeights weights; ///< as in calibration: 1 K weighs like 0.1 % wb
    /// Against a reference period: the chance that each detector calls a data set changed when
    /// nothing changed (the detectors' run-level decision).
    double falseAlarmRate = 0.01;
    /// Against a reference period: learn the line's own structure there (what the commissioned
    /// model always gets wrong, as a ridge regression on the inputs and the model's outputs) and
    /// take it off every period's measurements before a change is looked for. false: the
    /// causes' normal values alone carry the structure.
    bool learnLineStructure = true;
    /// Against a reference period: the line's structure is applied only within the conditions
    /// the reference saw: each of its features (inputs, the model's outputs, their filtered
    /// forms) is held at the edge of the range it had in the fit before the ridge is applied. A
    /// linear map fitted on a few weeks' weather is not a law for another season: its slope on
    /// ambient temperature or humidity is barely identified there and would extrapolate to an
    /// error that is the map's, not the line's. Measured on five study sets (reference-period.md):
    /// healthy pairs alarming 3 → 0 of 20 on the fresh seeds 741–743, naming level. false: applied
    /// as fitted everywhere, as before 2026-11-27 (late).
    bool lineStructureWithinReferenceRange = true;
    /// Against a reference of three or more batches, with the line's structure learnt: a
    /// reference batch whose typical value of an input lies outside what the other batches saw
    /// (a winter batch among summer ones) is left out of the causes' normal spread, as long as
    /// three batches remain. Each batch's structure is taken off by a map fitted on the others, so
    /// there the map extrapolated and the causes' values carry its error (a re-absorption of
    /// 4.1 ± 0.75 on a healthy winter batch beside 0.02, −0.70 and −0.01: a normal range of 0 to
    /// 4.3, within which a re-absorption of 1.6 was turned down); new data inside the reference's
    /// conditions are corrected by the map fitted on all of it. The notes name each batch left
    /// out. false: every batch's value in the spread, as before 2026-11-29.
    bool normalSpreadWithinReferenceConditions = true;
    /// Against a reference: a cause named early whose value, refitted with the causes named after
    /// it, lies back within its normal spread is withdrawn with a note (it had taken up their
    /// effect while alone). false: every cause named stays, as before 2026-11-27 (late).
    bool withdrawCausesTakenUpLater = true;
    /// Against a reference, once a detector has flagged a change: a lag (the meter's, the hot-air
    /// transmitter's) that shows no onset of its own is also fitted from the detector's change
    /// point (its time within its run, for every batch), and kept from there where it fits the
    /// training part better than from the start. A step of the process before the fault began,
    /// read without the lag, otherwise holds the lag fitted from the start down (a 60 s meter lag
    /// from 5 min of a one-hour training recording: 5.7 s from the start, 39 s from the change
    /// point at 11 min). false: from the start or its own onset only, as before 2026-11-28.
    bool lagFromChangePoint = true;
    /// Against a reference, once DryTwin's monitor has flagged a change: the batches wholly before
    /// its change point's 95 % interval ran as the reference did, and the causes are fitted and
    /// tested on the batches from the change on. A change that began at a batch change (after a
    /// cleaning, a maintenance) was otherwise fitted beside batches without it: a fouling of 0.2
    /// in the last two of four batches named nothing, the first two called a batch shift. The
    /// batches are taken in the order given (chronological: file names, a historian's times).
    /// false: every batch judged, as before 2026-11-28 (afternoon).
    bool judgeFromChangeOn = true;
    /// Against a reference, once a detector has found a change point: a batch after the one it
    /// lies in whose first minutes (before the onset time) already read changed is taken as
    /// changed from its start (physics::LineInputs::mechanismsFromStart): a fault that began
    /// 20 min into B03 and was not repaired is in B04 from its first minute. false: t_onset from
    /// every batch's start, as before 2026-11-28 (evening).
    bool changeGoesOnIntoLaterBatches = true;
    /// Against a reference period: a new batch whose typical value of an input lies outside what
    /// the reference saw (its 0.5-99.5 % range widened by a quarter of the span: a winter batch
    /// against summer runs) has no normal level to be compared with; both detectors judge only
    /// changes within it (its standardised statistics lose their own mean, and so do the null's).
    /// Every alarm on the healthy pairs of the study had such a batch. false: its level is
    /// judged like any other's, with a note, as before `9366b58`.
    bool judgeOnlyChangesBeyondReferenceConditions = true;
    /// Against a reference period: a cause counts against an output it acts on when its effect
    /// there does not point the way that output changed (or differs in size by more than a factor
    /// of 4), not whenever it raises that output's error: the lumped model may state a change's
    /// size wrongly on one output (Specificity.cpp, responseMismatch). false: the single-data-set
    /// rule (no output made significantly worse), as before 2026-11-27.
    bool referenceJudgesDirection = true;
    /// Against a reference period, a cause tried after another was named must lower the held-out
    /// error of every output it acts on (one-sided, at laterCauseAlpha, the causes named before it
    /// refitted with it), not merely point the way the outputs changed: a second finding sends a
    /// technician after something that is fine when it is only what is left of the first cause's
    /// imperfect form (a wall loss followed by a transport time, fouling by gas coupling; issue
    /// #72). false: judged as the first cause is, as before 2026-12-08.
    bool laterCauseImprovesEveryOutput = true;
    double laterCauseAlpha = 0.05;
    /// A cause a batch does not change (a gauge's offset, the wall's loss, the gas phase's
    /// coupling) must be estimated alike on the first and the second half of the batches
    /// (Specificity.cpp, `not_constant`). false: not checked, as before 2026-11-26.
    bool checkConstancyWithinBatch = true;
    /// A look-alike is ruled out only when the named cause is not significantly worse on any
    /// measured output; false: on the overall held-out loss alone, as before 2026-11-26.
    bool lookAlikeWorseOnNoOutput = true;
    /// Against a reference, once a detector has flagged a change: the share a cause must remove
    /// (minExplainedFraction) may also be counted of the change, the new data's held-out error
    /// beyond the reference's own level, not only of the whole error, whose noise and leftover
    /// structure the reference had too. false: of the whole error (or its fast part) alone, as
    /// before 2026-11-27 (evening).
    bool shareOfChangeOnceDetected = true;
    /// A cause downstream of the tube's outlet acts on the outlet channels alone: the meter's lag
    /// on X_out, the conveyor's transport time on X_out and T_out. The share it must remove
    /// (minExplainedFraction) may also be counted on those channels' held-out error, whole or fast
    /// part, which the error of channels it cannot touch (the tube outlet's) does not dilute.
    /// Issue #41's study: a 15 s meter lag on seeds 322 and 323 removed 7-11 % of the whole error
    /// and 10-12 % of its fast part. false: of every channel's error, as before 2026-11-29.
    bool shareOnTheChannelsItActsOn = true;
    /// Against a reference, once a detector has flagged a change: a fitted cause is judged against
    /// its normal spread at the spread's point estimate, not its upper 75 % bound (which keeps the
    /// causes' change test at its false-alarm rate). false: the bound, as before 2026-11-27 (late).
    bool pointSpreadOnceDetected = true;
    /// Against a reference, while neither detector has flagged a change: a cause named then is
    /// itself the claim that the line changed, so its fitted change must pass at the rate a
    /// detector states (falseAlarmRate, Bonferroni over the round's candidates), not at the 5 %
    /// that names a cause once a change is seen. false: z 1.96 either way, as before 2026-11-27 (night).
    bool undetectedChangeAtDetectorRate = true;
    /// DryTwin's cause test takes a second look at each named cause's fitted value (CauseTest):
    /// a change DryTwin names at the detector's rate is one its detector flags. Issue #41's
    /// study: on seed 323 the PCA monitor flagged runs whose causes DryTwin named right, while
    /// DryTwin's detector, judging the one-step screen, stayed silent. false: the screen alone,
    /// as before 2026-11-28.
    bool causeTestAtNamedFits = true;
    Status validate() const;
};

/// @brief One output's residual at a glance (question 1: what does the simulation get wrong?).
/// Residual = measured − simulated; moisture in % wb, temperature in °C.
struct OutputResidual {
    std::string output; ///< "X_out", "T_out", "X_hdt", "T_hdt"
    std::string unit;   ///< "% wb" or "°C"
    std::size_t rows = 0;
    double bias = 0;
    double biasSe = 0; ///< HAC standard error (per-batch Newey-West, batches independent)
    struct BatchBias {
        std::string batch;
        double mean = 0;
        double se = 0;
    };
    std::vector<BatchBias> perBatch;
    double withinBatchSd = 0; ///< standard deviation of the residual about its batch means
    double meanBatchHours = 0;
    double trendPerHour = 0; ///< pooled within-batch slope [unit/h]
    double trendSe = 0;
    double ljungBoxP = 1; ///< whiteness over 20 lags
    /// Strongest cross-correlations of the differenced residual with differenced inputs and
    /// proxy states over lags 0..300 s (10 s steps); `significant` beyond 4/√n.
    struct Correlate {
        std::string column;
        double lagS = 0;
        double ccf = 0;
        bool significant = false;
    };
    std::vector<Correlate> correlates;
    /// Mean residual per quintile of an operating variable.
    struct RegionBias {
        std::string column;
        std::string unit;
        std::vector<double> binUpper; ///< upper edge of each bin, in file units
        std::vector<double> mean;
    };
    std::vector<RegionBias> regions;
    double peakPeriodS = 0;    ///< strongest spectral line of the detrended residual (0: none)
    double peakPowerRatio = 0; ///< its power over the local background
    /// The residual every 60 s of every batch, for plots: time since batch start [s], value.
    std::vector<std::string> seriesBatch;
    std::vector<double> seriesTimeS;
    std::vector<double> seriesValue;
};

/// @brief A candidate cause and its score test (question 2).
struct Candidate {
    std::string cause;             ///< CONTRACT.md §4 name
    properties::Param parameter{}; ///< its model parameter
    double score = 0;              ///< z of the score test (positive: the mechanism helps)
    double pValue = 1;             ///< one-sided for parameters bounded at 0, two-sided otherwise
    double pHolm = 1;              ///< Holm-adjusted over all candidates of the round (reported)
    /// Against a reference: p is a timing cause's own score test (screened as alone), smaller than
    /// its change test's, whose z is the score column (a lag's one-step estimate understates it).
    bool pFromOwnScreen = false;
    double predictedReduction = 0; ///< share of the training loss one Gauss-Newton step would remove
    double linearEstimate = 0;     ///< one Gauss-Newton step from 0: U / (s̃ᵀs̃)
    double linearSe = 0;           ///< its HAC standard error
    /// Where its tangent shows an onset mid-batch and the score test from there is stronger, the
    /// screen, the ranking and the one-step estimate are from there [s into each batch]; -1: from
    /// each batch's start.
    double screenedFromS = -1;
    bool fitted = false;
    double fitLossBefore = 0; ///< training loss of the model without it (after its own refit)
    double fitLossAfter = 0;  ///< training loss with it fitted (h_HDT, k_HDT free again)
};

/// @brief Held-out accuracy of the physics model before and after a cause (question 4).
struct Gain {
    std::string split = "chronological_70_30";
    double maeMoistureBefore = 0, maeMoistureAfter = 0;       ///< X_out, % wb
    double maeTemperatureBefore = 0, maeTemperatureAfter = 0; ///< T_out, °C
    double r2MoistureBefore = 0, r2MoistureAfter = 0;
    double r2TemperatureBefore = 0, r2TemperatureAfter = 0;
    double pValue = 1; ///< one-sided Diebold-Mariano (HAC) on the weighted squared error
    double ljungBoxPMoistureBefore = 0, ljungBoxPMoistureAfter = 0;
    double lowFrequencyShareBefore = 0, lowFrequencyShareAfter = 0; ///< X_out residual below 0.01 Hz
    bool hasHybrid = false; ///< PGRL-CC retrained on top of each (filled by the Session)
    double hybridMaeMoistureBefore = 0, hybridMaeMoistureAfter = 0;
    double hybridMaeTemperatureBefore = 0, hybridMaeTemperatureAfter = 0;
};

/// @brief A cause's estimate in one part of the data: a batch, or a third of a single recording.
struct PartEstimate {
    std::string part; ///< batch id, or "batch id, part 2/3"
    double value = 0;
    double se = 0; ///< HAC standard error
};
/// @brief "B01 0.039±0.015; B02 …": each part's estimate with its 95 % interval (1.96 standard
/// errors), for a finding's per-part line and a turned-down cause's reason alike.
std::string describeParts(const std::vector<PartEstimate>& parts);

/// @brief A look-alike of a named cause: a cause that leaves much the same signature on these
/// data, fitted in its place and judged on the same held-out part.
struct LookAlike {
    std::string cause;
    properties::Param parameter{};
    double value = 0;
    double heldOutLossRatio = 1; ///< its held-out weighted squared error over the named cause's
    double pValue = 1;           ///< one-sided Diebold-Mariano that the named cause predicts better
    bool ruledOut = false;       ///< pValue below DiscoveryOptions::gainAlpha and no worseOutput
    /// Judged by the outlet channels' timing instead (a meter lag against a transport time): the
    /// delay the moisture and the temperature each ask for alone; pValue is then the one-sided
    /// held-out p that the later channel is later. Ruled out when the moisture is later (only a
    /// meter lag does that); not when the temperature is (the line's own thermal dynamics can
    /// delay it, so either cause fits) or the held-out part does not confirm which is later.
    bool byChannels = false;
    double moistureDelayS = 0, temperatureDelayS = 0;
    /// The measured output the named cause predicts significantly worse than this look-alike
    /// ("" when none): then it is not ruled out whatever pValue says.
    std::string worseOutput;
    /// Named in a later round on top of the cause (ruled out alone, yet the change needs both
    /// forms): then not ruled out, the finding names the group, and value is the joint fit's.
    bool namedAfter = false;
    double explainedAfter = 0; ///< the share of the held-out error it removed on top of the cause
};

/// @brief A named cause with its fitted parameter, evidence and gain.
struct Finding {
    std::string cause;
    properties::Param parameter{};
    double value = 0;
    double ci95Low = 0, ci95High = 0; ///< value ± 1.96 HAC standard errors of the score step
    /// Where later causes were named, value and interval are restated at the final model (every
    /// named cause fitted jointly); the evidence, the gain and the part-by-part values are from
    /// the fit when this cause was named: that value here (restated false: value is that one).
    bool restated = false;
    double valueWhenNamed = 0, ci95LowWhenNamed = 0, ci95HighWhenNamed = 0;
    double explainedFraction = 0;     ///< share of the held-out weighted squared error it removes
    double explainedFractionFast = 0; ///< share of its fast part (DiscoveryOptions::fastBandWindowS)
    bool fastPartCounted = false;     ///< the whole share fell short; the fast part's made it count
    /// A meter's lag or a transport time (DiscoveryOptions::shareOnTheChannelsItActsOn): the shares
    /// of the held-out squared error on the outlet channels it acts on, whole and fast part, it
    /// removes (either may be negative: the refit moves the other parameters too).
    bool judgedOnItsChannels = false;
    double explainedFractionOnItsChannels = 0, explainedFractionOnItsChannelsFast = 0;
    bool onItsChannelsCounted = false; ///< neither share over every channel made it count; its channels' did
    /// The output it helps most ("X_out" or "T_out") and that output's residual before it: the
    /// numbers of the evidence sentence, for a GUI that words it in its own language.
    std::string output;
    double biasBefore = 0, trendPerHourBefore = 0;
    std::string evidence; ///< one or two sentences an engineer can check on a plot
    Gain gain;
    /// Specificity: the estimate per batch (or per third of a single recording); consistent when
    /// each lies within its interval (widened by DiscoveryOptions::consistencyTolerance) of the
    /// pooled value, and the fit on the cooler half helps on the warmer half.
    std::vector<PartEstimate> perPart;
    bool consistent = true;
    bool transferChecked = false;
    double transferReduction = 0; ///< share of the warmer half's training loss the cooler half's fit removes
    /// An effect that starts mid-batch: its onset since the batch start [s], with the 95 %
    /// profile interval (hasOnset false: from the start).
    bool hasOnset = false;
    double onsetS = 0, onsetLowS = 0, onsetHighS = 0;
    /// With an onset, the batches it acts in from their start instead: a change that began in an
    /// earlier batch and went on (DiscoveryOptions::changeGoesOnIntoLaterBatches).
    std::vector<std::string> actsFromStartOf;
    /// Look-alikes: where one is not ruled out, the finding names the group, not one member.
    std::string group; ///< "" when the cause stands alone; else the group's name
    std::vector<LookAlike> lookAlikes;
    std::string tellApart; ///< the measurement that would tell the group's members apart
    /// The measured channels (X_out, T_out, X_hdt, T_hdt) its own effect moves beyond the
    /// practical floors; a look-alike is compared with it on those (not stored in files).
    std::array<bool, 4> actsOn{};
    /// Judged against a reference period: the cause's parameter fitted there (its normal value)
    /// and the interval a period's value normally falls in (its error and the spread between the
    /// reference's parts), so that the finding is a change, not a level.
    bool hasReference = false;
    double referenceValue = 0, referenceCi95Low = 0, referenceCi95High = 0;
    /// Against a reference: the change from the normal value in units of its combined uncertainty
    /// (this estimate's and the normal spread's), when it was judged; not stored in files.
    double changeZ = 0;
    /// Against a reference: on each channel it acts on, how much the line moved against what this
    /// cause's model form says (the best scale of its effect there; 1: as the model says). Judged
    /// by direction (DiscoveryOptions::referenceJudgesDirection); not stored in files.
    bool responseJudged = false;
    std::array<double, 4> responseScale{};
};

/// The outputs (0 X_out, 1 T_out, 2 X_hdt, 3 T_hdt) of a finding judged against a reference that
/// it acts on and where the line moved less than 2/3 or more than 1.5 times what the cause's model
/// form says: what the evidence sentence (engine and GUI) tells the engineer about.
std::vector<int> outputsMovedOtherThanModelled(const Finding& f);

/// @brief Structure left after the named causes that matches no mechanism (never forced onto one).
struct Signature {
    /// "periodic", "lagged_input", "batch_shift", "drift", or "dynamics" (the error follows the
    /// output's own rate of change: the line responds more slowly (lagS > 0) or faster than the
    /// model; lagS is the time constant that explains it, strength the share of variance)
    std::string type;
    std::string output;
    double periodS = 0;               ///< periodic
    std::string column;               ///< lagged_input
    double lagS = 0;                  ///< lagged_input
    std::vector<std::string> batches; ///< batch_shift
    double strength = 0;              ///< power ratio, |ccf|, shift in units, or trend per hour
};

/// @brief One round of the forward selection: what was tested and fitted, and why the best
/// candidate was named or not (so that a user can see why a suspected cause is absent).
struct Round {
    std::vector<Candidate> candidates; ///< fitted first, by training loss; then by evidence
    std::string best;                  ///< the fitted candidate with the lowest training loss
    double heldOutPValue = 1;          ///< its one-sided Diebold-Mariano p on the held-out part
    double explainedFraction = 0;      ///< of the held-out squared error left
    double explainedFractionFast = 0;  ///< of its fast part (DiscoveryOptions::fastBandWindowS)
    bool named = false;
    std::string reason; ///< why it stopped here, when not named
    /// Candidates that were tried and not named, and why ("no_held_out_gain", "compensation",
    /// "inconsistent", "below_floor", "line_dynamics", or "channels": a transport time where the
    /// moisture answers later than the temperature), with the sentence that explains it.
    struct Rejection {
        std::string cause, code, reason;
    };
    std::vector<Rejection> rejected;
};

/// @brief What the data allow for a cause that was not named: the one Gauss-Newton step from 0
/// at the final model (the named causes, h_HDT and k_HDT held as nuisance) with its HAC 95 %
/// interval, cut to the parameter's range. "Not named" then says how large it could still be.
struct Bound {
    std::string cause;
    properties::Param parameter{};
    double estimate = 0;
    double ci95Low = 0, ci95High = 0;
};

/// @brief Whether the data differ from the reference period at a stated false-alarm rate, by
/// DryTwin's physics-residual detector (the measured inputs and the commissioned model's errors)
/// and by a dynamic PCA monitor of the measured columns, both trained on the same reference.
struct ChangeDetection {
    bool changed = false;      ///< either detector
    double falseAlarmRate = 0; ///< per data set, per detector
    std::string decidedBy;     ///< "drytwin", "pca", "both" or ""
    /// DryTwin's detector: its monitor of the model's error (drytwin) or its test of the causes'
    /// parameters against their normal values (causeTest), each at half the rate (Bonferroni).
    bool drytwinChanged = false;
    /// The causes' change tests: the smallest one-sided (two-sided for an offset) p of a cause's
    /// parameter against its normal value (the spread at its upper bound), Bonferroni over the
    /// causes tested. Two looks: each cause's one-step estimate at the commissioned model (the
    /// screen), then each named cause's fitted value, which is better determined (a fouling the
    /// screen leaves at p 0.02 is at z 9 once fitted), and the inlet gauge's own scatter against
    /// the reference's (a noisier gauge is a change of the instrument, whatever the model's error).
    struct CauseTest {
        bool changed = false;
        double pValue = 1;       ///< Bonferroni-adjusted
        std::string cause;       ///< the one with the smallest p
        bool secondLook = false; ///< decided by the second look (a named fit or the gauge's scatter)
        /// Which look decided: "screen", "named_fit" or "gauge_scatter" (discover.json's `look`).
        std::string look() const {
            return !secondLook                              ? "screen"
                   : cause == "inlet_moisture_sensor_noise" ? "gauge_scatter"
                                                            : "named_fit";
        }
    } causeTest;
    /// A cause named against the reference (its fitted parameter beyond its normal spread, with a
    /// held-out gain): the line has changed even where the detectors, judging the data set as a
    /// whole at their stated rate, did not flag it. Its false-naming rate is the study's, not α.
    std::vector<std::string> namedCauses;
    bool namedChange() const { return !namedCauses.empty(); }
    /// Either detector, or a cause named: what the headline says.
    bool lineChanged() const { return changed || namedChange(); }
    monitoring::Detection drytwin, pca;
    std::vector<std::string> drytwinColumns, pcaColumns;
};

/// @brief The answer to the four questions.
struct DiscoveryResult {
    std::string verdict;                   ///< "cause_found", "no_structural_cause", "unexplained_structure"
    std::vector<OutputResidual> residuals; ///< of the starting model (after its refit of h_HDT, k_HDT)
    std::vector<OutputResidual> residualsAfter; ///< of the extended model
    std::vector<Candidate> ranking;             ///< the first round, best score first
    std::vector<Round> rounds;
    std::vector<Finding> findings; ///< in the order they were added
    std::vector<Signature> unexplained;
    std::vector<Bound> bounds;               ///< the causes tested in the last round and not named
    properties::ParameterSet baseParameters; ///< the starting model after its refit of h_HDT, k_HDT
    properties::ParameterSet parameters;     ///< the extended model's physics parameters
    std::size_t trainingRows = 0, heldOutRows = 0;
    /// What the data could not give: channels not measured, inputs that took their default.
    std::vector<std::string> notes;
    /// Judged against a reference period (discoverChange): what it held and whether, from when
    /// and by which detector the data differ from it.
    bool hasReference = false;
    std::string referencePath; ///< set by the caller that read it
    std::size_t referenceBatches = 0, referenceRows = 0;
    /// Against a reference: the batches left out of the causes' judgement because they lie wholly
    /// before the change point (DiscoveryOptions::judgeFromChangeOn), in their order.
    std::vector<std::string> batchesBeforeChange;
    /// Against a reference: the batches after the one the change began in, taken as changed from
    /// their start (DiscoveryOptions::changeGoesOnIntoLaterBatches), in their order.
    std::vector<std::string> batchesChangedFromStart;
    ChangeDetection detection;
    Ending ending;
};

/// @brief Discovery on measured batches (CONTRACT.md §2 `discover`, §4): residual analysis, a
/// score test per mechanism with a HAC variance and Holm's correction, fits of the leading
/// candidates with h_HDT and k_HDT free again, and a held-out Diebold-Mariano test before a cause
/// is kept, then specificity (no measured channel made worse, practical floors, consistency part
/// by part and between operating regions, a meter lag the line's own dynamics do not explain) and
/// its look-alikes fitted in its place; an onset is searched for each. Causes are added one at a
/// time until none helps. What is left is reported by its signature. Thread-safe for distinct
/// arguments. docs/discovery-study.md has what it achieves on each plant.
Expected<DiscoveryResult> discover(const std::vector<data::SiBatch>& batches,
                                   const hybrid::HybridModel& model, const DiscoveryOptions& options = {},
                                   const Progress& progress = {});

/// @brief What changed since the line ran well (CONTRACT.md §2 `discover --reference`). The
/// model is commissioned on @p reference (h_HDT, k_HDT and the inlet gauge's scatter share
/// fitted on all of it; each cause's estimate there, with its spread between the reference's
/// parts, as its normal value), then @p batches are judged against it: detection by both
/// monitors, and a cause named only when its estimate moved beyond its normal spread, its fit
/// predicts the held-out part better on every channel it acts on (the rules of discover(): held
/// out, specific, look-alikes, floors, onsets) and the fitted value lies outside the reference's
/// normal interval. The commissioned parameters stay fixed: a change is what they do not explain.
Expected<DiscoveryResult> discoverChange(const std::vector<data::SiBatch>& reference,
                                         const std::vector<data::SiBatch>& batches,
                                         const hybrid::HybridModel& model,
                                         const DiscoveryOptions& options = {}, const Progress& progress = {});

} // namespace drytwin::discovery
