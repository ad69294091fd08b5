// The topology of a small hand-made mesh (model/mesh_topology.hpp): the particle -> element
// map, the particle neighbours, the side neighbours with their sides and corners, and the
// lumped masses (§6.1-6.2), against the shares written out in the test.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_topology.hpp"

using namespace fpmshell;

namespace {

//  3 ----- 2
//  | e1  / | \      e0 = (0 1 2), e1 = (0 2 3), e2 = (1 4 2); unit right triangles
//  |   /  e0| e2\   (area 1/2 each)
//  0 ----- 1 ----- 4
Model three_triangles() {
    Model m;
    m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0, 0)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
    m.materials.push_back({"steel", "elastic", 1000, 2.1e11, 0.3});
    m.sections.push_back({0, 0.01, 2, 3});
    m.element_section.assign(m.triangles.size(), 0);
    return m;
}

std::vector<Index> as_vector(std::span<const Index> s) { return {s.begin(), s.end()}; }

}  // namespace

TEST(MeshTopology, ParticleMapsInAscendingOrder) {
    const MeshTopology t(three_triangles());
    EXPECT_EQ(t.n_particles(), 5);
    EXPECT_EQ(t.n_elements(), 3);
    EXPECT_EQ(as_vector(t.elements_of(0)), (std::vector<Index>{0, 1}));
    EXPECT_EQ(as_vector(t.elements_of(1)), (std::vector<Index>{0, 2}));
    EXPECT_EQ(as_vector(t.elements_of(2)), (std::vector<Index>{0, 1, 2}));
    EXPECT_EQ(as_vector(t.elements_of(3)), (std::vector<Index>{1}));
    EXPECT_EQ(as_vector(t.elements_of(4)), (std::vector<Index>{2}));
    EXPECT_EQ(as_vector(t.neighbours_of(0)), (std::vector<Index>{1, 2, 3}));
    EXPECT_EQ(as_vector(t.neighbours_of(2)), (std::vector<Index>{0, 1, 3, 4}));
    EXPECT_EQ(as_vector(t.neighbours_of(4)), (std::vector<Index>{1, 2}));
}

TEST(MeshTopology, SideNeighboursWithTheirSidesAndCorners) {
    const MeshTopology t(three_triangles());
    // side i of e runs from corner (i+1) to corner (i+2), index 3 e + i
    struct Expected {
        std::size_t side;
        Index neighbour;
        int neighbour_side;
    };
    const std::vector<Expected> shared{
        {0, 2, 1},  // e0 side 0 = (1, 2): e2's side 1 (opposite particle 4)
        {1, 1, 2},  // e0 side 1 = (2, 0): e1's side 2 (opposite particle 3)
        {5, 0, 1},  // e1 side 2 = (0, 2): e0's side 1 (opposite particle 1)
        {7, 0, 0},  // e2 side 1 = (2, 1): e0's side 0 (opposite particle 0)
    };
    for (const Expected& x : shared) {
        SCOPED_TRACE(x.side);
        EXPECT_EQ(t.side_neighbour[x.side], x.neighbour);
        EXPECT_EQ(t.side_neighbour_side[x.side], x.neighbour_side);
    }
    // e0 side 0 runs from particle 1 to particle 2: e2's corners 0 and 2
    EXPECT_EQ(t.side_neighbour_corner[2 * 0], 0);
    EXPECT_EQ(t.side_neighbour_corner[2 * 0 + 1], 2);
    // e0 side 1 runs from particle 2 to particle 0: e1's corners 1 and 0
    EXPECT_EQ(t.side_neighbour_corner[2 * 1], 1);
    EXPECT_EQ(t.side_neighbour_corner[2 * 1 + 1], 0);
    // e1 side 2 runs from e1's corner 0 (particle 0) to its corner 1 (particle 2): e0's corners 0
    // and 2
    EXPECT_EQ(t.side_neighbour_corner[2 * 5], 0);
    EXPECT_EQ(t.side_neighbour_corner[2 * 5 + 1], 2);
    // e2 side 1 runs from e2's corner 2 (particle 2) to its corner 0 (particle 1): e0's corners 2
    // and 1
    EXPECT_EQ(t.side_neighbour_corner[2 * 7], 2);
    EXPECT_EQ(t.side_neighbour_corner[2 * 7 + 1], 1);
    // every other side is on the boundary
    for (std::size_t side : {2u, 3u, 4u, 6u, 8u}) {
        SCOPED_TRACE(side);
        EXPECT_EQ(t.side_neighbour[side], -1);
        EXPECT_EQ(t.side_neighbour_side[side], -1);
        EXPECT_EQ(t.side_neighbour_corner[2 * side], -1);
    }
}

TEST(MeshTopology, ASideOfThreeElementsHasNoNeighbour) {
    Model m = three_triangles();
    m.nodes.push_back(Vec3(0.5, 0.5, 1.0));
    m.triangles.push_back({0, 2, 5});  // a fin on the diagonal (0, 2)
    m.element_section.push_back(0);
    const MeshTopology t(m);
    EXPECT_EQ(t.side_neighbour[1], -1);  // e0 side 1 = (2, 0)
    EXPECT_EQ(t.side_neighbour[5], -1);  // e1 side 2 = (0, 2)
    EXPECT_EQ(t.side_neighbour[3 * 3 + 2], -1);
    EXPECT_EQ(t.side_neighbour[0], 2);  // the others keep theirs
}

TEST(MeshTopology, LumpedMassesAndInertias) {
    const Model m = three_triangles();
    const MeshTopology t(m);
    const NodeInertiaShare share = lumped_node_share(1000, 0.01, 0.5);  // every element alike
    const std::vector<int> n_elements{2, 2, 3, 1, 1};
    for (std::size_t p = 0; p < 5; ++p) {
        SCOPED_TRACE(p);
        EXPECT_NEAR(t.particle_mass[p], n_elements[p] * share.mass, 1e-15 * share.mass);
        EXPECT_NEAR(t.particle_inertia[p], n_elements[p] * share.inertia, 1e-15 * share.inertia);
    }
    Real total = 0;
    for (Real mass : t.particle_mass) total += mass;
    EXPECT_NEAR(total, 1000 * 0.01 * 1.5, 1e-12);  // rho h A
    for (std::size_t e = 0; e < 3; ++e) {
        EXPECT_EQ(t.element_node_mass[e], share.mass);
        EXPECT_EQ(t.element_node_inertia[e], share.inertia);
    }
}

TEST(MeshTopology, MassesAreTheLumpedSharesOfTheirElements) {
    // a jittered plate of two sections: unequal shares. Reference: §6.1-6.2 written out here,
    // m = rho h A / 3 and J = m (A / 8 + h^2 / 12) per corner, summed over each particle's
    // elements. Tolerance 1e-14 relative: the same terms, at most 6 per particle, summed with
    // or without fused multiply-adds (a few ulps).
    PlateParams pp;
    pp.nx = 7;
    pp.ny = 5;
    MeshData mesh = generate_plate(pp);
    for (std::size_t p = 0; p < mesh.nodes.size(); ++p)
        mesh.nodes[p] += 0.01 * Vec3(std::sin(3.0 * static_cast<Real>(p)),
                                     std::cos(5.0 * static_cast<Real>(p)), 0.0);
    Model m;
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"steel", "elastic", 7800, 2.1e11, 0.3});
    m.materials.push_back({"alu", "elastic", 2700, 7e10, 0.33});
    m.sections.push_back({0, 0.01, 2, 3});
    m.sections.push_back({1, 0.013, 2, 3});
    for (std::size_t e = 0; e < m.triangles.size(); ++e)
        m.element_section.push_back(static_cast<Index>(e % 3 == 0));
    const MeshTopology t(m);
    std::vector<Real> mass(m.nodes.size(), 0.0), inertia(m.nodes.size(), 0.0);
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const auto& tri = m.triangles[e];
        const Section& sec = m.sections[static_cast<std::size_t>(m.element_section[e])];
        const Real rho = m.materials[static_cast<std::size_t>(sec.material)].density;
        const Real h = sec.thickness;
        const Vec3& p0 = m.nodes[static_cast<std::size_t>(tri[0])];
        const Real area = 0.5 * (m.nodes[static_cast<std::size_t>(tri[1])] - p0)
                                    .cross(m.nodes[static_cast<std::size_t>(tri[2])] - p0)
                                    .norm();
        const Real corner_mass = rho * h * area / 3.0;
        for (const Index p : tri) {
            mass[static_cast<std::size_t>(p)] += corner_mass;
            inertia[static_cast<std::size_t>(p)] += corner_mass * (area / 8.0 + h * h / 12.0);
        }
    }
    for (std::size_t p = 0; p < m.nodes.size(); ++p) {
        EXPECT_NEAR(t.particle_mass[p], mass[p], 1e-14 * mass[p]);
        EXPECT_NEAR(t.particle_inertia[p], inertia[p], 1e-14 * inertia[p]);
    }
}
