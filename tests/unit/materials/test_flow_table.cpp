// Tabulated flow curves (materials/j2/flow_table.hpp, theory.md eqs. 7.2-4 and 7.2-5):
// - a rate's position among the rates: linear between them, clamped outside;
// - the table on the union of its curves' points equals the blend of the curves evaluated on
//   their own points, inside them and past their last points, on a scalar and on every lane.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "fpmshell/materials/j2/flow_table.hpp"

using namespace fpmshell;

TEST(FlowTable, ARatePositionIsLinearBetweenTheRatesAndClampedOutside) {
    const std::vector<Real> rates{1e-3, 1.0, 100.0};
    EXPECT_EQ(rate_position(rates, 0.0), 0.0);
    EXPECT_EQ(rate_position(rates, 1e-3), 0.0);
    EXPECT_DOUBLE_EQ(rate_position(rates, 0.5005), 0.5);
    EXPECT_EQ(rate_position(rates, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(rate_position(rates, 25.75), 1.25);
    EXPECT_EQ(rate_position(rates, 100.0), 2.0);
    EXPECT_EQ(rate_position(rates, 1e9), 2.0);
    EXPECT_EQ(rate_position({0.0}, 50.0), 0.0);  // one curve: always it
}

TEST(FlowTable, TheTableIsTheBlendOfItsCurvesEverywhere) {
    const std::vector<PiecewiseLinearCurve> curves{
        PiecewiseLinearCurve({0.0, 0.01, 0.05, 0.2}, {200.0, 260.0, 300.0, 330.0}),
        PiecewiseLinearCurve({0.0, 0.03, 0.1}, {240.0, 320.0, 360.0}),
        PiecewiseLinearCurve({0.0, 0.002, 0.3}, {300.0, 330.0, 450.0})};
    const FlowTable table(curves, {0.0, 10.0, 1000.0});
    ASSERT_EQ(table.size(), 3U);
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> strain(0.0, 0.5), position(0.0, 2.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const Real alpha = trial % 7 == 0 ? 0.05 : strain(rng);  // sometimes on a point
        const Real u = trial % 5 == 0 ? std::floor(position(rng) + 0.5) : position(rng);
        const auto k = static_cast<std::size_t>(std::min(u, 1.0));
        const Real w = u - static_cast<Real>(k);
        const FlowValue<Real> a = curves[k].at(alpha), b = curves[k + 1].at(alpha);
        const FlowValue<Real> t = table.at(alpha, u);
        // the same straight lines from other points: equal to rounding
        EXPECT_NEAR(t.value, (1 - w) * a.value + w * b.value, 1e-12 * 450.0)
            << "alpha " << alpha << " u " << u;
        EXPECT_NEAR(t.slope, (1 - w) * a.slope + w * b.slope, 1e-9 * 6000.0);
    }
    // every lane of a pack as its scalar
    const RealPack alpha([](auto l) { return 0.04 * static_cast<Real>(l); });
    const RealPack u([](auto l) { return 0.27 * static_cast<Real>(l); });
    const FlowValue<RealPack> p = table_flow(table, alpha, u);
    for (int l = 0; l < k_lanes; ++l) {
        const FlowValue<Real> s = table.at(lane(alpha, l), lane(u, l));
        EXPECT_EQ(lane(p.value, l), s.value);
        EXPECT_EQ(lane(p.slope, l), s.slope);
    }
}
