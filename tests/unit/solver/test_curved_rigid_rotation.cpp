// Rigid rotation of a doubly-curved shell as the solver itself produces it (theory.md §2.6,
// eq. 2.6c): the particles carry the rotations of their tangent planes only, so a spin about an
// axis near their normals reaches the path elements with the part about each normal missing.
// The elements must supply it from their own rigid rotation; without that, the spin bends the
// shell by (rotation about the normal) x (tilt between particle and element normals), a strain
// that does not vanish under mesh refinement (the MacNeal-Harder hemisphere converged 11 % stiff).
#include <gtest/gtest.h>

#include <cmath>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

using namespace fpmshell;

namespace {

constexpr Real k_density = 7800, k_young = 2.1e11, k_thickness = 0.02;

/// A free spherical cap (radius 2, half angle 40 deg: particle and element normals differ by up
/// to ~5 deg) spinning rigidly at `rate` rad/s about `axis` through the sphere's centre.
Model spinning_cap(const Vec3& axis, Real rate, Index divisions, bool j2) {
    SphericalCapParams cp;
    cp.radius = 2.0;
    cp.half_angle_deg = 40;
    cp.sector_deg = 360;
    cp.divisions = divisions;
    const MeshData mesh = generate_spherical_cap(cp);
    Model m;
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    m.materials.push_back({"steel", "elastic", k_density, k_young, 0.3});
    m.sections.push_back({0, k_thickness, 2, 3});
    if (j2) {  // the plastic sections' path (5 x 7 points, trial check), far from yielding
        make_bilinear(m.materials[0], 250e6, 0.0);
        m.sections[0] = {0, k_thickness, 5, 7};
    }
    m.element_section.assign(m.triangles.size(), 0);
    m.control.bending = BendingKernel::Dkt;
    const Vec3 spin = rate * axis.normalized();
    for (Index p = 0; p < static_cast<Index>(m.nodes.size()); ++p) {
        InitialVelocity ic;
        ic.nodes = {p};
        ic.velocity = spin.cross(m.nodes[static_cast<std::size_t>(p)]);  // centre at the origin
        ic.angular_velocity = spin;  // the solver keeps its tangent-plane part
        m.initial_conditions.push_back(ic);
    }
    return m;
}

struct SpinResult {
    Real strain_to_kinetic = 0;  ///< strain energy / kinetic energy at the end
    Real max_moment = 0;         ///< largest nodal moment |m_int| over the run
    Real moment_scale = 0;       ///< D / R x total rotation: the moment of a spurious curvature
};

SpinResult spin(const Vec3& axis, Real rate, long steps, Index divisions, bool j2) {
    const Model m = spinning_cap(axis, rate, divisions, j2);
    ExplicitSolver s(m);
    SpinResult r;
    for (long i = 0; i < steps; ++i) {
        s.step(1e30);
        for (const Vec3& mi : s.state().m_int) r.max_moment = std::max(r.max_moment, mi.norm());
    }
    r.strain_to_kinetic = s.energy().internal / s.energy().kinetic;
    const Real bending_stiffness = k_young * std::pow(k_thickness, 3) / (12.0 * (1 - 0.09));
    const Real element_area = 0.5 * 4.0 * 4.0 * M_PI * (1 - std::cos(40.0 * M_PI / 180)) /
                              static_cast<Real>(m.triangles.size());
    r.moment_scale = bending_stiffness / 2.0 * rate * s.time() * element_area;
    return r;
}

}  // namespace

TEST(CurvedRigidRotation, SpinAboutAxesNearTheNormalsBendsNothing) {
    // Axes through the centre: along the apex normal, and tilted 17 and 45 deg from it; the
    // particles' normals lie within 40 deg of the apex one, so the spin has a large component
    // about every particle's normal.
    for (bool j2 : {false, true}) {
        for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(0.3, 0.1, 1), Vec3(1, -0.2, 1)}) {
            SCOPED_TRACE(::testing::Message()
                         << (j2 ? "J2" : "elastic") << ", axis " << axis.transpose());
            // 0.05 rad/s for 3000 steps (~0.1 s: 0.005 rad in all). The centripetal stretch of a
            // rigid spin is of order (rate t)^2, its energy of order (rate t)^4 against the
            // kinetic's rate^2: ~1e-9 of it (measured 2e-10 .. 1.4e-9). Without eq. 2.6c the
            // spurious curvature takes 0.3 to 100 times the kinetic energy.
            const SpinResult r = spin(axis, 0.05, 3000, 6, j2);
            EXPECT_LT(r.strain_to_kinetic, 1e-7);
            // Nodal moments: at most 1 % of D / R x rotation x element area, the nodal moment of
            // a curvature of (rotation about the normal) / R (measured 1.1e-4 of it; 1.3 to 1.9
            // times it without eq. 2.6c).
            EXPECT_LT(r.max_moment, 0.01 * r.moment_scale);
        }
    }
}
