// How a residual model is stored: its options, dictionary and matrices as JSON, and read back.
#include "residual/EigenJson.h"
#include "residual/ResidualModelInternal.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace drytwin::residual {

namespace {
/// Per-horizon (X_out, T_out) pairs as [[x, t], …] in model files, and back.
nlohmann::json pairsToJson(const std::vector<Eigen::Vector2d>& pairs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& k : pairs) {
        out.push_back({k(0), k(1)});
    }
    return out;
}

std::vector<Eigen::Vector2d> pairsFromJson(const nlohmann::json& j) {
    std::vector<Eigen::Vector2d> out;
    for (const auto& k : j) {
        out.emplace_back(k.at(0).get<double>(), k.at(1).get<double>());
    }
    return out;
}
} // namespace

using namespace detail;

std::string ResidualModel::toJson() const {
    nlohmann::json j;
    const auto& o = m_options;
    j["format_version"] = 1;
    j["options"] = {{"use_proxies", o.useProxies},
                    {"degree", o.degree},
                    {"residual_lags", o.residualLags},
                    {"orthogonal_projection", o.orthogonalProjection},
                    {"project_residual", o.projectResidual},
                    {"restore_base_part", o.restoreBasePart},
                    {"nest_references", o.nestReferences},
                    {"shrink_validation_fraction", o.shrinkValidationFraction},
                    {"correction_folds", o.correctionFolds},
                    {"correction_criterion", o.correctionByAbsoluteError ? "absolute" : "squared"},
                    {"bound_learnt_by_validation", o.boundLearntByValidation},
                    {"control_consistent_weights", o.controlConsistentWeights},
                    {"stability_constraint", o.stabilityConstraint},
                    {"stability_method",
                     o.stabilityMethod == StabilityMethod::Constrained ? "constrained" : "eigenvalue_pull"},
                    {"lambda_A", o.lambdaA},
                    {"lambda_B", o.lambdaB},
                    {"lambda_E", o.lambdaE},
                    {"lambda_C", o.lambdaC},
                    {"kappa1", o.kappa1},
                    {"kappa2", o.kappa2},
                    {"delta_pct", o.deltaPct},
                    {"moisture_target_pct", o.moistureTargetPct},
                    {"moisture_low_pct", o.moistureLowPct},
                    {"moisture_high_pct", o.moistureHighPct},
                    {"alpha_max", o.alphaMax},
                    {"radius_max", o.radiusMax},
                    {"input_driven", o.inputDriven},
                    {"realised_weight_half_life_steps", o.realisedWeightHalfLifeSteps},
                    {"realised_weight_prior_rows", o.realisedWeightPriorRows},
                    {"realised_reference_blend", o.realisedReferenceBlend},
                    {"realised_weight_by_absolute_error", o.realisedWeightByAbsoluteError},
                    {"realised_held_error_decay", o.realisedHeldErrorDecay},
                    {"realised_correction_change", o.realisedCorrectionChange},
                    {"realised_prior_per_horizon", o.realisedPriorPerHorizon},
                    {"input_range_margin", o.inputRangeMargin},
                    {"correction_folds_by_batch", o.correctionFoldsByBatch}};
    j["dictionary"] = {
        {"inputs", m_dict.inputNames()},
        {"mean", std::vector<double>(m_dict.mean().data(), m_dict.mean().data() + m_dict.mean().size())},
        {"scale", std::vector<double>(m_dict.scale().data(), m_dict.scale().data() + m_dict.scale().size())},
        {"features", m_dict.featureNames()}};
    j["base_features"] = m_baseIdx;
    j["residual_features"] = m_resIdx;
    j["projection_G"] = matrixToJson(m_projection);
    j["residual_projection_g"] = matrixToJson(m_residualProjection);
    j["feature_scale"] =
        std::vector<double>(m_featureScale.data(), m_featureScale.data() + m_featureScale.size());
    j["residual_scale"] = {m_eScale(0), m_eScale(1)};
    if (m_inputLow.size() > 0) {
        j["input_low"] = vectorToJson(m_inputLow);
        j["input_high"] = vectorToJson(m_inputHigh);
    }
    if (m_inputDriven) {
        j["input_driven_correction"] = nlohmann::json::parse(m_inputDriven->toJson());
    }
    j["A"] = matrixToJson(m_a);
    j["A_unconstrained"] = matrixToJson(m_aFree);
    j["B"] = matrixToJson(m_b);
    j["E"] = matrixToJson(m_e);
    j["C"] = matrixToJson(m_c);
    j["stability"] = {{"spectral_radius_before", m_cert.spectralRadiusBefore},
                      {"spectral_radius_after", m_cert.spectralRadiusAfter},
                      {"alpha", m_cert.alpha},
                      {"certificate_max_eig", m_cert.certificateMaxEig},
                      {"certified", m_cert.certified},
                      {"cholesky_passes", m_cert.choleskyPasses},
                      {"p_condition_number", m_cert.pConditionNumber},
                      {"P", matrixToJson(m_cert.p)}};
    const auto& cmp = m_comparison;
    j["stability_comparison"] = {{"loss_unconstrained", cmp.lossUnconstrained},
                                 {"loss_eigenvalue_pull", cmp.lossEigenvaluePull},
                                 {"loss_constrained", cmp.lossConstrained},
                                 {"radius_unconstrained", cmp.radiusUnconstrained},
                                 {"radius_eigenvalue_pull", cmp.radiusEigenvaluePull},
                                 {"radius_constrained", cmp.radiusConstrained},
                                 {"admm_iterations", cmp.admmIterations},
                                 {"outer_iterations", cmp.outerIterations}};
    j["reference_change_weight"] = m_referenceChange;
    j["correction_weight_horizons"] = m_shrinkHorizons;
    j["correction_weights"] = pairsToJson(m_shrink);
    j["reference_change_by_horizon"] = pairsToJson(m_referenceByHorizon);
    if (!m_decayByHorizon.empty()) {
        j["held_error_decay_by_horizon"] = pairsToJson(m_decayByHorizon);
    }
    if (!m_learntBound.empty()) {
        j["learnt_bound_by_horizon"] = pairsToJson(m_learntBound); // [% wb, °C]
    }
    j["training_snapshots"] = m_snapshots;
    j["training_seconds"] = m_trainSeconds;
    return j.dump();
}

Expected<ResidualModel> ResidualModel::fromJson(const std::string& text) {
    try {
        const auto j = nlohmann::json::parse(text);
        ResidualModel m;
        auto& o = m.m_options;
        const auto& jo = j.at("options");
        o.useProxies = jo.at("use_proxies");
        o.degree = jo.at("degree");
        o.residualLags = jo.at("residual_lags");
        o.orthogonalProjection = jo.at("orthogonal_projection");
        // Files from before Eq. 27 was implemented as written projected the features only.
        o.projectResidual = jo.value("project_residual", false);
        o.restoreBasePart = jo.value("restore_base_part", true);
        // Files from before issue #24 shrank towards zero.
        o.nestReferences = jo.value("nest_references", false);
        o.shrinkValidationFraction = jo.value("shrink_validation_fraction", 0.0);
        o.correctionFolds = jo.value("correction_folds", 0);
        o.correctionByAbsoluteError = jo.value("correction_criterion", std::string("squared")) == "absolute";
        o.boundLearntByValidation = jo.value("bound_learnt_by_validation", false);
        o.controlConsistentWeights = jo.at("control_consistent_weights");
        o.stabilityConstraint = jo.at("stability_constraint");
        // Files written before Eq. (30) was solved as stated used the eigenvalue pull.
        o.stabilityMethod = jo.value("stability_method", std::string("eigenvalue_pull")) == "constrained"
                                ? StabilityMethod::Constrained
                                : StabilityMethod::EigenvaluePull;
        o.lambdaA = jo.at("lambda_A");
        o.lambdaB = jo.at("lambda_B");
        o.lambdaE = jo.at("lambda_E");
        o.lambdaC = jo.at("lambda_C");
        o.kappa1 = jo.at("kappa1");
        o.kappa2 = jo.at("kappa2");
        o.deltaPct = jo.at("delta_pct");
        o.moistureTargetPct = jo.at("moisture_target_pct");
        o.moistureLowPct = jo.at("moisture_low_pct");
        o.moistureHighPct = jo.at("moisture_high_pct");
        o.alphaMax = jo.at("alpha_max");
        o.radiusMax = jo.at("radius_max");
        // Files from before issue #42: the PBM as the base, the trained κ_H alone, no clipping.
        o.inputDriven = jo.value("input_driven", false);
        o.realisedWeightHalfLifeSteps = jo.value("realised_weight_half_life_steps", 0.0);
        o.realisedWeightPriorRows = jo.value("realised_weight_prior_rows", 0.0);
        // Files from before 2026-11-27: the trained s_H alone.
        o.realisedReferenceBlend = jo.value("realised_reference_blend", false);
        o.realisedWeightByAbsoluteError = jo.value("realised_weight_by_absolute_error", false);
        o.realisedHeldErrorDecay = jo.value("realised_held_error_decay", false);
        o.realisedCorrectionChange = jo.value("realised_correction_change", false);
        o.realisedPriorPerHorizon = jo.value("realised_prior_per_horizon", false);
        o.inputRangeMargin = jo.value("input_range_margin", 0.0);
        o.correctionFoldsByBatch = jo.value("correction_folds_by_batch", false);
        if (auto st = o.validate(); !st) {
            return st.error();
        }
        m.m_dict =
            PolynomialDictionary(j.at("dictionary").at("inputs").get<std::vector<std::string>>(), o.degree);
        m.m_dict.setScaling(vectorFromJson(j.at("dictionary").at("mean")),
                            vectorFromJson(j.at("dictionary").at("scale")));
        m.m_baseIdx = j.at("base_features").get<std::vector<int>>();
        m.m_resIdx = j.at("residual_features").get<std::vector<int>>();
        m.m_projection = matrixFromJson(j.at("projection_G"));
        if (j.contains("residual_projection_g")) {
            m.m_residualProjection = matrixFromJson(j.at("residual_projection_g"));
        }
        m.m_featureScale = vectorFromJson(j.at("feature_scale"));
        const auto es = j.at("residual_scale").get<std::vector<double>>();
        m.m_eScale = Eigen::Vector2d(es.at(0), es.at(1));
        if (j.contains("input_low")) {
            m.m_inputLow = vectorFromJson(j.at("input_low"));
            m.m_inputHigh = vectorFromJson(j.at("input_high"));
            if (m.m_inputLow.size() != m.m_dict.inputCount() ||
                m.m_inputHigh.size() != m.m_dict.inputCount()) {
                return Error{ErrorKind::BadInput, "residual model",
                             "the inputs' range does not match the dictionary"};
            }
        }
        if (j.contains("input_driven_correction")) {
            auto c = InputDrivenCorrection::fromJson(j.at("input_driven_correction").dump());
            if (!c) {
                return c.error();
            }
            m.m_inputDriven = std::make_shared<const InputDrivenCorrection>(std::move(*c));
        }
        m.m_a = matrixFromJson(j.at("A"));
        m.m_aFree = matrixFromJson(j.at("A_unconstrained"));
        m.m_b = matrixFromJson(j.at("B"));
        m.m_e = matrixFromJson(j.at("E"));
        m.m_c = matrixFromJson(j.at("C"));
        const auto& s = j.at("stability");
        m.m_cert.spectralRadiusBefore = s.at("spectral_radius_before");
        m.m_cert.spectralRadiusAfter = s.at("spectral_radius_after");
        m.m_cert.alpha = s.at("alpha");
        m.m_cert.certificateMaxEig = s.at("certificate_max_eig");
        m.m_cert.certified = s.at("certified");
        m.m_cert.p = matrixFromJson(s.at("P"));
        m.m_cert.choleskyPasses = s.value("cholesky_passes", false);
        m.m_cert.pConditionNumber = s.value("p_condition_number", 0.0);
        if (j.contains("stability_comparison")) {
            const auto& c = j.at("stability_comparison");
            auto& cmp = m.m_comparison;
            cmp.lossUnconstrained = c.at("loss_unconstrained");
            cmp.lossEigenvaluePull = c.at("loss_eigenvalue_pull");
            cmp.lossConstrained = c.at("loss_constrained");
            cmp.radiusUnconstrained = c.at("radius_unconstrained");
            cmp.radiusEigenvaluePull = c.at("radius_eigenvalue_pull");
            cmp.radiusConstrained = c.at("radius_constrained");
            cmp.admmIterations = c.at("admm_iterations");
            cmp.outerIterations = c.at("outer_iterations");
        }
        m.m_snapshots = j.value("training_snapshots", std::size_t(0));
        m.m_referenceChange = j.value("reference_change_weight", 0.0);
        if (j.contains("correction_weight_horizons")) {
            m.m_shrinkHorizons = j.at("correction_weight_horizons").get<std::vector<int>>();
            m.m_shrink = pairsFromJson(j.at("correction_weights"));
            m.m_referenceByHorizon =
                pairsFromJson(j.value("reference_change_by_horizon", nlohmann::json::array()));
            m.m_learntBound = pairsFromJson(j.value("learnt_bound_by_horizon", nlohmann::json::array()));
            m.m_decayByHorizon =
                pairsFromJson(j.value("held_error_decay_by_horizon", nlohmann::json::array()));
            if (m.m_shrink.size() != m.m_shrinkHorizons.size() ||
                (!m.m_referenceByHorizon.empty() &&
                 m.m_referenceByHorizon.size() != m.m_shrinkHorizons.size()) ||
                (!m.m_decayByHorizon.empty() && m.m_decayByHorizon.size() != m.m_shrinkHorizons.size()) ||
                (!m.m_learntBound.empty() && m.m_learntBound.size() != m.m_shrinkHorizons.size()) ||
                !std::is_sorted(m.m_shrinkHorizons.begin(), m.m_shrinkHorizons.end())) {
                return Error{ErrorKind::BadInput, "residual model",
                             "correction weights do not match their horizons"};
            }
        }
        m.m_trainSeconds = j.value("training_seconds", 0.0);
        const Eigen::Index nx = m.m_a.rows();
        const bool shapesOk =
            m.m_a.cols() == nx && m.m_b.rows() == nx && m.m_e.rows() == nx && m.m_c.cols() == nx &&
            m.m_c.rows() == kOutputs &&
            nx == kOutputs * o.residualLags + static_cast<Eigen::Index>(m.m_resIdx.size()) &&
            m.m_e.cols() == 1 + (m.eq27() ? 0 : m.m_dict.inputCount() - 1) +
                                (o.useProxies ? kOutputs * std::min(o.residualLags, kPbmChangeLags) : 0) &&
            (!m.eq27() || (m.m_residualProjection.rows() == static_cast<Eigen::Index>(m.m_baseIdx.size()) &&
                           m.m_residualProjection.cols() == kOutputs));
        if (!shapesOk) {
            return Error{ErrorKind::BadInput, "residual model", "matrix shapes do not fit together"};
        }
        return m;
    } catch (const std::exception& e) {
        return Error{ErrorKind::BadInput, "residual model", std::string("malformed: ") + e.what()};
    }
}

} // namespace drytwin::residual
