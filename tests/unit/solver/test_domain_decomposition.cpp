// solver/domain_decomposition.hpp: what each rank of a distributed run computes and exchanges.
// Every rank's decomposition is made here in one process, and checked against the others: each
// unit and atom on one rank, each particle owned once and held by the ranks of its elements,
// the two exchanges matched message for message, and every position a held particle's normal
// reads either held or received. (tests/mpi/distributed_test.py runs them on real ranks.)
#include <gtest/gtest.h>

#include <set>

#include "../one_section_model.hpp"
#include "fpmshell/core/communicator.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "fpmshell/solver/unit_partition.hpp"

using namespace fpmshell;

namespace {

Model plate(Index n) { return test::alternate_plate(n); }

/// The decompositions of every rank of `ranks`.
std::vector<DomainDecomposition> decompose_all(const Model& m, const MeshTopology& topology,
                                               const ShellElements& elements, int ranks) {
    std::vector<DomainDecomposition> out;
    const std::vector<Real> cost = element_costs(m, elements.assembly().blocks());
    for (int r = 0; r < ranks; ++r)
        out.push_back(decompose(m, topology, elements.assembly(), cost, r, ranks));
    return out;
}

/// Every message of one exchange (peers, sends, receives: members of DomainDecomposition) is
/// what its peer expects: r's send to s is s's receive from r, and the other way.
template <class Peers, class Lists>
void expect_matched(const std::vector<DomainDecomposition>& d, Peers peers, Lists send,
                    Lists recv) {
    for (const DomainDecomposition& r : d)
        for (std::size_t k = 0; k < (r.*peers).size(); ++k) {
            const DomainDecomposition& s = d[static_cast<std::size_t>((r.*peers)[k])];
            const auto it = std::find((s.*peers).begin(), (s.*peers).end(), r.rank);
            ASSERT_NE(it, (s.*peers).end());
            const auto j = static_cast<std::size_t>(it - (s.*peers).begin());
            EXPECT_EQ((r.*send)[k], (s.*recv)[j]);
            EXPECT_EQ((r.*recv)[k], (s.*send)[j]);
        }
}

}  // namespace

TEST(DomainDecomposition, OneRankHoldsAndOwnsEverythingAndExchangesNothing) {
    const Model m = plate(12);
    const MeshTopology topology(m);
    const ShellElements elements(m, topology);
    const DomainDecomposition d = decompose_all(m, topology, elements, 1)[0];
    EXPECT_FALSE(d.distributed());
    EXPECT_EQ(static_cast<Index>(d.own_blocks.size()), elements.assembly().blocks().n_blocks());
    EXPECT_EQ(d.held_particles.size(), m.nodes.size());
    EXPECT_TRUE(d.held_not_owned.empty());
    EXPECT_TRUE(d.slot_peers.empty());
    EXPECT_TRUE(d.position_peers.empty());
    // the atoms' particles: every particle once
    std::vector<int> seen(m.nodes.size(), 0);
    for (const Index a : d.own_atoms)
        for (Index k = d.atom_particle_begin[static_cast<std::size_t>(a)];
             k < d.atom_particle_begin[static_cast<std::size_t>(a) + 1]; ++k)
            ++seen[static_cast<std::size_t>(d.atom_particles[static_cast<std::size_t>(k)])];
    for (const int s : seen) EXPECT_EQ(s, 1);
}

TEST(DomainDecomposition, RanksShareTheWorkAndMatchTheirExchanges) {
    if (!partitioning_available()) GTEST_SKIP() << "this build has no METIS";
    const Model m = plate(40);  // 3 200 triangles
    const MeshTopology topology(m);
    const ShellElements elements(m, topology);
    const ElementBlocks& units = elements.assembly().blocks();
    const std::size_t np = m.nodes.size();
    for (const int ranks : {2, 3}) {
        SCOPED_TRACE(::testing::Message() << ranks << " ranks");
        const std::vector<DomainDecomposition> d = decompose_all(m, topology, elements, ranks);
        // every unit on one rank, atoms whole
        std::vector<int> computed(static_cast<std::size_t>(d[0].n_units), 0);
        for (const DomainDecomposition& r : d) {
            for (const Index b : r.own_blocks) ++computed[static_cast<std::size_t>(b)];
            for (const Index i : r.own_alone)
                ++computed[static_cast<std::size_t>(units.n_blocks() + i)];
        }
        for (const int c : computed) EXPECT_EQ(c, 1);
        for (Index u = 0; u < d[0].n_units; ++u)
            EXPECT_EQ(
                d[0].unit_rank[static_cast<std::size_t>(u)],
                d[0].atom_rank[static_cast<std::size_t>(DomainDecomposition::atom_of_unit(u))]);
        // each particle summed by one rank, and held by its owner and the ranks of its elements
        std::vector<int> summed(np, 0);
        for (const DomainDecomposition& r : d)
            for (const Index a : r.own_atoms)
                for (Index k = r.atom_particle_begin[static_cast<std::size_t>(a)];
                     k < r.atom_particle_begin[static_cast<std::size_t>(a) + 1]; ++k) {
                    const auto p =
                        static_cast<std::size_t>(r.atom_particles[static_cast<std::size_t>(k)]);
                    ++summed[p];
                    EXPECT_EQ(r.particle_owner[p], r.rank);
                    EXPECT_TRUE(r.held[p]);
                }
        for (const int s : summed) EXPECT_EQ(s, 1);
        for (std::size_t e = 0; e < m.triangles.size(); ++e) {
            const Index u = units.block_lane[e] >= 0 ? units.block_lane[e] / k_lanes
                                                     : units.n_blocks() + units.alone_position[e];
            const int r = d[0].unit_rank[static_cast<std::size_t>(u)];
            for (const Index p : m.triangles[e])
                EXPECT_TRUE(d[static_cast<std::size_t>(r)].held[static_cast<std::size_t>(p)]);
        }
        // the exchanges: what r sends to s is what s receives from r, in the same order
        expect_matched(d, &DomainDecomposition::slot_peers, &DomainDecomposition::slot_send,
                       &DomainDecomposition::slot_recv);
        expect_matched(d, &DomainDecomposition::position_peers, &DomainDecomposition::position_send,
                       &DomainDecomposition::position_recv);
        // a held particle receives every slot it does not compute: its slots = own + received
        for (const DomainDecomposition& r : d) {
            std::multiset<std::size_t> received;
            for (const auto& list : r.slot_recv) received.insert(list.begin(), list.end());
            for (std::size_t p = 0; p < np; ++p) {
                if (!r.held[p]) continue;
                const std::span<const Index> elems = topology.elements_of(static_cast<Index>(p));
                const std::span<const std::size_t> slots = elements.assembly().particle_slots(p);
                for (std::size_t j = 0; j < elems.size(); ++j) {
                    const auto e = static_cast<std::size_t>(elems[j]);
                    const Index u = units.block_lane[e] >= 0
                                        ? units.block_lane[e] / k_lanes
                                        : units.n_blocks() + units.alone_position[e];
                    if (r.own_unit[static_cast<std::size_t>(u)]) continue;
                    EXPECT_EQ(received.count(slots[j]), 1u) << "particle " << p;
                }
            }
            // every node of a triangle around a held particle is held or received
            std::set<Index> positions;
            for (const auto& list : r.position_recv) positions.insert(list.begin(), list.end());
            for (const Index e : r.near_elements)
                for (const Index p : m.triangles[static_cast<std::size_t>(e)])
                    EXPECT_TRUE(r.held[static_cast<std::size_t>(p)] || positions.count(p) == 1);
        }
    }
}

TEST(Communicator, OneRankWithoutALauncher) {
    const Communicator& c = Communicator::world();
    EXPECT_EQ(c.size(), 1);
    EXPECT_TRUE(c.root());
    ExactSum s[1];
    s[0].add(0.1);
    c.sum(s);
    EXPECT_EQ(s[0].value(), 0.1);
    EXPECT_EQ(c.min_loc(2.5, 7), (std::pair<Real, Index>{2.5, 7}));
    EXPECT_EQ(c.max(3), 3);
    EXPECT_EQ(c.gather({'a', 'b'}).size(), 1u);
}
