// solver/unit_partition.hpp: the element loop's units cut into parts. The statistics are
// checked against a count written out here from the element parts alone; the cut against what
// any sensible cut of a square plate gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "../one_section_model.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "fpmshell/solver/unit_partition.hpp"

using namespace fpmshell;

namespace {

Model plate(Index n) { return test::alternate_plate(n); }

UnitPartition cut(const Model& m, int parts) {
    const ElementBlocks units = element_units(m);
    return partition_units(units, m.triangles, static_cast<Index>(m.nodes.size()),
                           element_costs(m, units), parts);
}

}  // namespace

TEST(UnitPartition, OnePartHoldsEverythingAndSharesNothing) {
    const Model m = plate(10);
    const UnitPartition p = cut(m, 1);
    ASSERT_EQ(p.parts.size(), 1u);
    EXPECT_EQ(p.parts[0].elements, static_cast<Index>(m.triangles.size()));
    EXPECT_EQ(p.parts[0].owned, static_cast<Index>(m.nodes.size()));
    EXPECT_EQ(p.parts[0].particles, static_cast<Index>(m.nodes.size()));
    EXPECT_EQ(p.parts[0].shared, 0);
    EXPECT_EQ(p.parts[0].remote_slots, 0);
    EXPECT_DOUBLE_EQ(p.imbalance(), 1.0);
}

TEST(UnitPartition, PartsKeepBlocksWholeAndTheirStatisticsAddUp) {
    if (!partitioning_available()) {
        const Model m = plate(4);
        EXPECT_THROW((void)cut(m, 2), std::runtime_error);
        GTEST_SKIP() << "this build has no METIS";
    }
    const Model m = plate(40);  // 3 200 triangles, 400 blocks of 8
    const ElementBlocks units = element_units(m);
    for (int parts : {2, 3, 4}) {
        SCOPED_TRACE(::testing::Message() << parts << " parts");
        const UnitPartition p = cut(m, parts);
        // a block's elements in one part
        for (Index b = 0; b < units.n_blocks(); ++b) {
            std::set<int> in;
            for (Index l = 0; l < k_lanes; ++l)
                in.insert(p.element_part[static_cast<std::size_t>(
                    units.block_elements[static_cast<std::size_t>(b * k_lanes + l)])]);
            EXPECT_EQ(in.size(), 1u) << "block " << b;
        }
        // the statistics from the element parts, counted here
        std::vector<std::vector<int>> corners(m.nodes.size(), std::vector<int>(parts, 0));
        for (std::size_t e = 0; e < m.triangles.size(); ++e)
            for (Index n : m.triangles[e])
                ++corners[static_cast<std::size_t>(n)][static_cast<std::size_t>(p.element_part[e])];
        Index owned = 0, elements = 0;
        for (int q = 0; q < parts; ++q) {
            Index local = 0, shared = 0, remote = 0;
            for (const auto& c : corners) {
                const int all = std::accumulate(c.begin(), c.end(), 0);
                const int mine = c[static_cast<std::size_t>(q)];
                if (mine == 0) continue;
                ++local;
                if (all > mine) {
                    ++shared;
                    remote += all - mine;
                }
            }
            const UnitPartition::Part& part = p.parts[static_cast<std::size_t>(q)];
            EXPECT_EQ(part.particles, local);
            EXPECT_EQ(part.shared, shared);
            EXPECT_EQ(part.remote_slots, remote);
            EXPECT_GT(part.elements, 0);
            owned += part.owned;
            elements += part.elements;
        }
        EXPECT_EQ(owned, static_cast<Index>(m.nodes.size()));
        EXPECT_EQ(elements, static_cast<Index>(m.triangles.size()));
        // an owner holds the particle: the part of its lowest element
        for (std::size_t n = 0; n < m.nodes.size(); ++n)
            EXPECT_GT(corners[n][static_cast<std::size_t>(p.particle_owner[n])], 0);
        // METIS balances the cost to its default tolerance (3 %) plus one block of 400 / parts
        EXPECT_LT(p.imbalance(), 1.03 + static_cast<Real>(parts) / 400.0 + 1e-9);
        // a good cut of a 40 x 40 plate: straight cuts share about 41 particles each, and a
        // part of 4 has at most 2 of them per neighbour; a scattered cut shares hundreds
        Index shared = 0;
        for (const auto& part : p.parts) shared += part.shared;
        EXPECT_LT(shared, 2 * 41 * 2 * (parts - 1) + 1);
        // the same parts every time (a fixed seed)
        EXPECT_EQ(cut(m, parts).unit_part, p.unit_part);
    }
}

TEST(UnitPartition, PlasticAndLoneElementsCostMore) {
    Model m = plate(3);                   // 18 triangles
    m.sections.push_back(m.sections[0]);  // element 0 alone in a section of its own: no block
    m.element_section[0] = 1;
    const ElementBlocks units = element_units(m);
    const std::vector<Real> elastic = element_costs(m, units);
    make_bilinear(m.materials[0], 250e6, 0.0);
    const std::vector<Real> plastic = element_costs(m, units);
    EXPECT_GT(units.n_alone(), 0);
    for (std::size_t e = 0; e < elastic.size(); ++e) {
        EXPECT_DOUBLE_EQ(plastic[e], 2.0 * elastic[e]);
        // 2 x 3 points: 6 / 15 of a 5 x 3 section, four times that alone
        EXPECT_DOUBLE_EQ(elastic[e], (units.block_lane[e] < 0 ? 4.0 : 1.0) * 6.0 / 15.0);
    }
}
