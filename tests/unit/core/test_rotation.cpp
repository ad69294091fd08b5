// Rotation algebra (theory.md §1.4): exp/log round trip over the whole range of angles,
// including angles near pi where the log must take its axis from the symmetric part.
#include <gtest/gtest.h>

#include <random>

#include "fpmshell/core/rotation.hpp"

using namespace fpmshell;

TEST(Rotation, ExpLogRoundTripAllAngles) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Real angle : {0.0, 1e-9, 1e-5, 1e-3, 5e-3, 0.0099, 0.0101, 0.3, 1.0, 2.5, 3.0, 3.14, 3.1415}) {
        for (int trial = 0; trial < 20; ++trial) {
            const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
            const Vec3 phi = angle * axis;
            const Mat3 r = rotation_matrix(phi);
            // Orthogonality to round-off: |R^T R - I| ~ 1e-15.
            EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-14);
            // Round trip: near pi the log loses ~sqrt(eps)/sin digits; 1e-9 rad is plenty.
            EXPECT_LT((rotation_vector(r) - phi).norm(), angle > 3.1 ? 1e-7 : 1e-15 + 1e-13 * angle)
                << "angle " << angle;
        }
    }
}

TEST(Rotation, MinimalRotationMapsAToB) {
    const Vec3 a = Vec3(1, 2, 3).normalized(), b = Vec3(-2, 0.5, 1).normalized();
    const Mat3 r = minimal_rotation(a, b);
    EXPECT_LT((r * a - b).norm(), 1e-14);
    // Its axis is a x b: a x b is left unchanged (round-off).
    const Vec3 axis = a.cross(b);
    EXPECT_LT((r * axis - axis).norm(), 1e-14);
}
