#pragma once

#include "common/Error.h"
#include "data/SiBatch.h"
#include "physics/LineSimulator.h"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace drytwin::residual {

/// The outputs the input-driven correction corrects: outlet moisture (% wb) and temperature (°C).
inline constexpr int kCorrectedOutputs = 2;

struct BatchView;

/// @brief How the input-driven correction turns the input history into features.
enum class InputBasis {
    /// Each input through a bank of cascaded first-order filters (Laguerre-like, fixed stable
    /// poles): a lifted state x_{k+1} = A_f x_k + B_f z_k whose A_f is diagonal with every
    /// eigenvalue in (0, 1), so Eq. (30) holds by construction (P = I, α = the slowest pole) and
    /// the free run is bounded for bounded inputs. Few parameters for long memory (minutes).
    FilterBank,
    /// The inputs at lags 0, s, 2s … up to a maximum (a FIR ridge regression): the reference a
    /// system-identification reviewer would try first (issue #42's anchor).
    LaggedInputs,
    /// Both side by side: the filter bank's long memory and the lags' sharp delays.
    FilterBankAndLags,
    /// Each of the three above fitted, the one with the smallest cross-validated error on the
    /// training part kept (issue #42: neither basis won on every line; which one does is a
    /// property of the line, to be found in its training data, never in the data it is judged on).
    ChosenByValidation,
};

/// @brief Options of the input-driven correction (issue #42): a linear model of the PBM's
/// free-run error from the inputs, the disturbances and the PBM's own proxy states and outputs,
/// never from a measured output.
struct InputDrivenOptions {
    InputBasis basis = InputBasis::ChosenByValidation;
    bool useProxies = true; ///< false: inputs and disturbances only (the external-input variant)
    /// The manipulated input (the hot-air temperature) among the correction's inputs. The
    /// training data come from a line under its own control loop, which moves the hot air in
    /// answer to the moisture error, so a regression of that error on the hot air's history (or
    /// on the PBM's proxies, which follow the hot air) learns the loop's answers as if they were
    /// the line's response (closed-loop identification bias): on the demo the hybrid with the
    /// correction believes −0.02 % wb/K where the plant's gain is −0.09. Taking the hot air out
    /// does not remove that path (the proxies keep it) and costs free-run accuracy (demo,
    /// cross-validated moisture MAE 0.112 → 0.131 % wb), so it stays in by default; the MPC forms
    /// the correction with the hot air held instead (Forecasters.cpp, docs/mpc.md). Off: its
    /// column is held at zero (the input count, and the model file's form, stay).
    bool manipulatedInput = true;
    /// Filter bank: time constants [s] of the cascades; each cascade has @ref cascadeOrder stages
    /// (the second stage's impulse response peaks at τ, which carries transport delays).
    std::vector<double> timeConstantsS{6, 20, 60, 180, 540};
    int cascadeOrder = 2;
    /// Lagged inputs: the largest lag and the stride [s].
    double maxLagS = 300;
    double lagStrideS = 10;
    /// Ridge penalties tried, per unit of training rows, on standardised features; the one with
    /// the smallest cross-validated absolute error is used.
    std::vector<double> ridgeGrid{1e-4, 1e-3, 1e-2, 1e-1, 1.0};
    /// Standardised inputs are clipped to the training range widened by this share of its span
    /// on each side: an input the line never showed, or a transmitter spike, cannot drive the
    /// correction beyond what it learnt.
    double rangeMargin = 0.25;
    /// Rows whose training error is beyond this many robust standard deviations (1.4826 × MAD)
    /// are dropped and the fit repeated once: transmitter spikes must not set the coefficients.
    double outlierCutoff = 6.0;
    /// Issue #75: the correction only where the training rows support it. A row whose basis lies
    /// outside what the training rows held (its leverage h = φᵀ(ΦᵀΦ + λI)⁻¹φ beyond the training
    /// rows' @ref supportQuantile, h_ref) keeps the share h_ref / h of its correction, and every
    /// correction is held within the range it took on the training rows. Clipping each input to
    /// its range does not keep their combination inside what was seen: on an unseen 5 × 4,000 demo
    /// set a new batch's start-up at an ambient 9 K colder than any training batch drove the
    /// moisture correction to −4.4 % wb where the training rows' corrections never left ±0.6.
    /// false: the correction as fitted (model files before 2026-12-08).
    bool supportGuard = true;
    double supportQuantile = 0.995;
    /// Issue #75: the correction is cut by @ref agreementZ times its jackknife standard error
    /// across the cross-validation's fits without each fold (whole batches where there are three
    /// or more), so that where the fits without one batch or another disagree (a correction that
    /// rests on one batch: an ambient seen only in one batch's start-up), what is left is the part
    /// they agree on. false: no cut (model files before 2026-12-08).
    bool agreementAcrossFolds = true;
    double agreementZ = 1.0;
    /// Issue #75: the correction is fitted within batches: each training batch's own level of
    /// the PBM's error is a parameter of its own (fixed effects), so that the coefficients learn
    /// only what repeats within batches (a start-up, a response to the feed or the hot air), and a
    /// batch not seen gets the mean level of those seen. With a few batches, each at its own
    /// ambient, their levels otherwise became a slope in the ambient that a new batch at another
    /// ambient followed the wrong way (an unseen 4 × 3,000 demo set: free-run moisture 1.45 times
    /// the PBM's error). false: one pooled fit (model files before 2026-12-08).
    bool withinBatch = true;
    /// Issue #75: the correction holds inside the training range of every input and fades
    /// linearly to nothing across the margin beyond it (@ref rangeMargin of the span), the
    /// smallest weight over the inputs: a batch at an ambient or a feed the training batches
    /// never showed runs on the physics alone, as a process engineer would expect of a
    /// correction learnt from other conditions. false: the correction holds out to the clip
    /// range (model files before 2026-12-08).
    bool rangeGuard = true;
    /// Issue #75: the share κ of the correction kept is the one with the smallest cross-validated
    /// error among those under which no held-out fold (a batch the fit had not seen, where there
    /// are three or more) comes out worse than the PBM: never worse on a batch it had not seen,
    /// not merely better on the whole. false: the smallest error over all folds together.
    bool everyFoldNoWorse = true;
    /// Issue #75: and only a κ under which the fit on the first two thirds of the training rows
    /// in time is no worse than the PBM on the last third: the correction must hold forward in
    /// time, as it is used (the data set's later part, a what-if run from now on), not only on a
    /// batch left out between others. false: no such check (model files before 2026-12-08).
    bool laterInTime = true;
    Status validate() const;
};

/// @brief The cross-validated error of the correction beside the PBM's on the training part.
struct InputDrivenValidation {
    double ridge = 0;
    int folds = 0;
    double maeMoisturePbm = 0, maeMoistureCorrected = 0;       ///< % wb, held-out folds
    double maeTemperaturePbm = 0, maeTemperatureCorrected = 0; ///< °C
    bool moistureUsed = false, temperatureUsed = false;
    std::string note; ///< why an output's correction is not used, in plain words; empty if both are
    /// With InputBasis::ChosenByValidation: each basis tried and its cross-validated error
    /// relative to the PBM's (mean over the two outputs; < 1 beats the PBM), in plain words.
    std::string basisChoice;
    /// With the support guard: the training rows' leverage at its @ref
    /// InputDrivenOptions::supportQuantile (h_ref), and the correction's range on them.
    double supportLeverage = 0;
    Eigen::Vector2d correctionLow{0, 0}, correctionHigh{0, 0}; ///< % wb, °C
};

/// @brief The basis's name as model files and reports write it ("filter_bank", …).
std::string basisName(InputBasis basis);

/// @brief The input-driven part of the hybrid (issue #42): ê_free,k = C φ(z_0 … z_k) with φ the
/// basis of the input history. The free-run hybrid is ŷ_mech + ê_free; the measured error's
/// feedback (the lifted residual model) sits on top of it. A correction that does not beat the
/// PBM in cross-validation on the training part is not used for that output (and says so).
class InputDrivenCorrection {
public:
    /// @brief Fits on the rows of the views (targets: the measured minus the PBM's outputs);
    /// the basis runs from each batch's first row (inputs only, so no row after the view is
    /// needed and none of the target is used). Ridge penalty by cross-validation: whole batches
    /// as folds when there are three or more, else three contiguous blocks of each batch.
    static Expected<InputDrivenCorrection> train(const std::vector<BatchView>& views,
                                                 const InputDrivenOptions& options);

    /// @brief The correction for every row of @p batch (% wb in @p moisturePct, °C in
    /// @p temperatureC), NaN where no input was ever finite yet. Missing inputs hold their last value.
    /// @p support, when given, receives each row's moisture correction over the one fitted (1: kept
    /// whole; less where the guards of issue #75 cut it).
    void correct(const data::SiBatch& batch, const physics::SimulationResult& pbm,
                 std::vector<double>& moisturePct, std::vector<double>& temperatureC,
                 std::vector<double>* support = nullptr) const;
    /// @brief The PBM's run with the correction added to its outlet outputs (rows the
    /// correction cannot form keep the PBM's values).
    physics::SimulationResult corrected(const data::SiBatch& batch,
                                        const physics::SimulationResult& pbm) const;
    /// @brief The share of the correction's own change over @p horizon steps that predicted the
    /// PBM's error's change on rows of the training data it was not fitted on (X_out, T_out; 1 for
    /// files before 2026-12-08): the forecasts take back the rest, so that a correction whose
    /// changes do not hold forward in time leaves the PBM with its error held.
    Eigen::Vector2d changeWeight(int horizon) const;
    /// @brief @p pbm with the correction formed from another run of the same rows added: the
    /// inputs of @p sourceBatch and the proxies of @p sourcePbm (the MPC forms it from a run with
    /// the hot air held, so that the correction carries no path from the hot air; Forecasters.cpp).
    physics::SimulationResult correctedFrom(const physics::SimulationResult& pbm,
                                            const data::SiBatch& sourceBatch,
                                            const physics::SimulationResult& sourcePbm) const;

    bool used() const { return m_validation.moistureUsed || m_validation.temperatureUsed; }
    const InputDrivenValidation& validation() const { return m_validation; }
    const InputDrivenOptions& options() const { return m_options; }
    int featureCount() const { return static_cast<int>(m_coefficients.rows()); }
    /// @brief Rows of input history before a row that its correction depends on (within 0.5 %
    /// for the filter bank's slowest cascade): a caller that forms the correction on a window of
    /// a longer record (the MPC) starts the window this far back, or the basis would take the
    /// line to have stood at the window's first inputs.
    std::size_t memoryRows() const;

    std::string toJson() const;
    static Expected<InputDrivenCorrection> fromJson(const std::string& json);

private:
    /// InputBasis::ChosenByValidation: each concrete basis trained, the best one kept.
    static Expected<InputDrivenCorrection> trainChoosingBasis(const std::vector<BatchView>& views,
                                                              const InputDrivenOptions& options);
    /// The raw inputs z of every row of a batch (rows × inputs), missing cells holding the
    /// last finite value (the first finite one before it).
    Eigen::MatrixXd inputSeries(const data::SiBatch& batch, const physics::SimulationResult& pbm) const;
    /// The basis φ for every row (rows × features, the constant first) from standardised,
    /// clipped inputs.
    /// @p inRange, when given, receives each row's operating-range weight (InputDrivenOptions::rangeGuard).
    Eigen::MatrixXd basisOf(const Eigen::MatrixXd& inputs, double stepS,
                            Eigen::VectorXd* inRange = nullptr) const;
    /// The support guard's leverage of standardised basis rows: h = ‖φ‖² ρ − ‖Wᵀφ‖² (see
    /// m_supportDirections).
    Eigen::VectorXd leverageOf(const Eigen::MatrixXd& standardisedBasis) const;
    /// Fits the support guard on the standardised training rows @p phi (inliers marked) at ridge
    /// penalty @p penalty (absolute): the directions, ρ and the reference leverage.
    void fitSupport(const Eigen::MatrixXd& phi, const std::vector<char>& inlier, const Eigen::MatrixXd& gram,
                    double penalty);
    /// The guards of issue #75 (the fits without each fold, leverage, range) on the fitted
    /// correction @p out of the standardised basis rows @p phi, in place.
    void applyGuards(const Eigen::MatrixXd& phi, Eigen::MatrixXd& out) const;
    int inputCount() const;
    Eigen::Index featureCountFor(int inputs) const;

    InputDrivenOptions m_options;
    Eigen::VectorXd m_inputMean, m_inputScale, m_inputLow, m_inputHigh; ///< standardised range
    Eigen::VectorXd m_featureMean, m_featureScale;                      ///< of the basis columns
    Eigen::MatrixXd m_coefficients;                                     ///< features × 2 (% wb, °C)
    /// The support guard: with ΦᵀΦ = Σ sᵢ vᵢvᵢᵀ over the training rows and the penalty λ,
    /// h(φ) = Σ (vᵢᵀφ)²/(sᵢ + λ) = ρ‖φ‖² − Σ (vᵢᵀφ)² (ρ − 1/(sᵢ + λ)) with ρ = 1/λ; the columns of
    /// W are vᵢ √(ρ − 1/(sᵢ + λ)) for the directions whose sᵢ exceeds 5 % of λ (the others add at
    /// most 5 % to their term, and only upwards). Empty: no guard.
    Eigen::MatrixXd m_supportDirections;
    double m_supportRho = 0;
    /// The fits without each fold (κ applied): column 2f + o is fold f's output o. Empty: no cut.
    Eigen::MatrixXd m_foldCoefficients;
    /// μ_H per horizon of input_driven::kChangeHorizons (X_out, T_out); empty: 1 everywhere.
    std::vector<Eigen::Vector2d> m_changeWeights;
    double m_stepS = 1.0;
    InputDrivenValidation m_validation;
};

} // namespace drytwin::residual
