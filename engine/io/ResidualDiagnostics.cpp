#include "io/ResidualDiagnostics.h"

#include "diagnostics/Correlation.h"
#include "diagnostics/Stability.h"
#include "diagnostics/WelchPsd.h"
#include "io/HybridTraining.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace drytwin::evaluation {

namespace {

nlohmann::json eigenJson(const Eigen::MatrixXd& a) {
    nlohmann::json j;
    for (const auto& l : diagnostics::eigenvalues(a)) {
        j["re"].push_back(l.real());
        j["im"].push_back(l.imag());
    }
    for (double r : diagnostics::contractionRates(a)) {
        j["contraction_rate_per_step"].push_back(std::isfinite(r) ? nlohmann::json(r)
                                                                  : nlohmann::json(nullptr));
    }
    j["spectral_radius"] = diagnostics::spectralRadius(a);
    return j;
}

} // namespace

std::string residualDiagnosticsJson(const EvaluationResult& evaluation, const io::ModelFile& model) {
    nlohmann::json j;
    j["units"] = {{"moisture_residual", "% wb"}, {"psd", "(% wb)^2/Hz"}, {"frequency", "Hz"}};
    for (const auto& m : evaluation.models) {
        nlohmann::json e;
        e["acf_lags_0_to_40"] = diagnostics::autocorrelation(m.moistureResidual, 40);
        if (auto psd = diagnostics::welchPsd(m.moistureResidual); psd) {
            e["psd"] = {{"frequency_hz", psd->frequencyHz}, {"density", psd->density}};
            e["low_frequency_share_below_0_01_hz"] = diagnostics::lowFrequencyShare(*psd, 0.01);
        }
        j["models"][m.name] = e;
    }
    bool present = false;
    if (auto rm = hybrid::loadResidualModel(model, hybrid::kPgrlCcKey, present); present && rm) {
        j["pgrl_cc_eigenvalues"] = {{"before", eigenJson(rm->aUnconstrained())},
                                    {"after", eigenJson(rm->a())}};
    }
    return j.dump(1) + "\n";
}

} // namespace drytwin::evaluation
