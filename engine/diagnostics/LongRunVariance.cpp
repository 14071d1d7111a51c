#include "diagnostics/LongRunVariance.h"

#include "diagnostics/Correlation.h"
#include "diagnostics/FftwPlanner.h"

#include <algorithm>
#include <cmath>
#include <fftw3.h>
#include <memory>

namespace drytwin::diagnostics {

namespace {

/// Direct sums up to this many products (n × lags); beyond, the FFT's O(n log n) wins.
constexpr double kDirectProducts = 1 << 17;

/// Σ_t (x_t − m)(x_{t+k} − m) for k = 0..maxLag through FFTW (Wiener-Khinchin, zero-padded so
/// that nothing wraps). Discovery asks for hundreds of windows of hundreds of lags on series of
/// 6,300 rows; summed directly they were a tenth of `drytwin discover`'s time. Round-off about
/// 1e-15 of the lag-0 sum, far below any threshold or test it feeds.
std::vector<double> laggedProductsByFft(const std::vector<double>& x, double m, int maxLag) {
    const std::size_t n = x.size();
    std::size_t size = 1;
    while (size < n + static_cast<std::size_t>(maxLag) + 1) {
        size *= 2;
    }
    const std::size_t nFreq = size / 2 + 1;
    std::unique_ptr<double, decltype(&fftw_free)> buf(fftw_alloc_real(size), &fftw_free);
    std::unique_ptr<fftw_complex, decltype(&fftw_free)> spec(fftw_alloc_complex(nFreq), &fftw_free);
    fftw_plan forward = nullptr, backward = nullptr;
    {
        std::lock_guard lock(fftwPlanMutex());
        forward = fftw_plan_dft_r2c_1d(static_cast<int>(size), buf.get(), spec.get(), FFTW_ESTIMATE);
        backward = fftw_plan_dft_c2r_1d(static_cast<int>(size), spec.get(), buf.get(), FFTW_ESTIMATE);
    }
    for (std::size_t i = 0; i < size; ++i) {
        buf.get()[i] = i < n ? x[i] - m : 0.0;
    }
    fftw_execute(forward);
    for (std::size_t k = 0; k < nFreq; ++k) {
        auto& c = spec.get()[k];
        c[0] = c[0] * c[0] + c[1] * c[1];
        c[1] = 0;
    }
    fftw_execute(backward); // unnormalised: size times the lagged sums
    std::vector<double> out(static_cast<std::size_t>(maxLag) + 1);
    for (std::size_t k = 0; k < out.size(); ++k) {
        out[k] = buf.get()[k] / static_cast<double>(size);
    }
    {
        std::lock_guard lock(fftwPlanMutex());
        fftw_destroy_plan(forward);
        fftw_destroy_plan(backward);
    }
    return out;
}

double meanOf(const std::vector<double>& x) {
    double m = 0;
    for (double v : x) {
        m += v;
    }
    return m / static_cast<double>(x.size());
}

} // namespace

double longRunVariance(const std::vector<double>& x, int lag, bool demean) {
    const std::size_t n = x.size();
    if (n == 0) {
        return 0;
    }
    const double m = demean ? meanOf(x) : 0.0;
    const int summed = std::max(0, std::min(lag, static_cast<int>(n) - 1)); // lags that exist
    // Σ_t (x_t − m)(x_{t+l} − m) for l = 0..summed: directly while cheap, by FFT beyond.
    std::vector<double> sums;
    if (static_cast<double>(n) * (summed + 1) > kDirectProducts) {
        sums = laggedProductsByFft(x, m, summed);
    } else {
        sums.resize(static_cast<std::size_t>(summed) + 1);
        for (std::size_t k = 0; k < sums.size(); ++k) {
            double s = 0;
            for (std::size_t t = k; t < n; ++t) {
                s += (x[t] - m) * (x[t - k] - m);
            }
            sums[k] = s;
        }
    }
    double v = sums[0] / static_cast<double>(n);
    for (int l = 1; l <= summed; ++l) {
        v += 2.0 * (1.0 - static_cast<double>(l) / (lag + 1)) *
             (sums[static_cast<std::size_t>(l)] / static_cast<double>(n));
    }
    return std::max(v, 0.0);
}

int bandwidthFromAutocorrelation(const std::vector<double>& x, double threshold, int maxLag) {
    maxLag = std::max(1, std::min(maxLag, static_cast<int>(x.size()) / 2));
    // Summed directly up to the first lag below the threshold while that is cheap (discovery asks
    // for this thousands of times; most white-ish series stop within a few lags), by FFT beyond.
    const int directLags =
        std::min(maxLag, std::max(1, static_cast<int>(kDirectProducts / std::max<std::size_t>(1, x.size()))));
    const auto acf = autocorrelation(x, directLags, threshold);
    for (int l = 1; l < static_cast<int>(acf.size()); ++l) {
        if (!(std::abs(acf[static_cast<std::size_t>(l)]) >= threshold)) {
            return l;
        }
    }
    if (directLags == maxLag) {
        return maxLag;
    }
    const auto sums = laggedProductsByFft(x, meanOf(x), maxLag);
    for (int l = directLags + 1; l <= maxLag; ++l) {
        if (!(std::abs(sums[static_cast<std::size_t>(l)] / sums[0]) >= threshold)) {
            return l;
        }
    }
    return maxLag;
}

} // namespace drytwin::diagnostics
