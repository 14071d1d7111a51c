#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "residual/ResidualModel.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::baselines {

/// @brief Options of the black-box LSTM baseline (libtorch, CPU). Small by default, so that it
/// trains in well under a minute on two cores.
struct LstmOptions {
    int hidden = 24;
    int sequenceLength = 64; ///< training windows [steps]
    int epochs = 30;
    int batchSize = 32;
    double learningRate = 3e-3;
    unsigned seed = 1;
    int threads = 2;
    Status validate() const;
};

/// @brief A black-box LSTM from inputs (u, d) and the measured outputs up to k to y_{k+1}
/// (paper §IV.B, "Black-Box (LSTM)"); multi-step prediction feeds back its own outputs.
/// Holds no Qt; libtorch stays inside this translation unit.
class LstmBaseline {
public:
    LstmBaseline();
    ~LstmBaseline();
    LstmBaseline(LstmBaseline&&) noexcept;
    LstmBaseline& operator=(LstmBaseline&&) noexcept;

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

    std::string toJson() const;
    static Expected<LstmBaseline> fromJson(const std::string& json);
    double trainingSeconds() const;
    const std::vector<double>& lossHistory() const; ///< mean training loss per epoch (standardised units)

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace drytwin::baselines
