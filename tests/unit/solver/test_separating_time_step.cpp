// The critical step of a material that separates (theory.md eq. 6.4-3): separation leaves
// flaps and fragments whose highest membrane modes reach their elements' own, which L_c / c at
// time_step_scale 0.9 exceeds for an equilateral triangle (ratio 0.83). A lone equilateral
// triangle kicked at one corner (its modes all excited):
// - of a separating material, it takes the exact membrane step (0.9 x 0.827 L_c / c) and runs
//   its 2 000 steps with the energy bounded (a diverging run grows tenfold in 15 steps);
// - of the same material eroding, the step stays 0.9 L_c / c (models without separation keep
//   their steps and bytes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fpmshell/elements/membrane_time_step.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/solver/element_time_steps.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

constexpr Real k_side = 0.004, k_rho = 7850, k_e = 2.1e11, k_nu = 0.3;

Model lone_triangle(bool separates) {
    Model m;
    m.nodes = {Vec3(0, 0, 0), Vec3(k_side, 0, 0),
               Vec3(0.5 * k_side, 0.5 * std::sqrt(3.0) * k_side, 0)};
    m.triangles = {{0, 1, 2}};
    m.materials.push_back({"steel", "elastic", k_rho, k_e, k_nu});
    make_bilinear(m.materials[0], 1e12, 1e9);  // elastic throughout: nothing fails
    add_plastic_strain_failure(m.materials[0], 0.5);
    m.materials[0].failure.separates = separates;
    m.sections.push_back({0, 0.0005, 5, 3});  // thin: the membrane sets the step
    m.element_section = {0};
    InitialVelocity kick;
    kick.nodes = {0};
    kick.velocity = Vec3(1.0, 0.3, 0);
    m.initial_conditions.push_back(kick);
    m.control.end_time = 1;
    return m;
}

Real l_c_over_c() {
    const Real lc = 2 * (0.25 * std::sqrt(3.0) * k_side * k_side) / k_side;
    return lc / std::sqrt(k_e / (k_rho * (1 - k_nu * k_nu)));
}

TEST(SeparatingTimeStep, ALoneTriangleTakesItsExactMembraneStepAndStaysBounded) {
    const Model m = lone_triangle(true);  // the solver keeps a reference
    ExplicitSolver s(m);
    Real worst = 0, energy0 = 0;
    for (int n = 0; n < 2000; ++n) {
        s.step(1e30);
        const EnergyBalance& e = s.energy();
        if (n == 0) energy0 = e.external_work;
        worst = std::max(worst, std::abs(e.kinetic + e.internal) / energy0);
    }
    Mat3 c;
    c << 1, k_nu, 0, k_nu, 1, 0, 0, 0, 0.5 * (1 - k_nu);
    const Real ratio =
        membrane_step_ratio(TriangleShape(k_side, 0.5 * k_side, 0.5 * std::sqrt(3.0) * k_side), c);
    // the step follows the vibrating triangle's current shape (re-evaluated past 5 % of L_c)
    EXPECT_LT(s.last_dt(), 0.9 * ratio * l_c_over_c() * 1.06);
    // bounded: the leapfrog energy of modes at omega dt <= 1.8 swings about the work given
    // (measured below 1.2 x), where a diverging run grows without bound
    EXPECT_LT(worst, 2.0);
}

TEST(SeparatingTimeStep, AnErodingMaterialKeepsTheStepOfLcOverC) {
    const Model m = lone_triangle(false);
    ExplicitSolver s(m);
    s.step(1e30);
    EXPECT_NEAR(s.last_dt(), 0.9 * l_c_over_c(), 1e-6 * l_c_over_c());
}

}  // namespace
}  // namespace fpmshell
