// The exact membrane step (theory.md eq. 6.4-3) where the L_c / c of §6.4 is no bound: a piece
// of one or two elements joined by their sides has its highest membrane mode above
// 2 / (0.9 L_c / c) (tools/theory_checks/test_dt_pieces.py: omega x 0.9 L_c / c = 2.18 for a lone
// equilateral triangle, 2.03 for two sharing a side, 2.11 for two sharing a corner only, 1.96
// for three in a row, 1.87 for a large patch); with L_c / c a lone triangle diverges in 11
// steps, two sharing a side in 32, two sharing a corner in 16.
// - A lone equilateral triangle kicked at one corner of a separating material takes the exact
//   step and runs 2 000 steps with the energy bounded.
// - Two triangles sharing a side take it too; three in a row keep 0.9 L_c / c (connected
//   meshes keep their steps and bytes).
// - Three triangles in a row whose middle one erodes: the two left sharing a corner take the
//   exact step from the erosion on and stay bounded; a restart resumes bitwise.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "fpmshell/elements/membrane_time_step.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/io/restart_archive.hpp"
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

TEST(ExactMembraneStep, ALoneTriangleTakesItsExactMembraneStepAndStaysBounded) {
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

TEST(ExactMembraneStep, TwoTrianglesSharingASideTakeItThreeInARowKeepLcOverC) {
    Model m = lone_triangle(false);
    const Real h = 0.5 * std::sqrt(3.0) * k_side;
    m.nodes.push_back(Vec3(1.5 * k_side, h, 0));
    m.triangles.push_back({1, 3, 2});
    m.element_section.push_back(0);
    {
        ExplicitSolver s(m);
        for (const Index e : {0, 1}) EXPECT_TRUE(s.elements().time_steps().exact_membrane(e));
        Real worst = 0, energy0 = 0;
        for (int n = 0; n < 2000; ++n) {
            s.step(1e30);
            if (n == 0) energy0 = s.energy().external_work;
            worst = std::max(worst, std::abs(s.energy().kinetic + s.energy().internal) / energy0);
        }
        EXPECT_LT(worst, 2.0);  // bounded (with L_c / c it diverges in 32 steps)
    }
    m.nodes.push_back(Vec3(k_side, 2 * h, 0));
    m.triangles.push_back({2, 3, 4});
    m.element_section.push_back(0);
    ExplicitSolver s(m);
    s.step(1e30);
    EXPECT_NEAR(s.last_dt(), 0.9 * l_c_over_c(), 1e-6 * l_c_over_c());
    for (const Index e : {0, 1, 2}) EXPECT_FALSE(s.elements().time_steps().exact_membrane(e));
}

TEST(ExactMembraneStep, TrianglesLeftSharingACornerByErosionTakeTheExactStep) {
    // 0 (0, 0, 2) and 2 (2, 3, 4) share corner 2 and each a side with 1 (1, 3, 2), which is of
    // a soft material failing at once; the corners 1 and 3 pulled apart tear it
    Model m = lone_triangle(false);
    const Real h = 0.5 * std::sqrt(3.0) * k_side;
    m.nodes.push_back(Vec3(1.5 * k_side, h, 0));
    m.nodes.push_back(Vec3(k_side, 2 * h, 0));
    m.triangles = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
    m.materials[0].failure = {};  // 0 and 2 elastic throughout
    m.materials.push_back({"soft", "elastic", k_rho, k_e, k_nu});
    make_bilinear(m.materials[1], 1e6, 1e6);
    add_plastic_strain_failure(m.materials[1], 1e-3);
    m.sections.push_back({1, 0.0005, 5, 3});
    m.element_section = {0, 1, 0};
    m.initial_conditions.clear();
    InitialVelocity apart;
    apart.nodes = {1};
    apart.velocity = Vec3(0, -20.0, 0);
    m.initial_conditions.push_back(apart);
    apart.nodes = {3};
    apart.velocity = Vec3(20.0, 20.0, 0);
    m.initial_conditions.push_back(apart);
    ExplicitSolver s(m);
    int n = 0;
    for (; n < 2000 && !s.elements().eroded(1); ++n) s.step(1e30);
    ASSERT_TRUE(s.elements().eroded(1));
    EXPECT_FALSE(s.elements().time_steps().exact_membrane(1));
    for (const Index e : {0, 2}) EXPECT_TRUE(s.elements().time_steps().exact_membrane(e));
    const Real energy0 = s.energy().external_work;
    Real worst = 0;
    for (int k = 0; k < 2000; ++k) {
        s.step(1e30);
        worst = std::max(
            worst, std::abs(s.energy().kinetic + s.energy().internal + s.energy().eroded_internal) /
                       energy0);
    }
    EXPECT_LT(worst, 2.0);  // bounded (as above); diverging, it grows without bound
    // a restart after the erosion resumes bitwise: the flags come back from the eroded elements
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("fpmshell_corner_held_restart_" + std::to_string(::getpid()) + ".bin");
    RestartWriter out;
    s.save(out);
    out.save(file);
    RestartReader in(file);
    ExplicitSolver resumed(m);
    resumed.load(in);
    std::filesystem::remove(file);
    for (const Index e : {0, 2}) EXPECT_TRUE(resumed.elements().time_steps().exact_membrane(e));
    for (int k = 0; k < 500; ++k) {
        s.step(1e30);
        resumed.step(1e30);
    }
    EXPECT_EQ(resumed.state().x, s.state().x);
    EXPECT_EQ(resumed.last_dt(), s.last_dt());
}

}  // namespace
}  // namespace fpmshell
