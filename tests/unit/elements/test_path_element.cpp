// The path element (theory.md §2) under its two rotation policies: within the small-angle
// bounds the series (the SIMD blocks') and the forms for any angle (the general element's) give
// the same local triangle to round-off; the series report every lane past a bound, and both
// report the path elements no stable step produces (§2.8).
#include <gtest/gtest.h>

#include <random>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/elements/path_element.hpp"

using namespace fpmshell;

namespace {

/// A triangle moved rigidly by the rotation `angle * axis` (about node 1), deformed by a small
/// strain `stretch` along x and bent by `bend` at each node.
TriangleMotion<Real> sample_motion(Real angle, Real stretch, Real bend) {
    const std::array<Vec3, 3> base{Vec3(0.1, -0.2, 0.3), Vec3(1.4, 0.1, 0.5), Vec3(0.3, 1.1, -0.2)};
    const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
    const Mat3 r = rotation_matrix(angle * axis);
    TriangleMotion<Real> m;
    for (std::size_t i = 0; i < 3; ++i) {
        Vec3 p = base[i] - base[0];
        p.x() *= 1.0 + stretch;
        m.base[i] = to_v3(base[i]);
        m.current[i] = to_v3(base[0] + r * p + Vec3(0.01, 0.02, -0.03));
        m.dtheta[i] = to_v3(angle * axis + Vec3(bend * Real(i + 1), -bend, 0.5 * bend));
        m.drill_axis[i] = V3<Real>{0.0, 0.0, 0.0};
    }
    return m;
}

Real max_difference(const LocalTriangle<Real>& a, const LocalTriangle<Real>& b) {
    Real d = std::max({std::abs(a.x2 - b.x2), std::abs(a.x3 - b.x3), std::abs(a.y3 - b.y3),
                       std::abs(a.area - b.area)});
    for (std::size_t i = 0; i < 3; ++i)
        d = std::max({d, std::abs(a.ux[i] - b.ux[i]), std::abs(a.uy[i] - b.uy[i])});
    for (std::size_t q = 0; q < 6; ++q) d = std::max(d, std::abs(a.th[q] - b.th[q]));
    for (std::size_t i = 0; i < 3; ++i)
        d = std::max({d, std::abs(a.frame_current.row[i].x - b.frame_current.row[i].x),
                      std::abs(a.frame_current.row[i].y - b.frame_current.row[i].y),
                      std::abs(a.frame_current.row[i].z - b.frame_current.row[i].z)});
    return d;
}

}  // namespace

TEST(PathElement, SeriesAndExactRotationsAgreeWithinTheBounds) {
    for (Real angle : {0.0, 1e-6, 1e-4, 5e-3}) {
        const TriangleMotion<Real> m = sample_motion(angle, 1e-4, 1e-4);
        LocalTriangle<Real> series, exact;
        PathElementChecks<Real> series_checks, exact_checks;
        EXPECT_TRUE(path_element<SeriesRotations>(m, series, series_checks)) << angle;
        EXPECT_TRUE(path_element<ExactRotations>(m, exact, exact_checks)) << angle;
        // The series are truncated below 1e-17 (core/rotation.hpp) and the two forms round
        // differently: O(1) coordinates through ~5 rotations, 1e-14 is ~50 eps.
        EXPECT_LT(max_difference(series, exact), 1e-14) << angle;
        EXPECT_EQ(series_checks.characteristic_length, exact_checks.characteristic_length);
        // the deformation is seen: the stretch of edge 1-2 and the bending rotations
        // edge 1-2, a_2 = (1.3, 0.3, 0.2), stretched by 1e-4 along x: d|a_2| = 1e-4 a_2x^2 / |a_2|
        // to first order (second-order terms ~1e-8 |a_2|)
        EXPECT_NEAR(exact.ux[1], 1e-4 * 1.3 * 1.3 / exact.x2, 1e-6 * exact.x2);
        EXPECT_GT(std::abs(exact.th[0]), 1e-5);
    }
}

TEST(PathElement, SeriesReportTheRotationsPastTheirBounds) {
    // a rigid rotation of 0.02 rad: past the 0.01 rad of the series, any angle for the forms
    const TriangleMotion<Real> m = sample_motion(0.02, 0.0, 0.0);
    LocalTriangle<Real> series, exact;
    PathElementChecks<Real> series_checks, exact_checks;
    EXPECT_FALSE(path_element<SeriesRotations>(m, series, series_checks));
    EXPECT_TRUE(series_checks.within_step_bounds);  // a step can produce it
    EXPECT_TRUE(path_element<ExactRotations>(m, exact, exact_checks));
    for (std::size_t q = 0; q < 6; ++q)
        EXPECT_LT(std::abs(exact.th[q]), 1e-14);  // rigid: no deformation (round-off)
}

TEST(PathElement, BothPoliciesReportWhatNoStableStepProduces) {
    // §2.8: a tilt past 90 deg, an area halved, a collapsed triangle
    const auto check = [](const TriangleMotion<Real>& m, const char* what) {
        LocalTriangle<Real> local;
        PathElementChecks<Real> checks;
        EXPECT_FALSE(path_element<SeriesRotations>(m, local, checks)) << what;
        EXPECT_FALSE(checks.within_step_bounds) << what;
        EXPECT_FALSE(path_element<ExactRotations>(m, local, checks)) << what;
        EXPECT_FALSE(checks.within_step_bounds) << what;
    };
    check(sample_motion(2.0, 0.0, 0.0), "tilt of 2 rad");
    check(sample_motion(0.0, -0.6, 0.0), "area 0.4 times the base");
    TriangleMotion<Real> collapsed = sample_motion(0.0, 0.0, 0.0);
    collapsed.current[2] =
        collapsed.current[0] + 0.5 * (collapsed.current[1] - collapsed.current[0]);
    check(collapsed, "collapsed");
}
