// Issue #42: the input-driven correction of the PBM's free run and the realised-weight guard.
#include "common/Units.h"
#include "hybrid/HybridTraining.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"
#include "residual/InputDrivenCorrection.h"
#include "residual/RealisedWeight.h"
#include "residual/ResidualModel.h"
#include "residual/TrailingHampel.h"

#include <QtTest>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

using namespace drytwin;
using namespace drytwin::residual;

namespace {

struct DataSet {
    std::vector<data::SiBatch> batches;
    std::vector<physics::SimulationResult> pbm;
    std::vector<BatchView> views() const {
        std::vector<BatchView> v;
        for (std::size_t i = 0; i < batches.size(); ++i) {
            v.push_back({&batches[i], &pbm[i], {0, batches[i].rows()}});
        }
        return v;
    }
};

/// The distributed plant with realistic transmitters, no mechanism: what the PBM gets wrong is
/// the line's own structure (a gas phase, residence-time spread), which the inputs drive.
const DataSet& distributed(unsigned seed) {
    static std::map<unsigned, DataSet> cache;
    auto it = cache.find(seed);
    if (it == cache.end()) {
        plant::PlantOptions o;
        o.plant = plant::PlantKind::Distributed;
        o.seed = seed;
        o.batches = 3;
        o.samples = 2500;
        auto r = plant::runPlant(o);
        DataSet d;
        d.batches = plant::toSiBatches(*r, seed);
        d.pbm = std::move(*hybrid::simulatePbm(d.batches, hybrid::HybridModel{}, {}));
        it = cache.emplace(seed, std::move(d)).first;
    }
    return it->second;
}

/// Free-run MAE (% wb, °C) of the PBM plus a correction over every kept row.
std::pair<double, double> freeRunMae(const DataSet& d, const InputDrivenCorrection* c) {
    double sx = 0, st = 0;
    int n = 0;
    for (std::size_t b = 0; b < d.batches.size(); ++b) {
        const auto& batch = d.batches[b];
        std::vector<double> cx(batch.rows(), 0.0), ct(batch.rows(), 0.0);
        if (c) {
            c->correct(batch, d.pbm[b], cx, ct);
        }
        for (std::size_t k = 0; k < batch.rows(); ++k) {
            const double ex =
                units::dryToWetPct(batch.xOutDb[k]) - units::dryToWetPct(d.pbm[b].xOutDb[k]) - cx[k];
            const double et = batch.tOutK[k] - d.pbm[b].tOutK[k] - ct[k];
            if (batch.keep[k] && std::isfinite(ex) && std::isfinite(et)) {
                sx += std::abs(ex);
                st += std::abs(et);
                ++n;
            }
        }
    }
    return {sx / n, st / n};
}

} // namespace

class TestInputDriven : public QObject {
    Q_OBJECT
private slots:
    void realisedWeightMatchesHandComputation() {
        // Half-life 1 step: decay 1/2. Targets t and corrections c; prior 2 rows.
        RealisedWeight w(1.0, 2.0);
        QCOMPARE(w.weight(), 1.0); // nothing realised: the trained weight
        w.add(1.0, 2.0);
        w.add(-1.0, 1.0);
        // Σ t c = 0.5·2 − 1 = 0, Σ c² = 0.5·4 + 1 = 3, Σ 1 = 1.5; prior = 2·3/1.5 = 4.
        QVERIFY(std::abs(w.weight() - (0.0 + 4.0) / (3.0 + 4.0)) < 1e-12);
        // A correction that always points the wrong way is switched off; a right one kept.
        RealisedWeight wrong(600, 30), right(600, 30);
        for (int i = 0; i < 2000; ++i) {
            const double c = std::sin(0.1 * i);
            wrong.add(-c, c);
            right.add(c, c);
        }
        QVERIFY(wrong.weight() < 0.05);
        QCOMPARE(right.weight(), 1.0);
    }

    void realisedWeightByAbsoluteErrorMatchesHandComputation() {
        // No forgetting (half-life 0), no prior: w minimises Σ |t − w c| over w = 0, 0.05, …, 1.
        // Rows (t, c): (1, 1), (1, 1), (0, 1) and a spike (−40, 1). Least squares: Σ t c / Σ c² =
        // −38 / 4, clipped to 0: the spike alone switches the correction off.
        RealisedWeight l1(0.0, 0.0, 1.0, true), l2(0.0, 0.0);
        for (const auto& [t, c] : std::vector<std::pair<double, double>>{{1, 1}, {1, 1}, {0, 1}, {-40, 1}}) {
            l1.add(t, c);
            l2.add(t, c);
        }
        QCOMPARE(l2.weight(), 0.0);
        // Σ |t − w| = 2(1 − w) + w + 40 + w = 42 for every w in [0, 1]: a tie, which goes to w₀ = 1.
        QCOMPARE(l1.weight(), 1.0);
        RealisedWeight median(0.0, 0.0, 0.0, true); // w₀ = 0: ties go to 0
        for (const auto& [t, c] : std::vector<std::pair<double, double>>{{0.3, 1}, {0.3, 1}, {0.9, 1}}) {
            median.add(t, c);
        }
        // The weighted median of t/c on the grid: 0.3.
        QVERIFY(std::abs(median.weight() - 0.3) < 1e-12);
        // The prior pulls towards w₀: 2 rows' worth of mean|c| = 1 at w₀ = 1 against three rows
        // at 0.3: cost(w) = 2|0.3 − w| + |0.9 − w| + 2|1 − w|, smallest at w = 0.9 (1.4; 1.5 at 1).
        RealisedWeight pulled(0.0, 2.0, 1.0, true);
        for (const auto& [t, c] : std::vector<std::pair<double, double>>{{0.3, 1}, {0.3, 1}, {0.9, 1}}) {
            pulled.add(t, c);
        }
        QVERIFY(std::abs(pulled.weight() - 0.9) < 1e-12);
        // Nothing realised: the trained weight w₀.
        QCOMPARE(RealisedWeight(600, 30, 0.4, true).weight(), 0.4);
    }

    void realisedWeightsUseOnlyTargetsMeasuredByTheOrigin() {
        const std::size_t n = 400, h = 30;
        std::vector<double> reference(n, 0.0), correction(n), measured(n), first, second;
        for (std::size_t i = 0; i < n; ++i) {
            correction[i] = std::cos(0.05 * double(i));
            measured[i] = -correction[i]; // the correction is harmful throughout
        }
        applyRealisedWeights(reference, correction, measured, h, 100, 5, first);
        // Row 200's forecast was made at row 170: what is measured after that cannot change it.
        for (std::size_t i = 171; i < n; ++i) {
            measured[i] = 10 * correction[i];
        }
        applyRealisedWeights(reference, correction, measured, h, 100, 5, second);
        for (std::size_t i = 0; i <= 200; ++i) {
            QCOMPARE(second[i], first[i]);
        }
        QVERIFY(std::abs(first[200]) < 0.2 * std::abs(correction[200]) + 1e-9); // mostly switched off
        QCOMPARE(first[0], correction[0]); // before anything is realised: the trained weight, 1
    }

    void beatsThePbmInFreeRunOnAnotherSeed() {
        const auto& train = distributed(4201);
        const auto& judged = distributed(4202);
        auto c = InputDrivenCorrection::train(train.views(), {});
        QVERIFY2(c.ok(), c ? "" : c.error().message().c_str());
        const auto& val = c->validation();
        qInfo("cross-validated on the training seed: X %.4f -> %.4f, T %.3f -> %.3f (%s)", val.maeMoisturePbm,
              val.maeMoistureCorrected, val.maeTemperaturePbm, val.maeTemperatureCorrected, val.note.c_str());
        // Uncalibrated parameters: moisture far off (the correction takes most of it), temperature
        // already close, where a correction that does not beat the PBM in cross-validation is off.
        QVERIFY(val.moistureUsed);
        QVERIFY(val.temperatureUsed || val.note.find("Outlet temperature") != std::string::npos);
        const auto pbm = freeRunMae(judged, nullptr);
        const auto corrected = freeRunMae(judged, &*c);
        qInfo("free run on an unseen seed: X %.4f -> %.4f %% wb, T %.3f -> %.3f °C", pbm.first,
              corrected.first, pbm.second, corrected.second);
        QVERIFY(corrected.first < 0.5 * pbm.first);
        QVERIFY(val.temperatureUsed ? corrected.second < pbm.second : corrected.second <= pbm.second + 1e-12);
    }

    void aSpikedInputCannotDriveTheCorrectionFar() {
        const auto& train = distributed(4201);
        auto c = InputDrivenCorrection::train(train.views(), {});
        QVERIFY(c.ok());
        const auto& judged = distributed(4202);
        data::SiBatch spiked = judged.batches[0];
        for (std::size_t k = 1000; k < 1006; ++k) {
            spiked.xInDb[k] *= 10; // a transmitter spike: 200 % wb
            spiked.tAmbK[k] += 200;
        }
        std::vector<double> cx, ct, sx, st;
        c->correct(judged.batches[0], judged.pbm[0], cx, ct);
        c->correct(spiked, judged.pbm[0], sx, st);
        double worstX = 0, worstT = 0;
        for (std::size_t k = 0; k < cx.size(); ++k) {
            worstX = std::max(worstX, std::abs(sx[k] - cx[k]));
            worstT = std::max(worstT, std::abs(st[k] - ct[k]));
        }
        qInfo("largest change of the correction by the spike: %.3f %% wb, %.3f °C", worstX, worstT);
        QVERIFY(worstX < 0.3);
        QVERIFY(worstT < 3.0);
    }

    void storedCorrectionPredictsTheSame() {
        const auto& train = distributed(4201);
        InputDrivenOptions o;
        o.basis = InputBasis::FilterBankAndLags;
        auto c = InputDrivenCorrection::train(train.views(), o);
        QVERIFY(c.ok());
        auto back = InputDrivenCorrection::fromJson(c->toJson());
        QVERIFY2(back.ok(), back ? "" : back.error().message().c_str());
        std::vector<double> ax, at, bx, bt;
        const auto& judged = distributed(4202);
        c->correct(judged.batches[1], judged.pbm[1], ax, at);
        back->correct(judged.batches[1], judged.pbm[1], bx, bt);
        for (std::size_t k = 0; k < ax.size(); k += 97) {
            QVERIFY(std::abs(ax[k] - bx[k]) < 1e-9 && std::abs(at[k] - bt[k]) < 1e-9);
        }
        QVERIFY(!InputDrivenCorrection::fromJson(R"({"basis": "filter_bank"})").ok());
    }

    void trailingHampelTakesSpikesOutAndLetsStepsThrough() {
        Eigen::MatrixXd z(200, 2);
        for (Eigen::Index k = 0; k < z.rows(); ++k) {
            z(k, 0) = 0.01 * std::sin(0.3 * double(k)) + (k >= 120 ? 3.0 : 0.0); // a genuine step
            z(k, 1) = 0.5;                                                       // not despiked
        }
        for (Eigen::Index k = 60; k < 66; ++k) {
            z(k, 0) += 40; // a six-sample spike
        }
        z(70, 1) = 99;
        const Eigen::MatrixXd before = z;
        const auto replaced = despikeTrailing(z, 1, 21, 6.0, 1.0);
        for (Eigen::Index k = 60; k < 66; ++k) {
            QVERIFY(std::abs(z(k, 0)) < 0.05);
        }
        QCOMPARE(z(70, 1), 99.0);
        // The step is held back for at most half the window, then passes unchanged.
        for (Eigen::Index k = 120 + 11; k < z.rows(); ++k) {
            QCOMPARE(z(k, 0), before(k, 0));
        }
        QVERIFY(replaced >= 6 && replaced <= 6 + 11);
        for (Eigen::Index k = 0; k < 60; ++k) {
            QCOMPARE(z(k, 0), before(k, 0)); // small variation is not a spike (the floor)
        }
    }

    void basisIsTheOneWithTheSmallestCrossValidatedError() {
        const auto& train = distributed(4201);
        auto chosen = InputDrivenCorrection::train(train.views(), InputDrivenOptions{});
        QVERIFY2(chosen.ok(), chosen ? "" : chosen.error().message().c_str());
        QVERIFY(chosen->options().basis != InputBasis::ChosenByValidation);
        const auto relative = [](const InputDrivenValidation& v) {
            return 0.5 * (std::min(1.0, v.maeMoistureCorrected / v.maeMoisturePbm) +
                          std::min(1.0, v.maeTemperatureCorrected / v.maeTemperaturePbm));
        };
        const double chosenScore = relative(chosen->validation());
        for (const auto basis :
             {InputBasis::FilterBank, InputBasis::LaggedInputs, InputBasis::FilterBankAndLags}) {
            InputDrivenOptions o;
            o.basis = basis;
            auto c = InputDrivenCorrection::train(train.views(), o);
            QVERIFY(c.ok());
            QVERIFY2(chosenScore <= relative(c->validation()) + 1e-12, basisName(basis).c_str());
            QVERIFY2(chosen->validation().basisChoice.find(basisName(basis)) != std::string::npos,
                     chosen->validation().basisChoice.c_str());
        }
        qInfo("%s", chosen->validation().basisChoice.c_str());
        // A file names a concrete basis; the choice itself is not a basis one can predict with.
        auto text = chosen->toJson();
        const auto at = text.find(basisName(chosen->options().basis));
        QVERIFY(at != std::string::npos);
        text.replace(at, basisName(chosen->options().basis).size(), "chosen_by_validation");
        QVERIFY(!InputDrivenCorrection::fromJson(text).ok());
    }

    void forecastsAreNoWorseThanTheTrivialOnesOnAnotherSeed() {
        // Issue #42: on a data set it was not trained on, PGRL-CC's H-step moisture forecast is no
        // worse than the better of holding the last measurement and the PBM with its last error
        // held; far ahead (where the error decorrelates) it lets the held error go and is better
        // than both, and better than with the trained s_H and the held error alone.
        const auto& train = distributed(4201);
        const auto& judged = distributed(4202);
        ResidualOptions realised, trainedOnly;
        trainedOnly.realisedReferenceBlend = false;
        trainedOnly.realisedHeldErrorDecay = false;
        trainedOnly.realisedWeightByAbsoluteError = false;
        auto a = ResidualModel::train(train.views(), realised);
        auto b = ResidualModel::train(train.views(), trainedOnly);
        QVERIFY2(a.ok(), a ? "" : a.error().message().c_str());
        QVERIFY(b.ok());
        for (int h : {1, 90}) {
            double model = 0, old = 0, persistence = 0, pbmHeld = 0;
            int n = 0;
            for (const auto& v : judged.views()) {
                const auto pa = a->predictHorizons(v, {h}).front(), pb = b->predictHorizons(v, {h}).front();
                const auto wet = [&](std::size_t k) { return units::dryToWetPct(v.batch->xOutDb[k]); };
                const auto pbm = [&](std::size_t k) { return units::dryToWetPct(v.pbm->xOutDb[k]); };
                for (std::size_t k = static_cast<std::size_t>(h); k < v.rows.size(); ++k) {
                    const std::size_t o = k - static_cast<std::size_t>(h);
                    const double y = wet(k), y0 = wet(o);
                    if (!v.batch->keep[k] || !v.batch->keep[o] || !std::isfinite(y) || !std::isfinite(y0) ||
                        !std::isfinite(pa.xOutPct[k]) || !std::isfinite(pb.xOutPct[k])) {
                        continue;
                    }
                    model += std::abs(y - pa.xOutPct[k]);
                    old += std::abs(y - pb.xOutPct[k]);
                    persistence += std::abs(y - y0);
                    pbmHeld += std::abs(y - (pbm(k) + y0 - pbm(o)));
                    ++n;
                }
            }
            QVERIFY(n > 5000);
            const double better = std::min(persistence, pbmHeld);
            qInfo("H = %d: skill %.3f (trained s_H and the held error alone: %.3f)", h, model / better,
                  old / better);
            QVERIFY2(model <= better, qPrintable(QString::number(model / better)));
            if (h == 90) {
                QVERIFY(model < 0.95 * better);
                QVERIFY(model < old);
            }
        }
    }

    void theLearntCorrectionIsHeldWithinWhatValidationSaw() {
        // Issue #42: a lifted state beyond anything the training rows held turned the summed
        // correction of a new batch into 15 % wb at 180 steps. The model stores the largest learnt
        // correction its cross-validation saw per horizon and holds the forecast's within κ_H times
        // it: a bound of 0 is then the learnt part switched off (κ_H = 0), a bound of 10⁹ no bound,
        // in every forecast form (one horizon after another, from one origin as the MPC asks, free
        // run), and the file keeps it.
        const auto& train = distributed(4201);
        const auto& judged = distributed(4202);
        // The bound is what is tested: κ_H as fitted (the information criterion keeps none of the
        // learnt part on this pair, and a bound on nothing would change nothing).
        ResidualOptions fitted;
        fitted.parsimoniousWeights = false;
        auto trained = ResidualModel::train(train.views(), fitted);
        QVERIFY2(trained.ok(), trained ? "" : trained.error().message().c_str());
        auto file = nlohmann::json::parse(trained->toJson());
        QVERIFY(file.contains("learnt_bound_by_horizon"));
        QCOMPARE(file["learnt_bound_by_horizon"].size(), file["correction_weight_horizons"].size());
        QVERIFY(file["learnt_bound_by_horizon"].back()[0].get<double>() > 0);
        const auto variant = [&](const std::function<void(nlohmann::json&)>& edit) {
            auto j = file;
            edit(j);
            auto m = ResidualModel::fromJson(j.dump());
            if (!m) {
                qFatal("%s", m.error().message().c_str());
            }
            return std::move(*m);
        };
        const auto setAll = [](nlohmann::json& array, double value) {
            for (auto& pair : array) {
                pair = {value, value};
            }
        };
        const ResidualModel boundZero = variant([&](auto& j) { setAll(j["learnt_bound_by_horizon"], 0.0); });
        const ResidualModel kappaZero = variant([&](auto& j) { setAll(j["correction_weights"], 0.0); });
        const ResidualModel boundHuge = variant([&](auto& j) { setAll(j["learnt_bound_by_horizon"], 1e9); });
        const ResidualModel noBound = variant([&](auto& j) { j.erase("learnt_bound_by_horizon"); });
        const auto same = [](const HybridPrediction& a, const HybridPrediction& b) {
            for (std::size_t i = 0; i < a.xOutPct.size(); ++i) {
                const double x = a.xOutPct[i] - b.xOutPct[i], t = a.tOutC[i] - b.tOutC[i];
                if (std::isfinite(x) && std::abs(x) > 1e-9) {
                    return false;
                }
                if (std::isfinite(t) && std::abs(t) > 1e-9) {
                    return false;
                }
            }
            return true;
        };
        const BatchView v = judged.views()[1];
        QVERIFY(same(boundZero.predictHorizons(v, {1, 30, 180})[2],
                     kappaZero.predictHorizons(v, {1, 30, 180})[2]));
        QVERIFY(same(boundHuge.predictHorizons(v, {30})[0], noBound.predictHorizons(v, {30})[0]));
        // Where κ_H > 0 the bound of 0 changes the forecast (the learnt part does something).
        const std::vector<int> horizons{1, 2, 5, 10, 20, 30, 60, 180};
        const auto zero = boundZero.predictHorizons(v, horizons), free = noBound.predictHorizons(v, horizons);
        bool anyDiffers = false;
        for (std::size_t i = 0; i < horizons.size(); ++i) {
            anyDiffers = anyDiffers || !same(zero[i], free[i]);
        }
        QVERIFY(anyDiffers);
        QVERIFY(same(boundZero.forecastFrom(v, 500, 180), kappaZero.forecastFrom(v, 500, 180)));
        QVERIFY(!same(boundZero.forecastFrom(v, 500, 180), noBound.forecastFrom(v, 500, 180)));
        QVERIFY(same(boundZero.predictFreeRun(v), kappaZero.predictFreeRun(v)));
        // The file keeps it, and a bound that does not match the horizons is refused.
        QCOMPARE(nlohmann::json::parse(boundZero.toJson())["learnt_bound_by_horizon"].back()[0].get<double>(),
                 0.0);
        auto bad = file;
        bad["learnt_bound_by_horizon"].erase(0);
        QVERIFY(!ResidualModel::fromJson(bad.dump()).ok());
    }

    void residualModelsFreeRunIsThePbmPlusTheCorrection() {
        const auto& train = distributed(4201);
        const auto& judged = distributed(4202);
        ResidualOptions with, without;
        without.inputDriven = false;
        auto a = ResidualModel::train(train.views(), with);
        auto b = ResidualModel::train(train.views(), without);
        QVERIFY2(a.ok(), a ? "" : a.error().message().c_str());
        QVERIFY(b.ok());
        QVERIFY(a->inputDriven() != nullptr && b->inputDriven() == nullptr);
        double maeWith = 0, maeWithout = 0;
        int n = 0;
        for (const auto& v : judged.views()) {
            const auto pa = a->predictFreeRun(v), pb = b->predictFreeRun(v);
            for (std::size_t k = 0; k < v.rows.size(); ++k) {
                const double y = units::dryToWetPct(v.batch->xOutDb[k]);
                if (v.batch->keep[k] && std::isfinite(y) && std::isfinite(pa.xOutPct[k]) &&
                    std::isfinite(pb.xOutPct[k])) {
                    maeWith += std::abs(y - pa.xOutPct[k]);
                    maeWithout += std::abs(y - pb.xOutPct[k]);
                    ++n;
                    // The residual is the hybrid minus the PBM the caller passed.
                    QVERIFY(std::abs(pa.xOutPct[k] - units::dryToWetPct(v.pbm->xOutDb[k]) -
                                     pa.residualXPct[k]) < 1e-9);
                }
            }
        }
        QVERIFY(n > 1000);
        QVERIFY(maeWith < 0.9 * maeWithout);
        // Stored and read back, the model predicts the same.
        auto back = ResidualModel::fromJson(a->toJson());
        QVERIFY2(back.ok(), back ? "" : back.error().message().c_str());
        const auto v = judged.views()[0];
        const auto p1 = a->predictHorizons(v, {1, 30}), p2 = back->predictHorizons(v, {1, 30});
        for (std::size_t k = 100; k < v.rows.size(); k += 101) {
            QVERIFY(std::abs(p1[1].xOutPct[k] - p2[1].xOutPct[k]) < 1e-9 || !std::isfinite(p1[1].xOutPct[k]));
        }
    }
};

QTEST_GUILESS_MAIN(TestInputDriven)
#include "TestInputDriven.moc"
