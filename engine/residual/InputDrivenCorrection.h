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
    void correct(const data::SiBatch& batch, const physics::SimulationResult& pbm,
                 std::vector<double>& moisturePct, std::vector<double>& temperatureC) const;
    /// @brief The PBM's run with the correction added to its outlet outputs (rows the
    /// correction cannot form keep the PBM's values).
    physics::SimulationResult corrected(const data::SiBatch& batch,
                                        const physics::SimulationResult& pbm) const;
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
    Eigen::MatrixXd basisOf(const Eigen::MatrixXd& inputs, double stepS) const;
    int inputCount() const;
    Eigen::Index featureCountFor(int inputs) const;

    InputDrivenOptions m_options;
    Eigen::VectorXd m_inputMean, m_inputScale, m_inputLow, m_inputHigh; ///< standardised range
    Eigen::VectorXd m_featureMean, m_featureScale;                      ///< of the basis columns
    Eigen::MatrixXd m_coefficients;                                     ///< features × 2 (% wb, °C)
    double m_stepS = 1.0;
    InputDrivenValidation m_validation;
};

} // namespace drytwin::residual
