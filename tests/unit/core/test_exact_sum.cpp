// core/exact_sum.hpp: the sum is the exact sum rounded once, whatever the order and grouping.
// Reference for random terms: terms k 2^-40 with integers |k| < 2^60 add exactly in __int128,
// whose conversion to double rounds once to nearest, ties to even (as ExactSum::value must).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "fpmshell/core/exact_sum.hpp"

using fpmshell::ExactSum;

namespace {

__extension__ typedef __int128 Int128;

double exact_sum(const std::vector<double>& terms) {
    ExactSum s;
    for (double x : terms) s.add(x);
    return s.value();
}

}  // namespace

TEST(ExactSum, CancellationAndRoundingCases) {
    EXPECT_EQ(exact_sum({1e308, 1.0, -1e308}), 1.0);                     // a plain sum gives 0
    EXPECT_EQ(exact_sum(std::vector<double>(10, 0.1)), 1.0);             // a plain sum: 1 - 2^-53
    const double u = std::ldexp(1.0, -53);                               // half an ulp of 1
    EXPECT_EQ(exact_sum({1.0, u}), 1.0);                                 // a tie: to even
    EXPECT_EQ(exact_sum({1.0 + 2 * u, u}), 1.0 + 4 * u);                 // a tie: to even, upwards
    EXPECT_EQ(exact_sum({1.0, u, std::ldexp(1.0, -106)}), 1.0 + 2 * u);  // past the tie
    EXPECT_EQ(exact_sum({1.0, -u, std::ldexp(1.0, -160)}), 1.0 - u);     // below 1: exact
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(exact_sum({tiny, tiny, tiny}), 3 * tiny);
    EXPECT_EQ(exact_sum({std::ldexp(1.0, -1022), -tiny}), std::ldexp(1.0, -1022) - tiny);
    const double big = std::numeric_limits<double>::max();
    EXPECT_EQ(exact_sum({big, big, -big}), big);
    EXPECT_EQ(exact_sum({big, big}), std::numeric_limits<double>::infinity());
    EXPECT_EQ(exact_sum({-big, -big}), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(exact_sum({3.5, -3.5}), 0.0);
    EXPECT_EQ(exact_sum({-2.0, 0.5}), -1.5);
    EXPECT_EQ(exact_sum({}), 0.0);
}

TEST(ExactSum, NanAndInfinityCombineAsIeeeAddition) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(exact_sum({1.0, inf, 5.0}), inf);
    EXPECT_EQ(exact_sum({-inf, 1e300}), -inf);
    EXPECT_TRUE(std::isnan(exact_sum({inf, 2.0, -inf})));
    EXPECT_TRUE(std::isnan(exact_sum({1.0, std::nan("")})));
    ExactSum a, b;
    a.add(inf);
    b.add(-inf);
    a.add(b);
    EXPECT_TRUE(std::isnan(a.value()));
}

TEST(ExactSum, RandomTermsGiveTheRoundedExactSumInAnyOrderAndGrouping) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<long long> k_of(-(1LL << 60), 1LL << 60);
    std::uniform_int_distribution<int> shift_of(0, 59);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<double> terms;
        Int128 reference = 0;
        const int n = 1 + trial * 5;
        for (int i = 0; i < n; ++i) {
            // integers of 1 to 60 bits: the exact sum often needs more than 53
            const long long k = k_of(rng) >> shift_of(rng);
            terms.push_back(std::ldexp(static_cast<double>(k), -40));        // exact: |k| < 2^53 or
            reference += static_cast<Int128>(std::ldexp(terms.back(), 40));  // rounded k
        }
        const double expected = std::ldexp(static_cast<double>(reference), -40);
        SCOPED_TRACE(::testing::Message() << "trial " << trial);
        EXPECT_EQ(exact_sum(terms), expected);
        std::shuffle(terms.begin(), terms.end(), rng);
        EXPECT_EQ(exact_sum(terms), expected);
        // in parts merged two ways: ExactSum::add, and the digit-wise total of digits()
        const std::size_t cut = terms.size() / 3;
        ExactSum first, second;
        for (std::size_t i = 0; i < terms.size(); ++i) (i < cut ? first : second).add(terms[i]);
        ExactSum::Digits total = first.digits();
        const ExactSum::Digits other = second.digits();
        for (std::size_t i = 0; i < total.size(); ++i) total[i] += other[i];
        EXPECT_EQ(ExactSum::from_digits(total).value(), expected);
        second.add(first);
        EXPECT_EQ(second.value(), expected);
    }
}

TEST(ExactSum, WideExponentRangeIsExact) {
    // terms from 2^-1000 to 2^1000 that cancel in pairs, around one small survivor
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> mantissa(1.0, 2.0);
    std::uniform_int_distribution<int> exponent(-1000, 1000);
    std::vector<double> terms{std::ldexp(1.0, -900) * 3.0};
    for (int i = 0; i < 500; ++i) {
        const double x = std::ldexp(mantissa(rng), exponent(rng));
        terms.push_back(x);
        terms.push_back(-x);
    }
    std::shuffle(terms.begin(), terms.end(), rng);
    EXPECT_EQ(exact_sum(terms), std::ldexp(1.0, -900) * 3.0);
}
