#pragma once
// Internals shared by the discovery files (not part of the engine's interface). Discovery answers
// four questions: what the simulation gets wrong (ResidualAnalysis.cpp), which cause could
// explain it and how large (CandidateTests.cpp), which cause to name and whether it is specific
// (Discovery.cpp: the starting model and the rounds; Selection.cpp: one round; Confirmation.cpp,
// Specificity.cpp, PracticalFloors.cpp and, for onsets and lags, Dynamics.cpp), and how to say so
// (FindingText.cpp). DiscoveryData.cpp: the options and the data split.

#include "discovery/Discovery.h"
#include "discovery/DiscoveryNotes.h"
#include "physics/LineInputs.h"
#include "physics/LineSimulator.h"

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace drytwin::discovery::detail {

using properties::Param;
using properties::ParameterSet;

constexpr double kHacAcfThreshold = 0.05; ///< HAC bandwidth: first lag whose |ACF| falls below this

/// One-sided upper tail of the standard normal.
double upperTail(double z);
/// Whether cause parameter @p p changes either way (an offset, whose range reaches below 0) rather
/// than by growing from 0 (a loss, a lag).
bool twoSided(Param p);
/// The p of a score or change z of cause parameter @p p: one-sided for a cause that grows from 0
/// (a loss, a lag), two-sided for an offset.
double changeP(Param p, double z);

/// The measured channels: outlet moisture and temperature, tube-outlet ones where measured.
enum Channel { kXOut = 0, kTOut = 1, kXHdt = 2, kTHdt = 3 };
inline constexpr const char* kChannelName[] = {"X_out", "T_out", "X_hdt", "T_hdt"};
inline constexpr const char* kChannelUnit[] = {"% wb", "°C", "% wb", "°C"};

/// Measured and simulated values of a channel at row k (simulation index j), in file units,
/// and the factor from a dry-basis (or kelvin) sensitivity to file units. False when missing.
bool channelAt(const data::SiBatch& b, const physics::SimulationResult& r, std::size_t j, std::size_t k,
               int c, double& obs, double& pred, double& toFile);
double channelWeight(const calibration::LossWeights& w, int c);

/// Residuals and output sensitivities of the training subset, stacked: one entry per
/// (row, measured channel), weighted by √w so that Σ r² is the calibration loss's sum.
struct Stack {
    Eigen::MatrixXd s;         ///< entries × parameters, file units per parameter unit, weighted
    Eigen::VectorXd r;         ///< weighted residuals
    std::vector<int> batch;    ///< per entry
    std::vector<int> row;      ///< per entry: position of its row in the batch's subset
    std::vector<int> channel;  ///< per entry
    std::vector<double> timeS; ///< per entry: time since its batch started [s]
    /// Per batch: its mechanisms act from its start whatever the onset (LineInputs::mechanismsFromStart).
    std::vector<char> batchFromStart;
    /// @brief Time since a cause acting from @p onsetS began at entry @p i [s]; < 0 before it.
    double sinceOnsetS(std::size_t i, double onsetS) const {
        const auto b = static_cast<std::size_t>(batch[i]);
        return timeS[i] - (b < batchFromStart.size() && batchFromStart[b] ? 0.0 : onsetS);
    }
};

/// An onset (time since each batch's start): where a cause starts to act, with its profile
/// interval and, for a scan, its likelihood ratio over "from the start".
struct Onset {
    bool found = false;
    double s = 0, lowS = 0, highS = 0, likelihoodRatio = 0;
};

/// A cause's parameter on a reference period (a time when the line ran as it should): its
/// value, the standard error of that value and the normal spread of one period about it.
struct ReferenceValue {
    double value = 0;
    double se = 0;     ///< HAC standard error of the pooled value
    double spread = 0; ///< between-part standard deviation beyond the parts' own errors (upper 75 % bound)
    double spreadPoint = 0; ///< the same at its point estimate (naming once a change is detected)
    std::vector<PartEstimate> parts;
};
/// The reference a change is judged against (ReferenceDiscovery.cpp): each cause's one-step
/// estimate at the commissioned model, and its fit on the reference alone when asked.
struct Reference {
    std::map<Param, ReferenceValue> linear;
    /// The cause fitted alone on the reference from the commissioned model (cached by the caller).
    std::function<Expected<ReferenceValue>(Param)> fitted;
    /// The reference's own held-out error at the commissioned model (its structure taken off,
    /// part by part), as heldOut() weighs it: the level a period has without a change.
    double normalHeldLoss = 0;
    /// A detector flagged the new data (DiscoveryResult::detection): the monitors before selection,
    /// the causes' test once the first round's ranking gives it (SelectionRound::run).
    mutable bool changeDetected = false;
    /// The causes' test's family: the first round's candidates (SelectionRound::run).
    mutable std::size_t candidatesTested = 0;
    /// The screen's level before a detected change widened it (DiscoveryOptions::screenAlpha): a
    /// lag that passes it is fitted even outside the leading few (SelectionRound::scoreAndFit).
    double strictScreenAlpha = 0.05;
    /// The change point of the detector that flagged the new data (its onset within the onset
    /// run, seconds since that run's start, with its 95 % interval); not found when none did.
    Onset changePoint;
};

/// The data of one discovery run: batches, their split, and the training rows the tests use.
struct Problem {
    const std::vector<data::SiBatch>* batches = nullptr;
    std::vector<physics::LineInputs> inputs;
    std::vector<data::RowRange> train, test;
    std::vector<std::vector<std::size_t>> subset; ///< per batch, training rows in the tests and fits
    std::vector<data::RowRef> subsetRefs;
    physics::SimulationOptions simulation;
    DiscoveryOptions options;
    double samplingStepS = 1; ///< median sampling step of the batches
    /// Set when the data are judged against a reference period: a cause is then screened by how
    /// far its estimate moved from the reference's, and named only beyond its normal spread.
    const Reference* reference = nullptr;
};

/// The problem with the counts discovery reports.
struct Prepared {
    Problem pr;
    std::size_t keptTrain = 0, keptTest = 0;
    double meanBatchHours = 0;
};
/// The split and the training subset (DiscoveryData.cpp); NotEnoughData when too few rows pass.
/// With @p allRowsTrain every kept row is a training row and nothing is held out (a reference
/// period: commissioned, never judged).
Expected<Prepared> prepare(const std::vector<data::SiBatch>& batches, const hybrid::HybridModel& model,
                           const DiscoveryOptions& options, bool allRowsTrain = false);
/// What the data cannot give (channels not measured, inputs that are constant).
std::vector<std::string> dataNotes(const std::vector<data::SiBatch>& batches);

Expected<Stack> stackAt(const Problem& pr, const ParameterSet& p, const std::vector<Param>& sens);
/// Σ of @p contribution per (batch, row), as one time series per batch.
std::vector<std::vector<double>> perRowSeries(const Stack& st, const Eigen::VectorXd& contribution);
/// Variance of Σ_t u_t with batches independent and a Newey-West window per batch that follows
/// the series' own memory. Autocovariances about 0 (a score) or about the mean.
double hacVarianceOfSum(const std::vector<std::vector<double>>& series, bool demean);

struct ScoreResult {
    double z = 0;
    double estimate = 0;
    double se = 0;
    double reduction = 0; ///< (s̃ᵀr)² / s̃ᵀs̃: the sum of squares one linearised step removes
};
/// Column @p cand of the stack projected off the nuisance columns.
Eigen::VectorXd projectedColumn(const Stack& st, const std::vector<int>& nuisance, int cand);
ScoreResult scoreTest(const Stack& st, const std::vector<int>& nuisance, int cand);
/// The columns 0..count-1 without @p skip: the others as nuisance when one column is tested.
std::vector<int> columnsBut(int count, int skip);
/// The score test of every remaining cause (the stack's columns after the nuisance ones, in the
/// order of @p remaining), with Holm's correction over them.
std::vector<Candidate> scoreCandidates(const Stack& st, const std::vector<int>& nuisance,
                                       const std::vector<Param>& remaining);

/// Held-out errors of a parameter set: per test batch, the X_out and T_out errors and the
/// weighted squared error of every measured channel, per kept row.
struct HeldOut {
    std::vector<std::vector<double>> loss; ///< per test batch, per row
    std::vector<double> obsX, predX, obsT, predT;
    std::vector<double> residualX; ///< concatenated, % wb
    /// Per test batch, per channel: the time and the error scaled by the square root of the
    /// channel's weight (so that its square adds up to `loss`), for the fast-band share.
    struct Series {
        std::vector<double> timeS, weightedError;
    };
    std::vector<std::array<Series, 4>> channels;
};
Expected<HeldOut> heldOut(const Problem& pr, const ParameterSet& p);
double fastBandSquaredError(const HeldOut& h, double windowS);
double meanOf(const std::vector<std::vector<double>>& series);
/// The shares of the held-out weighted squared error, and of its fast part
/// (DiscoveryOptions::fastBandWindowS; 0 when off), that @p after removes from @p before.
std::pair<double, double> explainedShares(const HeldOut& before, const HeldOut& after,
                                          const DiscoveryOptions& options);
/// The outlet channels a cause downstream of the tube's outlet acts on alone (the meter's lag:
/// X_out; the conveyor's transport time: X_out and T_out); none for any other cause
/// (DiscoveryOptions::shareOnTheChannelsItActsOn).
std::optional<std::array<bool, 4>> outletChannelsActedOn(Param p);
/// "the outlet moisture's" or "the outlet channels'", for the messages.
std::string outletChannelsName(const std::array<bool, 4>& channels);
/// The same shares on some measured channels' error alone (by Channel), whole and fast part.
std::pair<double, double> explainedSharesOnChannels(const HeldOut& before, const HeldOut& after,
                                                    const std::array<bool, 4>& channels,
                                                    const DiscoveryOptions& options);
/// Against a reference, once a change is detected: the share of the change (the held-out error
/// beyond the reference's own level) that @p after removes; 0 where that does not apply or the
/// excess is under a tenth of the normal level.
double shareOfChange(const Problem& pr, const HeldOut& before, const HeldOut& after);
Gain gainOf(const HeldOut& before, const HeldOut& after);
/// One-sided Diebold-Mariano p that @p better has a lower held-out loss than @p worse.
double heldOutPValue(const HeldOut& worse, const HeldOut& better);
/// Per channel: held-out mean squared error (file units²) and the one-sided p that @p after is
/// worse than @p before on it; NaN where the channel is not measured.
struct ChannelChange {
    double mseBefore = 0, mseAfter = 0, pWorse = 1;
    double changeSe = 0; ///< HAC standard error of mseAfter − mseBefore (0: unknown)
    bool measured = false;
};
std::array<ChannelChange, 4> channelChanges(const HeldOut& before, const HeldOut& after);
/// A channel a cause acts on, whose held-out error did not fall: the one-sided p that the fall
/// its own effect predicts (its weighted mean square @p effectMeanSquare, were the cause right on
/// that channel) was missed by chance. Small: the channel had the power to show the cause and did
/// not. Where the change's standard error is unknown, 0 (the channel counts against the cause).
double unimprovedChannelP(const ChannelChange& change, double effectMeanSquare);

/// Question 1 for every measured channel, over all kept rows of every batch.
std::vector<OutputResidual> analyse(const Problem& pr, const std::vector<physics::SimulationResult>& sims);
/// What is left that matches no mechanism, by signature.
std::vector<Signature> signatures(const std::vector<OutputResidual>& residuals);

/// Specificity (Specificity.cpp). Per-part estimates at the fitted model: one Gauss-Newton step
/// from the pooled value with each part's data alone, column @p cand against the nuisance ones.
struct Consistency {
    std::vector<PartEstimate> parts;
    bool consistent = true;
    bool opposite = false; ///< a part with a significantly opposite sign
    int strays = 0;        ///< parts outside their widened interval of the pooled value
};
Consistency consistencyAt(const Problem& pr, const Stack& atFit, const std::vector<int>& nuisance, int cand,
                          double pooled, double tolerance);
/// Whether an offset is constant within the batch: its one-step estimate on the first and on the
/// second half of every batch's span from @p onsetS (0: the batch start), pooled over the batches.
/// A gauge's offset reads the same early and late; a change that grows within the batch (fouling,
/// a drifting reading) does not, whichever offset it resembles.
struct Constancy {
    bool checked = false; ///< each half had information
    PartEstimate early, late;
    bool constant = true; ///< the halves differ by less than 3 standard errors or half the pooled value
};
/// The causes whose parameter a batch does not change, judged so (constancyWithinBatch).
bool constantWithinBatch(Param p);
Constancy constancyWithinBatch(const Stack& atFit, const std::vector<int>& nuisance, int cand, double pooled,
                               double onsetS);
/// Fitted on the parts with the cooler hot air (one step from the pooled fit with their data
/// alone), the share of the warmer parts' training loss without the cause that it removes
/// (negative: it hurts there). @p atStart: the model without the cause, entries paired with @p atFit.
struct Transfer {
    bool checked = false; ///< fewer than four parts, or one operating region: not checked
    double reduction = 0;
};
Transfer transferBetweenRegions(const Problem& pr, const Stack& atStart, const Stack& atFit,
                                const std::vector<int>& nuisance, int fitCol, double pooled);
/// The time constant of a first-order lag that would explain a channel's training error
/// (measured ≈ simulated − τ d(simulated)/dt, batch biases removed), with its HAC standard
/// error, z and the share of the error's variance it explains. With @p atTauS > 0 the regressor
/// is the exact first-order response at that τ (per second of τ) instead of −d/dt, so that a long
/// lag is judged by what it does; rows before @p fromS (since each batch's start) are left out.
struct ChannelLag {
    double tauS = 0, se = 0, z = 0, share = 0;
    bool ok = false;
};
ChannelLag lagOnChannel(const Problem& pr, const std::vector<physics::SimulationResult>& sims, int channel,
                        double atTauS = 0, double fromS = 0);
/// The onset from which the cause's column explains most: a scan of the score test's reduction,
/// with its likelihood ratio over "from the start" and its profile interval.
Onset findOnset(const Stack& st, const std::vector<int>& nuisance, int cand);
/// findOnset on the cause's own effect at its fitted value @p fitted (the simulation with it
/// against the same with the cause at 0, from the start) instead of its tangent at 0, with the
/// round's residual: for a cause whose effect is far from linear in its parameter (a long meter
/// lag), whose tangent at 0 finds no onset. Not found when the stacks' entries differ.
Expected<Onset> findOnsetOfEffect(const Problem& pr, const Stack& roundStack,
                                  const std::vector<int>& nuisance, int cand, Param cause,
                                  const ParameterSet& fitted);
/// The "dynamics" signature of a channel: its error follows its simulated rate of change
/// strongly enough that a colleague would see it (|z| > 6, a time constant above two sampling
/// steps, a tenth of the error's variance); none otherwise.
std::optional<Signature> dynamicsSignature(const Problem& pr,
                                           const std::vector<physics::SimulationResult>& sims, int channel);
/// 1σ of the inlet moisture about its 30 s centred mean [% wb], over every kept row.
double inletFastScatterPct(const Problem& pr);
/// One-sided p that the inlet gauge's fast scatter (as inletFastScatterPct, per batch) rose
/// against @p referencePr's: Welch's t on the batches' log scatter; 1 with fewer than two
/// batches a side.
double inletScatterRiseP(const Problem& pr, const Problem& referencePr);
/// True when the cause's practical floor is on its own parameter (an offset, a time constant).
bool hasOwnFloor(Param p);
/// Why a fitted cause is below its practical floor, or "" when it is not. @p before is the fit
/// with the cause set to 0 (used for the causes without a floor of their own: their effect on
/// what is measured), @p after the fit.
std::string belowFloor(const Problem& pr, Param p, double value, double meanBatchHours, const HeldOut& before,
                       const HeldOut& after);

/// Compensation: a measured channel the cause acts on whose held-out error it raises, or -1.
int worsenedChannel(const HeldOut& before, const HeldOut& after, const DiscoveryOptions& options,
                    const std::array<bool, 4>& actsOn);
/// What the specificity judgement needs of a candidate that predicted better on the held-out part.
struct SpecificityInput {
    const Problem& pr;
    Param parameter;
    double value; ///< its fitted value
    double meanBatchHours;
    const HeldOut& before; ///< the model without it
    const HeldOut& after;  ///< the fit with it
    const ParameterSet& fitParameters;
    const Stack& atFit;   ///< at the fit: nuisance columns, then the cause's (column atCol)
    const Stack& atStart; ///< the round's stack at the model without it
    const std::vector<int>& nuisance;
    int atCol;
    const std::vector<physics::SimulationResult>& currentSims; ///< the model without it, every row
    bool afterOtherCauses = false; ///< another cause was named before it (DiscoveryOptions::laterCause…)
};
/// Whether a cause is specific: no channel made worse, above its floor, consistent part by part
/// and between operating regions, and (a meter lag) not the line's own dynamics. code is "" when
/// it is specific, else "compensation", "below_floor", "inconsistent" or "line_dynamics".
struct Specificity {
    std::string code, why;
    Consistency consistency;
    Constancy constancy;          ///< the causes a batch does not change only (constantWithinBatch)
    std::array<bool, 4> actsOn{}; ///< the measured channels its own effect moves beyond the floors
    Transfer transfer;
    bool responseJudged = false;           ///< against a reference, by direction (responseMismatch)
    std::array<double, 4> responseScale{}; ///< ... each channel's best scale of the cause's effect
};
Expected<Specificity> judgeSpecificity(const SpecificityInput& in);
/// Against a reference: each channel's best scale of the cause's effect (<e, d> / <d, d>, e the
/// error before it, d what it changes) and the z of its distance from the nearer bound of 1/4 and
/// 4 (HAC); channel is the first channel the cause acts on whose scale lies significantly outside
/// them (the wrong way, not moved, or off by more than a factor of 4), or -1.
struct ResponseMismatch {
    int channel = -1;
    std::array<double, 4> scale{}, z{};
};
ResponseMismatch responseMismatch(const HeldOut& before, const HeldOut& after,
                                  const std::array<bool, 4>& actsOn);

/// inlet_moisture_sensor_noise, judged on the starting model (whose refit frees the scatter
/// share with h_HDT and k_HDT): a finding when the measured scatter is above the gauge's normal
/// one and removing it predicts clearly better on the held-out part; none otherwise.
Expected<std::optional<Finding>> inletScatterFinding(const Problem& pr, const ParameterSet& current,
                                                     const std::vector<Param>& nuisance, const HeldOut& held,
                                                     const std::vector<OutputResidual>& residuals,
                                                     const DiscoveryOptions& options);

/// A fitted candidate judged on the held-out part and for specificity (Confirmation.cpp).
struct ConfirmationInput {
    const Problem& pr;
    const Candidate& cand;
    const ParameterSet& fitParameters; ///< the candidate's fit (nuisance and the cause free)
    Onset onset;                       ///< where it was fitted from its onset
    double level;                      ///< the held-out test's level for this candidate
    double meanBatchHours;
    const HeldOut& currentHeld;                                ///< the model without it
    const Stack& roundStack;                                   ///< the round's stack at that model
    const std::vector<int>& nuisanceCols;                      ///< its nuisance columns
    int roundCol;                                              ///< the candidate's column in it
    const std::vector<Param>& nuisance;                        ///< the nuisance parameters
    const std::vector<physics::SimulationResult>& currentSims; ///< the model without it, every row
    bool afterOtherCauses = false;                             ///< another cause was named before it
};
struct Confirmation {
    std::optional<Finding> finding; ///< set when it is named
    std::optional<HeldOut> held;    ///< the fit's held-out errors
    std::string code, why;          ///< when not named: "no_held_out_gain" or a specificity code
    double pValue = 1, explained = 0, explainedFast = 0;
};
Expected<Confirmation> confirmCandidate(const ConfirmationInput& in);
/// The channel test of the outlet response time. A transport time delays both outlet channels
/// alike, a meter lag the moisture reading alone, and the line's own thermal dynamics (the
/// product's heat capacity, a pyrometer's response) can only make the temperature later. The
/// delay each channel asks for alone (dtau_conv fitted to it), and which channel is later.
struct ChannelTiming {
    double moistureDelayS = 0, temperatureDelayS = 0;
    /// One-sided held-out p that the later channel is better predicted at its own delay than at
    /// the other channel's.
    double pValue = 1;
    /// Where the temperature is the later one: one-sided held-out p that the moisture is predicted
    /// worse at the temperature's delay than at its own (the moisture contradicts that delay).
    double moistureWorseAtTemperatureDelayP = 1;
    enum class Pattern {
        Alike,            ///< within a transport time's floor: what a transport time does
        MoistureLater,    ///< only a meter lag does that
        TemperatureLater, ///< the temperature has dynamics of its own: its timing cannot tell
        Undecided,        ///< apart, but the held-out part does not confirm which is later
        /// The temperature later and the moisture asking for no more delay than the model's
        /// plus moistureFloorS: the temperature's own dynamics, neither a transport time (both
        /// channels) nor a meter lag (the moisture).
        TemperatureOnly,
    };
    Pattern pattern = Pattern::Alike;
    /// The moisture's own delay that is still normal [s]: Floors::moistureResponseS, at least
    /// the transport time's floor.
    double moistureFloorS = 0;
};
/// @p currentDelayS: the model's own conveyor delay before the fits.
ChannelTiming channelTiming(const Problem& pr, double currentDelayS, double moistureDelayS,
                            double temperatureDelayS, const HeldOut& atMoistureDelay,
                            const HeldOut& atTemperatureDelay);
/// Why a cause is `inconsistent` part by part, in numbers: the pooled value, how many parts stray
/// (or that one has the opposite sign) and each part's estimate with its 95 % interval.
std::string inconsistencyReason(const Consistency& c, Param p, double pooled);
/// Why an outlet delay is the line's own dynamics (Pattern::TemperatureOnly), in numbers.
std::string lineDynamicsReason(const ChannelTiming& timing);
/// A transport time where the temperature alone asks for a delay (TemperatureOnly), against a
/// reference, when the moisture does not contradict the temperature's delay: not the line's
/// dynamics, the transport time stays a candidate. Alone, or for a meter lag, false.
bool transportSparedByMoisture(const Problem& pr, const ChannelTiming& timing);
/// Why a transport time is ruled out by a later moisture (Pattern::MoistureLater), in numbers.
std::string moistureLaterReason(const ChannelTiming& timing);
/// A fit of dtau_conv alone from @p start with the given channel weights (discovery's refit).
using DelayFit = std::function<Expected<calibration::CalibrationResult>(
    const ParameterSet& start, const calibration::LossWeights& weights)>;
/// The channel test on the model @p current: dtau_conv fitted to the outlet moisture alone and
/// to the outlet temperature alone (from @p startDelayS), each judged on the held-out part.
Expected<ChannelTiming> timeOutletChannels(const Problem& pr, const ParameterSet& current, double startDelayS,
                                           const DelayFit& fitDelay);
/// A cause fitted in the named cause's place (the round's fit, made when not yet made): null
/// when its fit failed otherwise than by a cancel.
using PlaceFit = std::function<Expected<const ParameterSet*>(Param other)>;
/// The look-alikes of the named cause @p f still outside the model, each fitted in its place and
/// judged on the same held-out part (a meter lag and a transport time by @p timing, the outlet
/// channels', where it was measured); the finding names the group where one is not ruled out.
Status addLookAlikes(const Problem& pr, Finding& f, const std::vector<Param>& remaining,
                     const PlaceFit& fitInPlace, const HeldOut& namedHeld,
                     const std::optional<ChannelTiming>& timing);
/// The model as selection has extended it so far.
struct ModelSoFar {
    ParameterSet parameters;
    double loss = 0;              ///< on the training subset
    std::vector<Param> nuisance;  ///< refitted with every cause: h_HDT, k_HDT, ..., the causes named
    std::vector<Param> remaining; ///< the causes not yet named
    std::vector<physics::SimulationResult> sims; ///< every row of every batch
    std::vector<OutputResidual> residuals;       ///< question 1 on those
    HeldOut held;
};
/// Discovery's fit: @p free from @p start on the training subset, globally too when @p global,
/// with the loss's channel weights @p weights (null: the options').
using CauseFit = std::function<Expected<calibration::CalibrationResult>(
    const ParameterSet& start, const std::vector<Param>& free, bool global,
    const calibration::LossWeights* weights)>;
/// Discovery's fit on @p pr's training subset of @p batches, its own progress reported as
/// discovery's at @p fraction (read at each call), any stop a cancel.
CauseFit makeCauseFit(const std::vector<data::SiBatch>& batches, const Problem& pr, const Progress& progress,
                      const double& fraction);
/// The change test of each candidate against the reference (@p pr.reference): its score,
/// p-value and ranking by how far its one-step estimate moved from the reference's, in units of
/// the two estimates' errors and the reference's normal spread. No-op without a reference.
void scoreAgainstReference(const Problem& pr, std::vector<Candidate>& cands);
/// Whether a fitted finding moved beyond the reference's normal spread; fills its reference
/// value and interval. "" when it did, else the reason (code "within_normal_spread").
Expected<std::string> judgeAgainstReference(const Problem& pr, Finding& f);
/// Against a reference: drops each finding that, restated at the final model (refitted with the
/// causes named after it), lies back within its normal spread, with a note naming it.
Status withdrawTakenUp(const Problem& pr, DiscoveryResult& result);
/// Detection against a reference period (ChangeDetection.cpp): a dynamic PCA monitor of the
/// measured columns and DryTwin's physics-residual monitor (the measured inputs and the
/// commissioned model's error on each measured output), both fitted on @p reference and its
/// simulation @p refSims and judged on @p batches with theirs, @p sims.
/// The DryTwin monitor reads the model's error on @p referenceForModel and @p batchesForModel
/// (the measurements with the line's own structure taken off, LineStructure), the PCA monitor
/// the raw measured columns of @p reference and @p batches.
Expected<ChangeDetection>
detectChange(const std::vector<data::SiBatch>& reference, const std::vector<data::SiBatch>& referenceForModel,
             const std::vector<physics::SimulationResult>& refSims, const std::vector<data::SiBatch>& batches,
             const std::vector<data::SiBatch>& batchesForModel,
             const std::vector<physics::SimulationResult>& sims, const DiscoveryOptions& options);
/// DryTwin's second test (ChangeDetection.cpp): the first round's change tests of the causes
/// (@p ranking, at the commissioned model), Bonferroni over them at half the false-alarm rate;
/// then the decision of both detectors again.
void testCauses(const std::vector<Candidate>& ranking, ChangeDetection& d);
/// The cause test's second look (ChangeDetection::CauseTest): each named cause's fitted value
/// against its normal value with the spread's upper bound, and the inlet gauge's scatter rise
/// (@p scatterRiseP, inletScatterRiseP; 1 when not asked), Bonferroni over the @p tested causes.
Status testNamedCauses(const Problem& pr, const std::vector<Finding>& findings, std::size_t tested,
                       double scatterRiseP, ChangeDetection& d);
/// The detectors' decision from their parts: DryTwin's (monitor or causes), PCA's, either.
void decide(ChangeDetection& d);
/// The line's own structure learnt on a reference period (LineStructure.cpp): the commissioned
/// model's error on each measured output as a ridge regression on the inputs and the model's
/// outputs (raw and causally filtered), to be taken off the measurements of any period.
struct LineStructure {
    double lambda = 0;            ///< the ridge penalty chosen by cross-validation over the reference's parts
    std::array<bool, 4> fitted{}; ///< per channel (too few measured rows: not fitted, nothing taken off)
    /// A batch's measurements with the predicted structural error taken off (its simulation at
    /// the commissioned model gives the model's outputs).
    std::function<data::SiBatch(const data::SiBatch&, const physics::SimulationResult&)> apply;
    /// The reference so corrected, each part by a fit on the other parts (an honest null).
    std::vector<data::SiBatch> referenceCorrected;
    /// Reference batches whose conditions the other batches never saw: their correction is the
    /// map's extrapolation, so they stay out of the causes' normal spread
    /// (DiscoveryOptions::normalSpreadWithinReferenceConditions; filled by discoverAgainstReference).
    std::set<std::string> extrapolatedBatches;
};
/// @brief A measured input column of a batch: its file name, unit, and value at row k (file
/// units), NaN when missing.
struct InputColumn {
    const char* name;
    const char* unit;
    double (*at)(const data::SiBatch& b, std::size_t k);
};
/// @brief The inputs as the monitors and the operating-range notes read them (ChangeDetection.cpp).
const std::array<InputColumn, 8>& inputColumns();
/// @brief Notes for each new batch whose typical input value (its median) lies outside what the
/// reference saw (its 0.5-99.5 % range widened by a quarter of the span), naming the input, its
/// value and the reference's range (ReferenceDiscovery.cpp).
std::vector<std::string> operatingRangeNotes(const std::vector<data::SiBatch>& reference,
                                             const std::vector<data::SiBatch>& batches,
                                             bool levelNotJudged = true);
/// @brief A new batch whose typical value (median) of one input lies outside what the reference
/// saw (its 0.5-99.5 % range widened by a quarter of the span).
struct OutsideReference {
    std::size_t batch = 0;
    const InputColumn* input = nullptr;
    double typical = 0, low = 0, high = 0; ///< the batch's median and the reference's range, file units
    /// As a note's item (DiscoveryNotes.h).
    notes::InputOutsideRange asNoteItem() const { return {input->name, input->unit, typical, low, high}; }
};
/// @brief Every such batch and input (ReferenceDiscovery.cpp); the notes and the detectors use it.
std::vector<OutsideReference> outsideReference(const std::vector<data::SiBatch>& reference,
                                               const std::vector<data::SiBatch>& batches);
/// @brief The line's structure learnt on the reference (LineStructure.cpp); @p withinRange holds
/// each feature within the range the fit saw before the map is applied
/// (DiscoveryOptions::lineStructureWithinReferenceRange).
LineStructure learnLineStructure(const std::vector<data::SiBatch>& reference,
                                 const std::vector<physics::SimulationResult>& refSims, bool withinRange);
/// Progress at a fraction of the whole discovery; true when the user stopped it.
using StopAt = std::function<bool(double fraction, const std::string& detail)>;
/// One round of selection (Selection.cpp): the remaining causes' score tests at @p model, the
/// leading ones fitted, tried by training loss (the k-th at α/k) on the held-out part and for
/// specificity, the outlet channels' timing where an outlet delay is confirmed. Records the round
/// in @p result; where a cause is named, adds its finding with its look-alikes and extends
/// @p model by it. True when a cause was named.
Expected<bool> selectionRound(const Prepared& prepared, int round, const CauseFit& refit, const StopAt& stop,
                              ModelSoFar& model, DiscoveryResult& result);
/// The rounds of selection, one cause at a time, until a round names none or
/// DiscoveryOptions::maxCauses are named.
Status selectCauses(const Prepared& prepared, const CauseFit& refit, const StopAt& stop, ModelSoFar& model,
                    DiscoveryResult& result);
/// The end of selection: every finding restated at the extended model @p extended (later rounds
/// refit the causes named before), the bounds of what the last round tested and did not name,
/// what no cause explains (@p residuals: the extended model's, @p sims its simulation), the
/// verdict.
void conclude(const Problem& pr, const ParameterSet& extended, const std::vector<Param>& nuisance,
              const std::vector<physics::SimulationResult>& sims, std::vector<OutputResidual> residuals,
              DiscoveryResult& result);
/// The first measured output on which @p named (the named cause's held-out part) is significantly
/// worse than @p other (a look-alike's, fitted in its place) at level @p alpha; "" when none.
/// Only the channels @p namedActsOn counts (the named cause's own effect moves them): a look-alike's
/// gain on an output the named cause does not touch is not a different balance of one signature.
std::string outputPredictedWorse(const HeldOut& other, const HeldOut& named, double alpha,
                                 const std::array<bool, 4>& namedActsOn);
/// A look-alike @p other fitted in the named cause's place (@p fitted), judged on the same held-out
/// part: its loss ratio and the one-sided DM p that the named cause predicts better; ruled out
/// when that p is small and the named cause is worse on no output (outputPredictedWorse).
Expected<LookAlike> compareLookAlike(const Problem& pr, Param other, const ParameterSet& fitted,
                                     const std::array<bool, 4>& namedActsOn, const HeldOut& namedHeld,
                                     const DiscoveryOptions& options);

/// Look-alikes (FindingText.cpp): causes that leave much the same signature on outlet data.
struct LookAlikeGroup {
    const char* name;
    std::vector<Param> members;
    const char* tellApart; ///< the measurement that tells them apart
};
/// The group of @p p, or null when it has no look-alike.
const LookAlikeGroup* lookAlikeGroupOf(Param p);
/// The output a finding helps most ("X_out" or "T_out") and that output's residual before it.
void describeOutput(Finding& f, const std::vector<OutputResidual>& before);
/// The evidence sentences of a finding (its numbers filled in).
std::string findingEvidence(const Finding& f, const DiscoveryOptions& options);

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
/// What a colleague should look for on the residual plots for each cause.
const char* lookFor(Param p);

/// Where a change against the reference began (ChangeOnset.cpp): the first judged batch from which
/// DryTwin's monitor sees it (0: none), the detector whose change point sets the onset (null:
/// neither found one), and the batches after the onset batch that read changed from their start.
std::size_t firstBatchOfChange(const monitoring::Detection& d);
const monitoring::Detection* changePointDetector(const ChangeDetection& detection);
std::vector<std::size_t> batchesChangedFromStart(const monitoring::Detection& d, std::size_t firstJudged);

} // namespace drytwin::discovery::detail
