// LstmBaseline::train: standardisation and clip ranges, training streams with a carried state,
// a free-run loss, and early stopping on a validation part (LstmValidationSet.h).

#include "baselines/torch/LstmModel.h"
#include "baselines/torch/LstmValidationSet.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace drytwin::baselines::detail {

namespace {

std::size_t rowCount(const std::vector<residual::BatchView>& views) {
    std::size_t n = 0;
    for (const auto& v : views) {
        n += v.rows.size();
    }
    return n;
}

/// The spread of |values| without their largest 1 % (spikes, a dropout's jump).
double robustSpread(std::vector<double>& values) {
    if (values.empty()) {
        return 0;
    }
    const auto q = values.begin() + static_cast<long>(0.99 * double(values.size() - 1));
    std::nth_element(values.begin(), q, values.end());
    const double cap = *q;
    double sum = 0;
    std::size_t n = 0;
    for (double x : values) {
        if (x <= cap) {
            sum += x * x;
            ++n;
        }
    }
    return n > 0 ? std::sqrt(sum / double(n)) : 0.0;
}

/// Standardisation, the step change's spread and the clip ranges from the fitting rows, read
/// as predictions read them (held values, moving references).
Status fitScales(LstmModel& m, const std::vector<residual::BatchView>& fit) {
    std::array<double, kRaw> sum{};
    std::array<std::size_t, kRaw> n{};
    for (const auto& v : fit) {
        for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
            const Raw r = rawRow(*v.batch, k);
            for (std::size_t i = 0; i < kRaw; ++i) {
                if (std::isfinite(r[i])) {
                    sum[i] += r[i];
                    ++n[i];
                }
            }
        }
    }
    for (std::size_t i = 0; i < kRaw; ++i) {
        if (n[i] == 0) {
            return Error{ErrorKind::BadInput, "LSTM training", "a column has no value in the training rows"};
        }
        m.mean[i] = sum[i] / static_cast<double>(n[i]);
    }
    m.alpha = m.options.highPassSeconds > 0 ? 1.0 - std::exp(-1.0 / m.options.highPassSeconds) : 0.0;
    // Unit scales and no clipping first: the features are then the raw deviations.
    m.scale.fill(1.0);
    m.changeScale.fill(1.0);
    m.low.fill(-std::numeric_limits<double>::infinity());
    m.high.fill(std::numeric_limits<double>::infinity());
    auto eachFitRow = [&](const auto& use) {
        std::array<float, kFeatures> row{};
        std::array<double, kOutputs> held{}, reference{};
        for (const auto& v : fit) {
            Carry carry;
            for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
                m.readRow(*v.batch, k, carry, row.data(), held.data(), reference.data());
                use(*v.batch, k, row);
            }
        }
    };
    std::array<double, kRaw> sum2{};
    std::array<std::vector<double>, kOutputs> changes;
    eachFitRow([&](const data::SiBatch& b, std::size_t k, const std::array<float, kFeatures>& row) {
        for (std::size_t i = 0; i < kRaw; ++i) {
            sum2[i] += double(row[i]) * double(row[i]);
        }
        const Raw r = rawRow(b, k);
        for (std::size_t j = 0; j < kOutputs; ++j) {
            if (k > 0 && std::isfinite(r[kLevel + j]) && std::isfinite(rawRow(b, k - 1)[kLevel + j])) {
                changes[j].push_back(std::abs(double(row[kChange + j])));
            }
        }
    });
    const auto rows = static_cast<double>(rowCount(fit));
    for (std::size_t i = 0; i < kRaw; ++i) {
        const double rms = std::sqrt(sum2[i] / rows);
        m.scale[i] = rms > 1e-9 ? rms : 1.0;
    }
    for (std::size_t j = 0; j < kOutputs; ++j) {
        const double spread = robustSpread(changes[j]);
        m.changeScale[j] = spread > 1e-9 ? spread : 1e-3 * m.scale[kLevel + j];
    }
    // The standardised features' training range, widened by the margin, is the clip range.
    Features lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    eachFitRow([&](const data::SiBatch&, std::size_t, const std::array<float, kFeatures>& row) {
        for (std::size_t i = 0; i < kFeatures; ++i) {
            lo[i] = std::min(lo[i], double(row[i]));
            hi[i] = std::max(hi[i], double(row[i]));
        }
    });
    for (std::size_t i = 0; i < kFeatures; ++i) {
        const double width = hi[i] - lo[i];
        m.low[i] = lo[i] - m.options.clipMargin * width;
        m.high[i] = hi[i] + m.options.clipMargin * width;
    }
    return {};
}

/// Every fitting view's rows in order, one stream each, concatenated: features, targets (the
/// standardised change to the next row's measured output), their mask, and the held outputs and
/// their references in the targets' unit. One zero row at the end is where padding points.
struct Streams {
    std::vector<std::size_t> offset, length;
    torch::Tensor x, y, mask, level, reference;
    long padRow() const { return x.size(0) - 1; }
};

Streams makeStreams(const LstmModel& m, const std::vector<residual::BatchView>& fit) {
    Streams s;
    std::size_t total = 0;
    for (const auto& v : fit) {
        s.offset.push_back(total);
        s.length.push_back(v.rows.size());
        total += v.rows.size();
    }
    const auto rows = static_cast<long>(total) + 1;
    s.x = torch::zeros({rows, kFeatures}, torch::kFloat32);
    for (auto* t : {&s.y, &s.mask, &s.level, &s.reference}) {
        *t = torch::zeros({rows, kOutputs}, torch::kFloat32);
    }
    auto y = s.y.accessor<float, 2>();
    auto mask = s.mask.accessor<float, 2>();
    auto level = s.level.accessor<float, 2>();
    auto ref = s.reference.accessor<float, 2>();
    for (std::size_t i = 0; i < fit.size(); ++i) {
        const auto& v = fit[i];
        Carry carry;
        std::array<double, kOutputs> held{}, reference{};
        for (std::size_t k = v.rows.begin; k < v.rows.end; ++k) {
            const auto r = static_cast<long>(s.offset[i] + k - v.rows.begin);
            m.readRow(*v.batch, k, carry, s.x.data_ptr<float>() + r * kFeatures, held.data(),
                      reference.data());
            const Raw next = k + 1 < v.rows.end ? rawRow(*v.batch, k + 1) : Raw{};
            for (std::size_t j = 0; j < kOutputs; ++j) {
                const auto jj = static_cast<long>(j);
                level[r][jj] = static_cast<float>(held[j] / m.changeScale[j]);
                ref[r][jj] = static_cast<float>(reference[j] / m.changeScale[j]);
                if (k + 1 < v.rows.end && v.batch->keep[k + 1] && std::isfinite(next[kLevel + j])) {
                    y[r][jj] = static_cast<float>((next[kLevel + j] - held[j]) / m.changeScale[j]);
                    mask[r][jj] = 1.0f;
                }
            }
        }
    }
    return s;
}

/// One epoch over the streams, cut into segments from a random phase (so that their borders
/// move between epochs), several segments per optimiser step, each run in chunks of the
/// back-propagation length with the state carried from chunk to chunk. Each chunk's one-step
/// loss is joined by a free-run loss: its last rows predicted with the network's own outputs fed
/// back, as multi-step prediction does. Returns the mean loss.
double trainEpoch(LstmModel& m, torch::optim::Adam& optimizer, const Streams& streams, std::mt19937& rng) {
    const auto& o = m.options;
    const auto segment = static_cast<long>(o.segmentLength);
    const auto chunk = static_cast<long>(o.sequenceLength);
    // A segment that starts inside a stream starts from a zero state predictions never see: its
    // first rows only warm the state up.
    const long warmUp = std::min<long>(32, segment / 4);
    const long freeRun = std::min<long>(o.freeRunSteps, chunk - 1);
    // Every step of the free run counts alike: its error is scaled by 1/√s.
    const torch::Tensor stepWeight =
        freeRun > 1 ? torch::rsqrt(torch::arange(1, freeRun + 1, torch::kFloat32)).reshape({1, freeRun, 1})
                    : torch::Tensor();
    std::vector<std::array<std::size_t, 3>> segments; // stream, first row, rows
    for (std::size_t s = 0; s < streams.length.size(); ++s) {
        std::size_t start = 0;
        std::size_t end =
            std::uniform_int_distribution<std::size_t>(1, static_cast<std::size_t>(segment))(rng);
        while (start < streams.length[s]) {
            end = std::min(end, streams.length[s]);
            segments.push_back({s, start, end - start});
            start = end;
            end = start + static_cast<std::size_t>(segment);
        }
    }
    std::shuffle(segments.begin(), segments.end(), rng);
    const auto nSeg = static_cast<long>(segments.size());
    torch::Tensor index = torch::full({nSeg, segment}, streams.padRow(), torch::kLong);
    torch::Tensor warm = torch::ones({nSeg, segment, 1}, torch::kFloat32);
    {
        auto idx = index.accessor<long, 2>();
        auto w = warm.accessor<float, 3>();
        for (long g = 0; g < nSeg; ++g) {
            const auto& [s, first, rows] = segments[static_cast<std::size_t>(g)];
            for (long t = 0; t < static_cast<long>(rows); ++t) {
                idx[g][t] = static_cast<long>(streams.offset[s] + first) + t;
                if (first > 0 && t < warmUp) {
                    w[g][t][0] = 0.0f;
                }
            }
        }
    }
    const auto flat = index.reshape({-1});
    const auto gather = [&](const torch::Tensor& t) {
        return t.index_select(0, flat).reshape({nSeg, segment, t.size(1)});
    };
    const torch::Tensor X = gather(streams.x), Y = gather(streams.y), M = gather(streams.mask) * warm;
    const torch::Tensor L = gather(streams.level), R = gather(streams.reference);
    double total = 0;
    double weight = 0;
    // At least four optimiser steps per chunk position and epoch on a small data set.
    const long group = std::clamp<long>(nSeg / 4, 1, o.batchSize);
    for (long g0 = 0; g0 < nSeg; g0 += group) {
        const long g1 = std::min(nSeg, g0 + group);
        torch::Tensor h = torch::zeros({1, g1 - g0, o.hidden});
        torch::Tensor c = torch::zeros({1, g1 - g0, o.hidden});
        for (long t0 = 0; t0 < segment; t0 += chunk) {
            const long t1 = std::min(segment, t0 + chunk);
            const torch::Tensor x = X.slice(0, g0, g1).slice(1, t0, t1);
            const torch::Tensor y = Y.slice(0, g0, g1).slice(1, t0, t1);
            const torch::Tensor mask = M.slice(0, g0, g1).slice(1, t0, t1);
            const double count = mask.sum().item<double>();
            // The free run starts after row p−1 of the chunk: the state there is needed.
            const long p = t1 - t0 - freeRun;
            const bool branch = freeRun > 1 && p >= 1;
            auto first = m.net->lstm->forward(x.slice(1, 0, branch ? p : t1 - t0), std::make_tuple(h, c));
            torch::Tensor output = std::get<0>(first);
            CellState last = std::get<1>(first);
            if (branch) {
                auto rest = m.net->lstm->forward(x.slice(1, p, t1 - t0), last);
                output = torch::cat({output, std::get<0>(rest)}, 1);
                last = std::get<1>(rest);
            }
            if (count > 0) {
                torch::Tensor loss =
                    (torch::huber_loss(m.net->head->forward(output), y, at::Reduction::None, 1.0) * mask)
                        .sum() /
                    count;
                const torch::Tensor freeMask =
                    branch ? mask.slice(1, p - 1, p - 1 + freeRun) : torch::Tensor();
                const double freeCount = branch ? freeMask.sum().item<double>() : 0.0;
                if (freeCount > 0) {
                    const torch::Tensor level = L.slice(0, g0, g1).slice(1, t0, t1);
                    const torch::Tensor predicted =
                        m.freeRunLevels(std::get<1>(first), x, level.select(1, p - 1),
                                        R.slice(0, g0, g1).select(1, t0 + p - 1), p, freeRun);
                    const torch::Tensor target =
                        (y + level).slice(1, p - 1, p - 1 + freeRun); // next rows' levels
                    loss = loss + o.freeRunWeight *
                                      (torch::huber_loss(predicted * stepWeight, target * stepWeight,
                                                         at::Reduction::None, 1.0) *
                                       freeMask)
                                          .sum() /
                                      freeCount;
                }
                optimizer.zero_grad();
                loss.backward();
                torch::nn::utils::clip_grad_norm_(m.net->parameters(), 1.0);
                optimizer.step();
                total += loss.item<double>() * count;
                weight += count;
            }
            // Truncated back-propagation: the state goes on, its history does not.
            h = std::get<0>(last).detach();
            c = std::get<1>(last).detach();
        }
    }
    return weight > 0 ? total / weight : std::nan("");
}

} // namespace

Expected<LstmModel> trainLstmModel(const std::vector<residual::BatchView>& training, const LstmOptions& o,
                                   const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = o.validate(); !st) {
        return st.error();
    }
    torch::manual_seed(o.seed);
    torch::set_num_threads(o.threads);
    std::mt19937 rng(o.seed);
    LstmModel m;
    m.options = o;
    const ValidationSplit split = splitForValidation(training, o.validationFraction);
    if (rowCount(split.fit) < static_cast<std::size_t>(4 * o.sequenceLength)) {
        return Error{ErrorKind::BadInput, "LSTM training", "too few training rows"};
    }
    if (auto st = fitScales(m, split.fit); !st) {
        return st.error();
    }
    const Streams streams = makeStreams(m, split.fit);
    const ValidationSet val = makeValidationSet(m, split.validation, o.validationHorizon);
    const bool validating = val.usable();

    m.net = std::make_shared<Net>(o.hidden);
    torch::optim::Adam optimizer(m.net->parameters(), torch::optim::AdamOptions(o.learningRate));
    std::vector<torch::Tensor> best;
    double bestScore = std::numeric_limits<double>::infinity();
    int sinceBest = 0;
    bool stoppedByCaller = false;
    for (int epoch = 1; epoch <= o.epochs; ++epoch) {
        LstmEpoch record;
        record.epoch = epoch;
        record.trainingLoss = trainEpoch(m, optimizer, streams, rng);
        m.losses.push_back(record.trainingLoss);
        std::string detail = "epoch " + std::to_string(epoch) + ", loss " + fixed(record.trainingLoss, 4);
        double score = -static_cast<double>(epoch); // without validation the last epoch is kept
        if (validating) {
            const auto mae = scoreValidation(m, val, false);
            record.validationSkillMoisture = mae[0].of(0) / val.referenceMae[0][0];
            record.validationSkillTemperature = mae[0].of(1) / val.referenceMae[0][1];
            score = 0.5 * (record.validationSkillMoisture + record.validationSkillTemperature);
            detail += ", validation skill X " + fixed(record.validationSkillMoisture, 3) + " T " +
                      fixed(record.validationSkillTemperature, 3);
        }
        m.epochs.push_back(record);
        if (std::isfinite(score) && score < bestScore) {
            bestScore = score;
            best.clear();
            for (const auto& p : m.net->parameters()) {
                best.push_back(p.detach().clone());
            }
            m.validation.bestEpoch = epoch;
            sinceBest = 0;
        } else {
            ++sinceBest;
        }
        const auto action = progressAction(progress, "lstm", static_cast<double>(epoch) / o.epochs, detail);
        if (action == ProgressAction::Stop) {
            return cancelledError("lstm");
        }
        if (action == ProgressAction::StopKeepBest) {
            stoppedByCaller = true;
            break;
        }
        if (sinceBest >= o.patience) {
            break;
        }
    }
    if (best.empty()) { // no epoch scored a finite skill: keep the last
        m.validation.bestEpoch = static_cast<int>(m.epochs.size());
    } else {
        torch::NoGradGuard noGrad;
        auto params = m.net->parameters();
        for (std::size_t i = 0; i < params.size(); ++i) {
            params[i].copy_(best[i]);
        }
    }
    m.validation = summarise(m, split, val);

    const int run = static_cast<int>(m.epochs.size());
    const std::string kept = "kept epoch " + std::to_string(m.validation.bestEpoch);
    m.trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    m.ending.elapsedSeconds = m.trainSeconds;
    if (stoppedByCaller) {
        m.ending.termination = Termination::StoppedKeptBest;
        m.ending.message = "stopped after epoch " + std::to_string(run) + "; " + kept;
    } else if (run < o.epochs) {
        m.ending.termination = Termination::Converged;
        m.ending.message = "stopped early after epoch " + std::to_string(run) +
                           " (no better validation skill in " + std::to_string(o.patience) + " epochs); " +
                           kept;
    } else {
        m.ending.termination = Termination::BudgetExhausted;
        m.ending.message = "ran all " + std::to_string(run) + " epochs; " + kept;
    }
    return m;
}

} // namespace drytwin::baselines::detail
