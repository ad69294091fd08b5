// Nodal rigid bodies (solver/nodal_rigid_bodies.hpp, theory.md §6.11):
// - groups that share a particle are merged into one body;
// - a free plate made one rigid body and pushed off its centre translates with F/M, turns with
//   T/I, keeps every distance between its particles to rounding, and strains nothing;
// - a strip cut in two at its middle and joined by a weld of each pair of coincident particles
//   moves as the uncut strip does;
// - two particles welded at a distance keep that distance while the strip they join swings.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/nodal_rigid_bodies.hpp"
#include "one_section_model.hpp"

using namespace fpmshell;

namespace {

std::vector<Index> all_nodes(const Model& m) {
    std::vector<Index> all(m.nodes.size());
    for (std::size_t p = 0; p < all.size(); ++p) all[p] = static_cast<Index>(p);
    return all;
}

/// A plate of 1 x 0.5 m, `n` x `n` / 2 squares, thickness 0.01, in the xy plane.
Model flat_plate(Index n) {
    PlateParams pp;
    pp.length_x = 1;
    pp.length_y = 0.5;
    pp.nx = n;
    pp.ny = n / 2;
    pp.pattern = DiagonalPattern::Alternate;
    Model m = test::one_section_model(generate_plate(pp), 0.01);
    m.control.end_time = 1;
    return m;
}

/// A cantilever strip along x (2 x 0.2 m, 20 x 2 squares, h = 0.02) clamped at x = 0 and
/// loaded at its tip by a force along -z; `cut`: made of two strips of 10 x 2 squares whose
/// particles at x = 1 coincide, each pair welded as a nodal rigid body.
Model cantilever(bool cut) {
    Model m;
    auto add_strip = [&](Real x0, Real length, Index nx) {
        PlateParams pp;
        pp.length_x = length;
        pp.length_y = 0.2;
        pp.nx = nx;
        pp.ny = 2;
        pp.origin = Vec3(x0, 0, 0);
        const MeshData strip = generate_plate(pp);
        const auto offset = static_cast<Index>(m.nodes.size());
        m.nodes.insert(m.nodes.end(), strip.nodes.begin(), strip.nodes.end());
        for (auto t : strip.triangles) {
            for (Index& p : t) p += offset;
            m.triangles.push_back(t);
        }
    };
    if (cut) {
        add_strip(0, 1, 10);
        add_strip(1, 1, 10);
    } else {
        add_strip(0, 2, 20);
    }
    MeshData mesh;
    mesh.nodes = m.nodes;
    mesh.triangles = m.triangles;
    Model model = test::one_section_model(mesh, 0.02);
    model.control.end_time = 1;
    std::vector<Index> root, tip;
    for (std::size_t p = 0; p < model.nodes.size(); ++p) {
        if (model.nodes[p].x() < 1e-9) root.push_back(static_cast<Index>(p));
        if (model.nodes[p].x() > 2 - 1e-9) tip.push_back(static_cast<Index>(p));
    }
    BoundaryCondition clamp;
    clamp.nodes = root;
    clamp.fixed.fill(true);
    model.boundary.push_back(clamp);
    model.loads.push_back({LoadType::Force, tip, {}, 0, Vec3(0, 0, -100), -1});
    if (cut)  // the pairs of coincident particles at x = 1
        for (std::size_t p = 0; p < model.nodes.size(); ++p)
            for (std::size_t q = p + 1; q < model.nodes.size(); ++q)
                if ((model.nodes[p] - model.nodes[q]).norm() < 1e-9)
                    model.nodal_rigid_bodies.push_back(
                        {{static_cast<Index>(p), static_cast<Index>(q)}});
    return model;
}

}  // namespace

TEST(NodalRigidBodies, GroupsSharingAParticleAreOneBody) {
    Model m = flat_plate(4);
    m.nodal_rigid_bodies = {{{3, 1}}, {{1, 7}}, {{10, 12}}, {{7, 2}}};
    const NodalRigidBodies bodies(m);
    ASSERT_EQ(bodies.bodies().size(), 2u);
    EXPECT_EQ(bodies.bodies()[0], (std::vector<Index>{1, 2, 3, 7}));
    EXPECT_EQ(bodies.bodies()[1], (std::vector<Index>{10, 12}));
}

TEST(NodalRigidBodies, APlateMadeRigidTranslatesAndTurnsAsOneBodyWithoutStrain) {
    Model m = flat_plate(8);
    m.nodal_rigid_bodies.push_back({all_nodes(m)});
    // a force along +y at the corner (1, 0): about the centre (0.5, 0.25) a moment
    // 0.5 x F about +z
    const Real force = 2.0;
    Index corner = -1;
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        if ((m.nodes[p] - Vec3(1, 0, 0)).norm() < 1e-12) corner = static_cast<Index>(p);
    ASSERT_GE(corner, 0);
    m.loads.push_back({LoadType::Force, {corner}, {}, 0, Vec3(0, force, 0), -1});
    ExplicitSolver s(m);
    Real mass = 0, inertia_z = 0;
    Vec3 centre = Vec3::Zero();
    for (std::size_t p = 0; p < m.nodes.size(); ++p) {
        mass += s.state().mass[p];
        centre += s.state().mass[p] * m.nodes[p];
    }
    centre /= mass;
    for (std::size_t p = 0; p < m.nodes.size(); ++p)  // the particles' own inertia turns
        inertia_z +=
            s.state().mass[p] * (m.nodes[p] - centre).head<2>().squaredNorm();  // in-plane only
    const Real torque = (Vec3(1, 0, 0) - centre).cross(Vec3(0, force, 0)).z();
    while (s.time() < 0.02) s.step(1e30);
    // the centre's velocity and the spin about z, against the impulse of the force over the
    // time (both the half-step values: one step of the acceleration is the resolution); the
    // turn is small (1e-4 rad), so the moment arm stays
    Vec3 momentum = Vec3::Zero(), moment_of_momentum = Vec3::Zero(), now = Vec3::Zero();
    for (std::size_t p = 0; p < m.nodes.size(); ++p) now += s.state().mass[p] * s.state().x[p];
    now /= mass;
    for (std::size_t p = 0; p < m.nodes.size(); ++p) {
        momentum += s.state().mass[p] * s.state().v[p];
        moment_of_momentum += s.state().mass[p] * (s.state().x[p] - now).cross(s.state().v[p]);
    }
    const Real t = s.time();
    EXPECT_NEAR(momentum.y() / mass, force * t / mass, 1e-3 * force * t / mass);
    EXPECT_NEAR(momentum.x(), 0.0, 1e-9 * force * t);
    EXPECT_NEAR(momentum.z(), 0.0, 1e-12 * force * t);
    EXPECT_NEAR(moment_of_momentum.z() / inertia_z, torque * t / inertia_z,
                1e-3 * torque * t / inertia_z);
    // every distance as at the start, to rounding of the positions (1 m)
    for (std::size_t p = 1; p < m.nodes.size(); p += 7)
        for (std::size_t q = 0; q < p; q += 5)
            EXPECT_NEAR((s.state().x[p] - s.state().x[q]).norm(), (m.nodes[p] - m.nodes[q]).norm(),
                        1e-12);
    // a rigid motion strains nothing: no internal energy beyond rounding of the kinetic one
    EXPECT_LT(std::abs(s.energy().internal), 1e-9 * s.energy().kinetic);
    EXPECT_LT(std::abs(s.energy().error()), 1e-6);
}

TEST(NodalRigidBodies, AStripWeldedAtItsCutMovesAsTheUncutStrip) {
    const Model whole = cantilever(false);
    const Model cut = cantilever(true);
    ASSERT_EQ(cut.nodal_rigid_bodies.size(), 3u);
    Model loose = cut;  // the same two strips without the welds
    loose.nodal_rigid_bodies.clear();
    ExplicitSolver a(whole), b(cut), c(loose);
    auto tip_z = [](const Model& m, const ExplicitSolver& s) {
        Real z = 0;
        int n = 0;
        for (std::size_t p = 0; p < m.nodes.size(); ++p)
            if (m.nodes[p].x() > 2 - 1e-9) {
                z += s.state().x[p].z();
                ++n;
            }
        return z / n;
    };
    Real largest = 0, loose_apart = 0;
    while (a.time() < 0.02) {
        a.step(1e30);
        b.step(1e30);
        c.step(1e30);
        // the same steps but for the last bits (the cut strips' coordinates round otherwise)
        ASSERT_NEAR(a.time(), b.time(), 1e-9 * a.time());
        largest = std::max(largest, std::abs(tip_z(whole, a)));
        // The same tip motion. A welded particle turns in the tangent plane of its own half's
        // elements (theory.md §1.3), the uncut one in that of both: at the cut, where the
        // strip bends, the planes differ, by 7e-4 of the largest deflection at 0.02 s.
        ASSERT_NEAR(tip_z(cut, b), tip_z(whole, a), 2e-3 * largest + 1e-15) << "t = " << a.time();
        loose_apart = std::max(loose_apart, std::abs(tip_z(loose, c) - tip_z(whole, a)));
    }
    EXPECT_GT(largest, 1e-5);               // it did bend
    EXPECT_GT(loose_apart, 0.1 * largest);  // and without the welds its tip half falls off
}

TEST(NodalRigidBodies, TwoParticlesWeldedAtADistanceKeepIt) {
    Model m = cantilever(false);
    // a weld between two particles of the strip, 0.3 m apart along it
    Index p = -1, q = -1;
    for (std::size_t k = 0; k < m.nodes.size(); ++k) {
        if ((m.nodes[k] - Vec3(1.2, 0.1, 0)).norm() < 1e-9) p = static_cast<Index>(k);
        if ((m.nodes[k] - Vec3(1.5, 0.1, 0)).norm() < 1e-9) q = static_cast<Index>(k);
    }
    ASSERT_GE(p, 0);
    ASSERT_GE(q, 0);
    m.nodal_rigid_bodies.push_back({{p, q}});
    ExplicitSolver s(m);
    Real swing = 0;
    while (s.time() < 0.02) {
        s.step(1e30);
        const Vec3 d =
            s.state().x[static_cast<std::size_t>(q)] - s.state().x[static_cast<std::size_t>(p)];
        ASSERT_NEAR(d.norm(), 0.3, 1e-12);
        swing = std::max(swing, std::abs(d.z()));
    }
    EXPECT_GT(swing, 1e-6);  // the weld turned with the strip
    EXPECT_LT(std::abs(s.energy().error()), 1e-3);
}
