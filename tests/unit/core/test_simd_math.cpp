// vector_log, vector_exp and vector_pow (core/simd_math.hpp) against libm, over the range of
// doubles they take, and every lane of a pack against the same function on a scalar.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "fpmshell/core/simd_math.hpp"
#include "ulps.hpp"

using namespace fpmshell;

namespace {

using test::ulps;

}  // namespace

TEST(SimdMath, LogWithinTwoUlpOfLibm) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<Real> exponent(-1000.0, 1000.0), near_one(0.5, 2.0);
    Real worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const Real x = std::pow(2.0, exponent(rng)) * near_one(rng);  // 2^-1000 ... 2^1000
        worst = std::max(worst, ulps(vector_log(x), std::log(x)));
        const Real y = near_one(rng);  // around 1, where ln x is small
        if (y != 1.0) worst = std::max(worst, ulps(vector_log(y), std::log(y)));
    }
    EXPECT_LE(worst, 2.0);
    EXPECT_EQ(vector_log(1.0), 0.0);
    EXPECT_NEAR(vector_log(std::numeric_limits<Real>::min()), -708.3964185322641, 1e-12);
}

TEST(SimdMath, ExpWithinTwoUlpOfLibmAndZeroBelowRange) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<Real> x_of(-708.0, 709.0), small(-1.0, 1.0);
    Real worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const Real x = x_of(rng), y = small(rng);
        worst = std::max(worst, ulps(vector_exp(x), std::exp(x)));
        worst = std::max(worst, ulps(vector_exp(y), std::exp(y)));
    }
    EXPECT_LE(worst, 2.0);
    EXPECT_EQ(vector_exp(0.0), 1.0);
    EXPECT_EQ(vector_exp(-800.0), 0.0);
}

TEST(SimdMath, PowOfTheFlowCurves) {
    // alpha^n and alpha^(n-1) of a Johnson-Cook curve: relative 1e-15 of libm (the error of ln
    // times |n ln alpha| <= 300, plus that of exp)
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<Real> log10_alpha(-12.0, 0.5), n_of(0.05, 2.0);
    for (int i = 0; i < 20000; ++i) {
        const Real alpha = std::pow(10.0, log10_alpha(rng)), n = n_of(rng);
        for (Real e : {n, n - 1.0}) {
            const Real ref = std::pow(alpha, e);
            EXPECT_NEAR(vector_pow(alpha, e), ref, 1e-14 * ref) << alpha << " ^ " << e;
        }
    }
}

TEST(SimdMath, EveryLaneEqualsItsScalar) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<Real> exponent(-700.0, 700.0), x_of(-700.0, 700.0);
    for (int trial = 0; trial < 1000; ++trial) {
        RealPack positive, any, power;
        for (std::size_t l = 0; l < RealPack::size(); ++l) {
            positive[l] = std::exp(exponent(rng));
            any[l] = x_of(rng);
            power[l] = 0.01 * x_of(rng);
        }
        const RealPack ln = vector_log(positive), ex = vector_exp(any),
                       pw = vector_pow(positive, power);
        for (std::size_t l = 0; l < RealPack::size(); ++l) {
            EXPECT_EQ(ln[l], vector_log(Real{positive[l]}));
            EXPECT_EQ(ex[l], vector_exp(Real{any[l]}));
            EXPECT_EQ(pw[l], vector_pow(Real{positive[l]}, Real{power[l]}));
        }
    }
}
