// Lane-generic arithmetic for the element kernels that run on k_lanes elements at once
// (vectorised across elements, not within one element). A kernel written against a
// scalar type T compiles both for T = Real (one element, the reference and fallback) and for
// T = RealPack, the widest SIMD pack of doubles of the build's instruction set (2 for plain
// x86-64, 4 for x86-64-v3, 8 for x86-64-v4: cmake/simd.cmake), from the C++ Parallelism TS v2
// <experimental/simd> that GCC's libstdc++ ships. Pack arithmetic is lane-wise IEEE: a lane
// gives what the same expression gives in scalar code, up to the a*b+c the compiler contracts
// into one FMA in one and not in the other.
#pragma once

#include <array>
#include <cmath>
#include <experimental/simd>
#include <limits>
#include <type_traits>
#include <utility>

#include "fpmshell/core/types.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace fpmshell {

namespace stdx = std::experimental;

using RealPack = stdx::native_simd<Real>;
inline constexpr int k_lanes = static_cast<int>(RealPack::size());

/// The mask type of T: bool for Real, the pack's mask for RealPack.
template <class T>
using MaskOf = decltype(std::declval<T>() < std::declval<T>());

/// The small helpers of this file are forced inline: GCC otherwise keeps some pack-valued calls
/// (a 3x3 product is 9 pack FMAs, less than the call's spills; a call to max in the return
/// mapping spills its whole register file).
#define FPMSHELL_INLINE [[gnu::always_inline]] inline

/// a where m, b elsewhere.
[[nodiscard]] FPMSHELL_INLINE Real select(bool m, Real a, Real b) { return m ? a : b; }
[[nodiscard]] FPMSHELL_INLINE RealPack select(const RealPack::mask_type& m, const RealPack& a,
                                              const RealPack& b) {
    RealPack r = b;
    stdx::where(m, r) = a;
    return r;
}
[[nodiscard]] inline bool all_lanes(bool m) { return m; }
[[nodiscard]] FPMSHELL_INLINE bool all_lanes(const RealPack::mask_type& m) {
    return stdx::all_of(m);
}
[[nodiscard]] inline bool lane(bool m, int /*l*/) { return m; }
[[nodiscard]] inline bool lane(const RealPack::mask_type& m, int l) {
    return m[static_cast<std::size_t>(l)];
}
[[nodiscard]] inline Real lane(Real v, int /*l*/) { return v; }
[[nodiscard]] inline Real lane(const RealPack& v, int l) { return v[static_cast<std::size_t>(l)]; }
inline void set_lane(Real& v, int /*l*/, Real x) { v = x; }
inline void set_lane(RealPack& v, int l, Real x) { v[static_cast<std::size_t>(l)] = x; }
[[nodiscard]] inline bool any_lane(bool m) { return m; }
[[nodiscard]] FPMSHELL_INLINE bool any_lane(const RealPack::mask_type& m) {
    return stdx::any_of(m);
}
/// Asks the cache for packs [first, first + count) ahead of their use. The empty asm
/// statement keeps the loop: GCC 12 otherwise deletes a loop of prefetches whose bound it
/// cannot fold, as a loop without side effects (-ffinite-loops, the C++ default).
inline void prefetch_packs(const RealPack* first, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        __builtin_prefetch(first + i);
        asm volatile("" : : "r"(i));
    }
}
/// Number of lanes of T.
template <class T>
inline constexpr int lanes_of = std::is_same_v<T, Real> ? 1 : k_lanes;

using std::abs;
using std::max;
using std::min;
using std::sqrt;
[[nodiscard]] FPMSHELL_INLINE RealPack max(const RealPack& a, const RealPack& b) {
    return stdx::max(a, b);
}
[[nodiscard]] FPMSHELL_INLINE RealPack min(const RealPack& a, const RealPack& b) {
    return stdx::min(a, b);
}
// GCC 12 warns of an uninitialised variable inside its own AVX-512 sqrt intrinsic once inlined
// (GCC bug 105593, fixed in GCC 13); the pragma at this call site silences that false report.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
[[nodiscard]] FPMSHELL_INLINE RealPack sqrt(const RealPack& a) { return stdx::sqrt(a); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// 1 / x and sqrt(x) on the FMA units instead of the divider, for the return mapping: its
// iterations are chains of divisions and square roots, and the divider takes an 8-lane
// division every 16 cycles and a square root every 24 (Skylake-SP), not pipelined, where the two
// FMA ports take two operations a cycle. From the 14-bit estimates of AVX-512 (vrcp14, vrsqrt14),
// two Newton steps each square the relative error (2^-28, then below 2^-53): the result is
// within 2 ulp of the correctly rounded one (tests/unit/core/test_simd.cpp), not always equal
// to it. The same operations on a scalar and on every lane of a pack, so a lane equals its
// scalar. Without AVX-512: the division and the square root.
namespace simd_detail {
/// a b + c rounded once: the residuals below need it (1 - x y rounded after the product loses
/// the bits the step corrects), whatever the compiler's contraction (sanitizer and clang builds
/// turn it off)
[[nodiscard]] FPMSHELL_INLINE Real fused(Real a, Real b, Real c) { return std::fma(a, b, c); }
/// The AVX-512 instruction itself (the refinements below run on AVX-512 only): libstdc++'s
/// stdx::fma is a generic fallback that GCC 12 leaves out of line in large callers, and a call
/// there spills every vector register of the return mapping's iterations (Johnson-Cook kernels
/// 1.6-1.8 times slower).
[[nodiscard]] FPMSHELL_INLINE RealPack fused(const RealPack& a, const RealPack& b,
                                             const RealPack& c) {
#if defined(__AVX512F__)
    if constexpr (k_lanes == 8)
        return RealPack(_mm512_fmadd_pd(static_cast<__m512d>(a), static_cast<__m512d>(b),
                                        static_cast<__m512d>(c)));
    else
        return stdx::fma(a, b, c);
#else
    return stdx::fma(a, b, c);
#endif
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE T refined_reciprocal(const T& x, const T& y0) {
    T y = y0;
    for (int i = 0; i < 2; ++i) y = fused(y, fused(-x, y, T(1.0)), y);  // e = 1 - x y -> e^2
    return y;
}
/// Goldschmidt's iteration on g ~ sqrt(x), h ~ 1 / (2 sqrt(x)) from y0 ~ 1 / sqrt(x)
template <class T>
[[nodiscard]] FPMSHELL_INLINE T refined_sqrt(const T& x, const T& y0) {
    T g = x * y0, h = 0.5 * y0;
    T r = fused(-g, h, T(0.5));
    g = fused(g, r, g);
    h = fused(h, r, h);
    r = fused(-g, h, T(0.5));
    return fused(g, r, g);
}
}  // namespace simd_detail
/// 1 / x for x finite, normal and nonzero (else unspecified), within 2 ulp.
[[nodiscard]] FPMSHELL_INLINE Real pipelined_reciprocal(Real x) {
#if defined(__AVX512F__)
    const Real y0 = _mm_cvtsd_f64(_mm_rcp14_sd(_mm_setzero_pd(), _mm_set_sd(x)));
    return simd_detail::refined_reciprocal(x, y0);
#else
    return 1.0 / x;
#endif
}
[[nodiscard]] FPMSHELL_INLINE RealPack pipelined_reciprocal(const RealPack& x) {
#if defined(__AVX512F__)
    if constexpr (k_lanes == 8)
        return simd_detail::refined_reciprocal(x,
                                               RealPack(_mm512_rcp14_pd(static_cast<__m512d>(x))));
    else
#endif
        return 1.0 / x;
}
/// sqrt(x) for x >= 0 finite (0 gives 0), within 2 ulp; below the smallest normal number the
/// estimate is taken there (the root of a subnormal is unspecified).
[[nodiscard]] FPMSHELL_INLINE Real pipelined_sqrt(Real x) {
#if defined(__AVX512F__)
    const Real floor = std::numeric_limits<Real>::min();
    const Real y0 =
        _mm_cvtsd_f64(_mm_rsqrt14_sd(_mm_setzero_pd(), _mm_set_sd(x < floor ? floor : x)));
    return simd_detail::refined_sqrt(x, y0);
#else
    return std::sqrt(x);
#endif
}
[[nodiscard]] FPMSHELL_INLINE RealPack pipelined_sqrt(const RealPack& x) {
#if defined(__AVX512F__)
    if constexpr (k_lanes == 8) {
        const RealPack floor(std::numeric_limits<Real>::min());
        return simd_detail::refined_sqrt(
            x, RealPack(_mm512_rsqrt14_pd(static_cast<__m512d>(stdx::max(x, floor)))));
    } else
#endif
        return stdx::sqrt(x);
}

/// A 3-vector of T (one per lane).
template <class T>
struct V3 {
    T x, y, z;
};
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> operator+(const V3<T>& a, const V3<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> operator-(const V3<T>& a, const V3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> operator*(const T& s, const V3<T>& a) {
    return {s * a.x, s * a.y, s * a.z};
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE T dot(const V3<T>& a, const V3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> cross(const V3<T>& a, const V3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE T squared_norm(const V3<T>& a) {
    return dot(a, a);
}

/// A 3x3 matrix of T, stored by rows.
template <class T>
struct M3 {
    std::array<V3<T>, 3> row;
};
/// A v
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> operator*(const M3<T>& a, const V3<T>& v) {
    return {dot(a.row[0], v), dot(a.row[1], v), dot(a.row[2], v)};
}
/// A^T v
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> transpose_times(const M3<T>& a, const V3<T>& v) {
    return {a.row[0].x * v.x + a.row[1].x * v.y + a.row[2].x * v.z,
            a.row[0].y * v.x + a.row[1].y * v.y + a.row[2].y * v.z,
            a.row[0].z * v.x + a.row[1].z * v.y + a.row[2].z * v.z};
}
/// A B
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> operator*(const M3<T>& a, const M3<T>& b) {
    M3<T> r;
    for (std::size_t i = 0; i < 3; ++i) r.row[i] = transpose_times(b, a.row[i]);  // row_i(A) B
    return r;
}
/// A^T B
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> transpose_times(const M3<T>& a, const M3<T>& b) {
    const V3<T> c0{a.row[0].x, a.row[1].x, a.row[2].x}, c1{a.row[0].y, a.row[1].y, a.row[2].y},
        c2{a.row[0].z, a.row[1].z, a.row[2].z};
    return {{transpose_times(b, c0), transpose_times(b, c1), transpose_times(b, c2)}};
}
/// A B^T
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> times_transpose(const M3<T>& a, const M3<T>& b) {
    M3<T> r;
    for (std::size_t i = 0; i < 3; ++i) r.row[i] = b * a.row[i];
    return r;
}

/// Component i (0, 1, 2) of v.
template <class T>
[[nodiscard]] FPMSHELL_INLINE const T& component(const V3<T>& v, std::size_t i) {
    return i == 0 ? v.x : i == 1 ? v.y : v.z;
}

// Conversions from and to the Eigen types of core/types.hpp (one element, T = Real).
[[nodiscard]] inline V3<Real> to_v3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
[[nodiscard]] inline Vec3 to_vec3(const V3<Real>& v) { return {v.x, v.y, v.z}; }
[[nodiscard]] inline M3<Real> to_m3(const Mat3& m) {
    return {{V3<Real>{m(0, 0), m(0, 1), m(0, 2)}, V3<Real>{m(1, 0), m(1, 1), m(1, 2)},
             V3<Real>{m(2, 0), m(2, 1), m(2, 2)}}};
}
[[nodiscard]] inline Mat3 to_mat3(const M3<Real>& m) {
    Mat3 r;
    r << m.row[0].x, m.row[0].y, m.row[0].z, m.row[1].x, m.row[1].y, m.row[1].z, m.row[2].x,
        m.row[2].y, m.row[2].z;
    return r;
}

}  // namespace fpmshell
