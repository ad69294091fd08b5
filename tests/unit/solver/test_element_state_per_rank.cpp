// ShellElements on one rank of a distributed run keeps the state of the points (and of the
// failure criteria) of the elements it computes alone: the ranks' states add up to one
// process's, and a rank reading a whole state (a restart file's pieces) keeps its own
// elements' part of it bit for bit. Its slot array keeps its own blocks' and those it receives,
// each in a place of its own, and it sums no other. Every rank's decomposition is made here in one
// process; tests/mpi/distributed_test.py runs and resumes such ranks for real.
#include <gtest/gtest.h>

#include <set>

#include "../eroding_band.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "fpmshell/solver/unit_partition.hpp"

using namespace fpmshell;

namespace {

/// The eroding band's plate (two sections of a plastic law, one of them failing by
/// Johnson-Cook damage: state per point, the law's and the damage's) stretched and bent over a
/// few steps by one process, so that its points' states differ from their initial values and
/// from element to element.
struct StrainedPlate {
    Model m = test::eroding_band_plate(20, true);  // 800 triangles: blocks, a few alone
    MeshTopology topology{m};
    ShellElements whole{m, topology};

    StrainedPlate() {
        ParticleState s;
        s.resize(m.nodes.size());
        s.x = s.x_prev = m.nodes;
        for (int step = 1; step <= 5; ++step) {
            for (std::size_t p = 0; p < s.size(); ++p) {
                const Vec3& x0 = m.nodes[p];
                s.x_prev[p] = s.x[p];
                // a stretch growing with y and a bow along x: every element strains otherwise
                s.x[p] = x0 + 4e-3 * step * Vec3(x0.x() * (1 + x0.y()), 0, x0.x() * x0.x());
                s.dtheta[p] = Vec3(0, 1e-3 * x0.x(), 0);
            }
            whole.compute(s, 0.0, 1e-6);
        }
    }
};

std::vector<DomainDecomposition> decompose_all(const StrainedPlate& p, int ranks) {
    const std::vector<Real> cost = element_costs(p.m, p.whole.assembly().blocks());
    std::vector<DomainDecomposition> d;
    for (int r = 0; r < ranks; ++r)
        d.push_back(decompose(p.m, p.topology, p.whole.assembly(), cost, r, ranks));
    return d;
}

}  // namespace

TEST(ElementStatePerRank, RanksKeepTheirElementsStateAloneAndAddUpToOneProcess) {
    if (!partitioning_available()) GTEST_SKIP() << "this build has no METIS";
    const StrainedPlate plate;
    const std::size_t whole_numbers = plate.whole.kept_state_numbers();
    ASSERT_GT(whole_numbers, 0u);
    const std::vector<char> all = plate.whole.pack_state();
    for (const int ranks : {2, 3}) {
        SCOPED_TRACE(::testing::Message() << ranks << " ranks");
        const std::vector<DomainDecomposition> d = decompose_all(plate, ranks);
        std::size_t sum = 0;
        for (const DomainDecomposition& dr : d) {
            ShellElements part(plate.m, plate.topology, make_element_group, false);
            part.set_decomposition(&dr);
            const std::size_t kept = part.kept_state_numbers();
            EXPECT_LT(kept, whole_numbers);
            sum += kept;
            // computes: exactly the elements of the rank's units
            const std::vector<Index> mine = part.computed_elements();
            std::vector<std::uint8_t> is_mine(plate.m.triangles.size(), 0);
            for (const Index e : mine) is_mine[static_cast<std::size_t>(e)] = 1;
            for (Index e = 0; e < part.size(); ++e)
                EXPECT_EQ(part.computes(e), is_mine[static_cast<std::size_t>(e)] != 0) << e;
            // reading every element's state (a restart file's pieces), a rank keeps its own:
            // its pieces are then the whole's records of its elements, bit for bit
            std::vector<std::uint8_t> seen(plate.m.triangles.size(), 0);
            part.unpack_state(all, seen);
            for (const std::uint8_t c : seen) EXPECT_EQ(c, 1);
            std::vector<char> expected;
            ShellElements only_mine(plate.m, plate.topology);  // one process, the rank's records
            only_mine.set_decomposition(&dr);
            std::vector<std::uint8_t> seen_again(plate.m.triangles.size(), 0);
            only_mine.unpack_state(all, seen_again);
            EXPECT_EQ(part.pack_state(), only_mine.pack_state());
        }
        EXPECT_EQ(sum, whole_numbers);
    }
}

TEST(ElementStatePerRank, RanksPiecesMakeTheWholeStateAgain) {
    if (!partitioning_available()) GTEST_SKIP() << "this build has no METIS";
    const StrainedPlate plate;
    const std::vector<char> all = plate.whole.pack_state();
    const std::vector<DomainDecomposition> d = decompose_all(plate, 3);
    // each rank takes the whole state, keeps its part and writes its piece; one process reads
    // the three pieces: the same records as the process that computed them
    ShellElements joined(plate.m, plate.topology);
    std::vector<std::uint8_t> seen(plate.m.triangles.size(), 0);
    for (const DomainDecomposition& dr : d) {
        ShellElements part(plate.m, plate.topology, make_element_group, false);
        part.set_decomposition(&dr);
        std::vector<std::uint8_t> read(plate.m.triangles.size(), 0);
        part.unpack_state(all, read);
        joined.unpack_state(part.pack_state(), seen);
    }
    for (const std::uint8_t c : seen) EXPECT_EQ(c, 1);
    EXPECT_EQ(joined.pack_state(), all);
    // and the state is not the initial one (the check above compares something)
    const ShellElements fresh(plate.m, plate.topology);
    EXPECT_NE(fresh.pack_state(), all);
}

TEST(ElementStatePerRank, RanksKeepTheSlotsTheyWriteAndReceiveEachInAPlaceOfItsOwn) {
    if (!partitioning_available()) GTEST_SKIP() << "this build has no METIS";
    const StrainedPlate plate;
    const std::size_t whole_slots = plate.whole.assembly().slot_numbers();
    const ElementBlocks& blocks = plate.whole.assembly().blocks();
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    for (const int ranks : {2, 3}) {
        SCOPED_TRACE(::testing::Message() << ranks << " ranks");
        for (const DomainDecomposition& dr : decompose_all(plate, ranks)) {
            ShellElements part(plate.m, plate.topology, make_element_group, false);
            part.set_decomposition(&dr);
            const CornerAssembly& a = part.assembly();
            EXPECT_LT(a.slot_numbers(), whole_slots);
            // every slot this rank writes (its elements' corners) or receives, by its place:
            // distinct places, inside the array; a block's corners where block_slots says
            std::set<std::size_t> full, places;
            for (const Index e : part.computed_elements())
                for (std::size_t k = 0; k < 3; ++k)
                    full.insert(a.full_offset(static_cast<std::size_t>(e), k));
            for (const auto& offsets : dr.slot_recv) full.insert(offsets.begin(), offsets.end());
            for (const std::size_t f : full) {
                const std::size_t at = a.stored(f);
                EXPECT_TRUE(places.insert(at).second) << "two slots at " << at;
                EXPECT_LT(at + (CornerAssembly::k_components - 1) * w, a.slot_numbers());
            }
            // every slot the rank sums from the array (after the loop) is one it writes or
            // receives
            for (const Index p : a.plan().after)
                for (const std::size_t f : a.particle_slots(static_cast<std::size_t>(p)))
                    EXPECT_TRUE(full.count(f)) << "particle " << p << " sums a slot not here";
            auto& mutable_assembly = const_cast<CornerAssembly&>(a);
            for (const Index b : dr.own_blocks) {
                const auto e = static_cast<std::size_t>(
                    blocks.block_elements[static_cast<std::size_t>(b) * w + 2]);
                EXPECT_EQ(mutable_assembly.block_slots(b) + 2 - mutable_assembly.slots(),
                          static_cast<std::ptrdiff_t>(a.slot_offset(e, 0)));
            }
        }
    }
}
