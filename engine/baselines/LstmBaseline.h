#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "residual/ResidualModel.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::baselines {

/// @brief Options of the black-box LSTM baseline (libtorch, CPU). Small by default, so that it
/// trains in well under a minute on two cores for 10 batches of 6,300 rows.
struct LstmOptions {
    int hidden = 24;
    int sequenceLength = 64; ///< truncated back-propagation through time [steps]
    int segmentLength = 256; ///< rows a training stream is cut into, each run with a carried state
    int epochs = 30;         ///< at most; training stops early on the validation part
    int batchSize = 32;      ///< segments per optimiser step, at most (a quarter of them on little data)
    double learningRate = 3e-3;
    /// Share of the training rows held back for early stopping: whole trailing batches when
    /// there are enough of them, else the last share of each batch's rows.
    double validationFraction = 0.2;
    int patience = 8; ///< epochs without a better validation skill before training stops
    /// The kept network's validation skill is also reported this many steps ahead (multi-step
    /// prediction feeding back its own outputs; 0 or 1: one step only). Early stopping uses the
    /// one-step skill: choosing epochs by this one too did not predict the held-out skill better.
    int validationHorizon = 30;
    /// Each training chunk's last rows are also predicted with the network's own outputs fed
    /// back (as multi-step prediction does) for this many steps (0: one-step loss only) …
    int freeRunSteps = 30;
    double freeRunWeight = 1.0; ///< … and that loss weighs this much beside the one-step loss
    /// Inputs and measured outputs enter as their deviation from an exponential moving average
    /// over this time [s] (0: as levels about the training mean). Conditions that are constant
    /// within a batch (ambient, feed quality) then carry no batch identity a few training
    /// batches could teach the network to map to an offset, which on a new batch would be a drift.
    double highPassSeconds = 120;
    /// Standardised inputs are clipped to the training range widened by this share of it.
    double clipMargin = 0.25;
    unsigned seed = 1;
    /// libtorch intra-op threads. One: a small recurrent network's steps do not parallelise, a
    /// second thread only spins (same time, 1.6 times the CPU on 10 × 6,300 rows).
    int threads = 1;
    Status validate() const;
};

/// @brief One training epoch: the mean training loss (Huber, in units of the step change's
/// spread) and the one-step skill on the validation part (MAE over the better of persistence and
/// the PBM with its last error held; < 1 beats both).
struct LstmEpoch {
    int epoch = 0;
    double trainingLoss = 0;
    double validationSkillMoisture = 0;
    double validationSkillTemperature = 0;
};

/// @brief What the validation part said of the trained network (its best epoch).
struct LstmValidation {
    bool validated = false;       ///< false: too few rows to hold any back (no early stopping)
    bool beatsReferences = false; ///< both outputs' one-step skill < 1 on the validation part
    int bestEpoch = 0;            ///< 1-based; the weights kept
    std::size_t rows = 0;         ///< validation rows scored
    std::string part;             ///< which rows: "last 2 of 7 batches" or "last 20 % of each batch"
    double skillMoisture = 0;     ///< one step ahead, against the better reference
    double skillTemperature = 0;
    int horizon = 0; ///< the multi-step horizon also scored (0: none)
    double skillMoistureAhead = 0;
    double skillTemperatureAhead = 0;
    double maeMoisturePct = 0; ///< the network's, % wb
    double maeTemperatureC = 0;
    double referenceMaeMoisturePct = 0; ///< the better reference's
    double referenceMaeTemperatureC = 0;
    std::string message; ///< one English sentence: how it did and, if so, that it does not beat them
};

/// @brief A black-box LSTM from inputs (u, d) and the measured outputs up to k to y_{k+1}
/// (paper §IV.B, "Black-Box (LSTM)") in the nested form a system-identification reviewer expects:
/// the network predicts the step change Δy_{k+1} = y_{k+1} − y_k in units of its spread, its
/// output layer starts at zero (so the untrained network is "hold the last measurement"), inputs
/// and targets are standardised, inputs clipped to the training range widened by a margin, a
/// missing measured value holds the last one, and training stops early on a validation part and
/// keeps the best epoch's weights. Multi-step prediction feeds back its own outputs.
/// Holds no Qt; libtorch stays inside the translation unit.
class LstmBaseline {
public:
    LstmBaseline();
    ~LstmBaseline();
    LstmBaseline(LstmBaseline&&) noexcept;
    LstmBaseline& operator=(LstmBaseline&&) noexcept;

    /// @brief Trains on the rows of every view (views with a PBM run also give the validation
    /// part's second reference). Progress StopKeepBest ends training with the best epoch so far.
    static Expected<LstmBaseline> train(const std::vector<residual::BatchView>& training,
                                        const LstmOptions& options, const Progress& progress = {});
    /// @brief Predictions of the rows of the view made @p horizon steps before (1 = one step).
    residual::HybridPrediction predictAhead(const residual::BatchView& view, int horizon) const;
    /// @brief The same for several horizons at once (one per entry of @p horizons): every origin
    /// is rolled once up to the largest horizon, feeding back its own outputs, and read off at each.
    std::vector<residual::HybridPrediction> predictHorizons(const residual::BatchView& view,
                                                            const std::vector<int>& horizons) const;

    /// @brief Carries the network's state along a growing record one row at a time and forecasts
    /// from its end, so that a closed loop costs one cell step per sample instead of a pass over
    /// the whole record at every decision. Starts, like predictAhead, from a zero state at row 0.
    class Follower {
    public:
        explicit Follower(const LstmBaseline& model);
        ~Follower();
        Follower(Follower&&) noexcept;
        Follower& operator=(Follower&&) = delete;
        /// @brief Feeds rows up to and including @p row of @p record (inputs and measured outputs).
        void advanceTo(const data::SiBatch& record, std::size_t row);
        /// @brief Forecasts rows origin+1 … origin+horizon for each candidate, where origin is the
        /// last row fed and each candidate is the record with the inputs a plan would give after
        /// it (outputs there are not read). Entry [c] of the result belongs to candidate c.
        std::vector<residual::HybridPrediction> forecast(const std::vector<const data::SiBatch*>& candidates,
                                                         int horizon) const;
        /// @brief The last row fed (npos before the first).
        std::size_t lastRow() const;

    private:
        struct State;
        const LstmBaseline* m_model;
        std::unique_ptr<State> m_state;
    };

    /// @brief The model as JSON (format 2). fromJson refuses format 1 (the level-predicting
    /// network before issue #42) with a message to run train again.
    std::string toJson() const;
    static Expected<LstmBaseline> fromJson(const std::string& json);
    double trainingSeconds() const;
    const std::vector<double>& lossHistory() const; ///< mean training loss per epoch (standardised units)
    const std::vector<LstmEpoch>& epochs() const;   ///< one record per epoch run
    const LstmValidation& validation() const;
    /// @brief How training ended: converged (stopped early), budget exhausted (every epoch
    /// run), stopped with the best so far (by the caller).
    const Ending& ending() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::baselines
