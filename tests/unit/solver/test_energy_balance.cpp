// The energy balance's relative error (theory.md eqs. 6.8-1, 6.8-2): a ratio of physical
// energies, not of rounding errors. A model that does not move has energies of the order of the
// last bits of its positions; without the rounding floor the ratio of such energies can be
// anything up to 100 % (a triangle held by friction stopped its run at step 11 in the
// sanitizer build, whose arithmetic rounds differently).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fpmshell/solver/energy_balance.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "sliding_triangle.hpp"

using namespace fpmshell;

TEST(EnergyBalance, EnergiesAtTheRoundingLevelAreNotAnError) {
    EnergyBalance e;
    e.kinetic = 1.7e-24;               // the held triangle's below: velocities of rounding size
    EXPECT_DOUBLE_EQ(e.error(), 1.0);  // no floor: a ratio of rounding errors
    e.rounding = 1e-13;                // what rounding can put into the works of a few steps
    EXPECT_LT(std::abs(e.error()), 1e-10);
    // physical energies far above the floor: the error is theirs alone
    e.kinetic = 2.0;
    e.external_work = 1.0;
    EXPECT_DOUBLE_EQ(e.error(), 0.5);
}

TEST(EnergyBalance, ATriangleHeldByFrictionRunsWithABalanceAtTheRoundingLevel) {
    // The friction tests' triangle (legs 1 m, h = 0.01 m) on a fixed plane, pressed by its
    // weight m g and pushed along the plane by half the static friction (mu = 0.3): nothing
    // moves.
    const Real h = test::k_h, mu = 0.3;
    Model m = test::sliding_triangle({mu, Vec3::Zero(), 0.5 * mu});
    // far below the default (0.5): 2.4e-5 without the floor in an optimised g++ build, 1.0 in
    // the sanitizer build; with it the ratio is of the order of 1e-11
    m.control.energy_error_limit = 1e-6;
    const std::vector<Real> masses = ExplicitSolver(m).state().mass;  // (a copy: the solver goes)
    Real weight = 0;
    for (Real mass : masses) weight += mass * test::k_g;
    ExplicitSolver s(m);
    while (s.time() < 0.02) ASSERT_NO_THROW(s.step(1e30)) << "step " << s.steps();
    EXPECT_GT(s.steps(), 100);
    for (const Vec3& v : s.state().v) EXPECT_NEAR(v.x(), 0.0, 1e-9);  // held
    EXPECT_LT(std::abs(s.energy().error()), 1e-6);
    // The floor is of the order of the rounding of the positions (eps |x| ~ 2e-16 m per step
    // under forces of ~1e3 N): far below the work of the weight over 1e-8 of the thickness, so
    // that it cannot hide an imbalance anyone would see.
    EXPECT_GT(s.energy().rounding, 0.0);
    EXPECT_LT(s.energy().rounding, 1e-8 * weight * h);
}

// The forces of t_0 do work over the first half step too (eq. 6.8-3): the leapfrog kinetic
// energy of t_0, 1/2 m v^{-1/2} v^{1/2} with v^{-1/2} := v^0, already holds their effect, so the
// first cycle books them over dt_n v^{-1/2} and the second takes the last step's forces at half
// weight. A triangle that starts on a fixed plane moving into it at 1 m/s is stopped in the first
// step (a perfectly plastic impact): the contact takes its whole kinetic energy and the balance
// closes to rounding; it lost it unbooked before (-100 % at once: the run stopped).
TEST(EnergyBalance, AnImpactAtTheFirstStepIsBookedWhole) {
    Model m = test::sliding_triangle({0.0, Vec3(0, 0, -1)});
    m.loads.clear();  // no weight: the impact alone
    ExplicitSolver s(m);
    const Real kinetic0 = s.energy().kinetic;
    ASSERT_GT(kinetic0, 0.0);
    for (int step = 0; step < 20; ++step) ASSERT_NO_THROW(s.step(1e30)) << "step " << step;
    for (const Vec3& v : s.state().v) EXPECT_NEAR(v.z(), 0.0, 1e-12);  // stopped at once
    EXPECT_NEAR(s.energy().contact, kinetic0, 1e-12 * kinetic0);
    EXPECT_LT(std::abs(s.energy().error()), 1e-12);
}
