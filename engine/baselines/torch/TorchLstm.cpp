// The libtorch half of the LSTM baseline (LstmNetwork.h): the trained network's forecasts, its
// follower, its file form, and the module's entry point.

#include "baselines/LstmNetwork.h"
#include "baselines/torch/LstmModel.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

namespace drytwin::baselines {

using namespace detail;

namespace {
constexpr int kFormatVersion = 2;
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

/// @brief HybridPrediction::unknown without the engine's residual/ (the module is loaded on its
/// own): every value NaN.
residual::HybridPrediction unknownPrediction(std::size_t rows) {
    residual::HybridPrediction p;
    p.xOutPct.assign(rows, std::numeric_limits<double>::quiet_NaN());
    p.tOutC.assign(rows, std::numeric_limits<double>::quiet_NaN());
    p.residualXPct.assign(rows, std::numeric_limits<double>::quiet_NaN());
    p.residualTC.assign(rows, std::numeric_limits<double>::quiet_NaN());
    return p;
}

class TorchLstmNetwork final : public LstmNetwork {
public:
    explicit TorchLstmNetwork(LstmModel model) : m_model(std::move(model)) {}
    std::vector<residual::HybridPrediction> predictHorizons(const residual::BatchView& view,
                                                            const std::vector<int>& horizons) const override;
    std::unique_ptr<LstmFollowerState> follower() const override;
    std::string toJson() const override;
    double trainingSeconds() const override { return m_model.trainSeconds; }
    const std::vector<double>& lossHistory() const override { return m_model.losses; }
    const std::vector<LstmEpoch>& epochs() const override { return m_model.epochs; }
    const LstmValidation& validation() const override { return m_model.validation; }
    const Ending& ending() const override { return m_model.ending; }

private:
    LstmModel m_model;
};

std::vector<residual::HybridPrediction>
TorchLstmNetwork::predictHorizons(const residual::BatchView& v, const std::vector<int>& horizons) const {
    torch::NoGradGuard noGrad;
    const auto& im = m_model;
    const std::size_t n = v.batch->rows();
    const std::size_t count = v.rows.size();
    std::vector<residual::HybridPrediction> out(horizons.size(), unknownPrediction(count));
    std::size_t hMax = 1;
    for (int h : horizons) {
        hMax = std::max(hMax, static_cast<std::size_t>(std::max(1, h)));
    }
    if (count == 0 || n < 2 || horizons.empty()) {
        return out;
    }
    // Every origin whose prediction lands in the view at some horizon up to hMax.
    const std::size_t lo = v.rows.begin > hMax ? v.rows.begin - hMax : 0;
    const std::size_t hi = std::min(v.rows.end, n) - 1; // origins lo … hi−1 (targets ≥ origin + 1)
    if (hi <= lo) {
        return out;
    }
    Carry carry;
    const auto in = im.inputs(*v.batch, 0, n, carry);
    const torch::Tensor& f = in.features;
    const auto states = im.statesAfter(f, lo, hi);
    const auto origins = torch::arange(static_cast<long>(lo), static_cast<long>(hi), torch::kLong);
    im.rollout(
        states.first, states.second, in.held.index_select(0, origins), in.reference.index_select(0, origins),
        hMax,
        [&](std::size_t step) {
            // Rows past the batch end repeat the last (their predictions are never read).
            const auto rows = torch::clamp_max(origins + static_cast<long>(step), static_cast<long>(n) - 1);
            return f.index_select(1, rows).transpose(0, 1); // [origins, 1, features]
        },
        [&](std::size_t step, const torch::Tensor& y) {
            bool wanted = false;
            for (int h : horizons) {
                wanted = wanted || static_cast<std::size_t>(std::max(1, h)) == step;
            }
            if (!wanted) {
                return;
            }
            const auto yc = y.contiguous();
            const auto a = yc.accessor<double, 2>();
            for (std::size_t slot = 0; slot < horizons.size(); ++slot) {
                if (static_cast<std::size_t>(std::max(1, horizons[slot])) != step) {
                    continue;
                }
                for (std::size_t o = lo; o < hi; ++o) {
                    const std::size_t target = o + step;
                    if (target >= v.rows.begin && target < v.rows.end) {
                        const auto j = static_cast<long>(o - lo);
                        out[slot].xOutPct[target - v.rows.begin] = a[j][0];
                        out[slot].tOutC[target - v.rows.begin] = a[j][1];
                    }
                }
            }
        });
    return out;
}

class TorchLstmFollower final : public LstmFollowerState {
public:
    explicit TorchLstmFollower(const LstmModel& model) : m_model(model) {
        m_h = torch::zeros({1, 1, model.options.hidden});
        m_c = torch::zeros({1, 1, model.options.hidden});
    }
    void advanceTo(const data::SiBatch& record, std::size_t row) override;
    std::vector<residual::HybridPrediction> forecast(const std::vector<const data::SiBatch*>& candidates,
                                                     int horizon) const override;
    std::size_t lastRow() const override { return m_last; }

private:
    const LstmModel& m_model;
    torch::Tensor m_h, m_c;
    torch::Tensor m_held, m_reference; ///< [1, 2] the held outputs of the last row fed, their references
    Carry m_carry;
    std::size_t m_last = kNone;
};

std::unique_ptr<LstmFollowerState> TorchLstmNetwork::follower() const {
    return std::make_unique<TorchLstmFollower>(m_model);
}

void TorchLstmFollower::advanceTo(const data::SiBatch& record, std::size_t row) {
    torch::NoGradGuard noGrad;
    const auto& im = m_model;
    const std::size_t from = m_last == kNone ? 0 : m_last + 1;
    if (row < from || row >= record.rows()) {
        return;
    }
    const auto in = im.inputs(record, from, row + 1, m_carry);
    auto r = im.net->lstm->forward(in.features, std::make_tuple(m_h, m_c));
    m_h = std::get<0>(std::get<1>(r));
    m_c = std::get<1>(std::get<1>(r));
    const long rows = in.held.size(0);
    m_held = in.held.slice(0, rows - 1, rows).clone();
    m_reference = in.reference.slice(0, rows - 1, rows).clone();
    m_last = row;
}

std::vector<residual::HybridPrediction>
TorchLstmFollower::forecast(const std::vector<const data::SiBatch*>& candidates, int horizon) const {
    torch::NoGradGuard noGrad;
    const auto& im = m_model;
    const auto count = static_cast<std::size_t>(std::max(0, horizon));
    std::vector<residual::HybridPrediction> out(candidates.size(), unknownPrediction(count));
    const std::size_t origin = m_last;
    if (candidates.empty() || count == 0 || origin == kNone) {
        return out;
    }
    std::size_t rows = count;
    for (const auto* c : candidates) {
        rows = std::min(rows, c->rows() > origin + 1 ? c->rows() - origin - 1 : std::size_t{0});
    }
    if (rows == 0) {
        return out;
    }
    // Inputs of every candidate's rows origin+1 … origin+rows−1, batched over the candidates.
    const auto nc = static_cast<long>(candidates.size());
    torch::Tensor f;
    if (rows > 1) {
        std::vector<torch::Tensor> inputs;
        for (const auto* c : candidates) {
            Carry fromOrigin = m_carry; // each candidate continues from the state fed so far
            inputs.push_back(im.inputs(*c, origin + 1, origin + rows, fromOrigin).features);
        }
        f = torch::cat(inputs, 0); // [candidates, rows−1, features]
    }
    std::vector<torch::Tensor> ys;
    im.rollout(
        m_h.expand({1, nc, im.options.hidden}).contiguous(),
        m_c.expand({1, nc, im.options.hidden}).contiguous(), m_held.expand({nc, kOutputs}),
        m_reference.expand({nc, kOutputs}), rows,
        [&](std::size_t step) {
            return f.slice(1, static_cast<long>(step) - 1, static_cast<long>(step)); // row origin+step
        },
        [&](std::size_t, const torch::Tensor& y) { ys.push_back(y); });
    // One conversion at the end instead of one per step: [rows, candidates, outputs].
    const auto all = torch::stack(ys, 0).contiguous();
    const auto a = all.accessor<double, 3>();
    for (std::size_t step = 0; step < rows; ++step) {
        for (long c = 0; c < nc; ++c) {
            out[static_cast<std::size_t>(c)].xOutPct[step] = a[static_cast<long>(step)][c][0];
            out[static_cast<std::size_t>(c)].tOutC[step] = a[static_cast<long>(step)][c][1];
        }
    }
    return out;
}

std::string TorchLstmNetwork::toJson() const {
    const auto& im = m_model;
    const auto& o = im.options;
    const auto& vr = im.validation;
    nlohmann::json j;
    j["format_version"] = kFormatVersion;
    j["form"] = "step change of the measured outputs (zero = hold the last measurement)";
    j["options"] = {{"hidden", o.hidden},
                    {"sequence_length", o.sequenceLength},
                    {"segment_length", o.segmentLength},
                    {"epochs", o.epochs},
                    {"batch_size", o.batchSize},
                    {"learning_rate", o.learningRate},
                    {"validation_fraction", o.validationFraction},
                    {"patience", o.patience},
                    {"clip_margin", o.clipMargin},
                    {"free_run_steps", o.freeRunSteps},
                    {"high_pass_seconds", o.highPassSeconds},
                    {"free_run_weight", o.freeRunWeight},
                    {"validation_horizon", o.validationHorizon},
                    {"seed", o.seed}};
    j["mean"] = im.mean;
    j["alpha"] = im.alpha;
    j["scale"] = im.scale;
    j["change_scale"] = im.changeScale;
    j["clip_low"] = im.low;
    j["clip_high"] = im.high;
    j["loss_history"] = im.losses;
    nlohmann::json epochs = nlohmann::json::array();
    for (const auto& e : im.epochs) {
        epochs.push_back({{"epoch", e.epoch},
                          {"training_loss", e.trainingLoss},
                          {"validation_skill_moisture", e.validationSkillMoisture},
                          {"validation_skill_temperature", e.validationSkillTemperature}});
    }
    j["epochs"] = epochs;
    j["validation"] = {{"validated", vr.validated},
                       {"beats_references", vr.beatsReferences},
                       {"best_epoch", vr.bestEpoch},
                       {"rows", vr.rows},
                       {"part", vr.part},
                       {"skill_moisture", vr.skillMoisture},
                       {"skill_temperature", vr.skillTemperature},
                       {"horizon", vr.horizon},
                       {"skill_moisture_ahead", vr.skillMoistureAhead},
                       {"skill_temperature_ahead", vr.skillTemperatureAhead},
                       {"mae_moisture_pct", vr.maeMoisturePct},
                       {"mae_temperature_c", vr.maeTemperatureC},
                       {"reference_mae_moisture_pct", vr.referenceMaeMoisturePct},
                       {"reference_mae_temperature_c", vr.referenceMaeTemperatureC},
                       {"message", vr.message}};
    j["ending"] = {{"termination", terminationName(im.ending.termination)}, {"message", im.ending.message}};
    j["training_seconds"] = im.trainSeconds;
    for (const auto& p : im.net->named_parameters()) {
        const torch::Tensor t = p.value().to(torch::kFloat64).contiguous();
        std::vector<double> data(t.data_ptr<double>(), t.data_ptr<double>() + t.numel());
        j["parameters"][p.key()] = {{"shape", t.sizes().vec()}, {"data", data}};
    }
    return j.dump();
}

Expected<std::unique_ptr<LstmNetwork>> networkFromJson(const std::string& text) {
    try {
        const auto j = nlohmann::json::parse(text);
        const int version = j.value("format_version", 0);
        if (version == 1) {
            return Error{ErrorKind::BadInput, "lstm",
                         "written by an older DryTwin (LSTM format 1, which predicted the outputs' levels); "
                         "run train again on the calibrated model to get the current LSTM (format 2)"};
        }
        if (version != kFormatVersion) {
            return Error{ErrorKind::BadInput, "lstm",
                         "format_version " + std::to_string(version) + " is not " +
                             std::to_string(kFormatVersion)};
        }
        LstmModel im;
        const auto& o = j.at("options");
        im.options.hidden = o.at("hidden");
        im.options.sequenceLength = o.at("sequence_length");
        im.options.segmentLength = o.value("segment_length", im.options.segmentLength);
        im.options.epochs = o.at("epochs");
        im.options.batchSize = o.value("batch_size", im.options.batchSize);
        im.options.learningRate = o.value("learning_rate", im.options.learningRate);
        im.options.validationFraction = o.value("validation_fraction", im.options.validationFraction);
        im.options.patience = o.value("patience", im.options.patience);
        im.options.clipMargin = o.value("clip_margin", im.options.clipMargin);
        im.options.freeRunSteps = o.value("free_run_steps", im.options.freeRunSteps);
        im.options.highPassSeconds = o.at("high_pass_seconds");
        im.options.freeRunWeight = o.value("free_run_weight", im.options.freeRunWeight);
        im.options.validationHorizon = o.value("validation_horizon", im.options.validationHorizon);
        im.options.seed = o.value("seed", im.options.seed);
        if (auto st = im.options.validate(); !st) {
            return Error{ErrorKind::BadInput, "lstm.options", st.error().reason};
        }
        im.mean = j.at("mean").get<Raw>();
        im.alpha = j.at("alpha");
        im.scale = j.at("scale").get<Raw>();
        im.changeScale = j.at("change_scale").get<std::array<double, kOutputs>>();
        im.low = j.at("clip_low").get<std::array<double, kFeatures>>();
        im.high = j.at("clip_high").get<std::array<double, kFeatures>>();
        for (std::size_t i = 0; i < kRaw; ++i) {
            if (!(im.scale[i] > 0) || !std::isfinite(im.mean[i])) {
                return Error{ErrorKind::BadInput, "lstm.scale", "every scale must be positive and finite"};
            }
        }
        for (double s : im.changeScale) {
            if (!(s > 0) || !std::isfinite(s)) {
                return Error{ErrorKind::BadInput, "lstm.change_scale", "must be positive and finite"};
            }
        }
        im.losses = j.value("loss_history", std::vector<double>{});
        im.trainSeconds = j.value("training_seconds", 0.0);
        for (const auto& e : j.value("epochs", nlohmann::json::array())) {
            im.epochs.push_back({e.value("epoch", 0), e.value("training_loss", 0.0),
                                 e.value("validation_skill_moisture", 0.0),
                                 e.value("validation_skill_temperature", 0.0)});
        }
        if (j.contains("validation")) {
            const auto& v = j["validation"];
            auto& vr = im.validation;
            vr.validated = v.value("validated", false);
            vr.beatsReferences = v.value("beats_references", false);
            vr.bestEpoch = v.value("best_epoch", 0);
            vr.rows = v.value("rows", std::size_t{0});
            vr.part = v.value("part", std::string{});
            vr.skillMoisture = v.value("skill_moisture", 0.0);
            vr.skillTemperature = v.value("skill_temperature", 0.0);
            vr.horizon = v.value("horizon", 0);
            vr.skillMoistureAhead = v.value("skill_moisture_ahead", 0.0);
            vr.skillTemperatureAhead = v.value("skill_temperature_ahead", 0.0);
            vr.maeMoisturePct = v.value("mae_moisture_pct", 0.0);
            vr.maeTemperatureC = v.value("mae_temperature_c", 0.0);
            vr.referenceMaeMoisturePct = v.value("reference_mae_moisture_pct", 0.0);
            vr.referenceMaeTemperatureC = v.value("reference_mae_temperature_c", 0.0);
            vr.message = v.value("message", std::string{});
        }
        if (j.contains("ending")) {
            const std::string t = j["ending"].value("termination", std::string{"completed"});
            for (auto k : {Termination::Completed, Termination::Converged, Termination::BudgetExhausted,
                           Termination::StoppedKeptBest}) {
                if (t == terminationName(k)) {
                    im.ending.termination = k;
                }
            }
            im.ending.message = j["ending"].value("message", std::string{});
            im.ending.elapsedSeconds = im.trainSeconds;
        }
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
        return std::unique_ptr<LstmNetwork>(std::make_unique<TorchLstmNetwork>(std::move(im)));
    } catch (const std::exception& e) {
        return Error{ErrorKind::BadInput, "lstm", std::string("malformed: ") + e.what()};
    }
}

Expected<std::unique_ptr<LstmNetwork>> trainNetwork(const std::vector<residual::BatchView>& training,
                                                    const LstmOptions& options, const Progress& progress) {
    auto trained = trainLstmModel(training, options, progress);
    if (!trained) {
        return trained.error();
    }
    return std::unique_ptr<LstmNetwork>(std::make_unique<TorchLstmNetwork>(std::move(*trained)));
}

} // namespace

} // namespace drytwin::baselines

extern "C" __attribute__((visibility("default"))) const drytwin::baselines::LstmModuleEntry*
drytwin_lstm_module() {
    static const drytwin::baselines::LstmModuleEntry entry{drytwin::baselines::kLstmModuleInterfaceVersion,
                                                           &drytwin::baselines::trainNetwork,
                                                           &drytwin::baselines::networkFromJson};
    return &entry;
}
