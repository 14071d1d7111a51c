// Issue #42: which basis the input-driven correction uses is a property of the line, found by
// cross-validation in its training data (neither the filter bank nor the lags won on every line).
#include "residual/InputDrivenCorrection.h"
#include "residual/ResidualModel.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>

namespace drytwin::residual {

std::string basisName(InputBasis basis) {
    switch (basis) {
    case InputBasis::FilterBank:
        return "filter_bank";
    case InputBasis::LaggedInputs:
        return "lagged_inputs";
    case InputBasis::FilterBankAndLags:
        return "filter_bank_and_lags";
    case InputBasis::ChosenByValidation:
        break;
    }
    return "chosen_by_validation";
}

Expected<InputDrivenCorrection> InputDrivenCorrection::trainChoosingBasis(const std::vector<BatchView>& views,
                                                                          const InputDrivenOptions& options) {
    // The cross-validated error relative to the PBM's, averaged over the two outputs (an
    // output the correction does not beat counts as 1: the PBM is then used for it).
    const auto relativeError = [](const InputDrivenValidation& v) {
        const auto ratio = [](double corrected, double pbm) {
            return pbm > 0 ? std::min(1.0, corrected / pbm) : 1.0;
        };
        return 0.5 * (ratio(v.maeMoistureCorrected, v.maeMoisturePbm) +
                      ratio(v.maeTemperatureCorrected, v.maeTemperaturePbm));
    };
    std::optional<InputDrivenCorrection> best;
    double bestScore = std::numeric_limits<double>::infinity();
    std::string tried;
    for (const auto basis :
         {InputBasis::FilterBank, InputBasis::LaggedInputs, InputBasis::FilterBankAndLags}) {
        auto concrete = options;
        concrete.basis = basis;
        auto candidate = train(views, concrete);
        if (!candidate) {
            return candidate.error(); // the same rows feed every basis: no basis would do better
        }
        const double score = relativeError(candidate->validation());
        char line[96];
        std::snprintf(line, sizeof line, "%s%s %.3f", tried.empty() ? "" : ", ", basisName(basis).c_str(),
                      score);
        tried += line;
        if (score < bestScore) { // ties keep the earlier, smaller basis
            bestScore = score;
            best = std::move(*candidate);
        }
    }
    best->m_validation.basisChoice = basisName(best->m_options.basis) +
                                     " kept; cross-validated error relative to the physics model's: " + tried;
    return std::move(*best);
}

} // namespace drytwin::residual
