// The exact membrane critical step of an isolated lumped-mass triangle (theory.md eq. 6.4-3,
// elements/membrane_time_step.hpp), as a ratio to the L_c / c of §6.4:
// - against the 6-DOF eigenproblem of the element itself (K = A h B^T C B, mass rho h A / 3 per
//   corner), solved here directly;
// - against tools/theory_checks/test_dt.py's ratios of five shapes (0.83 ... 0.94: L_c / c is no
//   bound for the triangle on its own at time_step_scale 0.9);
// - independent of the triangle's size and of the scale of the elasticity given.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "fpmshell/elements/membrane_time_step.hpp"

namespace fpmshell {
namespace {

Mat3 plane_stress(Real e, Real nu) {
    Mat3 c;
    c << 1, nu, 0, nu, 1, 0, 0, 0, 0.5 * (1 - nu);
    return (e / (1 - nu * nu)) * c;
}

/// 2 / omega_max of the 6-DOF CST with corners (0,0), (x2,0), (x3,y3), over L_c / c.
Real ratio_from_the_element(Real x2, Real x3, Real y3, Real e, Real nu, Real rho, Real h) {
    const Real xs[3] = {0, x2, x3}, ys[3] = {0, 0, y3};
    const Real two_area = x2 * y3;
    Eigen::Matrix<Real, 3, 6> b = Eigen::Matrix<Real, 3, 6>::Zero();
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const Real bi = (ys[j] - ys[k]) / two_area, ci = (xs[k] - xs[j]) / two_area;
        b(0, 2 * i) = bi;
        b(1, 2 * i + 1) = ci;
        b(2, 2 * i) = ci;
        b(2, 2 * i + 1) = bi;
    }
    const Real area = 0.5 * two_area;
    const Eigen::Matrix<Real, 6, 6> k = area * h * b.transpose() * plane_stress(e, nu) * b;
    const Real mass = rho * h * area / 3;
    const Real omega2 =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 6, 6>>(k / mass).eigenvalues().maxCoeff();
    const Real longest = std::max({x2, std::hypot(x3 - x2, y3), std::hypot(x3, y3)});
    const Real lc = two_area / longest;
    const Real c = std::sqrt(e / (rho * (1 - nu * nu)));
    return (2 / std::sqrt(omega2)) / (lc / c);
}

TEST(MembraneTimeStep, IsTheIsolatedTrianglesHighestMode) {
    const Real shapes[][3] = {
        {1, 0.5, std::sqrt(3.0) / 2}, {1, 0, 1}, {2, 0, 1}, {1, 0.5, 0.1}, {1, 0.1, 0.3},
        {0.004, 0.0013, 0.0031}};
    for (const auto& s : shapes)
        for (const Real nu : {0.0, 0.3, 0.45}) {
            const Real expected = ratio_from_the_element(s[0], s[1], s[2], 2.1e11, nu, 7850, 0.002);
            EXPECT_NEAR(
                membrane_step_ratio(TriangleShape(s[0], s[1], s[2]), plane_stress(2.1e11, nu)),
                expected, 1e-12 * expected)
                << s[0] << " " << s[1] << " " << s[2] << " nu " << nu;
        }
}

TEST(MembraneTimeStep, MatchesTheTheoryChecksRatios) {
    // tools/theory_checks/test_dt.py (nu = 0.3): equilateral 0.827, right isosceles 0.923;
    // numpy's eigenvalues of the same element: 0.8268982306, 0.9234734203, 2:1 0.8727552375
    const Mat3 c = plane_stress(1.0, 0.3);
    EXPECT_NEAR(membrane_step_ratio(TriangleShape(1, 0.5, std::sqrt(3.0) / 2), c), 0.8268982306,
                1e-9);
    EXPECT_NEAR(membrane_step_ratio(TriangleShape(1, 0, 1), c), 0.9234734203, 1e-9);
    EXPECT_NEAR(membrane_step_ratio(TriangleShape(2, 0, 1), c), 0.8727552375, 1e-9);
    // every shape below 0.95: L_c / c at time_step_scale 0.9 exceeds the equilateral's own bound
    EXPECT_LT(membrane_step_ratio(TriangleShape(1, 0.5, std::sqrt(3.0) / 2), c), 0.9);
}

TEST(MembraneTimeStep, DependsOnTheShapeAlone) {
    const Mat3 c = plane_stress(2.1e11, 0.3);
    const Real r = membrane_step_ratio(TriangleShape(1, 0.3, 0.7), c);
    EXPECT_NEAR(membrane_step_ratio(TriangleShape(7e-3, 2.1e-3, 4.9e-3), c), r, 1e-12);
    EXPECT_NEAR(membrane_step_ratio(TriangleShape(1, 0.3, 0.7), (1e-6 / 12) * c), r, 1e-12);
    EXPECT_TRUE(std::isinf(membrane_step_ratio(TriangleShape(1, 0.5, 0), c)));  // degenerate
}

}  // namespace
}  // namespace fpmshell
