#include "baselines/LstmBaseline.h"

#include "common/Units.h"
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <torch/torch.h>

namespace drytwin::baselines {

namespace {

constexpr int kInputs = 8;  // T_hot, feed, X_in, T_in, T_amb, RH, X_out, T_out (measured)
constexpr int kOutputs = 2; // X_out [% wb], T_out [°C]

/// Raw feature row k of a batch, in file-like units.
std::array<double, kInputs> rawFeatures(const data::SiBatch& b, std::size_t k) {
    using namespace units;
    return {kelvinToCelsius(b.tHotK[k]), kgPerSToKgPerHour(b.feedKgPerS[k]), dryToWetPct(b.xInDb[k]),
            kelvinToCelsius(b.tInK[k]),  kelvinToCelsius(b.tAmbK[k]),        fractionToPercent(b.rhAmb[k]),
            dryToWetPct(b.xOutDb[k]),    kelvinToCelsius(b.tOutK[k])};
}

struct Net : torch::nn::Module {
    Net(int hidden)
        : lstm(torch::nn::LSTMOptions(kInputs, hidden).batch_first(true)), head(hidden, kOutputs) {
        register_module("lstm", lstm);
        register_module("head", head);
    }
    torch::nn::LSTM lstm;
    torch::nn::Linear head;
};

} // namespace

struct LstmBaseline::Impl {
    LstmOptions options;
    std::shared_ptr<Net> net;
    std::array<double, kInputs> mean{}, scale{};
    double trainSeconds = 0;
    std::vector<double> losses;

    torch::Tensor features(const data::SiBatch& b, std::size_t from, std::size_t to) const {
        torch::Tensor t = torch::empty({1, static_cast<long>(to - from), kInputs}, torch::kFloat64);
        auto acc = t.accessor<double, 3>();
        for (std::size_t k = from; k < to; ++k) {
            const auto f = rawFeatures(b, k);
            for (int i = 0; i < kInputs; ++i) {
                acc[0][static_cast<long>(k - from)][i] =
                    (f[static_cast<std::size_t>(i)] - mean[static_cast<std::size_t>(i)]) /
                    scale[static_cast<std::size_t>(i)];
            }
        }
        return t;
    }

    /// Standardised features of every row of a batch for prediction; a missing cell enters as
    /// its training mean.
    torch::Tensor batchFeatures(const data::SiBatch& b) const {
        return torch::nan_to_num(features(b, 0, b.rows()).to(torch::kFloat32), 0.0);
    }

    /// The cell's state (h, c) after each row, from one stateful pass over the batch.
    void statesAfterEachRow(const torch::Tensor& f, std::vector<torch::Tensor>& hs,
                            std::vector<torch::Tensor>& cs) const {
        const auto n = static_cast<std::size_t>(f.size(1));
        hs.assign(n, {});
        cs.assign(n, {});
        torch::Tensor hState = torch::zeros({1, 1, options.hidden});
        torch::Tensor cState = torch::zeros({1, 1, options.hidden});
        for (std::size_t k = 0; k < n; ++k) {
            auto r = net->lstm->forward(f.slice(1, static_cast<long>(k), static_cast<long>(k) + 1),
                                        std::make_tuple(hState, cState));
            hState = std::get<0>(std::get<1>(r));
            cState = std::get<1>(std::get<1>(r));
            hs[k] = hState;
            cs[k] = cState;
        }
    }
};

LstmBaseline::LstmBaseline() : m_impl(std::make_unique<Impl>()) {}
LstmBaseline::~LstmBaseline() = default;
LstmBaseline::LstmBaseline(LstmBaseline&&) noexcept = default;
LstmBaseline& LstmBaseline::operator=(LstmBaseline&&) noexcept = default;

Status LstmOptions::validate() const {
    if (hidden < 1 || hidden > 512 || sequenceLength < 4 || epochs < 1 || batchSize < 1 || threads < 1 ||
        !(learningRate > 0 && learningRate < 1)) {
        return Error{ErrorKind::BadInput, "LSTM options",
                     "need 1 ≤ hidden ≤ 512, sequence ≥ 4, epochs ≥ 1, batch ≥ 1, threads ≥ 1, 0 < rate < 1"};
    }
    return {};
}

double LstmBaseline::trainingSeconds() const {
    return m_impl->trainSeconds;
}
const std::vector<double>& LstmBaseline::lossHistory() const {
    return m_impl->losses;
}

Expected<LstmBaseline> LstmBaseline::train(const std::vector<residual::BatchView>& training,
                                           const LstmOptions& o, const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = o.validate(); !st) {
        return st.error();
    }
    torch::manual_seed(o.seed);
    torch::set_num_threads(o.threads);
    LstmBaseline model;
    auto& im = *model.m_impl;
    im.options = o;
    // Standardisation from the training rows.
    std::array<double, kInputs> sum{}, sum2{};
    std::size_t count = 0;
    for (const auto& v : training) {
        for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
            const auto f = rawFeatures(*v.batch, k);
            bool finite = true;
            for (double x : f) {
                finite = finite && std::isfinite(x);
            }
            if (!finite) {
                continue;
            }
            for (int i = 0; i < kInputs; ++i) {
                sum[static_cast<std::size_t>(i)] += f[static_cast<std::size_t>(i)];
                sum2[static_cast<std::size_t>(i)] +=
                    f[static_cast<std::size_t>(i)] * f[static_cast<std::size_t>(i)];
            }
            ++count;
        }
    }
    if (count < static_cast<std::size_t>(4 * o.sequenceLength)) {
        return Error{ErrorKind::BadInput, "LSTM training", "too few training rows"};
    }
    for (std::size_t i = 0; i < kInputs; ++i) {
        im.mean[i] = sum[i] / static_cast<double>(count);
        const double var = sum2[i] / static_cast<double>(count) - im.mean[i] * im.mean[i];
        im.scale[i] = var > 1e-12 ? std::sqrt(var) : 1.0;
    }
    // Training windows: inputs rows k..k+S−1, targets the measured outputs of rows k+1..k+S.
    std::vector<torch::Tensor> xs, ys;
    for (const auto& v : training) {
        const auto s = static_cast<std::size_t>(o.sequenceLength);
        for (std::size_t k = v.rows.begin; k + s + 1 <= v.rows.end; k += s / 2) {
            torch::Tensor f = im.features(*v.batch, k, k + s + 1);
            if (!torch::isfinite(f).all().item<bool>()) {
                continue; // windows with a missing value are skipped, not zero-filled
            }
            xs.push_back(f.slice(1, 0, static_cast<long>(s)));
            ys.push_back(f.slice(1, 1, static_cast<long>(s) + 1).slice(2, kInputs - kOutputs, kInputs));
        }
    }
    if (xs.empty()) {
        return Error{ErrorKind::BadInput, "LSTM training", "no complete training window"};
    }
    const torch::Tensor X = torch::cat(xs, 0).to(torch::kFloat32);
    const torch::Tensor Y = torch::cat(ys, 0).to(torch::kFloat32);
    im.net = std::make_shared<Net>(o.hidden);
    torch::optim::Adam optimizer(im.net->parameters(), torch::optim::AdamOptions(o.learningRate));
    const long n = X.size(0);
    for (int epoch = 0; epoch < o.epochs; ++epoch) {
        const torch::Tensor perm = torch::randperm(n, torch::kLong);
        double total = 0;
        long batches = 0;
        for (long start = 0; start < n; start += o.batchSize) {
            const torch::Tensor idx = perm.slice(0, start, std::min(n, start + o.batchSize));
            optimizer.zero_grad();
            auto out = std::get<0>(im.net->lstm->forward(X.index_select(0, idx)));
            const torch::Tensor loss = torch::mse_loss(im.net->head->forward(out), Y.index_select(0, idx));
            loss.backward();
            optimizer.step();
            total += loss.item<double>();
            ++batches;
        }
        im.losses.push_back(total / static_cast<double>(batches));
        if (reportProgress(progress, "lstm", static_cast<double>(epoch + 1) / o.epochs,
                           "epoch " + std::to_string(epoch + 1) + ", loss " +
                               std::to_string(im.losses.back()))) {
            return cancelledError("lstm");
        }
    }
    im.trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return model;
}

residual::HybridPrediction LstmBaseline::predictAhead(const residual::BatchView& v, int horizon) const {
    torch::NoGradGuard noGrad;
    const auto& im = *m_impl;
    const std::size_t count = v.rows.size();
    residual::HybridPrediction out = residual::HybridPrediction::unknown(count);
    const torch::Tensor f = im.batchFeatures(*v.batch);
    const auto h = static_cast<std::size_t>(std::max(1, horizon));
    std::vector<torch::Tensor> hs, cs;
    im.statesAfterEachRow(f, hs, cs);
    // From each origin k = target − h: one-step output, then feed predictions back (batched).
    std::vector<long> origins, targets;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t target = v.rows.begin + i;
        if (target >= h) {
            origins.push_back(static_cast<long>(target - h));
            targets.push_back(static_cast<long>(i));
        }
    }
    if (origins.empty()) {
        return out;
    }
    std::vector<torch::Tensor> h0, c0;
    for (long o : origins) {
        h0.push_back(hs[static_cast<std::size_t>(o)]);
        c0.push_back(cs[static_cast<std::size_t>(o)]);
    }
    torch::Tensor hState = torch::cat(h0, 1);
    torch::Tensor cState = torch::cat(c0, 1);
    torch::Tensor y = im.net->head->forward(hState.squeeze(0)); // predicted row origin+1, standardised
    for (std::size_t step = 1; step < h; ++step) {
        // Inputs of row origin+step (known), outputs replaced by the model's own prediction.
        std::vector<torch::Tensor> rows;
        for (long o : origins) {
            rows.push_back(f.slice(1, o + static_cast<long>(step), o + static_cast<long>(step) + 1));
        }
        torch::Tensor in = torch::cat(rows, 0).clone();
        in.slice(2, kInputs - kOutputs, kInputs) = y.unsqueeze(1);
        auto r = im.net->lstm->forward(in, std::make_tuple(hState, cState));
        hState = std::get<0>(std::get<1>(r));
        cState = std::get<1>(std::get<1>(r));
        y = im.net->head->forward(hState.squeeze(0));
    }
    const auto acc = y.to(torch::kFloat64).contiguous();
    const auto a = acc.accessor<double, 2>();
    for (std::size_t j = 0; j < targets.size(); ++j) {
        const auto i = static_cast<std::size_t>(targets[j]);
        out.xOutPct[i] = a[static_cast<long>(j)][0] * im.scale[6] + im.mean[6];
        out.tOutC[i] = a[static_cast<long>(j)][1] * im.scale[7] + im.mean[7];
    }
    return out;
}

std::vector<residual::HybridPrediction>
LstmBaseline::predictHorizons(const residual::BatchView& v, const std::vector<int>& horizons) const {
    torch::NoGradGuard noGrad;
    const auto& im = *m_impl;
    const std::size_t n = v.batch->rows();
    const std::size_t count = v.rows.size();
    std::vector<residual::HybridPrediction> out(horizons.size(), residual::HybridPrediction::unknown(count));
    std::size_t hMax = 1;
    for (int h : horizons) {
        hMax = std::max(hMax, static_cast<std::size_t>(std::max(1, h)));
    }
    if (count == 0 || n < 2) {
        return out;
    }
    const torch::Tensor f = im.batchFeatures(*v.batch);
    torch::Tensor allH, allC;
    {
        std::vector<torch::Tensor> hs, cs;
        im.statesAfterEachRow(f, hs, cs);
        allH = torch::cat(hs, 1);
        allC = torch::cat(cs, 1);
    }
    // Every origin whose prediction lands in the view at some horizon up to hMax.
    const std::size_t lo = v.rows.begin > hMax ? v.rows.begin - hMax : 0;
    const std::size_t hi = v.rows.end - 1; // origins lo … hi−1 (targets ≥ origin + 1)
    if (hi <= lo) {
        return out;
    }
    const auto origins = torch::arange(static_cast<long>(lo), static_cast<long>(hi), torch::kLong);
    torch::Tensor hState = allH.index_select(1, origins);
    torch::Tensor cState = allC.index_select(1, origins);
    torch::Tensor y = im.net->head->forward(hState.squeeze(0)); // row origin+1, standardised
    for (std::size_t step = 1; step <= hMax; ++step) {
        for (std::size_t slot = 0; slot < horizons.size(); ++slot) {
            if (static_cast<std::size_t>(std::max(1, horizons[slot])) != step) {
                continue;
            }
            const auto acc = y.to(torch::kFloat64).contiguous();
            const auto a = acc.accessor<double, 2>();
            for (std::size_t o = lo; o < hi; ++o) {
                const std::size_t target = o + step;
                if (target >= v.rows.begin && target < v.rows.end) {
                    const auto j = static_cast<long>(o - lo);
                    out[slot].xOutPct[target - v.rows.begin] = a[j][0] * im.scale[6] + im.mean[6];
                    out[slot].tOutC[target - v.rows.begin] = a[j][1] * im.scale[7] + im.mean[7];
                }
            }
        }
        if (step == hMax) {
            break;
        }
        // Inputs of row origin+step (known), outputs replaced by the model's own prediction;
        // rows past the batch end repeat the last (their predictions are never read).
        const auto rows = torch::clamp_max(origins + static_cast<long>(step), static_cast<long>(n) - 1);
        torch::Tensor in = f.index_select(1, rows).transpose(0, 1).clone(); // [origins, 1, inputs]
        in.slice(2, kInputs - kOutputs, kInputs) = y.unsqueeze(1);
        auto r = im.net->lstm->forward(in, std::make_tuple(hState, cState));
        hState = std::get<0>(std::get<1>(r));
        cState = std::get<1>(std::get<1>(r));
        y = im.net->head->forward(hState.squeeze(0));
    }
    return out;
}

struct LstmBaseline::Follower::State {
    torch::Tensor h, c;
    std::size_t last = static_cast<std::size_t>(-1);
};

LstmBaseline::Follower::Follower(const LstmBaseline& model)
    : m_model(&model), m_state(std::make_unique<State>()) {
    m_state->h = torch::zeros({1, 1, model.m_impl->options.hidden});
    m_state->c = torch::zeros({1, 1, model.m_impl->options.hidden});
}
LstmBaseline::Follower::~Follower() = default;
LstmBaseline::Follower::Follower(Follower&&) noexcept = default;

std::size_t LstmBaseline::Follower::lastRow() const {
    return m_state->last;
}

void LstmBaseline::Follower::advanceTo(const data::SiBatch& record, std::size_t row) {
    torch::NoGradGuard noGrad;
    const auto& im = *m_model->m_impl;
    auto& st = *m_state;
    const std::size_t from = st.last == static_cast<std::size_t>(-1) ? 0 : st.last + 1;
    if (row < from || row >= record.rows()) {
        return;
    }
    const torch::Tensor f = torch::nan_to_num(im.features(record, from, row + 1).to(torch::kFloat32), 0.0);
    auto r = im.net->lstm->forward(f, std::make_tuple(st.h, st.c));
    st.h = std::get<0>(std::get<1>(r));
    st.c = std::get<1>(std::get<1>(r));
    st.last = row;
}

std::vector<residual::HybridPrediction>
LstmBaseline::Follower::forecast(const std::vector<const data::SiBatch*>& candidates, int horizon) const {
    torch::NoGradGuard noGrad;
    const auto& im = *m_model->m_impl;
    const auto count = static_cast<std::size_t>(std::max(0, horizon));
    std::vector<residual::HybridPrediction> out(candidates.size(),
                                                residual::HybridPrediction::unknown(count));
    const std::size_t origin = m_state->last;
    if (candidates.empty() || count == 0 || origin == static_cast<std::size_t>(-1)) {
        return out;
    }
    std::size_t rows = count;
    for (const auto* c : candidates) {
        rows = std::min(rows, c->rows() > origin + 1 ? c->rows() - origin - 1 : std::size_t{0});
    }
    // Inputs of every candidate's rows origin+1 … origin+rows−1, batched over the candidates.
    std::vector<torch::Tensor> inputs;
    for (const auto* c : candidates) {
        inputs.push_back(torch::nan_to_num(
            im.features(*c, origin + 1, origin + std::max<std::size_t>(rows, 1)).to(torch::kFloat32), 0.0));
    }
    const auto nc = static_cast<long>(candidates.size());
    const torch::Tensor f =
        rows > 1 ? torch::cat(inputs, 0) : torch::Tensor(); // [candidates, rows−1, inputs]
    torch::Tensor hState = m_state->h.expand({1, nc, im.options.hidden}).contiguous();
    torch::Tensor cState = m_state->c.expand({1, nc, im.options.hidden}).contiguous();
    torch::Tensor y = im.net->head->forward(hState.squeeze(0)); // row origin+1, standardised
    std::vector<torch::Tensor> ys{y};
    for (std::size_t step = 0; step + 1 < rows; ++step) {
        // Inputs of the next row, outputs replaced by the model's own prediction.
        torch::Tensor in = f.slice(1, static_cast<long>(step), static_cast<long>(step) + 1).clone();
        in.slice(2, kInputs - kOutputs, kInputs) = y.unsqueeze(1);
        auto r = im.net->lstm->forward(in, std::make_tuple(hState, cState));
        hState = std::get<0>(std::get<1>(r));
        cState = std::get<1>(std::get<1>(r));
        y = im.net->head->forward(hState.squeeze(0));
        ys.push_back(y);
    }
    // One conversion at the end instead of one per step: [rows, candidates, outputs].
    const auto all = torch::stack(ys, 0).to(torch::kFloat64).contiguous();
    const auto a = all.accessor<double, 3>();
    for (std::size_t step = 0; step < rows; ++step) {
        for (long c = 0; c < nc; ++c) {
            out[static_cast<std::size_t>(c)].xOutPct[step] =
                a[static_cast<long>(step)][c][0] * im.scale[6] + im.mean[6];
            out[static_cast<std::size_t>(c)].tOutC[step] =
                a[static_cast<long>(step)][c][1] * im.scale[7] + im.mean[7];
        }
    }
    return out;
}

std::string LstmBaseline::toJson() const {
    const auto& im = *m_impl;
    nlohmann::json j;
    j["format_version"] = 1;
    j["options"] = {{"hidden", im.options.hidden},
                    {"sequence_length", im.options.sequenceLength},
                    {"epochs", im.options.epochs},
                    {"batch_size", im.options.batchSize},
                    {"learning_rate", im.options.learningRate},
                    {"seed", im.options.seed}};
    j["mean"] = im.mean;
    j["scale"] = im.scale;
    j["loss_history"] = im.losses;
    j["training_seconds"] = im.trainSeconds;
    for (const auto& p : im.net->named_parameters()) {
        const torch::Tensor t = p.value().to(torch::kFloat64).contiguous();
        std::vector<double> data(t.data_ptr<double>(), t.data_ptr<double>() + t.numel());
        j["parameters"][p.key()] = {{"shape", t.sizes().vec()}, {"data", data}};
    }
    return j.dump();
}

Expected<LstmBaseline> LstmBaseline::fromJson(const std::string& text) {
    try {
        const auto j = nlohmann::json::parse(text);
        LstmBaseline m;
        auto& im = *m.m_impl;
        im.options.hidden = j.at("options").at("hidden");
        im.options.sequenceLength = j.at("options").at("sequence_length");
        im.options.epochs = j.at("options").at("epochs");
        im.mean = j.at("mean").get<std::array<double, kInputs>>();
        im.scale = j.at("scale").get<std::array<double, kInputs>>();
        im.losses = j.value("loss_history", std::vector<double>{});
        im.trainSeconds = j.value("training_seconds", 0.0);
        im.net = std::make_shared<Net>(im.options.hidden);
        torch::NoGradGuard noGrad;
        for (auto& p : im.net->named_parameters()) {
            const auto& e = j.at("parameters").at(p.key());
            const auto shape = e.at("shape").get<std::vector<long>>();
            const auto data = e.at("data").get<std::vector<double>>();
            if (shape != p.value().sizes().vec() || static_cast<long>(data.size()) != p.value().numel()) {
                return Error{ErrorKind::BadInput, "lstm." + p.key(), "shape does not fit the network"};
            }
            p.value().copy_(torch::tensor(data, torch::kFloat64).reshape(shape).to(torch::kFloat32));
        }
        return m;
    } catch (const std::exception& e) {
        return Error{ErrorKind::BadInput, "lstm", std::string("malformed: ") + e.what()};
    }
}

} // namespace drytwin::baselines
