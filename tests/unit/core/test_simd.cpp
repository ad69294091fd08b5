// pipelined_reciprocal and pipelined_sqrt (core/simd.hpp) against the correctly rounded 1 / x
// and sqrt(x) over the range of doubles the return mapping gives them, and every lane of a pack
// against the same function on a scalar.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "fpmshell/core/simd.hpp"
#include "ulps.hpp"

using namespace fpmshell;

namespace {

using test::ulps;

/// 2^-1000 ... 2^1000 times [1, 2), either sign when `negative`.
template <class Check>
void over_the_doubles(unsigned seed, bool negative, const Check& check) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<Real> exponent(-1000.0, 1000.0), mantissa(1.0, 2.0);
    for (int i = 0; i < 200000; ++i) {
        const Real x = std::ldexp(mantissa(rng), static_cast<int>(exponent(rng)));
        check(negative && i % 2 ? -x : x);
    }
}

}  // namespace

// 2 ulp: the bound of the two Newton steps from the 14-bit estimate (core/simd.hpp); a correctly
// rounded division would give 0.5, the one-step scheme about 2^14.
TEST(PipelinedReciprocal, WithinTwoUlpOfTheDivision) {
    Real worst = 0;
    int inexact = 0;
    over_the_doubles(7, true, [&](Real x) {
        const Real r = pipelined_reciprocal(x);
        worst = std::max(worst, ulps(r, 1.0 / x));
        inexact += r != 1.0 / x;
    });
    EXPECT_LE(worst, 2.0);
    EXPECT_LT(inexact, 20000);  // most results are the correctly rounded ones (about 0.1 % differ)
    EXPECT_EQ(pipelined_reciprocal(1.0), 1.0);
    EXPECT_EQ(pipelined_reciprocal(4.0), 0.25);
}

TEST(PipelinedSqrt, WithinTwoUlpOfTheSquareRootAndZeroAtZero) {
    Real worst = 0;
    over_the_doubles(
        11, false, [&](Real x) { worst = std::max(worst, ulps(pipelined_sqrt(x), std::sqrt(x))); });
    EXPECT_LE(worst, 2.0);
    EXPECT_EQ(pipelined_sqrt(0.0), 0.0);
    EXPECT_EQ(static_cast<Real>(pipelined_sqrt(RealPack(0.0))[0]), 0.0);
    EXPECT_EQ(pipelined_sqrt(4.0), 2.0);
}

TEST(PipelinedDivision, EveryLaneEqualsItsScalar) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<Real> exponent(-300.0, 300.0), mantissa(1.0, 2.0);
    for (int i = 0; i < 20000; ++i) {
        RealPack x;
        for (int l = 0; l < k_lanes; ++l)
            set_lane(x, l, std::ldexp(mantissa(rng), static_cast<int>(exponent(rng))));
        const RealPack r = pipelined_reciprocal(x), s = pipelined_sqrt(x);
        for (int l = 0; l < k_lanes; ++l) {
            ASSERT_EQ(lane(r, l), pipelined_reciprocal(lane(x, l)));
            ASSERT_EQ(lane(s, l), pipelined_sqrt(lane(x, l)));
        }
    }
}
