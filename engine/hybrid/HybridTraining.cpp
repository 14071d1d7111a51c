#include "hybrid/HybridTraining.h"

#include "hybrid/Evaluation.h"

#include <chrono>

namespace drytwin::hybrid {

Expected<std::vector<physics::SimulationResult>> simulatePbm(const std::vector<data::SiBatch>& batches,
                                                             const HybridModel& model,
                                                             const properties::ModelSwitches& switches,
                                                             const Progress& progress) {
    std::vector<physics::LineInputs> inputs;
    for (const auto& b : batches) {
        inputs.push_back(physics::toLineInputs(b));
    }
    physics::SimulationOptions so = model.simulationOptions();
    so.switches = switches;
    return physics::simulateBatches(inputs, model.parameters, so, 0, progress);
}

std::vector<residual::BatchView> splitViews(const std::vector<data::SiBatch>& batches,
                                            const std::vector<physics::SimulationResult>& pbm, bool test,
                                            double trainFraction) {
    std::vector<std::size_t> rows;
    for (const auto& b : batches) {
        rows.push_back(b.rows());
    }
    const auto split = data::chronologicalSplit(rows, trainFraction);
    std::vector<residual::BatchView> views;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        const auto& range = test ? split.test[b] : split.train[b];
        if (range.size() > 0) {
            views.push_back({&batches[b], &pbm[b], range});
        }
    }
    return views;
}

Expected<TrainingResult> trainResidualModels(const std::vector<data::SiBatch>& batches,
                                             const HybridModel& model,
                                             const residual::ResidualOptions& options,
                                             const baselines::LstmOptions& lstmOptions,
                                             const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    auto pbm = simulatePbm(batches, model, model.switches, progress);
    if (!pbm) {
        return pbm.error();
    }
    const auto views = splitViews(batches, *pbm, false);
    if (reportProgress(progress, "train", 0.3, "PGRL-CC")) {
        return cancelledError("train");
    }
    auto full = residual::ResidualModel::train(views, options);
    if (!full) {
        return full.error();
    }
    if (reportProgress(progress, "train", 0.7, "external-input residual")) {
        return cancelledError("train");
    }
    residual::ResidualOptions ext = options;
    ext.useProxies = false;
    auto extModel = residual::ResidualModel::train(views, ext);
    if (!extModel) {
        return extModel.error();
    }
    auto lstm = baselines::LstmBaseline::train(views, lstmOptions, progress);
    if (!lstm) {
        return lstm.error();
    }
    reportProgress(progress, "train", 1.0, "done");
    TrainingResult r{std::move(*full), std::move(*extModel), std::move(*lstm), 0, {}};
    r.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.ending = {Termination::Completed, "PGRL-CC, external-input residual and LSTM trained",
                r.elapsedSeconds};
    return r;
}

void storeResidualModels(HybridModel& model, TrainingResult&& trained) {
    model.pgrlCc = std::make_shared<const residual::ResidualModel>(std::move(trained.pgrlCc));
    model.extInput = std::make_shared<const residual::ResidualModel>(std::move(trained.extInput));
    model.lstm = std::make_shared<const baselines::LstmBaseline>(std::move(trained.lstm));
}

Expected<AblationResult> runAblation(const std::vector<data::SiBatch>& batches, const HybridModel& model,
                                     const Progress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    struct Variant {
        const char* name;
        const char* description;
        int physics;  ///< 0 none, 1 no clamp, 2 no L_v correction, 3 no C_p(X)
        int learning; ///< 0 none, 4 no P⊥, 5 no CC weights, 6 no stability constraint
    };
    const Variant variants[] = {
        {"full", "PGRL-CC, all components", 0, 0},
        {"no_aw_clamp", "1. no a_w clamping", 1, 0},
        {"no_lv_correction", "2. no L_v correction", 2, 0},
        {"no_cp_moisture", "3. no C_p(X) dependency", 3, 0},
        {"no_orthogonal_projection", "4. no orthogonal learning (P_perp)", 0, 4},
        {"no_cc_weights", "5. no control-consistent weights", 0, 5},
        {"no_stability_constraint", "6. no stability constraint (EDMDc-S)", 0, 6},
    };
    std::vector<AblationRow> rows;
    std::vector<physics::SimulationResult> basePbm;
    int done = 0;
    for (const auto& v : variants) {
        if (reportProgress(progress, "ablation", done / 7.0, v.name)) {
            return cancelledError("ablation");
        }
        properties::ModelSwitches sw = model.switches;
        sw.clampWaterActivity = sw.clampWaterActivity && v.physics != 1;
        sw.latentHeatCorrection = sw.latentHeatCorrection && v.physics != 2;
        sw.moistureDependentCp = sw.moistureDependentCp && v.physics != 3;
        // The base PBM run serves the full model and the three learning variants; the physics
        // variants each need their own.
        std::vector<physics::SimulationResult> variantPbm;
        if (v.physics != 0 || basePbm.empty()) {
            auto sims = simulatePbm(batches, model, sw);
            if (!sims) {
                return sims.error();
            }
            (v.physics == 0 ? basePbm : variantPbm) = std::move(*sims);
        }
        const auto& pbm = v.physics == 0 ? basePbm : variantPbm;
        residual::ResidualOptions o;
        o.orthogonalProjection = v.learning != 4;
        o.controlConsistentWeights = v.learning != 5;
        o.stabilityConstraint = v.learning != 6;
        auto m = residual::ResidualModel::train(splitViews(batches, pbm, false), o);
        if (!m) {
            return m.error();
        }
        const auto scored = evaluation::scorePredictions(
            splitViews(batches, pbm, true),
            [&](const residual::BatchView& view) { return m->predictOneStep(view); }, 20);
        AblationRow row;
        row.maeMoisture = scored.moisture.mae;
        row.r2Moisture = scored.moisture.r2;
        row.maeTemperature = scored.temperature.mae;
        row.r2Temperature = scored.temperature.r2;
        row.ljungBoxPMoisture = scored.moisture.ljungBoxP;
        row.variant = v.name;
        row.description = v.description;
        rows.push_back(row);
        ++done;
    }
    reportProgress(progress, "ablation", 1.0, "done");
    AblationResult result{std::move(rows), {}};
    result.ending = {Termination::Completed, "seven variants trained and scored",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
    return result;
}

} // namespace drytwin::hybrid
