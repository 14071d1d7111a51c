#include "hybrid/ResidualDiagnostics.h"

#include "diagnostics/Correlation.h"
#include "diagnostics/Stability.h"
#include "diagnostics/WelchPsd.h"

namespace drytwin::hybrid {

namespace {

EigenSpectrum spectrum(const Eigen::MatrixXd& a) {
    EigenSpectrum s;
    s.eigenvalues = diagnostics::eigenvalues(a);
    s.contractionRatePerStep = diagnostics::contractionRates(a);
    s.spectralRadius = diagnostics::spectralRadius(a);
    return s;
}

} // namespace

ResidualDiagnostics residualDiagnostics(const evaluation::EvaluationResult& evaluation,
                                        const HybridModel& model) {
    ResidualDiagnostics d;
    for (const auto& m : evaluation.models) {
        ModelResidualDiagnostics e;
        e.name = m.name;
        e.acf = diagnostics::autocorrelation(m.moistureResidual, 40);
        if (auto psd = diagnostics::welchPsd(m.moistureResidual); psd) {
            e.hasPsd = true;
            e.psdFrequencyHz = psd->frequencyHz;
            e.psdDensity = psd->density;
            e.lowFrequencyShareBelow0p01Hz = diagnostics::lowFrequencyShare(*psd, 0.01);
        }
        d.models.push_back(std::move(e));
    }
    if (model.pgrlCc) {
        d.hasPgrlCcEigenvalues = true;
        d.pgrlCcBefore = spectrum(model.pgrlCc->aUnconstrained());
        d.pgrlCcAfter = spectrum(model.pgrlCc->a());
    }
    return d;
}

} // namespace drytwin::hybrid
