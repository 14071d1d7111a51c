#include "baselines/torch/LstmValidationSet.h"

#include "common/Units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace drytwin::baselines::detail {

void Mae::add(int output, double error) {
    sum[static_cast<std::size_t>(output)] += std::abs(error);
    ++n[static_cast<std::size_t>(output)];
}

double Mae::of(int output) const {
    const auto j = static_cast<std::size_t>(output);
    return n[j] > 0 ? sum[j] / static_cast<double>(n[j]) : std::numeric_limits<double>::quiet_NaN();
}

std::string fixed(double x, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, x);
    return buf;
}

ValidationSplit splitForValidation(const std::vector<residual::BatchView>& views, double share) {
    ValidationSplit s;
    double total = 0;
    for (const auto& v : views) {
        total += static_cast<double>(v.rows.size());
    }
    std::size_t held = 0;
    std::size_t first = views.size();
    while (first > 0 && static_cast<double>(held) < 0.6 * share * total) {
        --first;
        held += views[first].rows.size();
    }
    if (first >= 2 && static_cast<double>(held) <= 1.75 * share * total) {
        s.fit.assign(views.begin(), views.begin() + static_cast<long>(first));
        s.validation.assign(views.begin() + static_cast<long>(first), views.end());
        s.part = "the last " + std::to_string(views.size() - first) + " of " + std::to_string(views.size()) +
                 " training batches";
        return s;
    }
    for (const auto& v : views) {
        const auto cut =
            v.rows.begin + static_cast<std::size_t>(std::round((1.0 - share) * double(v.rows.size())));
        if (cut > v.rows.begin) {
            s.fit.push_back({v.batch, v.pbm, {v.rows.begin, cut}});
        }
        if (cut < v.rows.end) {
            s.validation.push_back({v.batch, v.pbm, {cut, v.rows.end}});
        }
    }
    s.part = "the last " + std::to_string(static_cast<int>(std::lround(share * 100))) +
             " % of each batch's training rows";
    return s;
}

ValidationSet makeValidationSet(const LstmModel& m, const std::vector<residual::BatchView>& validation,
                                int horizon) {
    ValidationSet val;
    val.horizon = horizon;
    std::vector<Pass> passes;
    std::array<std::array<Mae, 2>, 2> reference; // [one step, horizon][persistence, PBM with its error held]
    bool everyPbm = true;
    long longest = 0;
    for (std::size_t vi = 0; vi < validation.size(); ++vi) {
        const auto& v = validation[vi];
        const auto& b = *v.batch;
        Carry carry;
        passes.push_back(m.inputs(b, 0, v.rows.end, carry));
        longest = std::max(longest, passes.back().features.size(1));
        everyPbm = everyPbm && v.pbm != nullptr;
        for (std::size_t which = 0; which < (horizon > 1 ? 2u : 1u); ++which) {
            const std::size_t h = which == 0 ? 1 : static_cast<std::size_t>(horizon);
            for (std::size_t k = std::max(v.rows.begin, h); k < v.rows.end; ++k) {
                if (!b.keep[k]) {
                    continue;
                }
                const Raw now = rawRow(b, k);
                const Raw last = rawRow(b, k - h); // the last measurement the prediction saw
                bool any = false;
                for (int j = 0; j < kOutputs; ++j) {
                    const auto i = static_cast<std::size_t>(kLevel + j);
                    if (!std::isfinite(now[i]) || !std::isfinite(last[i])) {
                        continue; // the references need that measurement: the same values for all
                    }
                    if (!any && which == 1) {
                        val.rolloutOrigins.push_back({static_cast<long>(vi), static_cast<long>(k - h)});
                    }
                    any = true;
                    val.entries[which].push_back({static_cast<long>(vi), static_cast<long>(k - h), j, now[i],
                                                  val.rolloutOrigins.size() - 1});
                    reference[which][0].add(j, now[i] - last[i]);
                    if (v.pbm != nullptr) {
                        const auto pbm = [&](std::size_t r) {
                            return j == 0 ? units::dryToWetPct(v.pbm->xOutDb[r])
                                          : units::kelvinToCelsius(v.pbm->tOutK[r]);
                        };
                        reference[which][1].add(j, now[i] - (pbm(k) + last[i] - pbm(k - h)));
                    }
                }
                val.rows += which == 0 && any ? 1 : 0;
            }
        }
    }
    for (std::size_t which = 0; which < 2; ++which) {
        for (int j = 0; j < kOutputs; ++j) {
            const double p = reference[which][0].of(j);
            const double q = everyPbm ? reference[which][1].of(j) : p;
            val.referenceMae[which][static_cast<std::size_t>(j)] = std::min(p, std::isfinite(q) ? q : p);
        }
    }
    const auto nv = static_cast<long>(passes.size());
    val.features = torch::zeros({nv, longest, kFeatures}, torch::kFloat32);
    val.held = torch::zeros({nv, longest, kOutputs}, torch::kFloat64);
    val.reference = torch::zeros({nv, longest, kOutputs}, torch::kFloat64);
    for (long s = 0; s < nv; ++s) {
        const auto& pass = passes[static_cast<std::size_t>(s)];
        const long rows = pass.features.size(1);
        val.features[s].slice(0, 0, rows) = pass.features.squeeze(0);
        val.held[s].slice(0, 0, rows) = pass.held;
        val.reference[s].slice(0, 0, rows) = pass.reference;
    }
    return val;
}

std::array<Mae, 2> scoreValidation(const LstmModel& m, const ValidationSet& val, bool ahead) {
    torch::NoGradGuard noGrad;
    std::array<Mae, 2> mae;
    const auto heldAcc = val.held.accessor<double, 3>();
    const auto scoreOneStep = [&](const torch::Tensor& out, bool rowMajor) {
        const auto a = out.accessor<double, 3>();
        for (const auto& e : val.entries[0]) {
            const double change = rowMajor ? a[e.origin][e.view][e.output] : a[e.view][e.origin][e.output];
            mae[0].add(e.output, e.observed - (heldAcc[e.view][e.origin][e.output] +
                                               m.changeScale[static_cast<std::size_t>(e.output)] * change));
        }
    };
    if (!ahead) {
        const auto out = m.net->head->forward(std::get<0>(m.net->lstm->forward(val.features)));
        scoreOneStep(out.to(torch::kFloat64).contiguous(), false);
        return mae;
    }
    const long nv = val.features.size(0);
    const long longest = val.features.size(1);
    std::vector<torch::Tensor> hs, cs;
    torch::Tensor h = torch::zeros({1, nv, m.options.hidden});
    torch::Tensor c = torch::zeros({1, nv, m.options.hidden});
    for (long t = 0; t < longest; ++t) {
        auto r = m.net->lstm->forward(val.features.slice(1, t, t + 1), std::make_tuple(h, c));
        h = std::get<0>(std::get<1>(r));
        c = std::get<1>(std::get<1>(r));
        hs.push_back(h);
        cs.push_back(c);
    }
    const torch::Tensor allH = torch::cat(hs, 0); // [longest, views, hidden]
    const torch::Tensor allC = torch::cat(cs, 0);
    scoreOneStep(m.net->head->forward(allH).to(torch::kFloat64).contiguous(), true);
    const auto n = static_cast<long>(val.rolloutOrigins.size());
    torch::Tensor views = torch::empty({n}, torch::kLong), rows = torch::empty({n}, torch::kLong);
    for (long i = 0; i < n; ++i) {
        views[i] = val.rolloutOrigins[static_cast<std::size_t>(i)][0];
        rows[i] = val.rolloutOrigins[static_cast<std::size_t>(i)][1];
    }
    // Row-major [longest · views, …] tensors and the origins' places in them.
    const auto byRow = [&](const torch::Tensor& t) { return t.transpose(0, 1).reshape({longest * nv, -1}); };
    const torch::Tensor at = rows * nv + views;
    const torch::Tensor features = byRow(val.features);
    torch::Tensor y;
    m.rollout(
        allH.reshape({longest * nv, -1}).index_select(0, at).unsqueeze(0),
        allC.reshape({longest * nv, -1}).index_select(0, at).unsqueeze(0),
        byRow(val.held).index_select(0, at), byRow(val.reference).index_select(0, at),
        static_cast<std::size_t>(val.horizon),
        [&](std::size_t step) {
            const auto next = torch::clamp_max(rows + static_cast<long>(step), longest - 1) * nv + views;
            return features.index_select(0, next).unsqueeze(1);
        },
        [&](std::size_t step, const torch::Tensor& predicted) {
            if (step == static_cast<std::size_t>(val.horizon)) {
                y = predicted.contiguous();
            }
        });
    const auto ya = y.accessor<double, 2>();
    for (const auto& e : val.entries[1]) {
        mae[1].add(e.output, e.observed - ya[static_cast<long>(e.rollout)][e.output]);
    }
    return mae;
}

LstmValidation summarise(const LstmModel& m, const ValidationSplit& split, const ValidationSet& val) {
    const bool validating = val.usable();
    const bool ahead = val.usableAhead();
    LstmValidation vr = m.validation; // the best epoch
    vr.validated = validating;
    vr.part = split.part;
    vr.rows = val.rows;
    if (!validating) {
        vr.bestEpoch = static_cast<int>(m.epochs.size());
        vr.message = "Too few validation rows (" + std::to_string(val.rows) +
                     "): the LSTM ran every epoch without early stopping and is NOT checked against the "
                     "references.";
        return vr;
    }
    const auto mae = scoreValidation(m, val, ahead);
    vr.maeMoisturePct = mae[0].of(0);
    vr.maeTemperatureC = mae[0].of(1);
    vr.referenceMaeMoisturePct = val.referenceMae[0][0];
    vr.referenceMaeTemperatureC = val.referenceMae[0][1];
    vr.skillMoisture = vr.maeMoisturePct / vr.referenceMaeMoisturePct;
    vr.skillTemperature = vr.maeTemperatureC / vr.referenceMaeTemperatureC;
    if (ahead) {
        vr.horizon = val.horizon;
        vr.skillMoistureAhead = mae[1].of(0) / val.referenceMae[1][0];
        vr.skillTemperatureAhead = mae[1].of(1) / val.referenceMae[1][1];
    }
    vr.beatsReferences = vr.skillMoisture < 1 && vr.skillTemperature < 1;
    const bool x = !(vr.skillMoisture < 1); // NaN counts as not beating
    const bool t = !(vr.skillTemperature < 1);
    const std::string verdict = vr.beatsReferences
                                    ? "it beats both"
                                    : std::string("it does NOT beat them for ") +
                                          (x && t ? "X_out and T_out"
                                           : x    ? "X_out"
                                                  : "T_out") +
                                          " (its forecasts are still given; prefer the references)";
    vr.message =
        "On the validation part (" + vr.part + ", " + std::to_string(vr.rows) +
        " rows) the LSTM's one-step skill is " + fixed(vr.skillMoisture, 3) + " for X_out and " +
        fixed(vr.skillTemperature, 3) +
        " for T_out against the better of persistence and the PBM with its last error held: " + verdict + ".";
    if (ahead) {
        vr.message += " " + std::to_string(vr.horizon) + " steps ahead: " + fixed(vr.skillMoistureAhead, 3) +
                      " and " + fixed(vr.skillTemperatureAhead, 3) + ".";
    }
    return vr;
}

} // namespace drytwin::baselines::detail
