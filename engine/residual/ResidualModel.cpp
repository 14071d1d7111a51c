// What the residual model starts from: its options checked and the observed residual of Eq. (20).
#include "residual/ResidualModel.h"
#include "residual/ResidualModelInternal.h"

#include "common/Units.h"

#include <cmath>

namespace drytwin::residual {

using namespace detail;

Status ResidualOptions::validate() const {
    if (degree < 1 || degree > 3) {
        return Error{ErrorKind::BadInput, "degree", "dictionary degree must be 1, 2 or 3"};
    }
    if (residualLags < 1 || residualLags > 60) {
        return Error{ErrorKind::BadInput, "residualLags", "must lie in [1, 60]"};
    }
    for (double l : {lambdaA, lambdaB, lambdaE, lambdaC, kappa1, kappa2, deltaPct}) {
        if (!(l >= 0 && std::isfinite(l))) {
            return Error{ErrorKind::BadInput, "ridge and weight parameters", "must be finite and ≥ 0"};
        }
    }
    if (!(moistureLowPct < moistureHighPct)) {
        return Error{ErrorKind::BadInput, "moisture constraints", "low must be below high"};
    }
    if (!(alphaMax > 0 && alphaMax < 1 && radiusMax > 0 && radiusMax < alphaMax)) {
        return Error{ErrorKind::BadInput, "alphaMax", "need 0 < radiusMax < alphaMax < 1"};
    }
    if (correctionFolds < 0 || correctionFolds > 10) {
        return Error{ErrorKind::BadInput, "correctionFolds", "must lie in [0, 10]"};
    }
    if (!(shrinkValidationFraction >= 0 && shrinkValidationFraction < 0.6)) {
        return Error{ErrorKind::BadInput, "shrinkValidationFraction", "must lie in [0, 0.6)"};
    }
    if (!(realisedWeightHalfLifeSteps >= 0 && realisedWeightPriorRows >= 0 && inputRangeMargin >= 0 &&
          std::isfinite(realisedWeightHalfLifeSteps + realisedWeightPriorRows + inputRangeMargin))) {
        return Error{ErrorKind::BadInput, "realised weights",
                     "half-life, prior rows and the input range margin must be finite and ≥ 0"};
    }
    if (inputDriven) {
        return inputDrivenOptions.validate();
    }
    return {};
}

HybridPrediction HybridPrediction::unknown(std::size_t rows) {
    HybridPrediction p;
    p.xOutPct.assign(rows, kNaN);
    p.tOutC.assign(rows, kNaN);
    p.residualXPct.assign(rows, kNaN);
    p.residualTC.assign(rows, kNaN);
    return p;
}

bool observedResidual(const data::SiBatch& b, const physics::SimulationResult& pbm, std::size_t k, double& ex,
                      double& et) {
    ex = units::dryToWetPct(b.xOutDb[k]) - units::dryToWetPct(pbm.xOutDb[k]);
    et = b.tOutK[k] - pbm.tOutK[k];
    return std::isfinite(ex) && std::isfinite(et);
}

} // namespace drytwin::residual
