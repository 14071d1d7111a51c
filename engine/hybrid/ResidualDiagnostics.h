#pragma once

#include "hybrid/Evaluation.h"
#include "hybrid/HybridModel.h"

#include <complex>
#include <string>
#include <vector>

namespace drytwin::hybrid {

/// @brief Diagnostics of one model's held-out moisture residual (paper Fig. 4).
struct ModelResidualDiagnostics {
    std::string name;        ///< model key
    std::vector<double> acf; ///< autocorrelation at lags 0..40
    bool hasPsd = false;     ///< false when the series is too short for Welch's method
    std::vector<double> psdFrequencyHz;
    std::vector<double> psdDensity;          ///< (% wb)²/Hz
    double lowFrequencyShareBelow0p01Hz = 0; ///< share of the residual's power below 0.01 Hz
};

/// @brief Eigenvalues of a state matrix with their contraction rates (paper Fig. 6).
struct EigenSpectrum {
    std::vector<std::complex<double>> eigenvalues;
    std::vector<double> contractionRatePerStep; ///< −ln|λ|; infinite for λ = 0
    double spectralRadius = 0;
};

/// @brief Residual diagnostics of an evaluation, as data for plots and reports.
struct ResidualDiagnostics {
    std::vector<ModelResidualDiagnostics> models;
    bool hasPgrlCcEigenvalues = false;
    EigenSpectrum pgrlCcBefore; ///< A fitted without the stability constraint
    EigenSpectrum pgrlCcAfter;  ///< A as used
};

/// @brief ACF and Welch PSD of every evaluated model's held-out moisture residual and, when the
/// model holds PGRL-CC, the eigenvalues of A before and after the stability constraint.
ResidualDiagnostics residualDiagnostics(const evaluation::EvaluationResult& evaluation,
                                        const HybridModel& model);

} // namespace drytwin::hybrid
