// Nodal rigid bodies (solver/nodal_rigid_bodies.hpp, theory.md §6.11):
// - groups that share a particle are merged into one body;
// - a free plate made one rigid body and pushed off its centre translates with F/M, turns with
//   T/I, keeps every distance between its particles to rounding, and strains nothing;
// - a strip cut in two at its middle and joined by a weld of each pair of coincident particles
//   moves as the uncut strip does;
// - two particles welded at a distance keep that distance while the strip they join swings;
// - the section of a rigid material moves as one body and its elements set no time step.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/nodal_rigid_bodies.hpp"
#include "one_section_model.hpp"

using namespace fpmshell;

namespace {

/// A rigid group of the particles `nodes` (no failure).
NodalRigidBody group(std::vector<Index> nodes) {
    NodalRigidBody g;
    g.nodes = std::move(nodes);
    return g;
}

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

/// Appends a strip of `nx` x 2 squares, `length` x 0.2 m, from x = x0 (its own particles).
void append_strip(MeshData& mesh, Real x0, Real length, Index nx) {
    PlateParams pp;
    pp.length_x = length;
    pp.length_y = 0.2;
    pp.nx = nx;
    pp.ny = 2;
    pp.origin = Vec3(x0, 0, 0);
    const MeshData strip = generate_plate(pp);
    const auto offset = static_cast<Index>(mesh.nodes.size());
    mesh.nodes.insert(mesh.nodes.end(), strip.nodes.begin(), strip.nodes.end());
    for (auto t : strip.triangles) {
        for (Index& p : t) p += offset;
        mesh.triangles.push_back(t);
    }
}

/// Welds every pair of coincident particles (a nodal rigid body each).
void weld_coincident_particles(Model& m) {
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        for (std::size_t q = p + 1; q < m.nodes.size(); ++q)
            if ((m.nodes[p] - m.nodes[q]).norm() < 1e-9)
                m.nodal_rigid_bodies.push_back(
                    group(std::vector<Index>{static_cast<Index>(p), static_cast<Index>(q)}));
}

/// Clamps the particles at x = 0 and loads those at x = tip by 100 N each along -z.
void clamp_root_and_load_tip(Model& m, Real tip) {
    std::vector<Index> root, loaded;
    for (std::size_t p = 0; p < m.nodes.size(); ++p) {
        if (m.nodes[p].x() < 1e-9) root.push_back(static_cast<Index>(p));
        if (m.nodes[p].x() > tip - 1e-9) loaded.push_back(static_cast<Index>(p));
    }
    BoundaryCondition clamp;
    clamp.nodes = root;
    clamp.fixed.fill(true);
    m.boundary.push_back(clamp);
    m.loads.push_back({LoadType::Force, loaded, {}, 0, Vec3(0, 0, -100), -1});
}

/// A cantilever strip along x (2 x 0.2 m, 20 x 2 squares, h = 0.02) clamped at x = 0 and
/// loaded at its tip by a force along -z; `cut`: made of two strips of 10 x 2 squares whose
/// particles at x = 1 coincide, each pair welded as a nodal rigid body.
Model cantilever(bool cut) {
    MeshData mesh;
    if (cut) {
        append_strip(mesh, 0, 1, 10);
        append_strip(mesh, 1, 1, 10);
    } else {
        append_strip(mesh, 0, 2, 20);
    }
    Model model = test::one_section_model(mesh, 0.02);
    model.control.end_time = 1;
    clamp_root_and_load_tip(model, 2);
    if (cut) weld_coincident_particles(model);  // the pairs at x = 1
    return model;
}

}  // namespace

TEST(NodalRigidBodies, GroupsSharingAParticleAreOneBody) {
    Model m = flat_plate(4);
    m.nodal_rigid_bodies = {group(std::vector<Index>{3, 1}), group(std::vector<Index>{1, 7}),
                            group(std::vector<Index>{10, 12}), group(std::vector<Index>{7, 2})};
    const NodalRigidBodies bodies(m);
    ASSERT_EQ(bodies.bodies().size(), 2u);
    EXPECT_EQ(bodies.bodies()[0], (std::vector<Index>{1, 2, 3, 7}));
    EXPECT_EQ(bodies.bodies()[1], (std::vector<Index>{10, 12}));
}

TEST(NodalRigidBodies, APlateMadeRigidTranslatesAndTurnsAsOneBodyWithoutStrain) {
    Model m = flat_plate(8);
    m.nodal_rigid_bodies.push_back(group(all_nodes(m)));
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
    m.nodal_rigid_bodies.push_back(group(std::vector<Index>{p, q}));
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

namespace {

/// A strip clamped at x = 0: an inner half of 10 x 2 elastic squares and an outer half of
/// `outer_nx` x 2 squares (none for 0) in a section of its own, of a rigid material or an
/// elastic one, joined by welds of their coincident particles at x = 1; a force along -z at the
/// tip.
Model half_rigid_strip(Index outer_nx, bool rigid) {
    MeshData mesh;
    append_strip(mesh, 0, 1, 10);
    const std::size_t inner_elements = mesh.triangles.size();
    if (outer_nx > 0) append_strip(mesh, 1, 1, outer_nx);
    Model model = test::one_section_model(mesh, 0.02);
    model.control.end_time = 1;
    if (outer_nx > 0) {
        Material outer = model.materials[0];
        outer.name = "outer";
        outer.rigid = rigid;
        model.materials.push_back(outer);
        model.sections.push_back({1, 0.02, 2, 3});
        for (std::size_t e = inner_elements; e < model.triangles.size(); ++e)
            model.element_section[e] = 1;
        weld_coincident_particles(model);
    }
    clamp_root_and_load_tip(model, outer_nx > 0 ? 2 : 1);
    return model;
}

}  // namespace

TEST(NodalRigidBodies, ASectionOfARigidMaterialMovesAsOneBodyAndSetsNoStep) {
    const Model rigid = half_rigid_strip(40, true);
    const Model elastic = half_rigid_strip(40, false);
    const Model inner = half_rigid_strip(0, false);
    ExplicitSolver s(rigid);
    // the outer half's elements, four times shorter (L_c 0.34 of the inner ones'), would set
    // the step; rigid, they do not: the step is the inner half's alone (the same elements, the
    // same bits)
    EXPECT_EQ(s.stable_dt(), ExplicitSolver(inner).stable_dt());
    EXPECT_GT(s.stable_dt(), 2.5 * ExplicitSolver(elastic).stable_dt());
    // one body: the outer half and the welded particles of the inner half at x = 1
    const NodalRigidBodies bodies(rigid);
    ASSERT_EQ(bodies.bodies().size(), 1u);
    EXPECT_EQ(bodies.bodies()[0].size(), 41u * 3u + 3u);
    while (s.time() < 0.02) s.step(1e30);
    std::vector<std::size_t> outer;
    for (std::size_t p = 0; p < rigid.nodes.size(); ++p)
        if (rigid.nodes[p].x() > 1 - 1e-9) outer.push_back(p);
    Real turned = 0;
    for (std::size_t i = 0; i < outer.size(); i += 5)
        for (std::size_t j = 0; j < i; j += 3) {
            const std::size_t p = outer[i], q = outer[j];
            // the outer half keeps its shape to rounding of positions of about 1 m
            EXPECT_NEAR((s.state().x[p] - s.state().x[q]).norm(),
                        (rigid.nodes[p] - rigid.nodes[q]).norm(), 1e-12);
            turned = std::max(turned, std::abs(s.state().x[p].z() - s.state().x[q].z()));
        }
    EXPECT_GT(turned, 1e-6);  // it turned with the bending inner half
    EXPECT_LT(std::abs(s.energy().error()), 1e-3);
}

// A rigid material's fixed components (eq. 6.11-6, LS-DYNA's *MAT_RIGID CMO = 1): held in all
// six, the rigid half of the loaded strip does not move at all and the clamped-and-held strip
// keeps its energy balance; held in its translations only, its centre of mass stays where it
// is while it turns with the bending inner half.
TEST(NodalRigidBodies, ARigidMaterialHoldsTheComponentsItFixes) {
    const auto outer_particles = [](const Model& m) {
        std::vector<std::size_t> outer;
        for (std::size_t p = 0; p < m.nodes.size(); ++p)
            if (m.nodes[p].x() > 1 - 1e-9) outer.push_back(p);
        return outer;
    };
    Model held = half_rigid_strip(40, true);
    held.materials[1].rigid_fixed.fill(true);
    ExplicitSolver s(held);
    while (s.time() < 0.02) s.step(1e30);
    const NodalRigidBodies bodies(held);
    ASSERT_EQ(bodies.fixed().size(), 1u);
    EXPECT_TRUE(bodies.fixed()[0][0] && bodies.fixed()[0][5]);
    for (const std::size_t p : outer_particles(held)) {
        EXPECT_EQ(s.state().x[p], held.nodes[p]);  // exactly: a zero velocity and no turn
        EXPECT_EQ(s.state().v[p], Vec3::Zero());
    }
    EXPECT_LT(std::abs(s.energy().error()), 1e-3);

    Model pinned = half_rigid_strip(40, true);
    for (std::size_t k = 0; k < 3; ++k) pinned.materials[1].rigid_fixed[k] = true;
    ExplicitSolver t(pinned);
    const std::vector<std::size_t> outer = outer_particles(pinned);
    const auto centre = [&](const std::vector<Vec3>& x) {
        Vec3 c = Vec3::Zero();
        Real mass = 0;
        for (const std::size_t p : outer) {
            c += t.state().mass[p] * x[p];
            mass += t.state().mass[p];
        }
        return Vec3(c / mass);
    };
    const Vec3 start = centre(pinned.nodes);
    Real turned = 0;
    while (t.time() < 0.02) {
        t.step(1e30);
        // the centre of mass at x^n is where the body turns about: it stays to rounding
        EXPECT_LT((centre(t.state().x) - start).norm(), 1e-12);
    }
    for (const std::size_t p : outer)
        turned = std::max(turned, std::abs(t.state().x[p].z() - pinned.nodes[p].z()));
    EXPECT_GT(turned, 1e-6);  // it turned
}

TEST(NodalRigidBodies, ARigidPartOfLightParticlesPushesWithItsWholeMassInContact) {
    // a rigid plate (1 x 1 m, 20 x 20 squares: 441 particles of 0.18 kg, 78 kg in all) moving up
    // at 1 m/s under a free elastic triangle of 1.56 kg lying 0.04 m above it
    PlateParams pp;
    pp.nx = pp.ny = 20;
    const MeshData plate = generate_plate(pp);
    MeshData mesh = plate;
    const auto first = static_cast<Index>(mesh.nodes.size());
    for (const Vec3& c : {Vec3(0.4, 0.4, 0.05), Vec3(0.6, 0.4, 0.05), Vec3(0.4, 0.6, 0.05)})
        mesh.nodes.push_back(c);
    mesh.triangles.push_back({first, first + 1, first + 2});
    Model m = test::one_section_model(mesh, 0.01);
    m.control.end_time = 1;
    Material hard = m.materials[0];
    hard.name = "hard";
    hard.rigid = true;
    m.materials.push_back(hard);
    m.sections.push_back({1, 0.01, 2, 3});
    for (std::size_t e = 0; e < plate.triangles.size(); ++e) m.element_section[e] = 1;
    std::vector<Index> plate_nodes, all_elements;
    for (Index p = 0; p < first; ++p) plate_nodes.push_back(p);
    for (Index e = 0; e < m.n_elements(); ++e) all_elements.push_back(e);
    const Real v0 = 1;
    m.initial_conditions.push_back({plate_nodes, Vec3(0, 0, v0), Vec3::Zero()});
    ContactDefinition self;
    self.elements = all_elements;
    m.contacts.push_back(self);
    ExplicitSolver s(m);
    Real plate_mass = 0, triangle_mass = 0;
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        (p < static_cast<std::size_t>(first) ? plate_mass : triangle_mass) += s.state().mass[p];
    while (s.time() < 0.08) s.step(1e30);  // the impact at 0.04 s
    Real momentum = 0, plate_momentum = 0;
    for (std::size_t p = 0; p < m.nodes.size(); ++p) {
        momentum += s.state().mass[p] * s.state().v[p].z();
        if (p < static_cast<std::size_t>(first))
            plate_momentum += s.state().mass[p] * s.state().v[p].z();
    }
    // contact forces are equal and opposite; velocities are differences of positions over a
    // step (rounding of 1e-12 m/s per step)
    EXPECT_NEAR(momentum, plate_mass * v0, 1e-9 * plate_mass * v0);
    // a perfectly plastic impact (§8.3): both at the common velocity
    const Real common = plate_mass * v0 / (plate_mass + triangle_mass);
    for (std::size_t p = static_cast<std::size_t>(first); p < m.nodes.size(); ++p)
        EXPECT_NEAR(s.state().v[p].z(), common, 1e-3 * v0);
    // the plate's centre (the triangle is off it: the plate turns a little too)
    EXPECT_NEAR(plate_momentum / plate_mass, common, 1e-3 * v0);
    // the triangle lies on the plate, h apart, within the sweeps' tolerance
    EXPECT_LT(s.contact_statistics()->max_penetration, 1e-3 * 0.01);
}
