#pragma once

// Two parcels at once. The physics of Eqs. 1–19 is written once, as templates over the number
// type: `double` for one parcel (plant, tests, reference path) and `Pack2` for two parcels in
// one SSE2 register (the PBM's batched right-hand sides). exp and log of a Pack2 come from
// glibc's libmvec through its documented x86-64 vector ABI: both lanes in one call, within
// 4 ulp of the scalar functions. On other targets Pack2 is not used.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <type_traits>

#if defined(__x86_64__) && defined(__SSE2__) && defined(__GLIBC__)
#include <emmintrin.h>
#define DRYTWIN_HAVE_PACK2 1
extern "C" __m128d _ZGVbN2v_exp(__m128d);
extern "C" __m128d _ZGVbN2v_log(__m128d);
#else
#define DRYTWIN_HAVE_PACK2 0
#endif

namespace drytwin::properties {

using Pack2 = Eigen::Array2d;

/// Functions the physics templates call, for both number types.
namespace math {

inline double exp(double x) {
    return std::exp(x);
}
inline double log(double x) {
    return std::log(x);
}
inline double maxOf(double a, double b) {
    return std::max(a, b);
}
inline double minOf(double a, double b) {
    return std::min(a, b);
}
/// @p value where @p x > 0, else 0 (@p value may be NaN where x ≤ 0; it is then discarded).
inline double ifPositive(double x, double value) {
    return x > 0 ? value : 0.0;
}
/// A constant of the number type T.
template <class T> T constant(double v) {
    if constexpr (std::is_same_v<T, double>) {
        return v;
    } else {
        return T::Constant(v);
    }
}

#if DRYTWIN_HAVE_PACK2
inline Pack2 exp(const Pack2& x) {
    Pack2 r;
    _mm_storeu_pd(r.data(), _ZGVbN2v_exp(_mm_loadu_pd(x.data())));
    return r;
}
inline Pack2 log(const Pack2& x) {
    Pack2 r;
    _mm_storeu_pd(r.data(), _ZGVbN2v_log(_mm_loadu_pd(x.data())));
    return r;
}
inline Pack2 maxOf(const Pack2& a, double b) {
    return a.max(b);
}
inline Pack2 minOf(const Pack2& a, double b) {
    return a.min(b);
}
inline Pack2 ifPositive(const Pack2& x, const Pack2& value) {
    return (x > 0.0).select(value, 0.0);
}
#endif

} // namespace math
} // namespace drytwin::properties
