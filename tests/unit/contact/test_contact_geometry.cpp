// Narrow and broad phase of contact: the closest point of a triangle (face, edge, corner
// regions) and the bucket grid against a brute-force search.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "fpmshell/contact/bucket_grid.hpp"
#include "fpmshell/contact/closest_point.hpp"

using namespace fpmshell;

TEST(ClosestPoint, FaceEdgeAndCornerRegions) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    // above the face: the projection, weights = barycentric coordinates
    TriangleClosestPoint r = closest_point_on_triangle(Vec3(0.2, 0.3, 0.7), a, b, c);
    EXPECT_TRUE(r.in_face);
    EXPECT_NEAR(r.xi[0], 0.5, 1e-14);
    EXPECT_NEAR(r.xi[1], 0.2, 1e-14);
    EXPECT_NEAR(r.xi[2], 0.3, 1e-14);
    EXPECT_NEAR((r.point - Vec3(0.2, 0.3, 0)).norm(), 0, 1e-14);
    // just outside the edge b-c but within the 0.02 tolerance: still the face
    r = closest_point_on_triangle(Vec3(0.51, 0.505, 0.3), a, b, c);
    EXPECT_TRUE(r.in_face);
    // beyond the edge b-c: the nearest point of the edge
    r = closest_point_on_triangle(Vec3(1, 1, 0.5), a, b, c);
    EXPECT_FALSE(r.in_face);
    EXPECT_NEAR((r.point - Vec3(0.5, 0.5, 0)).norm(), 0, 1e-14);
    EXPECT_NEAR(r.xi[1], 0.5, 1e-14);
    EXPECT_NEAR(r.xi[2], 0.5, 1e-14);
    EXPECT_EQ(r.xi[0], 0);
    // beyond the corner a: the corner itself
    r = closest_point_on_triangle(Vec3(-1, -2, 3), a, b, c);
    EXPECT_FALSE(r.in_face);
    EXPECT_EQ(r.xi[0], 1);
    EXPECT_NEAR(r.point.norm(), 0, 1e-14);
}

TEST(ClosestPoint, AgreesWithDenseSampling) {
    // The point found is at least as close as any of 20 000 sampled points of the triangle.
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (int trial = 0; trial < 50; ++trial) {
        const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
        const Vec3 p = 2 * Vec3(u(rng), u(rng), u(rng));
        const TriangleClosestPoint r = closest_point_on_triangle(p, a, b, c, 0.0);
        Real best = 1e30;
        for (int i = 0; i <= 200; ++i)
            for (int j = 0; i + j <= 200; ++j) {
                const Real s = i / 200.0, t = j / 200.0;
                best = std::min(best, (p - (a + s * (b - a) + t * (c - a))).norm());
            }
        const Real found = (p - r.point).norm();
        EXPECT_LE(found, best + 1e-12) << trial;
        EXPECT_GE(found, best - 0.02) << trial;  // sampling step 1/200 of the edges of size < 3.5
        EXPECT_NEAR(r.xi[0] + r.xi[1] + r.xi[2], 1, 1e-12);
    }
}

TEST(BucketGrid, FindsEveryBoxThatContainsThePoint) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(0, 10), s(0.05, 0.8);
    std::vector<Vec3> lo, hi;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 c(u(rng), u(rng), 0.2 * u(rng));
        const Vec3 half(s(rng), s(rng), s(rng));
        lo.push_back(c - half);
        hi.push_back(c + half);
    }
    BucketGrid grid;
    grid.build(lo, hi, 1.0);
    for (int q = 0; q < 500; ++q) {
        const Vec3 p(u(rng), u(rng), 0.2 * u(rng));
        std::vector<Index> found;
        grid.for_each_near(p, [&](Index i) { found.push_back(i); });
        std::sort(found.begin(), found.end());
        EXPECT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end())
            << "an item twice";
        for (int i = 0; i < 2000; ++i) {
            const bool inside = (p.array() >= lo[static_cast<std::size_t>(i)].array()).all() &&
                                (p.array() <= hi[static_cast<std::size_t>(i)].array()).all();
            if (inside) {
                EXPECT_TRUE(std::binary_search(found.begin(), found.end(), i)) << q << " " << i;
            }
        }
    }
    // A point outside every box finds nothing, and the bucket count stays bounded.
    std::size_t n = 0;
    grid.for_each_near(Vec3(100, 100, 100), [&](Index) { ++n; });
    EXPECT_EQ(n, 0U);
    EXPECT_LE(grid.buckets(), 4 * 2000 + 64);
}
