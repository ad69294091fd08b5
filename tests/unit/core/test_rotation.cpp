// Rotation algebra (theory.md §1.4): exp/log round trip over the whole range of angles,
// including angles near pi where the log must take its axis from the symmetric part.
#include <gtest/gtest.h>

#include <random>

#include "fpmshell/core/rotation.hpp"

using namespace fpmshell;

TEST(Rotation, ExpLogRoundTripAllAngles) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Real angle :
         {0.0, 1e-9, 1e-5, 1e-3, 5e-3, 0.0099, 0.0101, 0.3, 1.0, 2.5, 3.0, 3.14, 3.1415}) {
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
    const Mat3 r = to_mat3(minimal_rotation(to_v3(a), to_v3(b)));
    EXPECT_LT((r * a - b).norm(), 1e-14);
    // Its axis is a x b: a x b is left unchanged (round-off).
    const Vec3 axis = a.cross(b);
    EXPECT_LT((r * axis - axis).norm(), 1e-14);
}

// The accumulated rotation of a particle is a quaternion: it must be the rotation matrix of
// the same increments, on both sides of the series/closed-form switch at |phi| = 0.01, and
// its product over many steps must give the product of the matrices.
TEST(Rotation, QuaternionMatchesTheRotationMatrix) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (Real angle : {0.0, 1e-9, 1e-5, 1e-3, 0.0099, 0.0101, 0.3, 1.0, 2.5, 3.1}) {
        for (int trial = 0; trial < 20; ++trial) {
            const Vec3 phi = angle * Vec3(u(rng), u(rng), u(rng)).normalized();
            const Quat q = rotation_quaternion(phi);
            EXPECT_NEAR(q.norm(), 1.0, 1e-15) << "angle " << angle;  // unit by construction
            EXPECT_LT((q.toRotationMatrix() - rotation_matrix(phi)).norm(), 4e-15)
                << "angle " << angle;  // a few ulp of 1
            // the rotation vector comes back (1e-13 rad: the log's round-off, as above)
            EXPECT_LT((rotation_vector(q) - phi).norm(), 1e-15 + 1e-13 * angle)
                << "angle " << angle;
        }
    }
    // 10^5 steps of increments like those of a run (|phi| < 0.01): the products agree to
    // round-off growing like the number of steps (1e-16 each).
    Quat q = Quat::Identity();
    Mat3 r = Mat3::Identity();
    for (int step = 0; step < 100000; ++step) {
        const Vec3 phi = 0.005 * Vec3(u(rng), u(rng), u(rng));
        q = rotation_quaternion(phi) * q;
        r = rotation_matrix(phi) * r;
    }
    EXPECT_LT((q.normalized().toRotationMatrix() - r).norm(), 1e-10);
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
}
