#include "diagnostics/WelchPsd.h"

#include "diagnostics/FftwPlanner.h"

#include <cmath>
#include <fftw3.h>
#include <memory>
#include <mutex>

namespace drytwin::diagnostics {

namespace {
constexpr double kPi = 3.141592653589793238462643383279502884;
} // namespace

std::mutex& fftwPlanMutex() {
    static std::mutex m; // FFTW's planner is not thread-safe; execution is.
    return m;
}

Status WelchOptions::validate() const {
    if (!(sampleRateHz > 0 && std::isfinite(sampleRateHz))) {
        return Error{ErrorKind::BadInput, "sampleRateHz", "must be a positive number of Hz"};
    }
    if (segmentLength < 4) {
        return Error{ErrorKind::BadInput, "segmentLength", "must be at least 4 samples"};
    }
    if (overlap < 0 || overlap >= segmentLength) {
        return Error{ErrorKind::BadInput, "overlap", "must lie in [0, segmentLength)"};
    }
    return {};
}

Expected<Psd> welchPsd(const std::vector<double>& x, const WelchOptions& options) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    const auto nper = static_cast<std::size_t>(options.segmentLength);
    const auto step = nper - static_cast<std::size_t>(options.overlap);
    if (x.size() < nper) {
        return Error{ErrorKind::BadInput, "welchPsd",
                     "series of " + std::to_string(x.size()) + " samples is shorter than one segment (" +
                         std::to_string(nper) + ")"};
    }
    for (double v : x) {
        if (!std::isfinite(v)) {
            return Error{ErrorKind::BadInput, "welchPsd", "the series holds NaN or infinite values"};
        }
    }
    // Periodic Hann window (scipy.signal.get_window('hann', n)).
    std::vector<double> window(nper);
    double windowPower = 0;
    for (std::size_t i = 0; i < nper; ++i) {
        window[i] = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / static_cast<double>(nper));
        windowPower += window[i] * window[i];
    }
    const double scale = 1.0 / (options.sampleRateHz * windowPower);
    const std::size_t nFreq = nper / 2 + 1;

    std::unique_ptr<double, decltype(&fftw_free)> in(fftw_alloc_real(nper), &fftw_free);
    std::unique_ptr<fftw_complex, decltype(&fftw_free)> out(fftw_alloc_complex(nFreq), &fftw_free);
    fftw_plan plan = nullptr;
    {
        std::lock_guard lock(fftwPlanMutex());
        plan = fftw_plan_dft_r2c_1d(static_cast<int>(nper), in.get(), out.get(), FFTW_ESTIMATE);
    }
    Psd psd;
    psd.density.assign(nFreq, 0.0);
    const std::size_t nSeg = (x.size() - nper) / step + 1;
    for (std::size_t s = 0; s < nSeg; ++s) {
        const double* seg = x.data() + s * step;
        double m = 0;
        for (std::size_t i = 0; i < nper; ++i) {
            m += seg[i];
        }
        m /= static_cast<double>(nper);
        for (std::size_t i = 0; i < nper; ++i) {
            in.get()[i] = (seg[i] - m) * window[i];
        }
        fftw_execute(plan);
        for (std::size_t k = 0; k < nFreq; ++k) {
            const double re = out.get()[k][0];
            const double im = out.get()[k][1];
            psd.density[k] += (re * re + im * im) * scale;
        }
    }
    {
        std::lock_guard lock(fftwPlanMutex());
        fftw_destroy_plan(plan);
    }
    for (std::size_t k = 0; k < nFreq; ++k) {
        psd.density[k] /= static_cast<double>(nSeg);
        // One-sided: double all but DC and (for even lengths) Nyquist.
        const bool nyquist = (nper % 2 == 0) && k == nFreq - 1;
        if (k != 0 && !nyquist) {
            psd.density[k] *= 2.0;
        }
    }
    psd.frequencyHz.resize(nFreq);
    for (std::size_t k = 0; k < nFreq; ++k) {
        psd.frequencyHz[k] = static_cast<double>(k) * options.sampleRateHz / static_cast<double>(nper);
    }
    return psd;
}

double lowFrequencyShare(const Psd& psd, double cutoffHz) {
    double low = 0;
    double total = 0;
    for (std::size_t k = 0; k < psd.density.size(); ++k) {
        total += psd.density[k];
        if (psd.frequencyHz[k] <= cutoffHz) {
            low += psd.density[k];
        }
    }
    return total > 0 ? low / total : std::nan("");
}

} // namespace drytwin::diagnostics
