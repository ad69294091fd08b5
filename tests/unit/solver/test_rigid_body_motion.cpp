// Rigid bodies held and driven by `boundary` entries of type rigid_body (theory.md eq. 6.11-7,
// LS-DYNA's *BOUNDARY_PRESCRIBED_MOTION_RIGID): a strip clamped at x = 0 whose outer half
// (x > 1) is a rigid part,
// - driven up at a velocity that ramps in: the body's centre of mass moves at the curve's
//   velocity at every half step, to rounding, while it turns freely with the bending strip, and
//   the drive's work (booked as a support's reaction) closes the energy balance;
// - given a displacement: its centre follows the curve to rounding;
// - turned about y at a prescribed angular velocity: every particle of it turns so, its centre
//   free;
// - an entry whose elements are not one rigid body is an InputError.
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/nodal_rigid_bodies.hpp"
#include "one_section_model.hpp"

using namespace fpmshell;

namespace {

/// A 2 m x 0.2 m strip of 20 x 2 squares, h = 0.02, clamped at x = 0; the elements beyond
/// x = 1 are a rigid material's section (the particles at x = 1 join the body). Returns the model
/// and the rigid elements.
std::pair<Model, std::vector<Index>> strip_with_rigid_end() {
    PlateParams pp;
    pp.length_x = 2;
    pp.length_y = 0.2;
    pp.nx = 20;
    pp.ny = 2;
    pp.pattern = DiagonalPattern::Alternate;
    Model m = test::one_section_model(generate_plate(pp), 0.02);
    m.control.end_time = 1;
    Material rigid = m.materials[0];
    rigid.name = "tool";
    rigid.rigid = true;
    m.materials.push_back(rigid);
    m.sections.push_back({1, 0.02, 2, 3});
    std::vector<Index> tool;
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        Vec3 c = Vec3::Zero();
        for (const Index p : m.triangles[e]) c += m.nodes[static_cast<std::size_t>(p)] / 3;
        if (c.x() > 1) {
            m.element_section[e] = 1;
            tool.push_back(static_cast<Index>(e));
        }
    }
    BoundaryCondition clamp;
    for (std::size_t p = 0; p < m.nodes.size(); ++p)
        if (m.nodes[p].x() < 1e-9) clamp.nodes.push_back(static_cast<Index>(p));
    clamp.fixed.fill(true);
    m.boundary.push_back(clamp);
    return {m, tool};
}

/// The centre of mass of the particles of body 0 at positions x (or velocities).
Vec3 body_mean(const ExplicitSolver& s, const NodalRigidBodies& bodies,
               const std::vector<Vec3>& field) {
    Vec3 sum = Vec3::Zero();
    Real mass = 0;
    for (const Index ip : bodies.bodies()[0]) {
        const auto p = static_cast<std::size_t>(ip);
        sum += s.state().mass[p] * field[p];
        mass += s.state().mass[p];
    }
    return sum / mass;
}

}  // namespace

TEST(RigidBodyMotion, AVelocityDrivesTheBodysCentreWhileItTurnsFreely) {
    auto [m, tool] = strip_with_rigid_end();
    m.curves.push_back({"ramp", {{0, 0}, {0.005, 1}}});
    BoundaryCondition drive;
    drive.rigid_elements = tool;
    drive.prescribed = PrescribedKind::Velocity;
    drive.value = Vec3(0, 0, 2);
    drive.components = {false, false, true};
    drive.curve = 0;
    m.boundary.push_back(drive);
    ExplicitSolver s(m);
    const NodalRigidBodies bodies(m);
    ASSERT_EQ(bodies.bodies().size(), 1u);
    EXPECT_TRUE(bodies.fixed()[0][2] && !bodies.fixed()[0][0] && !bodies.fixed()[0][4]);
    Real turned = 0;
    while (s.time() < 0.01) {
        const Real t0 = s.time();
        s.step(1e30);
        const Real t_half = 0.5 * (t0 + s.time());
        // the centre's velocity is the curve's at the half step (velocities of order 1: rounding)
        const Vec3 v = body_mean(s, bodies, s.state().v);
        EXPECT_NEAR(v.z(), 2 * std::min(t_half / 0.005, 1.0), 1e-12) << "t " << t0;
        turned = std::max(turned, std::abs(s.state().omega[bodies.bodies()[0].back()].y()));
    }
    EXPECT_GT(turned, 0.1);  // it turns with the bending strip (free about y)
    // the drive put in the strip's strain and kinetic energy: booked as a support's work
    EXPECT_GT(s.energy().external_work, 1.0);
    EXPECT_LT(std::abs(s.energy().error()), 1e-8);  // 1e-11 measured
}

TEST(RigidBodyMotion, ADisplacementMovesTheCentreAlongTheCurve) {
    auto [m, tool] = strip_with_rigid_end();
    // (t / 0.01)^2 at 21 points: the body starts at rest (a jump of velocity at t = 0 would be
    // an impulse whose first half step the balance cannot book)
    Curve lift{"lift", {}};
    for (int i = 0; i <= 20; ++i) lift.points.push_back({0.0005 * i, (i / 20.0) * (i / 20.0)});
    m.curves.push_back(lift);
    BoundaryCondition drive;
    drive.rigid_elements = tool;
    drive.prescribed = PrescribedKind::Displacement;
    drive.value = Vec3(0, 0, 0.01);
    drive.curve = 0;  // all three components: the centre goes straight up by 1 cm
    m.boundary.push_back(drive);
    ExplicitSolver s(m);
    const NodalRigidBodies bodies(m);
    const Vec3 start = body_mean(s, bodies, m.nodes);
    while (s.time() < 0.008) {
        s.step(1e30);
        const Vec3 c = body_mean(s, bodies, s.state().x);
        // positions of about 1.5 m: rounding
        EXPECT_NEAR(c.x(), start.x(), 1e-12);
        EXPECT_NEAR(c.z(), start.z() + 0.01 * curve_factor(m.curves, 0, s.time()), 1e-12)
            << "t " << s.time();
    }
    // the curve's kinks are impulses, each booked by the trapezoid to O(dt^2): 8e-9 measured
    EXPECT_LT(std::abs(s.energy().error()), 1e-7);
}

TEST(RigidBodyMotion, AnAngularVelocityTurnsTheBodyAboutTheHeldAxis) {
    auto [m, tool] = strip_with_rigid_end();
    m.curves.push_back({"ramp", {{0, 0}, {0.002, 1}}});
    BoundaryCondition turn;
    turn.rigid_elements = tool;
    turn.prescribed = PrescribedKind::AngularVelocity;
    turn.value = Vec3(0, -3, 0);
    turn.curve = 0;
    turn.components = {false, true, false};  // about y only; the rest free
    m.boundary.push_back(turn);
    ExplicitSolver s(m);
    const NodalRigidBodies bodies(m);
    EXPECT_TRUE(bodies.fixed()[0][4] && !bodies.fixed()[0][3] && !bodies.fixed()[0][2]);
    while (s.time() < 0.005) s.step(1e30);
    for (const Index p : bodies.bodies()[0]) {
        // omega about y, in each particle's tangent plane: the prescribed value less its part
        // along the particle's normal, whose y component the alternate diagonals' uneven
        // lumping tilts by ~1e-8
        EXPECT_NEAR(s.state().omega[static_cast<std::size_t>(p)].y(), -3.0, 1e-6) << p;
    }
    EXPECT_LT(std::abs(s.energy().error()), 1e-8);  // 3e-10 measured
}

TEST(RigidBodyMotion, ElementsOfTwoBodiesAreAnError) {
    auto [m, tool] = strip_with_rigid_end();
    BoundaryCondition drive;
    drive.rigid_elements = {0, tool.front()};  // an elastic element and a rigid one
    drive.fixed.fill(true);
    m.boundary.push_back(drive);
    EXPECT_THROW((void)NodalRigidBodies(m), InputError);
}
