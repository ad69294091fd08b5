// Natural logarithm, exponential and power written once for T = Real and T = RealPack
// (core/simd.hpp), for the flow curves of the return mapping: libstdc++'s <experimental/simd>
// computes log and exp of a pack lane by lane with the scalar libm calls, which cost the
// Johnson-Cook return mapping most of its time. The same polynomial runs on a scalar and on
// every lane of a pack, so a lane equals its scalar (up to the FMA contractions of simd.hpp).
//
// Accuracy (tests/unit/core/test_simd_math.cpp): within 2 ulp of libm over the domain below.
// Domain: log of a positive normal number (zero, a subnormal, a negative number or a NaN gives
// an unspecified value); exp of x in [-708, 709] (below: 0; above: the value at 709).
#pragma once

#include <bit>
#include <cstdint>

#include "fpmshell/core/simd.hpp"

namespace fpmshell {

namespace simd_math_detail {

using IntPack = stdx::rebind_simd_t<std::int64_t, RealPack>;

[[nodiscard]] FPMSHELL_INLINE std::int64_t bits_of(Real x) {
    return std::bit_cast<std::int64_t>(x);
}
[[nodiscard]] FPMSHELL_INLINE IntPack bits_of(const RealPack& x) {
    return stdx::__proposed::simd_bit_cast<IntPack>(x);
}
[[nodiscard]] FPMSHELL_INLINE Real real_of(std::int64_t i) { return std::bit_cast<Real>(i); }
[[nodiscard]] FPMSHELL_INLINE RealPack real_of(const IntPack& i) {
    return stdx::__proposed::simd_bit_cast<RealPack>(i);
}
template <class T>
using IntOf = decltype(bits_of(std::declval<T>()));

// ln 2 split in two: k ln2_hi is exact for |k| < 2^11 (the low 11 bits of ln2_hi are zero)
inline constexpr Real k_ln2_hi = 6.93147180369123816490e-01;  // 0x3FE62E42FEE00000
inline constexpr Real k_ln2_lo = 1.90821492927058770002e-10;  // 0x3DEA39EF35793C76
inline constexpr std::int64_t k_mantissa_bits = 0x000fffffffffffffLL;
inline constexpr std::int64_t k_exponent_one = 0x3ff0000000000000LL;  // bits of 1.0

}  // namespace simd_math_detail

/// ln x for x > 0 normal. x = 2^e m with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(s),
/// s = (m - 1) / (m + 1), |s| <= 0.1716, by its Taylor series to s^21 (the next term is below
/// 2^-60 of the sum); ln x = e ln 2 + ln m.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T vector_log(const T& x) {
    using namespace simd_math_detail;
    using I = IntOf<T>;
    const I bits = bits_of(x);
    // shifts by a pack of counts: libstdc++'s shift of a simd by a scalar count gives garbage
    // when clang 14 compiles it (-O2); by a pack it is right with both compilers
    I exponent = (bits >> I(52)) - 1023;
    T m = real_of(I((bits & k_mantissa_bits) | k_exponent_one));  // [1, 2)
    const auto high = m > 1.4142135623730951;
    m = select(high, 0.5 * m, m);
    T e;
    if constexpr (std::is_same_v<T, Real>)
        e = static_cast<Real>(exponent) + (high ? 1.0 : 0.0);
    else
        e = stdx::static_simd_cast<RealPack>(exponent) + select(high, T(1.0), T(0.0));
    const T s = (m - 1.0) / (m + 1.0);
    const T w = s * s;
    // p = 1/3 + w/5 + ... + w^9/21 by Estrin's scheme (pairs, then powers w^2, w^4, w^8): a
    // shorter chain of dependent FMAs than Horner's, which bounds the iteration's latency
    const T w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
    const T q0 = 1.0 / 3.0 + w * (1.0 / 5.0), q1 = 1.0 / 7.0 + w * (1.0 / 9.0);
    const T q2 = 1.0 / 11.0 + w * (1.0 / 13.0), q3 = 1.0 / 15.0 + w * (1.0 / 17.0);
    const T q4 = 1.0 / 19.0 + w * (1.0 / 21.0);
    const T p = (q0 + w2 * q1) + w4 * (q2 + w2 * q3) + w8 * q4;
    const T log_m = 2.0 * s + (2.0 * s) * (w * p);
    return e * k_ln2_hi + (log_m + e * k_ln2_lo);
}

/// e^x: x = k ln 2 + r with k the nearest integer to x / ln 2, |r| <= ln 2 / 2; e^r by its
/// Taylor series to r^13 (the next term is below 2^-56 of e^r); 2^k put in the exponent bits.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T vector_exp(const T& x) {
    using namespace simd_math_detail;
    using I = IntOf<T>;
    const T xc = max(T(-708.0), min(x, T(709.0)));
    // round to nearest by adding 1.5 2^52: the integer k sits in the low bits of the sum
    constexpr Real shifter = 6755399441055744.0;  // 1.5 * 2^52
    const T shifted = xc * 1.4426950408889634 + shifter;
    const T k = shifted - shifter;
    const T r = (xc - k * k_ln2_hi) - k * k_ln2_lo;
    // sum of r^j / j!, j = 0 ... 13, by Estrin's scheme (as vector_log)
    const T r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const T q0 = 1.0 + r, q1 = 0.5 + r * (1.0 / 6.0);
    const T q2 = 1.0 / 24.0 + r * (1.0 / 120.0), q3 = 1.0 / 720.0 + r * (1.0 / 5040.0);
    const T q4 = 1.0 / 40320.0 + r * (1.0 / 362880.0);
    const T q5 = 1.0 / 3628800.0 + r * (1.0 / 39916800.0);
    const T q6 = 1.0 / 479001600.0 + r * (1.0 / 6227020800.0);
    const T p = ((q0 + r2 * q1) + r4 * (q2 + r2 * q3)) + r8 * ((q4 + r2 * q5) + r4 * q6);
    const I k_int = bits_of(shifted) - bits_of(T(shifter));
    const T two_k = real_of(I((k_int + 1023) << I(52)));  // a pack count, as in vector_log
    return select(x < -708.0, T(0.0), p * two_k);
}

/// 1 / sqrt(x) for x > 0 normal, with neither a division nor a square root (whose unit a pack
/// of them keeps busy for tens of cycles): a first guess from the bits of x (Lomont 2003's
/// constant for doubles, within 3.5e-2), then Newton's y <- y (3/2 - x y^2 / 2), each step
/// squaring the relative error: 1.8e-3, 4.7e-6, 3.3e-11, then rounding.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T vector_rsqrt(const T& x) {
    using namespace simd_math_detail;
    using I = IntOf<T>;
    T y = real_of(I(0x5fe6eb50c7b537a9LL) - (bits_of(x) >> I(1)));  // a pack count (vector_log)
    const T half = 0.5 * x;
    for (int k = 0; k < 4; ++k) y = y * (1.5 - half * y * y);
    return y;
}

/// x^y = e^(y ln x) for x > 0 normal (0 for x = 0 is the caller's to select).
template <class T>
[[nodiscard]] FPMSHELL_INLINE T vector_pow(const T& x, const T& y) {
    return vector_exp(y * vector_log(x));
}

}  // namespace fpmshell
