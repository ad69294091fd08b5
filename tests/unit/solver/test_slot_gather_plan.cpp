// The plan that sums each particle's corner slots as soon as its last block is done, from a ring
// of block slots (solver/slot_gather_plan.hpp):
// - the element loop's schedule replayed with a distinct value in every slot: each particle
//   sums, in element order, exactly the values its elements wrote, for 1, 2 and 3 ranges, on a
//   generated plate (most particles from the ring) and on the same plate numbered at random
//   (no ring: every particle after the loop);
// - every particle is summed exactly once; a particle with a slot of an element computed alone
//   is summed after the loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/slot_gather_plan.hpp"

using namespace fpmshell;

namespace {

constexpr auto w = static_cast<std::size_t>(k_lanes);
constexpr std::size_t group_reals = SlotGatherPlan::k_components * w;

/// The particle -> slot map of triangles all in blocks (element e in block e / k_lanes, lane
/// e % k_lanes), plus `alone` elements after them with 3 slots each; slots in element order.
struct SlotMap {
    Index n_blocks = 0;
    std::vector<Index> begin;
    std::vector<std::size_t> offset;
};

SlotMap slot_map(const std::vector<std::array<Index, 3>>& tri, Index n_particles,
                 std::size_t n_alone) {
    SlotMap m;
    const std::size_t n_blocked = (tri.size() - n_alone) / w * w;
    m.n_blocks = static_cast<Index>(n_blocked / w);
    std::vector<std::vector<std::size_t>> of(static_cast<std::size_t>(n_particles));
    for (std::size_t e = 0; e < tri.size(); ++e)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t slot = e < n_blocked ? (3 * (e / w) + k) * w + e % w
                                                   : 3 * n_blocked + 3 * (e - n_blocked) + k;
            of[static_cast<std::size_t>(tri[e][k])].push_back(slot / w * group_reals + slot % w);
        }
    m.begin.push_back(0);
    for (const auto& slots : of) {
        m.offset.insert(m.offset.end(), slots.begin(), slots.end());
        m.begin.push_back(static_cast<Index>(m.offset.size()));
    }
    return m;
}

/// Reals of the full slot array of a map without elements alone: its blocks' slots.
std::size_t block_reals(const SlotMap& m) {
    return static_cast<std::size_t>(m.n_blocks) * SlotGatherPlan::k_block_reals;
}

/// A distinct value for component c of full-array offset `at`.
Real slot_value(std::size_t at, std::size_t c) {
    return static_cast<Real>(at) + 0.125 * static_cast<Real>(c);
}

/// Replays ShellElements::compute's schedule: range by range, tile by tile, each block writes
/// its slots (ring, and the full array if kept), each tile ends with its ready particles'
/// sums; then the particles after the loop. Returns every particle's 6 sums.
std::vector<std::array<Real, 6>> replay(const SlotGatherPlan& plan, const SlotMap& m,
                                        std::size_t full_reals) {
    constexpr Index tile = SlotGatherPlan::k_tile_blocks,
                    ring_blocks = SlotGatherPlan::k_ring_blocks;
    std::vector<Real> full(full_reals, -1.0);
    for (std::size_t at = block_reals(m); at < full_reals; ++at)
        full[at] = slot_value(at / group_reals * group_reals + at % w,
                              at % group_reals / w);  // elements alone
    std::vector<std::array<Real, 6>> sums(m.begin.size() - 1, {-7, -7, -7, -7, -7, -7});
    auto sum = [&](Index p, const Real* base) {
        std::array<Real, 6> s{};
        for (Index k = m.begin[static_cast<std::size_t>(p)];
             k < m.begin[static_cast<std::size_t>(p) + 1]; ++k)
            for (std::size_t c = 0; c < 6; ++c)
                s[c] += base[plan.offset[static_cast<std::size_t>(k)] + c * w];
        sums[static_cast<std::size_t>(p)] = s;
    };
    for (std::size_t r = 0; r < static_cast<std::size_t>(plan.ranges()); ++r) {
        std::vector<Real> ring(plan.use_ring() ? plan.rings[r].size() : 0, -3.0);
        const Index first = plan.range_begin[r], end = plan.range_begin[r + 1];
        for (Index t = plan.range_first_tile[r]; t < plan.range_first_tile[r + 1]; ++t) {
            const Index from = first + (t - plan.range_first_tile[r]) * tile;
            for (Index b = from; b < std::min(end, from + tile); ++b)
                for (std::size_t k = 0; k < SlotGatherPlan::k_block_reals; ++k) {
                    const std::size_t at =
                        static_cast<std::size_t>(b) * SlotGatherPlan::k_block_reals + k;
                    const Real v =
                        slot_value(at / group_reals * group_reals + at % w, at % group_reals / w);
                    if (!plan.use_ring() || plan.keep[static_cast<std::size_t>(b)]) full[at] = v;
                    if (plan.use_ring())
                        ring[static_cast<std::size_t>((b - first) % ring_blocks) *
                                 SlotGatherPlan::k_block_reals +
                             k] = v;
                }
            for (Index k = plan.ready_begin[static_cast<std::size_t>(t)];
                 k < plan.ready_begin[static_cast<std::size_t>(t) + 1]; ++k)
                sum(plan.ready[static_cast<std::size_t>(k)], ring.data());
        }
    }
    for (Index p : plan.after) sum(p, full.data());
    return sums;
}

/// What every particle must get: the values of its own slots, in element order.
std::vector<std::array<Real, 6>> expected_sums(const SlotMap& m) {
    std::vector<std::array<Real, 6>> sums(m.begin.size() - 1);
    for (std::size_t p = 0; p + 1 < m.begin.size(); ++p) {
        std::array<Real, 6> s{};
        for (Index k = m.begin[p]; k < m.begin[p + 1]; ++k)
            for (std::size_t c = 0; c < 6; ++c)
                s[c] += slot_value(m.offset[static_cast<std::size_t>(k)], c);
        sums[p] = s;
    }
    return sums;
}

MeshData plate(Index n) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    return generate_plate(pp);
}

/// Every particle summed exactly once, from the ring or after the loop.
void expect_each_particle_once(const SlotGatherPlan& plan, std::size_t n_particles) {
    std::vector<Index> all(plan.ready);
    all.insert(all.end(), plan.after.begin(), plan.after.end());
    std::sort(all.begin(), all.end());
    std::vector<Index> each(n_particles);
    std::iota(each.begin(), each.end(), 0);
    EXPECT_EQ(all, each);
}

}  // namespace

TEST(SlotGatherPlan, EveryParticleSumsExactlyItsOwnSlotsFromTheRingForAnyRangeCount) {
    // 2 x 120^2 = 28 800 triangles, 3 600 blocks of 8: several tiles per range, and rows of
    // 240 triangles (30 blocks) between the first and the last block of a particle.
    const MeshData mesh = plate(120);
    const auto np = static_cast<Index>(mesh.nodes.size());
    const SlotMap m = slot_map(mesh.triangles, np, 0);
    for (int ranges : {1, 2, 3}) {
        SCOPED_TRACE(ranges);
        const SlotGatherPlan plan = make_slot_gather_plan(m.n_blocks, ranges, m.begin, m.offset);
        ASSERT_TRUE(plan.use_ring());
        expect_each_particle_once(plan, static_cast<std::size_t>(np));
        // the generated plate is numbered row by row: nearly every particle from the ring (the
        // others: on the seams between ranges)
        EXPECT_LT(plan.after.size(), static_cast<std::size_t>(ranges) * 2 * 130u);
        // exact equality: the same values added in the same order
        EXPECT_EQ(replay(plan, m, block_reals(m)), expected_sums(m));
    }
}

TEST(SlotGatherPlan, UnevenRangesGiveTheSameSums) {
    // the ranges a RangeBalancer sets: any contiguous cut, a range of a few blocks or none
    const MeshData mesh = plate(120);
    const auto np = static_cast<Index>(mesh.nodes.size());
    const SlotMap m = slot_map(mesh.triangles, np, 0);
    const auto expected = expected_sums(m);
    for (const std::vector<Index>& begin :
         {std::vector<Index>{0, 3, m.n_blocks}, std::vector<Index>{0, m.n_blocks - 17, m.n_blocks},
          std::vector<Index>{0, 1000, 1000, m.n_blocks},
          std::vector<Index>{0, 333, 2900, m.n_blocks}}) {
        SCOPED_TRACE(::testing::Message() << "second range from block " << begin[1]);
        const SlotGatherPlan plan = make_slot_gather_plan(begin, m.begin, m.offset);
        expect_each_particle_once(plan, static_cast<std::size_t>(np));
        EXPECT_EQ(replay(plan, m, block_reals(m)), expected);
    }
}

TEST(SlotGatherPlan, AMeshWithoutLocalityGoesWithoutTheRing) {
    MeshData mesh = plate(60);
    std::mt19937 rng(7);
    std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
    const auto np = static_cast<Index>(mesh.nodes.size());
    const SlotMap m = slot_map(mesh.triangles, np, 0);
    const SlotGatherPlan plan = make_slot_gather_plan(m.n_blocks, 2, m.begin, m.offset);
    EXPECT_FALSE(plan.use_ring());
    EXPECT_TRUE(plan.ready.empty());
    EXPECT_EQ(plan.after.size(), static_cast<std::size_t>(np));
    EXPECT_TRUE(std::all_of(plan.keep.begin(), plan.keep.end(), [](auto k) { return k == 1; }));
    EXPECT_EQ(replay(plan, m, block_reals(m)), expected_sums(m));
}

TEST(SlotGatherPlan, ParticlesOfElementsComputedAloneAreSummedAfterTheLoop) {
    const MeshData mesh = plate(40);
    const auto np = static_cast<Index>(mesh.nodes.size());
    const std::size_t n_alone = 5 + 3 * w;  // more than a block's worth, not a multiple of it
    const SlotMap m = slot_map(mesh.triangles, np, n_alone);
    const SlotGatherPlan plan = make_slot_gather_plan(m.n_blocks, 2, m.begin, m.offset);
    ASSERT_TRUE(plan.use_ring());
    expect_each_particle_once(plan, static_cast<std::size_t>(np));
    const std::size_t n_blocked = static_cast<std::size_t>(m.n_blocks) * w;
    for (std::size_t e = n_blocked; e < mesh.triangles.size(); ++e)
        for (Index p : mesh.triangles[e])
            EXPECT_NE(std::find(plan.after.begin(), plan.after.end(), p), plan.after.end())
                << "particle " << p;
    const std::size_t full_reals =
        (3 * n_blocked + 3 * (mesh.triangles.size() - n_blocked) + w - 1) / w * group_reals;
    EXPECT_EQ(replay(plan, m, full_reals), expected_sums(m));
}

TEST(SlotGatherPlan, ADistributedRunSumsItsSharedParticlesAfterAndSkipsTheOthers) {
    // the modes a DomainDecomposition gives: every third particle skipped (another rank's),
    // every fifth after the loop (shared), the rest as the plan finds
    const MeshData mesh = plate(120);
    const auto np = static_cast<std::size_t>(mesh.nodes.size());
    const SlotMap m = slot_map(mesh.triangles, static_cast<Index>(np), 0);
    std::vector<GatherMode> mode(np, GatherMode::Any);
    for (std::size_t p = 0; p < np; ++p)
        mode[p] = p % 3 == 0 ? GatherMode::Skip : p % 5 == 0 ? GatherMode::After : GatherMode::Any;
    const SlotGatherPlan plan = make_slot_gather_plan(m.n_blocks, 2, m.begin, m.offset, mode);
    ASSERT_TRUE(plan.use_ring());  // half of the summed particles from the ring still
    std::vector<int> seen(np, 0);
    for (const Index p : plan.ready) ++seen[static_cast<std::size_t>(p)];
    for (const Index p : plan.after) ++seen[static_cast<std::size_t>(p)];
    for (std::size_t p = 0; p < np; ++p) EXPECT_EQ(seen[p], mode[p] == GatherMode::Skip ? 0 : 1);
    for (const Index p : plan.ready) EXPECT_EQ(mode[static_cast<std::size_t>(p)], GatherMode::Any);
    // the sums of the particles it makes are those of a run without modes
    const auto sums = replay(plan, m, block_reals(m)), expected = expected_sums(m);
    for (std::size_t p = 0; p < np; ++p) {
        if (mode[p] == GatherMode::Skip) continue;
        EXPECT_EQ(sums[p], expected[p]) << "particle " << p;
    }
}
