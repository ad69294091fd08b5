// Boundary conditions (solver/boundary_conditions.hpp, theory.md §6.7, §2.6):
// - what each constraint leaves of a particle's rotation: the tangent plane of a free particle,
//   the free axis of a symmetry plane, all three axes of a kink particle, nothing of a clamp;
// - the drill axis that follows (eq. 2.6c): the normal, the normal turned into the symmetry
//   plane, or none;
// - prescribed velocities, displacements, accelerations and angular velocities reach their
//   targets, with the reactions m / (c1 dt_n) times the change they make.
#include <gtest/gtest.h>

#include "fpmshell/solver/boundary_conditions.hpp"

using namespace fpmshell;

namespace {

/// Four free particles (no elements are needed by the constraints themselves).
Model four_particles() {
    Model m;
    m.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    return m;
}

BoundaryCondition fixed(std::vector<Index> nodes, std::array<bool, 6> dofs) {
    BoundaryCondition bc;
    bc.nodes = std::move(nodes);
    bc.fixed = dofs;
    return bc;
}

}  // namespace

TEST(BoundaryConditions, RotationConstraintsAndDrillAxes) {
    Model m = four_particles();
    m.boundary.push_back(fixed({1}, {true, false, false, false, true, true}));  // symmetry x
    m.boundary.push_back(fixed({2}, {true, true, true, true, true, true}));     // clamp
    const std::vector<std::uint8_t> kink{0, 0, 0, 1};
    const BoundaryConditions bc(m, kink);
    const Vec3 n = Vec3(0.6, 0.0, 0.8);  // a normal tilted out of the symmetry plane x = 0
    const Vec3 w(1.0, 2.0, 3.0);

    // Free particle: rotation in the tangent plane, the drill axis is the normal.
    EXPECT_TRUE(bc.rotates_in_tangent_plane(0));
    EXPECT_TRUE(bc.tangent_plane_only(0));
    EXPECT_NEAR(bc.tangent_part(0, w, n).dot(n), 0.0, 1e-15);
    EXPECT_TRUE(bc.drill_axis(0, n).isApprox(n));
    EXPECT_FALSE(bc.constrained(0));

    // Symmetry plane x: only the rotation about x is free; the drill axis is the normal with
    // its x component removed, normalised.
    EXPECT_FALSE(bc.rotates_in_tangent_plane(1));
    const Vec3 w1 = bc.without_constrained_rotation(1, w, n);
    EXPECT_DOUBLE_EQ(w1.x(), 1.0);
    EXPECT_DOUBLE_EQ(w1.y(), 0.0);
    EXPECT_DOUBLE_EQ(w1.z(), 0.0);
    EXPECT_TRUE(bc.drill_axis(1, n).isApprox(Vec3::UnitZ()));
    EXPECT_TRUE(bc.constrained(1));
    EXPECT_EQ(bc.without_fixed_translation(1, w), Vec3(0.0, 2.0, 3.0));

    // Clamp: no rotation left, no drill axis.
    EXPECT_EQ(bc.without_constrained_rotation(2, w, n), Vec3::Zero());
    EXPECT_EQ(bc.drill_axis(2, n), Vec3::Zero());

    // Kink particle: three free rotations, nothing removed, no drill axis.
    EXPECT_FALSE(bc.rotates_in_tangent_plane(3));
    EXPECT_EQ(bc.without_constrained_rotation(3, w, n), w);
    EXPECT_EQ(bc.drill_axis(3, n), Vec3::Zero());
}

TEST(BoundaryConditions, PrescribedMotionsReachTheirTargetsWithTheirReactions) {
    Model m = four_particles();
    m.curves.push_back({"ramp", {{0.0, 0.0}, {1.0, 1.0}}});
    BoundaryCondition velocity;
    velocity.nodes = {0};
    velocity.prescribed = PrescribedKind::Velocity;
    velocity.value = Vec3(0, 0, 2.0);
    velocity.curve = 0;
    BoundaryCondition displacement;
    displacement.nodes = {1};
    displacement.prescribed = PrescribedKind::Displacement;
    displacement.value = Vec3(0.1, 0, 0);
    BoundaryCondition spin;
    spin.nodes = {2};
    spin.prescribed = PrescribedKind::AngularVelocity;
    spin.value = Vec3(0, 0, 3.0);
    m.boundary = {velocity, displacement, spin};
    BoundaryConditions bc(m, std::vector<std::uint8_t>(4, 0));
    EXPECT_TRUE(bc.has_prescribed_motions());
    EXPECT_TRUE(bc.prescribed_translation(0));
    EXPECT_TRUE(bc.prescribed_rotation(2));
    EXPECT_EQ(bc.drill_axis(2, Vec3::UnitZ()), Vec3::Zero());  // a prescribed rotation is complete

    ParticleState s;
    s.resize(4);
    s.x0 = m.nodes;
    s.x = m.nodes;
    s.mass.assign(4, 2.0);
    s.inertia.assign(4, 0.5);
    PrescribedMotionTimes at;
    at.load_time = 0.5;
    at.t_half = 0.55;
    at.t_next = 0.6;
    at.dt_n = 0.1;
    at.dt_new = 0.1;
    at.c1 = 1.0;
    bc.impose_prescribed_motions(s, m.curves, at);
    // velocity: ramp(t_{n+1/2}) times the value; reaction m / dt_n times the change
    EXPECT_DOUBLE_EQ(s.v[0].z(), 0.55 * 2.0);
    EXPECT_DOUBLE_EQ(s.reaction[0].z(), 2.0 / 0.1 * (0.55 * 2.0));
    // displacement (no curve): x^{n+1} = x0 + value after this step
    EXPECT_NEAR((s.x[1] + at.dt_new * s.v[1] - s.x0[1] - displacement.value).norm(), 0.0, 1e-15);
    // angular velocity: about the fixed axis, reaction moment J / dt_n times the change
    EXPECT_DOUBLE_EQ(s.omega[2].z(), 3.0);
    EXPECT_DOUBLE_EQ(s.reaction_moment[2].z(), 0.5 / 0.1 * 3.0);

    // Relaxation: the prescribed velocity is reached as a position, its integral over the
    // curve up to the load level (0.5^2 / 2 = 0.125 times the value).
    ParticleState r = s;
    r.x = m.nodes;
    r.v.assign(4, Vec3::Zero());
    at.relaxation = true;
    bc.impose_prescribed_motions(r, m.curves, at);
    EXPECT_NEAR(r.x[0].z() + at.dt_new * r.v[0].z(), 0.125 * 2.0, 1e-15);
}

// A prescription of some translation components (boundary.prescribe.components, LS-DYNA's
// *BOUNDARY_PRESCRIBED_MOTION of one DOF) sets only those: the other components keep the
// particle's own velocity, move it freely (inverse mass 1 / m there), carry no reaction, and stay
// in the out-of-balance force; two entries on one particle prescribe both their components.
TEST(BoundaryConditions, PrescribedComponentsLeaveTheOthersFree) {
    Model m = four_particles();
    BoundaryCondition along_x;
    along_x.nodes = {0, 1};
    along_x.prescribed = PrescribedKind::Velocity;
    along_x.value = Vec3(2.0, 5.0, 5.0);  // only x is prescribed: y and z are ignored
    along_x.components = {true, false, false};
    BoundaryCondition along_z;
    along_z.nodes = {1};
    along_z.prescribed = PrescribedKind::Displacement;
    along_z.value = Vec3(0, 0, 0.3);
    along_z.components = {false, false, true};
    m.boundary = {along_x, along_z};
    BoundaryConditions bc(m, std::vector<std::uint8_t>(4, 0));
    EXPECT_TRUE(bc.prescribed_translation(0));
    EXPECT_FALSE(bc.prescribed_translation(2));
    EXPECT_EQ(bc.free_inverse_mass(0, 2.0), Vec3(0.0, 0.5, 0.5));
    EXPECT_EQ(bc.free_inverse_mass(1, 2.0), Vec3(0.0, 0.5, 0.0));
    EXPECT_EQ(bc.without_constrained_translation(0, Vec3(1, 2, 3)), Vec3(0, 2, 3));
    EXPECT_EQ(bc.without_constrained_translation(1, Vec3(1, 2, 3)), Vec3(0, 2, 0));
    EXPECT_EQ(bc.where_not_prescribed(1, Vec3(7, 8, 9), Vec3(1, 2, 3)), Vec3(1, 8, 3));

    ParticleState s;
    s.resize(4);
    s.x0 = m.nodes;
    s.x = m.nodes;
    s.mass.assign(4, 2.0);
    s.inertia.assign(4, 0.5);
    s.v[0] = Vec3(-1.0, 0.25, -0.5);
    s.v[1] = Vec3(-1.0, 0.25, -0.5);
    PrescribedMotionTimes at;
    at.t_half = 0.05;
    at.t_next = 0.1;
    at.dt_n = 0.1;
    at.dt_new = 0.1;
    bc.impose_prescribed_motions(s, m.curves, at);
    EXPECT_EQ(s.v[0], Vec3(2.0, 0.25, -0.5));
    EXPECT_EQ(s.reaction[0], Vec3(2.0 / 0.1 * 3.0, 0, 0));
    EXPECT_DOUBLE_EQ(s.v[1].x(), 2.0);
    EXPECT_DOUBLE_EQ(s.v[1].y(), 0.25);
    EXPECT_NEAR(s.x[1].z() + at.dt_new * s.v[1].z(), 0.3, 1e-15);  // reaches its displacement
    EXPECT_DOUBLE_EQ(s.reaction[1].y(), 0.0);
}

// A prescribed acceleration (LS-DYNA's VAD 1): the half-step velocity steps by dt_n a(t_n) from
// the one before, whatever the forces gave, and the change is the reaction's.
TEST(BoundaryConditions, APrescribedAccelerationStepsTheVelocity) {
    Model m = four_particles();
    m.curves.push_back({"ramp", {{0.0, 0.0}, {1.0, 1.0}}});
    BoundaryCondition push;
    push.nodes = {3};
    push.prescribed = PrescribedKind::Acceleration;
    push.value = Vec3(0, 4.0, 0);
    push.curve = 0;
    push.components = {false, true, false};
    m.boundary = {push};
    BoundaryConditions bc(m, std::vector<std::uint8_t>(4, 0));
    EXPECT_TRUE(bc.prescribed_translation(3));
    ParticleState s;
    s.resize(4);
    s.x0 = s.x = m.nodes;
    s.mass.assign(4, 2.0);
    s.inertia.assign(4, 0.5);
    s.v_prev[3] = Vec3(1.0, -3.0, 0.5);
    s.v[3] = Vec3(1.5, 7.0, 0.5);  // what the forces gave: x and z stay, y is prescribed
    PrescribedMotionTimes at;
    at.load_time = 0.5;
    at.t_half = 0.55;
    at.t_next = 0.6;
    at.dt_n = 0.1;
    at.dt_new = 0.1;
    at.c1 = 1.0;
    bc.impose_prescribed_motions(s, m.curves, at);
    EXPECT_DOUBLE_EQ(s.v[3].y(), -3.0 + 0.1 * 0.5 * 4.0);  // v^{n-1/2} + dt_n ramp(t_n) a
    EXPECT_EQ(s.v[3].x(), 1.5);
    EXPECT_EQ(s.v[3].z(), 0.5);
    EXPECT_DOUBLE_EQ(s.reaction[3].y(), 2.0 / 0.1 * (-3.0 + 0.2 - 7.0));
}
