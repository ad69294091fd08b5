// Unit tests of the structured mesh generators (mesh/generators.hpp): counts, total area
// against the exact area of the discrete surface (or the smooth surface within the
// discretisation error), orientation of every triangle, and the named edge sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "fpmshell/mesh/generators.hpp"

namespace fpmshell {
namespace {

constexpr Real k_pi = std::numbers::pi_v<Real>;

Vec3 normal_of(const MeshData& m, std::size_t e) {  // area-weighted normal (2 x area)
    const auto& t = m.triangles[e];
    const Vec3& a = m.nodes[static_cast<std::size_t>(t[0])];
    const Vec3& b = m.nodes[static_cast<std::size_t>(t[1])];
    const Vec3& c = m.nodes[static_cast<std::size_t>(t[2])];
    return (b - a).cross(c - a);
}

Vec3 centroid_of(const MeshData& m, std::size_t e) {
    const auto& t = m.triangles[e];
    return (m.nodes[static_cast<std::size_t>(t[0])] + m.nodes[static_cast<std::size_t>(t[1])] +
            m.nodes[static_cast<std::size_t>(t[2])]) /
           3.0;
}

Real total_area(const MeshData& m) {
    Real a = 0;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) a += 0.5 * normal_of(m, e).norm();
    return a;
}

/// Number of triangles touching each node.
std::vector<int> valence(const MeshData& m) {
    std::vector<int> v(m.nodes.size(), 0);
    for (const auto& t : m.triangles)
        for (const Index i : t) ++v[static_cast<std::size_t>(i)];
    return v;
}

/// Edges used by exactly one triangle (the boundary of the surface).
std::size_t boundary_edge_count(const MeshData& m) {
    std::map<std::pair<Index, Index>, int> edges;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const Index a = t[static_cast<std::size_t>(k)];
            const Index b = t[static_cast<std::size_t>((k + 1) % 3)];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    return static_cast<std::size_t>(
        std::count_if(edges.begin(), edges.end(), [](const auto& e) { return e.second == 1; }));
}

bool is_sorted_unique(const std::vector<Index>& s) {
    return std::adjacent_find(s.begin(), s.end(), std::greater_equal<>()) == s.end();
}

// Plate: node/triangle counts for every pattern, area exactly a*b, every normal +z, and the
// edge sets hold exactly the nodes on each edge.
TEST(Generators, PlateCountsAreaNormalsAndEdgeSets) {
    for (const auto pattern : {DiagonalPattern::Right, DiagonalPattern::Left,
                               DiagonalPattern::Alternate, DiagonalPattern::Cross}) {
        PlateParams p;
        p.length_x = 3.0;
        p.length_y = 1.7;
        p.nx = 5;
        p.ny = 3;
        p.origin = Vec3(1, -2, 0.5);
        p.pattern = pattern;
        const MeshData m = generate_plate(p);
        const bool cross = pattern == DiagonalPattern::Cross;
        EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(6 * 4 + (cross ? 15 : 0)));
        EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(cross ? 60 : 30));
        EXPECT_NEAR(total_area(m), 3.0 * 1.7, 1e-12);
        for (std::size_t e = 0; e < m.triangles.size(); ++e) {
            const Vec3 n = normal_of(m, e);
            EXPECT_GT(n.z(), 0.0);
            EXPECT_NEAR(n.x(), 0.0, 1e-14);
            EXPECT_NEAR(n.y(), 0.0, 1e-14);
        }
        for (const Vec3& x : m.nodes) EXPECT_EQ(x.z(), 0.5);
        const auto& s = m.node_sets;
        ASSERT_EQ(s.size(), 5U);
        EXPECT_EQ(s.at("xmin").size(), 4U);
        EXPECT_EQ(s.at("xmax").size(), 4U);
        EXPECT_EQ(s.at("ymin").size(), 6U);
        EXPECT_EQ(s.at("ymax").size(), 6U);
        EXPECT_EQ(s.at("boundary").size(), 16U);
        for (const Index i : s.at("xmin")) EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].x(), 1.0);
        for (const Index i : s.at("xmax")) EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].x(), 4.0);
        for (const Index i : s.at("ymin"))
            EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].y(), -2.0);
        for (const Index i : s.at("ymax"))
            EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].y(), -2.0 + 1.7);
        for (const auto& [name, members] : s) EXPECT_TRUE(is_sorted_unique(members)) << name;
        EXPECT_EQ(boundary_edge_count(m), 16U);
    }
}

// The diagonal patterns differ as documented: on a 2 x 2 plate the centre node touches 6
// triangles with right/left diagonals, 8 with alternating diagonals (checkerboard) and 8 with
// the cross pattern (plus the 4 of each cell centre).
TEST(Generators, PlatePatternsPlaceTheDiagonalsAsDocumented) {
    PlateParams p;
    p.nx = 2;
    p.ny = 2;
    const Index centre = 4;  // node (1, 1)
    p.pattern = DiagonalPattern::Right;
    EXPECT_EQ(valence(generate_plate(p))[centre], 6);
    p.pattern = DiagonalPattern::Left;
    EXPECT_EQ(valence(generate_plate(p))[centre], 6);
    p.pattern = DiagonalPattern::Alternate;
    EXPECT_EQ(valence(generate_plate(p))[centre], 8);
    p.pattern = DiagonalPattern::Cross;
    const MeshData cross = generate_plate(p);
    EXPECT_EQ(valence(cross)[centre], 8);
    EXPECT_EQ(valence(cross)[9], 4);  // first cell centre
    // Right: the first cell is cut along (0,0)-(1,1), i.e. nodes 0 and 4 share a triangle.
    p.pattern = DiagonalPattern::Right;
    const MeshData right = generate_plate(p);
    EXPECT_EQ(right.triangles[0], (std::array<Index, 3>{0, 1, 4}));
    p.pattern = DiagonalPattern::Left;
    EXPECT_EQ(generate_plate(p).triangles[0], (std::array<Index, 3>{0, 1, 3}));
}

// Cylinder panel: the area equals that of the flat facets (divisions_arc chords x length),
// every normal points away from the y axis, the end and arc sets lie where documented.
TEST(Generators, CylinderPanelAreaOutwardNormalsAndSets) {
    CylinderPanelParams p;
    p.radius = 300;
    p.length = 600;
    p.angle_deg = 80;
    p.angle_start_deg = -40;
    p.divisions_arc = 8;
    p.divisions_length = 6;
    for (const auto pattern : {DiagonalPattern::Right, DiagonalPattern::Cross}) {
        p.pattern = pattern;
        const MeshData m = generate_cylinder_panel(p);
        const Real dphi = 80.0 * k_pi / 180.0 / 8.0;
        if (pattern == DiagonalPattern::Right) {
            EXPECT_EQ(m.nodes.size(), 9U * 7U);
            EXPECT_EQ(m.triangles.size(), 96U);
            EXPECT_NEAR(total_area(m), 8 * 2 * 300 * std::sin(dphi / 2) * 600, 1e-8);
        }
        for (const Vec3& x : m.nodes) EXPECT_NEAR(std::hypot(x.x(), x.z()), 300.0, 1e-9);
        for (std::size_t e = 0; e < m.triangles.size(); ++e) {
            const Vec3 c = centroid_of(m, e);
            EXPECT_GT(normal_of(m, e).dot(Vec3(c.x(), 0, c.z())), 0.0);
        }
        const auto& s = m.node_sets;
        for (const Index i : s.at("y0")) EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].y(), 0.0);
        for (const Index i : s.at("y1")) EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].y(), 600.0);
        const Real phi0 = -40.0 * k_pi / 180.0;
        const Real phi1 = 40.0 * k_pi / 180.0;
        for (const Index i : s.at("arc0")) {
            const Vec3& x = m.nodes[static_cast<std::size_t>(i)];
            EXPECT_NEAR(x.x(), 300 * std::sin(phi0), 1e-9);
            EXPECT_NEAR(x.z(), 300 * std::cos(phi0), 1e-9);
        }
        for (const Index i : s.at("arc1"))
            EXPECT_NEAR(m.nodes[static_cast<std::size_t>(i)].x(), 300 * std::sin(phi1), 1e-9);
        EXPECT_EQ(s.at("y0").size(), 9U);
        EXPECT_EQ(s.at("arc0").size(), 7U);
        EXPECT_EQ(s.at("boundary").size(), 2U * 9U + 2U * 5U);
    }
}

// A 360 degree cylinder is a closed tube: the seam is merged (no duplicate nodes, only the two
// end circles are open), no arc sets, and the area is that of the regular polygon prism.
TEST(Generators, ClosedCylinderMergesTheSeam) {
    CylinderPanelParams p;
    p.radius = 2;
    p.length = 5;
    p.angle_deg = 360;
    p.angle_start_deg = 0;
    p.divisions_arc = 12;
    p.divisions_length = 4;
    const MeshData m = generate_cylinder_panel(p);
    EXPECT_EQ(m.nodes.size(), 12U * 5U);
    EXPECT_EQ(m.triangles.size(), 96U);
    EXPECT_EQ(boundary_edge_count(m), 24U);
    EXPECT_EQ(m.node_sets.count("arc0"), 0U);
    EXPECT_EQ(m.node_sets.count("arc1"), 0U);
    EXPECT_EQ(m.node_sets.at("y0").size(), 12U);
    EXPECT_EQ(m.node_sets.at("boundary").size(), 24U);
    EXPECT_NEAR(total_area(m), 12 * 2 * 2 * std::sin(k_pi / 12) * 5, 1e-10);
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const Vec3 c = centroid_of(m, e);
        EXPECT_GT(normal_of(m, e).dot(Vec3(c.x(), 0, c.z())), 0.0);
    }
}

// Square tube: counts, area exactly perimeter x length, every normal outwards (away from the
// axis, along the wall normal), the seam of the whole tube merged, and the sets.
TEST(Generators, SquareTubeQuarterAndWhole) {
    SquareTubeParams p;
    p.width = 0.1;
    p.length = 0.4;
    p.divisions_width = 5;
    p.divisions_length = 8;
    for (const Real sector : {90.0, 360.0}) {
        p.sector_deg = sector;
        const bool quarter = sector == 90.0;
        const MeshData m = generate_square_tube(p);
        const Index around = quarter ? 10 : 20;
        EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>((quarter ? around + 1 : around) * 9));
        EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(2 * around * 8));
        EXPECT_NEAR(total_area(m), (quarter ? 0.1 : 0.4) * 0.4, 1e-14);
        for (std::size_t e = 0; e < m.triangles.size(); ++e) {
            const Vec3 c = centroid_of(m, e);
            const Vec3 n = normal_of(m, e).normalized();
            // the wall normal is +-x or +-y, pointing the way the centroid lies from the axis
            EXPECT_NEAR(std::abs(n.x()) + std::abs(n.y()), 1.0, 1e-12);
            EXPECT_GT(n.dot(Vec3(c.x(), c.y(), 0)), 0.0);
        }
        EXPECT_EQ(boundary_edge_count(m),
                  static_cast<std::size_t>(quarter ? 2 * around + 16 : 2 * around));
        const auto& s = m.node_sets;
        EXPECT_EQ(s.at("bottom").size(), static_cast<std::size_t>(quarter ? around + 1 : around));
        for (const Index i : s.at("top")) EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].z(), 0.4);
        for (const Index i : s.at("corners")) {
            const Vec3& x = m.nodes[static_cast<std::size_t>(i)];
            EXPECT_NEAR(std::abs(x.x()), 0.05, 1e-15);
            EXPECT_NEAR(std::abs(x.y()), 0.05, 1e-15);
        }
        EXPECT_EQ(s.at("corners").size(), static_cast<std::size_t>(quarter ? 9 : 36));
        EXPECT_EQ(s.count("x0"), quarter ? 1U : 0U);
        if (quarter) {
            for (const Index i : s.at("x0"))
                EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].x(), 0.0);
            for (const Index i : s.at("y0"))
                EXPECT_EQ(m.nodes[static_cast<std::size_t>(i)].y(), 0.0);
            EXPECT_EQ(s.at("x0").size(), 9U);
        }
        for (const auto& [name, set] : s) EXPECT_TRUE(is_sorted_unique(set)) << name;
    }
}

// Hexagonal caps: n rings give 1 + 3 n (n + 1) nodes and 6 n^2 triangles (the paper's meshes:
// 127, 469 and 631 particles), every interior node has 6 triangles (the classic structured
// hexagonal pattern), normals point outwards and the area converges to 2 pi R^2 (1 - cos a)
// at second order.
TEST(Generators, HexagonalSphericalCapCountsPatternAndArea) {
    const Real r = 22.27;
    const Real alpha = 26.67 * k_pi / 180.0;
    const Real exact = 2 * k_pi * r * r * (1 - std::cos(alpha));
    std::map<Index, Real> error;
    for (const auto& [n, expected_nodes] :
         {std::pair<Index, std::size_t>{6, 127}, {12, 469}, {14, 631}}) {
        SphericalCapParams p;
        p.radius = r;
        p.half_angle_deg = 26.67;
        p.divisions = n;
        const MeshData m = generate_spherical_cap(p);
        EXPECT_EQ(m.nodes.size(), expected_nodes);
        EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(6 * n * n));
        const MeshSize size = spherical_cap_mesh_size(p);
        EXPECT_EQ(size.nodes, static_cast<double>(expected_nodes));
        EXPECT_EQ(size.triangles, 6.0 * n * n);
        const auto v = valence(m);
        const auto& rim = m.node_sets.at("rim");
        EXPECT_EQ(rim.size(), static_cast<std::size_t>(6 * n));
        for (std::size_t i = 0; i < m.nodes.size(); ++i) {
            if (!std::binary_search(rim.begin(), rim.end(), static_cast<Index>(i))) {
                EXPECT_EQ(v[i], 6) << "node " << i;
            }
        }
        for (std::size_t e = 0; e < m.triangles.size(); ++e)
            EXPECT_GT(normal_of(m, e).dot(centroid_of(m, e)), 0.0);
        for (const Vec3& x : m.nodes) EXPECT_NEAR(x.norm(), r, 1e-12 * r);
        for (const Index i : rim)
            EXPECT_NEAR(m.nodes[static_cast<std::size_t>(i)].z(), r * std::cos(alpha), 1e-12 * r);
        EXPECT_EQ(m.node_sets.at("apex"), std::vector<Index>{0});
        EXPECT_EQ(m.nodes[0], Vec3(0, 0, r));
        EXPECT_EQ(m.node_sets.count("edge0"), 0U);
        EXPECT_EQ(boundary_edge_count(m), static_cast<std::size_t>(6 * n));
        // Inscribed flat facets: area below the exact one, by O(h^2) with h = R alpha / n.
        const Real h = r * alpha / static_cast<Real>(n);
        const Real rel = (exact - total_area(m)) / exact;
        EXPECT_GT(rel, 0.0);
        EXPECT_LT(rel, (h / r) * (h / r));
        error[n] = rel;
    }
    EXPECT_LT(error[12], error[6] / 3.5);  // second-order convergence (ratio 4)
}

// Cap sectors: a quarter (90 degrees, 2k segments on ring k) and sixth/half sectors (hexagonal):
// counts, area fraction of the full cap, outward normals, edge0 in the plane y = 0 and edge1 in
// the plane at azimuth = sector, both including the apex.
TEST(Generators, SphericalCapSectors) {
    const Real r = 10;
    for (const Real sector : {60.0, 90.0, 180.0, 270.0}) {
        SphericalCapParams p;
        p.radius = r;
        p.half_angle_deg = 40;
        p.sector_deg = sector;
        p.divisions = 8;
        const MeshData m = generate_spherical_cap(p);
        const Index c = spherical_cap_ring_segments(sector, 1);
        EXPECT_EQ(c, sector == 90.0 ? 2 : sector == 270.0 ? 6 : static_cast<Index>(sector / 60));
        EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(1 + c * 8 * 9 / 2 + 8));
        EXPECT_EQ(m.triangles.size(), static_cast<std::size_t>(c * 64));
        const MeshSize size = spherical_cap_mesh_size(p);
        EXPECT_EQ(size.nodes, static_cast<double>(m.nodes.size()));
        const Real alpha = 40 * k_pi / 180;
        const Real exact = 2 * k_pi * r * r * (1 - std::cos(alpha)) * sector / 360;
        EXPECT_NEAR(total_area(m), exact, 0.01 * exact);
        for (std::size_t e = 0; e < m.triangles.size(); ++e)
            EXPECT_GT(normal_of(m, e).dot(centroid_of(m, e)), 0.0);
        const auto& e0 = m.node_sets.at("edge0");
        const auto& e1 = m.node_sets.at("edge1");
        EXPECT_EQ(e0.size(), 9U);
        EXPECT_EQ(e1.size(), 9U);
        EXPECT_EQ(e0.front(), 0);
        EXPECT_EQ(e1.front(), 0);
        const Real phi = sector * k_pi / 180;
        for (const Index i : e0) {
            EXPECT_NEAR(m.nodes[static_cast<std::size_t>(i)].y(), 0.0, 1e-12);
            EXPECT_GE(m.nodes[static_cast<std::size_t>(i)].x(), 0.0);
        }
        for (const Index i : e1) {  // in the plane through the z axis at azimuth phi
            const Vec3& x = m.nodes[static_cast<std::size_t>(i)];
            EXPECT_NEAR(-std::sin(phi) * x.x() + std::cos(phi) * x.y(), 0.0, 1e-12 * r);
        }
        EXPECT_EQ(m.node_sets.at("rim").size(), static_cast<std::size_t>(c * 8 + 1));
    }
    EXPECT_EQ(spherical_cap_ring_segments(45, 1), 0);
    EXPECT_EQ(spherical_cap_ring_segments(400, 1), 0);
}

// Annulus: counts, the exact area of the polygonal annulus (n_theta * (ro^2 - ri^2) sin(dtheta)
// / 2), normals +z, and the slit: with 360 degrees edge0 and edge1 are distinct nodes at the
// same positions, so the ring is cut open.
TEST(Generators, AnnulusAreaNormalsAndSlit) {
    AnnulusParams p;
    p.inner_radius = 6;
    p.outer_radius = 10;
    p.divisions_radial = 4;
    p.divisions_angle = 24;
    const MeshData m = generate_annulus(p);
    EXPECT_EQ(m.nodes.size(), 5U * 25U);
    EXPECT_EQ(m.triangles.size(), 2U * 4U * 24U);
    const Real dtheta = 2 * k_pi / 24;
    EXPECT_NEAR(total_area(m), 24 * 0.5 * (100 - 36) * std::sin(dtheta), 1e-10);
    for (std::size_t e = 0; e < m.triangles.size(); ++e) EXPECT_GT(normal_of(m, e).z(), 0.0);
    const auto& e0 = m.node_sets.at("edge0");
    const auto& e1 = m.node_sets.at("edge1");
    ASSERT_EQ(e0.size(), 5U);
    ASSERT_EQ(e1.size(), 5U);
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_NE(e0[k], e1[k]);
        EXPECT_NEAR(
            (m.nodes[static_cast<std::size_t>(e0[k])] - m.nodes[static_cast<std::size_t>(e1[k])])
                .norm(),
            0.0, 1e-12);
    }
    // Open ring: inner 25 + outer 25 + 2 x 4 slit edges.
    EXPECT_EQ(boundary_edge_count(m), 24U + 24U + 8U);
    for (const Index i : m.node_sets.at("inner"))
        EXPECT_NEAR(m.nodes[static_cast<std::size_t>(i)].norm(), 6.0, 1e-12);
    for (const Index i : m.node_sets.at("outer"))
        EXPECT_NEAR(m.nodes[static_cast<std::size_t>(i)].norm(), 10.0, 1e-12);
    EXPECT_EQ(m.node_sets.at("inner").size(), 25U);

    p.sector_deg = 90;
    p.pattern = DiagonalPattern::Cross;
    const MeshData q = generate_annulus(p);
    EXPECT_EQ(q.triangles.size(), 4U * 4U * 24U);
    for (std::size_t e = 0; e < q.triangles.size(); ++e) EXPECT_GT(normal_of(q, e).z(), 0.0);
    for (const Index i : q.node_sets.at("edge1"))
        EXPECT_NEAR(q.nodes[static_cast<std::size_t>(i)].x(), 0.0, 1e-12);
}

// Violated preconditions are refused with std::invalid_argument, never a crash.
TEST(Generators, RejectBadParameters) {
    PlateParams plate;
    plate.nx = 0;
    EXPECT_THROW((void)generate_plate(plate), std::invalid_argument);
    CylinderPanelParams cyl;
    cyl.angle_deg = 360;
    cyl.divisions_arc = 2;
    EXPECT_THROW((void)generate_cylinder_panel(cyl), std::invalid_argument);
    SphericalCapParams cap;
    cap.sector_deg = 100;
    EXPECT_THROW((void)generate_spherical_cap(cap), std::invalid_argument);
    AnnulusParams ann;
    ann.outer_radius = ann.inner_radius;
    EXPECT_THROW((void)generate_annulus(ann), std::invalid_argument);
    SquareTubeParams tube;
    tube.sector_deg = 180;
    EXPECT_THROW((void)generate_square_tube(tube), std::invalid_argument);
}

}  // namespace
}  // namespace fpmshell
