// The edge criterion of particle separation (solver/edge_opening.hpp, theory.md eq. 7.7-1) on a
// plate of 2 x 2 squares: a failed element opens the side its membrane force pulls hardest
// across, among the sides that reach the boundary; never a side in compression, never at a
// pinned particle; no element is cut out of the sheet; choices open by traction.
#include <gtest/gtest.h>

#include <functional>

#include "../one_section_model.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/edge_opening.hpp"

namespace fpmshell {
namespace {

struct Plate {
    Model model;
    MeshTopology topology;
    std::vector<std::uint8_t> pinned;
    std::function<bool(Index)> failed = [](Index) { return false; };
    Plate() : model(make()), topology(model), pinned(model.nodes.size(), 0) {}
    static Model make() {
        PlateParams pp;
        pp.nx = pp.ny = 2;
        return test::one_section_model(generate_plate(pp), 0.01);
    }
    [[nodiscard]] EdgeOpening::Mesh mesh() const {
        return {model.triangles, topology, model.nodes, pinned, failed};
    }
};

TEST(EdgeOpening, AnElementOpensTheSideItsTensionPullsHardestAcross) {
    const Plate plate;
    const EdgeOpening opening(plate.model.n_elements());
    // every element of this plate has a corner on the boundary: each has candidates
    for (Index e = 0; e < plate.model.n_elements(); ++e) {
        // N in the element's frame, x along its side from corner 0 to corner 1 (its side 2):
        // tension across that side (N_yy) pulls across it with traction N_yy, across the others
        // less; every side of this plate has an end on the boundary, so each is a candidate
        const Index across_first =
            plate.topology.side_neighbour[3 * static_cast<std::size_t>(e) + 2];
        const EdgeOpening::Choice c = opening.side_to_open(plate.mesh(), e, Voigt3(0, 1e5, 0));
        // (unless e or the element across has a single shared side: opening it would cut that
        // element out of the sheet)
        const auto shared_sides = [&](Index f) {
            int n = 0;
            for (std::size_t i = 0; i < 3; ++i)
                n += plate.topology.side_neighbour[3 * static_cast<std::size_t>(f) + i] >= 0;
            return n;
        };
        if (across_first >= 0 && shared_sides(e) >= 2 && shared_sides(across_first) >= 2) {
            EXPECT_EQ(c.across, across_first) << "element " << e;
            EXPECT_NEAR(c.traction, 1e5, 1e-6);
        } else {
            EXPECT_TRUE(c.across < 0 || c.across != across_first) << "element " << e;
            EXPECT_LT(c.traction, 1e5);
        }
        // in compression it waits
        EXPECT_LT(opening.side_to_open(plate.mesh(), e, Voigt3(-1e5, -1e5, 0)).across, 0);
    }
    // equibiaxial tension: every side carries the same traction; the first in corner order wins
    const EdgeOpening::Choice c = opening.side_to_open(plate.mesh(), 0, Voigt3(1e5, 1e5, 0));
    ASSERT_GE(c.across, 0);
    EXPECT_NEAR(c.traction, 1e5, 1e-6);
}

TEST(EdgeOpening, PinnedParticlesNeverSplit) {
    Plate plate;
    const EdgeOpening opening(plate.model.n_elements());
    for (auto& p : plate.pinned) p = 1;
    for (Index e = 0; e < plate.model.n_elements(); ++e)
        EXPECT_LT(opening.side_to_open(plate.mesh(), e, Voigt3(1e5, 1e5, 0)).across, 0);
}

TEST(EdgeOpening, NoElementIsCutOutOfTheSheet) {
    const Plate plate;
    EdgeOpening opening(plate.model.n_elements());
    const EdgeOpening::Mesh mesh = plate.mesh();
    // open sides in order of traction until nothing more may open: every element keeps a
    // closed side shared with another element and borders two open sides at most
    for (int round = 0; round < 10; ++round) {
        std::vector<Real> choices;
        for (Index e = 0; e < plate.model.n_elements(); ++e) {
            const EdgeOpening::Choice c = opening.side_to_open(mesh, e, Voigt3(1e5, 2e5, 3e4));
            if (c.across >= 0) choices.insert(choices.end(), {Real(e), Real(c.across), c.traction});
        }
        if (opening.open_chosen(mesh, choices).empty()) break;
    }
    EXPECT_FALSE(opening.open().empty());
    for (Index e = 0; e < plate.model.n_elements(); ++e) {
        EXPECT_LE(opening.open_sides_of(e), 2);
        int closed = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const Index across = plate.topology.side_neighbour[3 * static_cast<std::size_t>(e) + i];
            if (across >= 0 && !opening.is_open(e, across)) ++closed;
        }
        EXPECT_GE(closed, 1) << "element " << e;
    }
}

TEST(EdgeOpening, ChoicesOpenByTractionLargestFirst) {
    const Plate plate;
    EdgeOpening opening(plate.model.n_elements());
    const Index e = 0;
    // two neighbours of element 0 across its shared sides
    std::vector<Index> across;
    for (std::size_t i = 0; i < 3; ++i)
        if (const Index f = plate.topology.side_neighbour[i]; f >= 0) across.push_back(f);
    ASSERT_GE(across.size(), 1u);
    // the same side chosen twice (from both elements), with repeats: opened once
    const std::vector<ElementPair> opened = opening.open_chosen(
        plate.mesh(), {Real(e), Real(across[0]), 2.0, Real(across[0]), Real(e), 2.0});
    ASSERT_EQ(opened.size(), 1u);
    EXPECT_TRUE(opening.is_open(across[0], e));
    EXPECT_EQ(opening.open_sides_of(e), 1);
    EXPECT_EQ(opening.open_sides_of(across[0]), 1);
}

}  // namespace
}  // namespace fpmshell
