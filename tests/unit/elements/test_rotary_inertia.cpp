// The rotary inertia shares of control.rotary_inertia (elements/lumped_inertia.hpp, theory.md
// §6.2) against the formulas written out here: option B (Kennedy, Belytschko & Lin), Abaqus's
// factor R = [16 + (3 L^2 / 4 h^2)^4]^(1/4) (eq. 6.2a) and OpenRadioss's A/4.5 + h^2/12
// (eq. 6.2b); the masses are the same for all; the bending step of thick elements stays below a
// limit however large the inertia.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fpmshell/elements/bending_time_step.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"

using namespace fpmshell;

TEST(RotaryInertia, BelytschkoIsTheOptionBShareBitwise) {
    const NodeInertiaShare b =
        node_inertia_share(RotaryInertia::Belytschko, 7800, 0.002, 3e-5, 6e-3);
    const NodeInertiaShare l = lumped_node_share(7800, 0.002, 3e-5);
    EXPECT_EQ(b.mass, l.mass);
    EXPECT_EQ(b.inertia, l.inertia);
    EXPECT_EQ(b.gyration2, l.gyration2);
}

TEST(RotaryInertia, RadiossShareIsMassTimesAreaOver4p5PlusThicknessSquaredOver12) {
    const Real rho = 2700, h = 0.001, area = 2e-5;
    const NodeInertiaShare s = node_inertia_share(RotaryInertia::Radioss, rho, h, area, 5e-3);
    const Real m = rho * h * area / 3;
    // tolerance: a few roundings of the same products
    EXPECT_NEAR(s.mass, m, 1e-15 * m);
    EXPECT_NEAR(s.inertia, m * (area / 4.5 + h * h / 12), 1e-15 * s.inertia);
}

TEST(RotaryInertia, AbaqusFactorFollowsItsFormulaAndLimits) {
    // q = 3 L^2 / (4 h^2) on both sides of the branch at q = 2, against the formula as written
    // (1e-14: pow against two square roots, a few ulps)
    for (const Real q : {0.0, 0.3, 1.0, 1.999, 2.0, 2.001, 5.0, 40.0}) {
        const Real h = 0.01, edge = std::sqrt(q * 4 * h * h / 3);
        const Real expected = std::pow(16 + std::pow(q, 4), 0.25);
        EXPECT_NEAR(abaqus_rotary_factor(h, edge), expected, 1e-14 * expected) << q;
    }
    EXPECT_EQ(abaqus_rotary_factor(0.01, 0.0), 2.0);  // an element far thicker than long
    // a very thin element: R -> q (q^4 alone would overflow at q = 1e80)
    const Real thin = abaqus_rotary_factor(1e-40, 1.0);
    EXPECT_NEAR(thin, 0.75e80, 1e-14 * 0.75e80);
    const Real rho = 7800, h = 0.002, area = 1e-4, edge = 0.012;
    const NodeInertiaShare s = node_inertia_share(RotaryInertia::Abaqus, rho, h, area, edge);
    const Real m = rho * h * area / 3;
    // the element's R rho A h^3 / 12 split over its 3 nodes
    const Real expected = abaqus_rotary_factor(h, edge) * rho * area * h * h * h / 12 / 3;
    EXPECT_NEAR(s.mass, m, 1e-15 * m);
    EXPECT_NEAR(s.inertia, expected, 1e-14 * expected);
}

TEST(RotaryInertia, ThinRightTrianglesAbaqusMatchesOptionBAndRadiossIsLarger) {
    // right isosceles triangle, legs L (shortest edge), h = L / 20: Abaqus's R h^2 / 12 tends to
    // L^2 / 16 = A / 8 (option B's in-plane term); OpenRadioss's A / 4.5 is 16/9 of it.
    const Real legs = 0.01, h = legs / 20, area = 0.5 * legs * legs;
    const Real b = node_inertia_share(RotaryInertia::Belytschko, 1, h, area, legs).gyration2;
    const Real a = node_inertia_share(RotaryInertia::Abaqus, 1, h, area, legs).gyration2;
    const Real r = node_inertia_share(RotaryInertia::Radioss, 1, h, area, legs).gyration2;
    // option B adds h^2 / 12 (0.3 % of A / 8 here), Abaqus's R differs from q by < 1e-6
    EXPECT_NEAR(a / b, 1.0, 4e-3);
    EXPECT_NEAR(r / b, (area / 4.5 + h * h / 12) / (area / 8 + h * h / 12), 1e-14);
    EXPECT_GT(r / b, 1.7);
}

TEST(RotaryInertia, TheBendingStepOfThickElementsIsBoundedWhateverTheInertia) {
    // theory.md §6.2: the square tube's elements (steel, h = 3 mm, right triangles with legs
    // 3.33 x 6.25 mm and 1.67 x 3.125 mm), bending step / membrane step L_c / c (§6.4) with
    // option B, eq. 6.2a, eq. 6.2b and J -> infinity; within 0.005 of the figures quoted there
    // (their last digit)
    struct Case {
        Real x, y, option_b, abaqus, radioss, limit;
    };
    const Real e = 210e9, nu = 0.3, rho = 7850, h = 3e-3;
    for (const Case& c : {Case{3.333e-3, 6.25e-3, 0.86, 0.79, 0.95, 1.25},
                          Case{1.667e-3, 3.125e-3, 0.51, 0.53, 0.52, 0.63}}) {
        const TriangleShape shape(c.x, 0.0, c.y);
        Mat3 d;
        d << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
        d *= e / (1 - nu * nu) * h * h * h / 12;
        const Real area = 0.5 * c.x * c.y;
        const Real membrane =
            2 * area / std::hypot(c.x, c.y) / std::sqrt(e / (rho * (1 - nu * nu)));
        auto ratio = [&](RotaryInertia kind, Real inertia_factor) {
            const NodeInertiaShare s = node_inertia_share(kind, rho, h, area, std::min(c.x, c.y));
            return bending_critical_dt(BendingKernel::Dkt, shape, d, s.mass,
                                       inertia_factor * s.inertia) /
                   membrane;
        };
        EXPECT_NEAR(ratio(RotaryInertia::Belytschko, 1), c.option_b, 0.005) << c.x;
        EXPECT_NEAR(ratio(RotaryInertia::Abaqus, 1), c.abaqus, 0.005) << c.x;
        EXPECT_NEAR(ratio(RotaryInertia::Radioss, 1), c.radioss, 0.005) << c.x;
        EXPECT_NEAR(ratio(RotaryInertia::Belytschko, 1e6), c.limit, 0.005) << c.x;
        EXPECT_LT(ratio(RotaryInertia::Belytschko, 1e12), c.limit + 0.005) << c.x;
    }
}
