// solver/range_balancer.hpp: ranges of equal measured time, changed only past the tolerance.
#include <gtest/gtest.h>

#include "fpmshell/solver/range_balancer.hpp"

using namespace fpmshell;

namespace {

/// k_steps_per_check steps of `cost` seconds per block, timed in tiles of 16 blocks within the
/// ranges `current`; the balancer's answer at the check.
std::optional<std::vector<Index>> steps_until_check(RangeBalancer& balancer,
                                                    const std::vector<Index>& current,
                                                    const std::vector<double>& cost) {
    std::optional<std::vector<Index>> out = balancer.next_ranges(current);  // sizes it
    EXPECT_FALSE(out.has_value());
    for (int step = 0; step < RangeBalancer::k_steps_per_check; ++step) {
        for (std::size_t r = 0; r + 1 < current.size(); ++r)
            for (Index b = current[r]; b < current[r + 1]; b += 16) {
                const Index end = std::min(current[r + 1], b + 16);
                double seconds = 0;
                for (Index k = b; k < end; ++k) seconds += cost[static_cast<std::size_t>(k)];
                balancer.record(b, end, seconds);
            }
        out = balancer.next_ranges(current);
        if (step + 1 < RangeBalancer::k_steps_per_check) {
            EXPECT_FALSE(out.has_value());
        }
    }
    return out;
}

}  // namespace

TEST(RangeBalancer, ExpensiveBlocksInOneRangeMoveTheCut) {
    // 320 blocks; the last 64 cost 9 times the others (a plastic zone at the end of the mesh)
    std::vector<double> cost(320, 1e-6);
    for (std::size_t b = 256; b < 320; ++b) cost[b] = 9e-6;
    RangeBalancer balancer;
    const auto ranges = steps_until_check(balancer, {0, 160, 320}, cost);
    ASSERT_TRUE(ranges.has_value());
    // total 256 + 576 = 832 units, half 416: blocks 0-255 (256) and 160 / 9 ~ 17.8 of the
    // costly ones, to a tile of 16 blocks (times are known per tile)
    EXPECT_EQ((*ranges)[0], 0);
    EXPECT_EQ((*ranges)[2], 320);
    EXPECT_GE((*ranges)[1], 256);
    EXPECT_LE((*ranges)[1], 288);
}

TEST(RangeBalancer, BalancedRangesStay) {
    std::vector<double> cost(300, 2e-6);
    cost[10] = 3e-6;  // a small unevenness, within the tolerance
    RangeBalancer balancer;
    EXPECT_FALSE(steps_until_check(balancer, {0, 100, 200, 300}, cost).has_value());
}
