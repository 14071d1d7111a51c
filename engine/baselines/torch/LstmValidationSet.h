#pragma once

// Inside engine/baselines only: the validation part of the LSTM baseline's training, which
// decides early stopping and says whether the network beats the trivial references.

#include "baselines/torch/LstmModel.h"

#include <array>
#include <string>
#include <vector>

namespace drytwin::baselines::detail {

/// @brief Mean absolute error of each output.
struct Mae {
    std::array<double, kOutputs> sum{};
    std::array<std::size_t, kOutputs> n{};
    void add(int output, double error);
    double of(int output) const; ///< NaN with nothing added
};

/// @brief @p x with @p digits decimals.
std::string fixed(double x, int digits);

/// @brief The training views cut into a fitting part and a validation part: whole trailing
/// views (batches, in the chronological split) when that takes a sensible share and leaves at
/// least two to fit on, else the last share of each view's rows.
struct ValidationSplit {
    std::vector<residual::BatchView> fit, validation;
    std::string part; ///< which rows, in words
};
ValidationSplit splitForValidation(const std::vector<residual::BatchView>& views, double share);

/// @brief A validation part held ready for one pass per epoch: every view's batch from row 0 to
/// the view's end (the state runs in as it does when predicting) and what is scored there, one
/// step and `horizon` steps ahead, with the references' MAE on the same values.
struct ValidationSet {
    torch::Tensor features;  ///< [views, longest, kFeatures], zero-padded
    torch::Tensor held;      ///< [views, longest, 2] the held outputs
    torch::Tensor reference; ///< [views, longest, 2] their references
    int horizon = 0;         ///< the multi-step horizon scored (≤ 1: none)
    /// One scored value: the prediction of an output from origin (view, row).
    struct Entry {
        long view, origin;
        int output;
        double observed;
        std::size_t rollout; ///< index into rolloutOrigins (multi-step entries)
    };
    std::array<std::vector<Entry>, 2> entries;                  ///< one step, horizon steps
    std::vector<std::array<long, 2>> rolloutOrigins;            ///< (view, row) of multi-step origins
    std::array<std::array<double, kOutputs>, 2> referenceMae{}; ///< the better reference's
    std::size_t rows = 0;                                       ///< rows scored one step ahead
    /// Enough rows, and references with an error, to judge by.
    bool usable() const { return rows >= 50 && referenceMae[0][0] > 0 && referenceMae[0][1] > 0; }
    bool usableAhead() const {
        return usable() && !entries[1].empty() && referenceMae[1][0] > 0 && referenceMae[1][1] > 0;
    }
};
ValidationSet makeValidationSet(const LstmModel& m, const std::vector<residual::BatchView>& validation,
                                int horizon);

/// @brief MAE of each output on the validation part with the current weights: [0] one step
/// ahead (one pass of the whole sequences); with @p ahead also [1] the horizon's steps ahead, the
/// network's own outputs fed back (a pass row by row for the cell states, then one rollout).
std::array<Mae, 2> scoreValidation(const LstmModel& m, const ValidationSet& val, bool ahead);

/// @brief What the validation part says of the weights kept, in numbers and one sentence.
LstmValidation summarise(const LstmModel& m, const ValidationSplit& split, const ValidationSet& val);

} // namespace drytwin::baselines::detail
