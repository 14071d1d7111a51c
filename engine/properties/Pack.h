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
// Four parcels at once where the compiler targets AVX2 (-march=native on any x86-64 of the last
// decade): libmvec's AVX2 variants, the same accuracy as the two-lane ones.
#if DRYTWIN_HAVE_PACK2 && defined(__AVX2__)
#include <immintrin.h>
#define DRYTWIN_HAVE_PACK4 1
extern "C" __m256d _ZGVdN4v_exp(__m256d);
extern "C" __m256d _ZGVdN4v_log(__m256d);
#else
#define DRYTWIN_HAVE_PACK4 0
#endif

namespace drytwin::properties {

using Pack2 = Eigen::Array2d;
using Pack4 = Eigen::Array4d;

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
namespace detail {
/// One libmvec call for all lanes of @p x: @p Two for a Pack2, @p Four for a Pack4 (template
/// arguments, so that each call is a direct one).
template <auto Two, auto Four, class E> auto allLanes(const Eigen::ArrayBase<E>& x) {
    using Plain = typename E::PlainObject;
    Plain in = x, r;
    if constexpr (Plain::SizeAtCompileTime == 2) {
        _mm_storeu_pd(r.data(), Two(_mm_loadu_pd(in.data())));
    } else {
#if DRYTWIN_HAVE_PACK4
        static_assert(Plain::SizeAtCompileTime == 4, "packs of two or four doubles");
        _mm256_storeu_pd(r.data(), Four(_mm256_loadu_pd(in.data())));
#else
        static_assert(Plain::SizeAtCompileTime == 2, "packs of two doubles");
#endif
    }
    return r;
}
} // namespace detail

/// exp and log of a pack (or of an expression of one: templates, so that Pack2 and Pack4
/// expressions each find their own width) through libmvec, all lanes in one call.
#if DRYTWIN_HAVE_PACK4
template <class E> auto exp(const Eigen::ArrayBase<E>& x) {
    return detail::allLanes<_ZGVbN2v_exp, _ZGVdN4v_exp>(x);
}
template <class E> auto log(const Eigen::ArrayBase<E>& x) {
    return detail::allLanes<_ZGVbN2v_log, _ZGVdN4v_log>(x);
}
#else
template <class E> auto exp(const Eigen::ArrayBase<E>& x) {
    return detail::allLanes<_ZGVbN2v_exp, nullptr>(x);
}
template <class E> auto log(const Eigen::ArrayBase<E>& x) {
    return detail::allLanes<_ZGVbN2v_log, nullptr>(x);
}
#endif
template <class E> auto maxOf(const Eigen::ArrayBase<E>& a, double b) {
    return typename E::PlainObject(a.max(b));
}
template <class E> auto minOf(const Eigen::ArrayBase<E>& a, double b) {
    return typename E::PlainObject(a.min(b));
}
template <class E, class F> auto ifPositive(const Eigen::ArrayBase<E>& x, const Eigen::ArrayBase<F>& value) {
    return typename E::PlainObject((x > 0.0).select(value, 0.0));
}
#endif

} // namespace math
} // namespace drytwin::properties
