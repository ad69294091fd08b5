// Shape-function matrices of the triangle (theory.md §3.1, §4.3, §4.7):
// - CST: any linear displacement field gives its exact constant strain (membrane patch test);
// - BCIZ and DKT rotation-only B matrices equal the reference numbers of
//   tools/theory_checks/bending_b_reference.py (independent Python implementation, plate.py);
// - both reproduce any constant-curvature field exactly when w_i = 0 (theory.md §4.3 check).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "fpmshell/elements/cst_membrane.hpp"
#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/elements/triangle_shape.hpp"

using namespace fpmshell;

TEST(Membrane, LinearFieldGivesExactConstantStrain) {
    const Real x2 = 1.7, x3 = 0.4, y3 = 1.1;
    const std::array<Real, 3> x{0.0, x2, x3}, y{0.0, 0.0, y3};
    // u = a + G x: strain [G00, G11, G01 + G10]; the deformation displacements are taken
    // relative to node 1 (u_1 = 0, theory.md §2.4).
    const Real g00 = 0.3, g01 = -0.2, g10 = 0.7, g11 = -0.4;
    std::array<Real, 3> ux, uy;
    for (std::size_t i = 0; i < 3; ++i) {
        ux[i] = g00 * x[i] + g01 * y[i];
        uy[i] = g10 * x[i] + g11 * y[i];
    }
    const std::array<Real, 3> eps = cst_strain(cst_gradients(x2, x3, y3, 1.0 / (x2 * y3)), ux, uy);
    EXPECT_NEAR(eps[0], g00, 1e-14);  // exact in exact arithmetic: round-off only
    EXPECT_NEAR(eps[1], g11, 1e-14);
    EXPECT_NEAR(eps[2], g01 + g10, 1e-14);
}

namespace {

// Reference values from plate.py for the triangle (0,0), (1.3,0), (0.4,0.9), printed by
// tools/theory_checks/bending_b_reference.py.
const Real k_bciz_ref[3][6] = {{-0.088757396449704123, -1.8836291913214984, -0.088757396449704123,
                                -0.47337278106508834, -0.17751479289940825, -0.049309664694280067},
                               {2.1904448827525744, -0.26286312611098933, 0.50953320184089401,
                                0.53644045097036541, 0.47775586237124706, -0.46399785716025022},
                               {1.3609467455621296, -0.74731536269997789, -0.69033530571992086,
                                0.02191540653079067, 0.67061143984220883, 0.92702169625246522}};
const Real k_dkt_ref[3][6] = {{-0.25693893735130852, 0.037272006344171327, -0.34615384615384609,
                               1.1153846153846152, -0.60309278350515461, -0.23195876288659784},
                              {0.74781919111816009, 0.0095162569389373262, 1.0213675213675213,
                               0.67948717948717952, -0.45303550973654061, 0.68900343642611683},
                              {0.18160190325138781, 0.85091197462331492, -1.1025641025641026,
                               0.68376068376068366, -0.92096219931271461, 1.0389461626575027}};

}  // namespace

TEST(Bending, MatricesMatchIndependentReference) {
    const TriangleShape s(1.3, 0.4, 0.9);
    const Mat36 bciz = bending_b_bciz(s, {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0});
    const Mat36 dkt = bending_b_dkt(s, {0.2, 0.5, 0.3});
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 6; ++c) {
            EXPECT_NEAR(bciz(r, c), k_bciz_ref[r][c], 1e-13);  // same formulas: round-off
            EXPECT_NEAR(dkt(r, c), k_dkt_ref[r][c], 1e-13);
        }
}

TEST(Bending, ConstantCurvatureReproducedExactly) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(0.2, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        const TriangleShape s(u(rng), u(rng) - 1.0, u(rng));
        // w = 1/2 (A x^2 + B y^2) + C x y minus its linear interpolant (so that w_i = 0):
        // the curvature [-w,xx, -w,yy, -2 w,xy] = [-A, -B, -2C] is unchanged by the removal.
        const Real a = 0.3, b = -0.7, c = 0.45;
        // Linear interpolant l = l0 + l1 x + l2 y through the nodal w values.
        Eigen::Matrix3d m;
        Eigen::Vector3d wv;
        for (int i = 0; i < 3; ++i) {
            m.row(i) << 1, s.x[i], s.y[i];
            wv(i) = 0.5 * (a * s.x[i] * s.x[i] + b * s.y[i] * s.y[i]) + c * s.x[i] * s.y[i];
        }
        const Eigen::Vector3d l = m.colPivHouseholderQr().solve(wv);
        Eigen::Matrix<Real, 6, 1> theta;  // theta_x = w,y ; theta_y = -w,x at the nodes
        for (int i = 0; i < 3; ++i) {
            const Real wx = a * s.x[i] + c * s.y[i] - l(1);
            const Real wy = b * s.y[i] + c * s.x[i] - l(2);
            theta(2 * i) = wy;
            theta(2 * i + 1) = -wx;
        }
        for (const TrianglePoint& p : triangle_rule(7)) {
            for (const Mat36& bb : {bending_b_bciz(s, p.L), bending_b_dkt(s, p.L)}) {
                const Voigt3 k = bb * theta;
                // Exact in exact arithmetic (theory.md §4.3, 1e-13 in plate.py): round-off.
                EXPECT_NEAR(k(0), -a, 1e-11);
                EXPECT_NEAR(k(1), -b, 1e-11);
                EXPECT_NEAR(k(2), -2 * c, 1e-11);
            }
        }
    }
}

TEST(Quadrature, WeightsSumAndPolynomialExactness) {
    for (int n : {3, 7}) {
        Real sum = 0, quad = 0;
        for (const auto& p : triangle_rule(n)) {
            sum += p.weight;
            quad += p.weight * p.L[0] * p.L[0];  // integral of L1^2 / A = 1/6
        }
        EXPECT_NEAR(sum, 1.0, 1e-15);
        EXPECT_NEAR(quad, 1.0 / 6.0, 1e-15);
    }
    for (int n : {2, 3, 5}) {
        Real sum = 0, z2 = 0;
        for (const auto& p : thickness_rule(n)) {
            sum += p.weight;
            z2 += p.weight * p.zeta * p.zeta;  // integral of zeta^2 over [-1,1] = 2/3
        }
        EXPECT_NEAR(sum, 2.0, 1e-15);
        EXPECT_NEAR(z2, 2.0 / 3.0, 1e-15);
    }
    EXPECT_THROW((void)triangle_rule(4), std::invalid_argument);
}

// Every rule through the thickness (theory.md §4.5) integrates the monomials of its degree
// exactly: Gauss with n points up to degree 2n - 1, Lobatto up to 2n - 3 (Abramowitz & Stegun
// 25.4.29, 25.4.32), and is symmetric, its points ascending in [-1, 1]; Lobatto's ends are the
// surfaces. Tolerance 1e-14: sums of up to 10 terms of order 1, each with its rounding.
TEST(Quadrature, EachThicknessRuleIsExactToItsDegree) {
    const auto check = [](std::span<const ThicknessPoint> rule, int degree, const char* family) {
        const int n = static_cast<int>(rule.size());
        for (int d = 0; d <= degree; ++d) {
            Real q = 0;
            for (const ThicknessPoint& p : rule) q += p.weight * std::pow(p.zeta, d);
            const Real exact = d % 2 == 1 ? 0.0 : 2.0 / (d + 1);
            EXPECT_NEAR(q, exact, 1e-14) << family << " " << n << " points, degree " << d;
        }
        // one degree more is not exact (the rule is the one of its family, not a finer one)
        Real q = 0;
        for (const ThicknessPoint& p : rule) q += p.weight * std::pow(p.zeta, degree + 1);
        EXPECT_GT(std::abs(q - 2.0 / (degree + 2)), 1e-6) << family << " " << n;
        for (std::size_t i = 0; i < rule.size(); ++i) {
            EXPECT_EQ(rule[i].zeta, -rule[rule.size() - 1 - i].zeta) << family << " " << n;
            EXPECT_EQ(rule[i].weight, rule[rule.size() - 1 - i].weight) << family << " " << n;
            if (i > 0) {
                EXPECT_LT(rule[i - 1].zeta, rule[i].zeta) << family << " " << n;
            }
        }
    };
    for (int n = 1; n <= k_max_thickness_points; ++n) {
        check(gauss_thickness_rule(n), 2 * n - 1, "Gauss");
        if (n >= 3) {
            check(lobatto_thickness_rule(n), 2 * n - 3, "Lobatto");
            EXPECT_EQ(lobatto_thickness_rule(n).front().zeta, -1.0);
        }
    }
    // the default rule of a count: Gauss for 1 and 2, Lobatto from 3 (model-format.md)
    EXPECT_EQ(thickness_rule(2).data(), gauss_thickness_rule(2).data());
    EXPECT_EQ(thickness_rule(4).data(), lobatto_thickness_rule(4).data());
    EXPECT_THROW((void)gauss_thickness_rule(11), std::invalid_argument);
    EXPECT_THROW((void)lobatto_thickness_rule(2), std::invalid_argument);
}
