// Fictitious reverse motion (theory.md §2): a rigid motion of any size leaves no deformation
// (zero displacements and rotations, to round-off); a known deformation superposed on a large
// rigid motion is recovered unchanged (objectivity).
#include <gtest/gtest.h>

#include <random>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/elements/reverse_motion.hpp"

using namespace fpmshell;

namespace {

std::array<Vec3, 3> sample_triangle() {
    return {Vec3(0.1, -0.2, 0.3), Vec3(1.4, 0.1, 0.5), Vec3(0.3, 1.1, -0.2)};
}

Vec2 displacement(const ReversedTriangle& rt, std::size_t i) {
    return {rt.local.ux[i], rt.local.uy[i]};
}

Vec2 rotation(const ReversedTriangle& rt, std::size_t i) {
    return {rt.local.th[2 * i], rt.local.th[2 * i + 1]};
}

Real max_deformation(const ReversedTriangle& rt) {
    Real m = 0;
    for (std::size_t i = 0; i < 3; ++i)
        m = std::max({m, displacement(rt, i).norm(), rotation(rt, i).norm()});
    return m;
}

}  // namespace

TEST(ReverseMotion, RigidMotionUpTo180DegreesGivesNoDeformation) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-1, 1);
    const auto base = sample_triangle();
    for (Real angle : {0.0, 1e-6, 0.01, 0.5, 1.5, 2.5, 3.0, 3.14159}) {
        for (int trial = 0; trial < 10; ++trial) {
            const Vec3 axis = Vec3(u(rng), u(rng), u(rng)).normalized();
            const Mat3 r = rotation_matrix(angle * axis);
            const Vec3 shift(u(rng), u(rng), u(rng));
            std::array<Vec3, 3> cur, dth;
            for (int i = 0; i < 3; ++i) {
                cur[i] = r * base[i] + shift;
                dth[i] = angle * axis;
            }
            const ReversedTriangle rt = reverse_motion(base, cur, dth, k_no_drill_axes);
            ASSERT_GT(rt.local.area, 0.0);  // not degenerate (a tilt past 90 deg is computed)
            // Round-off of O(1) coordinates through ~5 rotations: 1e-12 is ~1e4 eps.
            EXPECT_LT(max_deformation(rt), 1e-12) << "angle " << angle;
            // The convected frame is the base frame carried by the rigid rotation (§2.7).
            const Vec3 ex = (base[1] - base[0]).normalized();
            EXPECT_LT((to_vec3(rt.local.frame_current.row[0]) - r * ex).norm(), 1e-12);
        }
    }
}

TEST(ReverseMotion, DeformationIsRecoveredUnderLargeRigidRotation) {
    // Base triangle in the xy plane: local frame = global, so the expected deformation is known.
    const std::array<Vec3, 3> base{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 1.5, 0)};
    // Small in-plane strain field u = G X with G symmetric (no rotation), and small bending
    // rotations (no rigid part: they sum to zero and have no common component).
    Mat3 g = Mat3::Zero();
    g(0, 0) = 1e-4;
    g(1, 1) = -2e-4;
    g(0, 1) = g(1, 0) = 0.5e-4;
    const std::array<Vec3, 3> bend{Vec3(1e-4, -2e-4, 0), Vec3(-3e-4, 1e-4, 0), Vec3(2e-4, 1e-4, 0)};
    std::array<Vec3, 3> deformed;
    for (int i = 0; i < 3; ++i) deformed[i] = base[i] + g * (base[i] - base[0]);
    const ReversedTriangle ref = reverse_motion(base, deformed, bend, k_no_drill_axes);

    const Mat3 r = rotation_matrix(Vec3(0.7, -1.9, 1.2));  // 2.3 rad rigid rotation
    std::array<Vec3, 3> cur, dth;
    for (int i = 0; i < 3; ++i) {
        cur[i] = r * deformed[i] + Vec3(3, -1, 2);
        dth[i] = rotation_vector(r * rotation_matrix(bend[i]));  // rigid after deformation
    }
    const ReversedTriangle rt = reverse_motion(base, cur, dth, k_no_drill_axes);
    for (std::size_t i = 0; i < 3; ++i) {
        // Same deformation to round-off (the rigid rotation is removed exactly, §2.6).
        EXPECT_LT((displacement(rt, i) - displacement(ref, i)).norm(), 1e-14);
        EXPECT_LT((rotation(rt, i) - rotation(ref, i)).norm(), 1e-13);
    }
    // The strain-free reference recovers the imposed displacement field: u_2 = G a_2 (edge
    // 1->2 keeps its direction because G is symmetric and the edge lies along x).
    EXPECT_NEAR(ref.local.ux[1], 2e-4, 1e-8);  // second-order terms (|G|^2 |a| ~ 1e-8)
    EXPECT_NEAR(ref.local.th[0], 1e-4, 1e-7);
    EXPECT_NEAR(ref.local.th[1], -2e-4, 1e-7);
}

TEST(ReverseMotion, RigidRotationOfTangentPlaneIncrementsGivesNoDeformation) {
    // Curved-shell nodes (theory.md §2.6, eq. 2.6c): each node's increment is the rigid
    // rotation less its part about the node's own normal d_i, tilted by up to ~25 deg from the
    // element's. With the drill axes the element restores that part from its own rigid rotation
    // and sees no deformation; without them it sees -(omega . d_i) d_i, whose in-plane part
    // is a bending rotation of ~|omega| sin(tilt).
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-1, 1);
    const auto base = sample_triangle();
    const Vec3 na = (base[1] - base[0]).cross(base[2] - base[0]).normalized();
    for (Real angle : {1e-4, 0.01, 0.5}) {
        for (int trial = 0; trial < 10; ++trial) {
            const Vec3 axis =
                (na + 0.5 * Vec3(u(rng), u(rng), u(rng))).normalized();  // near the normals
            const Mat3 r = rotation_matrix(angle * axis);
            std::array<Vec3, 3> cur, dth, drill;
            for (std::size_t i = 0; i < 3; ++i) {
                cur[i] = r * base[i] + Vec3(0.3, -0.1, 0.2);
                drill[i] = (na + 0.25 * Vec3(u(rng), u(rng), u(rng))).normalized();
                dth[i] = angle * axis - (angle * axis).dot(drill[i]) * drill[i];
            }
            // Round-off of O(1) coordinates through ~5 rotations: 1e-12 is ~1e4 eps.
            EXPECT_LT(max_deformation(reverse_motion(base, cur, dth, drill)), 1e-12)
                << "angle " << angle;
            // The same increments without their drill axes: a spurious bending rotation of
            // order angle x tilt (> 1e-3 angle for these tilts), the inconsistency the axes remove.
            EXPECT_GT(max_deformation(reverse_motion(base, cur, dth, k_no_drill_axes)),
                      1e-3 * angle);
        }
    }
}
