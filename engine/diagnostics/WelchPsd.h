#pragma once

#include "common/Error.h"

#include <vector>

namespace drytwin::diagnostics {

/// @brief Options of Welch's method; defaults follow scipy.signal.welch with a Hann window.
struct WelchOptions {
    double sampleRateHz = 1.0;
    int segmentLength = 256; ///< nperseg
    int overlap = 128;       ///< noverlap
    Status validate() const;
};

/// @brief One-sided power spectral density (density scaling, constant detrend per segment,
/// periodic Hann window, mean over segments), as scipy.signal.welch.
struct Psd {
    std::vector<double> frequencyHz;
    std::vector<double> density; ///< [unit²/Hz]
};

/// @brief Welch PSD of @p x. Fails when the series is shorter than one segment or holds NaN.
/// FFTs by FFTW; thread-safe (FFTW planning is serialised internally).
Expected<Psd> welchPsd(const std::vector<double>& x, const WelchOptions& options = {});

/// @brief Share of the total power below @p cutoffHz (0..1): the paper's "low-frequency energy".
double lowFrequencyShare(const Psd& psd, double cutoffHz);

} // namespace drytwin::diagnostics
