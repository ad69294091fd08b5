// Gravity (theory.md eq. 6.7-4, `loads` of type gravity): each loaded particle takes its mass
// times the acceleration, scaled by the load's curve.
// - A free plate (a rigid translation: no internal force) falls with the acceleration g at
//   every particle, to the rounding of its positions, and its energy balance closes: the kinetic
//   energy is the work of gravity.
// - On some elements, only their particles are loaded, each by m g.
// - A curve scales it: at half the curve's value, half the force.
#include <gtest/gtest.h>

#include "fpmshell/solver/explicit_solver.hpp"
#include "one_section_model.hpp"
#include "run_to.hpp"

using namespace fpmshell;

namespace {

const Vec3 k_g(0.0, 0.0, -9.81);

Model falling_plate() {
    Model m = test::alternate_plate(6);
    Load gravity;
    gravity.type = LoadType::Gravity;
    for (Index p = 0; p < m.n_particles(); ++p) gravity.nodes.push_back(p);
    gravity.vector = k_g;
    m.loads.push_back(gravity);
    m.control.end_time = 1;
    return m;
}

}  // namespace

TEST(Gravity, AFreePlateFallsAtGAndItsBalanceCloses) {
    const Model m = falling_plate();
    ExplicitSolver s(m);
    test::run_to(s, 2e-3);
    for (Index p = 0; p < m.n_particles(); ++p) {
        // the internal forces of the translation are zero to the rounding of the positions
        // (E dx / L with dx ~ 1e-16 m: ~1e-4 Pa, a few 1e-7 of g on these particles)
        EXPECT_LT((s.acceleration(p) - k_g).norm(), 1e-6 * k_g.norm()) << "particle " << p;
        EXPECT_NEAR(s.state().f_ext[static_cast<std::size_t>(p)].z(),
                    s.state().mass[static_cast<std::size_t>(p)] * k_g.z(), 1e-15);
    }
    const EnergyBalance& e = s.energy();
    EXPECT_GT(e.kinetic, 0.0);
    EXPECT_NEAR(e.kinetic, e.external_work, 1e-9 * e.kinetic);
    EXPECT_LT(std::abs(e.error()), 1e-9);
}

TEST(Gravity, OnSomeElementsOnlyTheirParticlesAreLoadedAndACurveScalesIt) {
    Model m = falling_plate();
    // the elements left of x = 0.5: their particles alone, at half the acceleration
    std::vector<std::uint8_t> loaded(static_cast<std::size_t>(m.n_particles()), 0);
    Load& gravity = m.loads[0];
    gravity.nodes.clear();
    for (const auto& t : m.triangles) {
        Real xc = 0;
        for (const Index p : t) xc += m.nodes[static_cast<std::size_t>(p)].x() / 3;
        if (xc < 0.5)
            for (const Index p : t) loaded[static_cast<std::size_t>(p)] = 1;
    }
    for (Index p = 0; p < m.n_particles(); ++p)
        if (loaded[static_cast<std::size_t>(p)]) gravity.nodes.push_back(p);
    m.curves.push_back({"half", {{0, 0.5}, {1, 0.5}}});
    gravity.curve = 0;
    ExplicitSolver s(m);
    s.step(1e30);
    for (Index p = 0; p < m.n_particles(); ++p) {
        const auto up = static_cast<std::size_t>(p);
        const Vec3 expected =
            loaded[up] ? Vec3(0.5 * s.state().mass[up] * k_g) : Vec3(Vec3::Zero());
        EXPECT_EQ(s.state().f_ext[up], expected) << "particle " << p;
    }
}
