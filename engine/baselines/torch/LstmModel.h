#pragma once

// Inside engine/baselines only: the LSTM baseline's network, its features and its forecasts.
// LstmBaseline.h is the public face; libtorch stays behind it.

#include "baselines/LstmBaseline.h"

#include <array>
#include <memory>
#include <torch/torch.h>
#include <tuple>
#include <utility>
#include <vector>

namespace drytwin::baselines::detail {

inline constexpr int kRaw = 8;                    // T_hot, feed, X_in, T_in, T_amb, RH, X_out, T_out
inline constexpr int kOutputs = 2;                // X_out [% wb], T_out [°C]
inline constexpr int kLevel = 6;                  // the measured outputs among raw columns and features
inline constexpr int kChange = kRaw;              // the features y_k − y_{k−1} of each output
inline constexpr int kFeatures = kRaw + kOutputs; // raw columns, then the outputs' last step change

using Raw = std::array<double, kRaw>;
using Features = std::array<double, kFeatures>;
using CellState = std::tuple<torch::Tensor, torch::Tensor>; ///< (h, c), each [1, N, hidden]

/// @brief Raw row k of a batch in file-like units (°C, kg/h, % wb, %); NaN where missing.
Raw rawRow(const data::SiBatch& b, std::size_t k);

/// @brief What a pass over a batch carries from row to row: the last finite value of each raw
/// column (a missing cell, a dropout or an output not yet measured, holds it) and its moving
/// reference (the exponential moving average, or the training mean in the level form).
struct Carry {
    Raw held{};
    Raw reference{};
    std::array<bool, kRaw> seen{};
};

/// @brief The network: an LSTM and a linear head whose zero output is "hold the last measurement".
struct Net : torch::nn::Module {
    explicit Net(int hidden);
    torch::nn::LSTM lstm;
    torch::nn::Linear head;
};

/// @brief Rows [from, to) of a batch as the network reads them: features [1, rows, kFeatures],
/// and the outputs' held values and their references [rows, 2] (file units).
struct Pass {
    torch::Tensor features, held, reference;
};

/// @brief The trained LSTM baseline: network, standardisation, clip ranges and the record of
/// its training. Feature i of a row is (x_i − r_i) / s_i clipped to [low_i, high_i], where x_i is
/// the held raw value and r_i its reference; features kChange… are y_k − y_{k−1} over the
/// step change's spread. The network's output is that spread's multiple Δy_{k+1}.
struct LstmModel {
    LstmOptions options;
    std::shared_ptr<Net> net;
    Raw mean{};       ///< training mean of each raw column (the reference of the level form)
    Raw scale{};      ///< spread of each raw column about its reference
    double alpha = 0; ///< weight of a new row in the moving reference (0: the level form)
    std::array<double, kOutputs> changeScale{}; ///< spread of y_{k+1} − y_k: the output's unit
    Features low{}, high{};                     ///< clip range of the standardised features
    double trainSeconds = 0;
    std::vector<double> losses;
    std::vector<LstmEpoch> epochs;
    LstmValidation validation;
    Ending ending;

    /// @brief Reads row k into @p carry and writes its standardised, clipped features to @p row
    /// (kFeatures values); @p held and @p reference get the outputs' held values and references.
    void readRow(const data::SiBatch& b, std::size_t k, Carry& carry, float* row, double* held,
                 double* reference) const;
    /// @brief The same for rows [from, to).
    Pass inputs(const data::SiBatch& b, std::size_t from, std::size_t to, Carry& carry) const;

    /// @brief The cell's state after each of rows from … to−1, from a zero state at row 0 of
    /// @p features ([1, n, kFeatures]): one pass over the rows before @p from, then row by row.
    std::pair<torch::Tensor, torch::Tensor> statesAfter(const torch::Tensor& features, std::size_t from,
                                                        std::size_t to) const;

    /// @brief The free run of training: from @p state after row p−1 of the chunk @p x
    /// ([B, rows, kFeatures]), the outputs' held values and references there (@p level0,
    /// @p reference0 [B, 2], in units of the step change's spread), the network's own outputs fed
    /// back for @p steps rows. The predicted levels [B, steps, 2] of rows p … p+steps−1, with
    /// their gradient.
    torch::Tensor freeRunLevels(const CellState& state, const torch::Tensor& x, const torch::Tensor& level0,
                                const torch::Tensor& reference0, long p, long steps) const;

    /// @brief Multi-step prediction from N origins: @p h, @p c [1, N, hidden] after each
    /// origin's row, @p y [N, 2] the held outputs there and @p reference their references (file
    /// units, double). next(step) gives the features [N, 1, kFeatures] of row origin+step, whose
    /// outputs are replaced by the network's own; emit(step, y) receives the prediction of row
    /// origin+step (step = 1 … hMax).
    template <class Next, class Emit>
    void rollout(torch::Tensor h, torch::Tensor c, torch::Tensor y, torch::Tensor reference, std::size_t hMax,
                 const Next& next, const Emit& emit) const;

    /// @brief Two entries of a per-feature or per-output array as a tensor.
    torch::Tensor pair(const double* values, torch::ScalarType type = torch::kFloat32) const {
        return torch::tensor({values[0], values[1]}, type);
    }
};

/// @brief LstmBaseline::train's work (LstmTraining.cpp).
Expected<LstmModel> trainLstmModel(const std::vector<residual::BatchView>& training,
                                   const LstmOptions& options, const Progress& progress);

template <class Next, class Emit>
void LstmModel::rollout(torch::Tensor h, torch::Tensor c, torch::Tensor y, torch::Tensor reference,
                        std::size_t hMax, const Next& next, const Emit& emit) const {
    const torch::Tensor unit = pair(changeScale.data(), torch::kFloat64);
    const torch::Tensor sigma = pair(scale.data() + kLevel, torch::kFloat64);
    const torch::Tensor levelLow = pair(low.data() + kLevel), levelHigh = pair(high.data() + kLevel);
    const torch::Tensor levelLow64 = levelLow.to(torch::kFloat64),
                        levelHigh64 = levelHigh.to(torch::kFloat64);
    const torch::Tensor changeLow = pair(low.data() + kChange), changeHigh = pair(high.data() + kChange);
    torch::Tensor out = net->head->forward(h.squeeze(0)); // standardised change of row origin+1
    y = y + out.to(torch::kFloat64) * unit;
    emit(std::size_t{1}, y);
    for (std::size_t step = 1; step < hMax; ++step) {
        // Row origin+step with the predicted outputs, read as readRow reads a measured row.
        reference =
            reference + alpha * sigma * torch::clamp((y - reference) / sigma, levelLow64, levelHigh64);
        torch::Tensor in = next(step).clone();
        in.slice(2, kLevel, kLevel + kOutputs) =
            torch::clamp(((y - reference) / sigma).to(torch::kFloat32), levelLow, levelHigh).unsqueeze(1);
        in.slice(2, kChange, kChange + kOutputs) = torch::clamp(out, changeLow, changeHigh).unsqueeze(1);
        auto r = net->lstm->forward(in, std::make_tuple(h, c));
        h = std::get<0>(std::get<1>(r));
        c = std::get<1>(std::get<1>(r));
        out = net->head->forward(h.squeeze(0));
        y = y + out.to(torch::kFloat64) * unit;
        emit(step + 1, y);
    }
}

} // namespace drytwin::baselines::detail
