// How the input-driven correction is stored in model files (JSON), and read back.
#include "residual/EigenJson.h"
#include "residual/InputDrivenCorrection.h"
#include "residual/InputDrivenInternal.h"

#include <nlohmann/json.hpp>

namespace drytwin::residual {

namespace {} // namespace

std::string InputDrivenCorrection::toJson() const {
    nlohmann::json j;
    const auto& o = m_options;
    j["basis"] = basisName(o.basis); // a trained correction's basis is always a concrete one
    j["use_proxies"] = o.useProxies;
    j["manipulated_input"] = o.manipulatedInput;
    j["time_constants_s"] = o.timeConstantsS;
    j["cascade_order"] = o.cascadeOrder;
    j["max_lag_s"] = o.maxLagS;
    j["lag_stride_s"] = o.lagStrideS;
    j["range_margin"] = o.rangeMargin;
    j["range_guard"] = o.rangeGuard;
    j["within_batch"] = o.withinBatch;
    j["input_mean"] = vectorToJson(m_inputMean);
    j["input_scale"] = vectorToJson(m_inputScale);
    j["input_low"] = vectorToJson(m_inputLow);
    j["input_high"] = vectorToJson(m_inputHigh);
    j["feature_mean"] = vectorToJson(m_featureMean);
    j["feature_scale"] = vectorToJson(m_featureScale);
    j["coefficients"] = matrixToJson(m_coefficients);
    j["step_s"] = m_stepS;
    const auto& v = m_validation;
    j["validation"] = {{"ridge", v.ridge},
                       {"folds", v.folds},
                       {"mae_moisture_pbm", v.maeMoisturePbm},
                       {"mae_moisture_corrected", v.maeMoistureCorrected},
                       {"mae_temperature_pbm", v.maeTemperaturePbm},
                       {"mae_temperature_corrected", v.maeTemperatureCorrected},
                       {"moisture_used", v.moistureUsed},
                       {"temperature_used", v.temperatureUsed},
                       {"note", v.note},
                       {"basis_choice", v.basisChoice}};
    if (!m_changeWeights.empty()) {
        nlohmann::json weights = nlohmann::json::array();
        for (const auto& w : m_changeWeights) {
            weights.push_back({w(0), w(1)});
        }
        j["change_weights"] = {{"horizons_steps", input_driven::kChangeHorizons}, {"weights", weights}};
    }
    if (m_foldCoefficients.size() > 0) {
        j["agreement"] = {{"z", o.agreementZ}, {"fold_coefficients", matrixToJson(m_foldCoefficients)}};
    }
    if (m_supportDirections.size() > 0) {
        j["support"] = {{"quantile", o.supportQuantile},
                        {"rho", m_supportRho},
                        {"leverage", v.supportLeverage},
                        {"correction_low", vectorToJson(v.correctionLow)},
                        {"correction_high", vectorToJson(v.correctionHigh)},
                        {"directions", matrixToJson(m_supportDirections)}};
    }
    return j.dump();
}

Expected<InputDrivenCorrection> InputDrivenCorrection::fromJson(const std::string& text) {
    try {
        const auto j = nlohmann::json::parse(text);
        InputDrivenCorrection m;
        auto& o = m.m_options;
        const auto basis = j.at("basis").get<std::string>();
        if (basis == "lagged_inputs") {
            o.basis = InputBasis::LaggedInputs;
        } else if (basis == "filter_bank_and_lags") {
            o.basis = InputBasis::FilterBankAndLags;
        } else if (basis == "filter_bank") {
            o.basis = InputBasis::FilterBank;
        } else {
            return Error{ErrorKind::BadInput, "input_driven.basis",
                         "\"" + basis +
                             "\" is not a basis (filter_bank, lagged_inputs or filter_bank_and_lags)"};
        }
        o.useProxies = j.at("use_proxies").get<bool>();
        // Files written before the option had the hot air among the inputs.
        o.manipulatedInput = j.value("manipulated_input", true);
        o.timeConstantsS = j.at("time_constants_s").get<std::vector<double>>();
        o.cascadeOrder = j.at("cascade_order").get<int>();
        o.maxLagS = j.at("max_lag_s").get<double>();
        o.lagStrideS = j.at("lag_stride_s").get<double>();
        o.rangeMargin = j.at("range_margin").get<double>();
        o.rangeGuard = j.value("range_guard", false); // files before 2026-12-08: no fade
        o.withinBatch = j.value("within_batch", false);
        if (auto s = o.validate(); !s) {
            return s.error();
        }
        m.m_inputMean = vectorFromJson(j.at("input_mean"));
        m.m_inputScale = vectorFromJson(j.at("input_scale"));
        m.m_inputLow = vectorFromJson(j.at("input_low"));
        m.m_inputHigh = vectorFromJson(j.at("input_high"));
        m.m_featureMean = vectorFromJson(j.at("feature_mean"));
        m.m_featureScale = vectorFromJson(j.at("feature_scale"));
        m.m_coefficients = matrixFromJson(j.at("coefficients"));
        m.m_stepS = j.at("step_s").get<double>();
        const auto& v = j.at("validation");
        auto& val = m.m_validation;
        val.ridge = v.at("ridge").get<double>();
        val.folds = v.at("folds").get<int>();
        val.maeMoisturePbm = v.at("mae_moisture_pbm").get<double>();
        val.maeMoistureCorrected = v.at("mae_moisture_corrected").get<double>();
        val.maeTemperaturePbm = v.at("mae_temperature_pbm").get<double>();
        val.maeTemperatureCorrected = v.at("mae_temperature_corrected").get<double>();
        val.moistureUsed = v.at("moisture_used").get<bool>();
        val.temperatureUsed = v.at("temperature_used").get<bool>();
        val.note = v.at("note").get<std::string>();
        val.basisChoice = v.value("basis_choice", std::string()); // files before the choice have none
        // Files before 2026-12-08 have no support guard and no cut: their correction stays as fitted.
        if (j.contains("change_weights")) {
            const auto& c = j.at("change_weights");
            if (c.at("horizons_steps").get<std::vector<int>>() != input_driven::kChangeHorizons) {
                return Error{ErrorKind::BadInput, "input_driven.change_weights",
                             "horizons differ from the ones this version fits"};
            }
            for (const auto& w : c.at("weights")) {
                m.m_changeWeights.emplace_back(w.at(0).get<double>(), w.at(1).get<double>());
            }
            if (m.m_changeWeights.size() != input_driven::kChangeHorizons.size()) {
                return Error{ErrorKind::BadInput, "input_driven.change_weights",
                             "one weight pair per horizon"};
            }
        }
        o.agreementAcrossFolds = j.contains("agreement");
        if (o.agreementAcrossFolds) {
            o.agreementZ = j.at("agreement").at("z").get<double>();
            m.m_foldCoefficients = matrixFromJson(j.at("agreement").at("fold_coefficients"));
        }
        o.supportGuard = j.contains("support");
        if (o.supportGuard) {
            const auto& g = j.at("support");
            o.supportQuantile = g.at("quantile").get<double>();
            m.m_supportRho = g.at("rho").get<double>();
            val.supportLeverage = g.at("leverage").get<double>();
            const Eigen::VectorXd low = vectorFromJson(g.at("correction_low"));
            const Eigen::VectorXd high = vectorFromJson(g.at("correction_high"));
            m.m_supportDirections = matrixFromJson(g.at("directions"));
            if (low.size() != kCorrectedOutputs || high.size() != kCorrectedOutputs ||
                !(m.m_supportRho > 0) || !(val.supportLeverage > 0)) {
                return Error{ErrorKind::BadInput, "input_driven.support",
                             "needs rho and leverage > 0 and a range of two outputs"};
            }
            val.correctionLow = low;
            val.correctionHigh = high;
        }
        const int n = m.inputCount();
        const Eigen::Index features = m.featureCountFor(n);
        if (m.m_inputMean.size() != n || m.m_inputScale.size() != n || m.m_inputLow.size() != n ||
            m.m_inputHigh.size() != n || m.m_featureMean.size() != features ||
            m.m_featureScale.size() != features || m.m_coefficients.rows() != features ||
            m.m_coefficients.cols() != kCorrectedOutputs ||
            (m.m_supportDirections.size() > 0 && m.m_supportDirections.rows() != features) ||
            (m.m_foldCoefficients.size() > 0 && (m.m_foldCoefficients.rows() != features ||
                                                 m.m_foldCoefficients.cols() % kCorrectedOutputs != 0 ||
                                                 m.m_foldCoefficients.cols() < 2 * kCorrectedOutputs))) {
            return Error{ErrorKind::BadInput, "input_driven", "sizes of the stored correction do not agree"};
        }
        return m;
    } catch (const std::exception& e) {
        return Error{ErrorKind::BadInput, "input_driven", e.what()};
    }
}

} // namespace drytwin::residual
