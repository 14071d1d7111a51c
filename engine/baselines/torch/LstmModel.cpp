#include "baselines/torch/LstmModel.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>

namespace drytwin::baselines::detail {

Raw rawRow(const data::SiBatch& b, std::size_t k) {
    using namespace units;
    return {kelvinToCelsius(b.tHotK[k]), kgPerSToKgPerHour(b.feedKgPerS[k]), dryToWetPct(b.xInDb[k]),
            kelvinToCelsius(b.tInK[k]),  kelvinToCelsius(b.tAmbK[k]),        fractionToPercent(b.rhAmb[k]),
            dryToWetPct(b.xOutDb[k]),    kelvinToCelsius(b.tOutK[k])};
}

Net::Net(int hidden)
    : lstm(torch::nn::LSTMOptions(kFeatures, hidden).batch_first(true)), head(hidden, kOutputs) {
    register_module("lstm", lstm);
    register_module("head", head);
    // A zero output is "hold the last measurement": training starts from persistence.
    torch::NoGradGuard noGrad;
    head->weight.zero_();
    head->bias.zero_();
}

void LstmModel::readRow(const data::SiBatch& b, std::size_t k, Carry& carry, float* row, double* held,
                        double* reference) const {
    const Raw r = rawRow(b, k);
    const Raw before = carry.held;
    const auto seenBefore = carry.seen;
    for (std::size_t i = 0; i < kRaw; ++i) {
        if (std::isfinite(r[i])) {
            if (!carry.seen[i]) {
                carry.reference[i] = alpha > 0 ? r[i] : mean[i];
            }
            carry.held[i] = r[i];
            carry.seen[i] = true;
        }
        // The reference moves by the clipped deviation: a spike does not drag it along.
        carry.reference[i] +=
            alpha * scale[i] * std::clamp((carry.held[i] - carry.reference[i]) / scale[i], low[i], high[i]);
        const double z = carry.seen[i] ? (carry.held[i] - carry.reference[i]) / scale[i] : 0.0;
        row[i] = static_cast<float>(std::clamp(z, low[i], high[i]));
    }
    for (std::size_t j = 0; j < kOutputs; ++j) {
        const std::size_t i = kLevel + j;
        const double d = carry.seen[i] && seenBefore[i] ? (carry.held[i] - before[i]) / changeScale[j] : 0.0;
        row[kChange + j] = static_cast<float>(std::clamp(d, low[kChange + j], high[kChange + j]));
        held[j] = carry.seen[i] ? carry.held[i] : mean[i];
        reference[j] = carry.seen[i] ? carry.reference[i] : mean[i];
    }
}

Pass LstmModel::inputs(const data::SiBatch& b, std::size_t from, std::size_t to, Carry& carry) const {
    const auto rows = static_cast<long>(to > from ? to - from : 0);
    Pass p{torch::zeros({1, rows, kFeatures}, torch::kFloat32),
           torch::zeros({rows, kOutputs}, torch::kFloat64), torch::zeros({rows, kOutputs}, torch::kFloat64)};
    float* f = p.features.data_ptr<float>();
    double* held = p.held.data_ptr<double>();
    double* reference = p.reference.data_ptr<double>();
    for (std::size_t k = from; k < to; ++k) {
        const std::size_t i = k - from;
        readRow(b, k, carry, f + i * kFeatures, held + i * kOutputs, reference + i * kOutputs);
    }
    return p;
}

std::pair<torch::Tensor, torch::Tensor> LstmModel::statesAfter(const torch::Tensor& features,
                                                               std::size_t from, std::size_t to) const {
    torch::Tensor h = torch::zeros({1, 1, options.hidden});
    torch::Tensor c = torch::zeros({1, 1, options.hidden});
    if (from > 0) {
        auto r = net->lstm->forward(features.slice(1, 0, static_cast<long>(from)), std::make_tuple(h, c));
        h = std::get<0>(std::get<1>(r));
        c = std::get<1>(std::get<1>(r));
    }
    std::vector<torch::Tensor> hs, cs;
    for (std::size_t k = from; k < to; ++k) {
        auto r = net->lstm->forward(features.slice(1, static_cast<long>(k), static_cast<long>(k) + 1),
                                    std::make_tuple(h, c));
        h = std::get<0>(std::get<1>(r));
        c = std::get<1>(std::get<1>(r));
        hs.push_back(h);
        cs.push_back(c);
    }
    return {torch::cat(hs, 1), torch::cat(cs, 1)};
}

torch::Tensor LstmModel::freeRunLevels(const CellState& state, const torch::Tensor& x,
                                       const torch::Tensor& level0, const torch::Tensor& reference0, long p,
                                       long steps) const {
    // Levels here are in units of the step change's spread; features want the raw spread's.
    const torch::Tensor unit = pair(changeScale.data()) / pair(scale.data() + kLevel);
    const torch::Tensor levelLow = pair(low.data() + kLevel), levelHigh = pair(high.data() + kLevel);
    const torch::Tensor changeLow = pair(low.data() + kChange), changeHigh = pair(high.data() + kChange);
    torch::Tensor h = std::get<0>(state);
    torch::Tensor c = std::get<1>(state);
    torch::Tensor out = net->head->forward(h.squeeze(0));
    torch::Tensor level = level0 + out;
    torch::Tensor reference = reference0;
    std::vector<torch::Tensor> levels{level};
    for (long s = 1; s < steps; ++s) {
        reference = reference + alpha * torch::clamp((level - reference) * unit, levelLow, levelHigh) / unit;
        const torch::Tensor in =
            torch::cat({x.slice(1, p - 1 + s, p + s).slice(2, 0, kLevel),
                        torch::clamp((level - reference) * unit, levelLow, levelHigh).unsqueeze(1),
                        torch::clamp(out, changeLow, changeHigh).unsqueeze(1)},
                       2);
        auto r = net->lstm->forward(in, std::make_tuple(h, c));
        h = std::get<0>(std::get<1>(r));
        c = std::get<1>(std::get<1>(r));
        out = net->head->forward(h.squeeze(0));
        level = level + out;
        levels.push_back(level);
    }
    return torch::stack(levels, 1);
}

} // namespace drytwin::baselines::detail
