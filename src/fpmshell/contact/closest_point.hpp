// Closest point of a triangle to a point (narrow phase of contact, theory.md §8.1): the
// barycentric weights xi_k of the point of the triangle nearest to p, and whether it lies in
// the face (the orthogonal projection of p falls inside, within a relative tolerance) or on
// an edge or a corner.
#pragma once

#include <algorithm>
#include <array>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct TriangleClosestPoint {
    std::array<Real, 3> xi{};   ///< weights of the corners a, b, c (sum 1, all >= 0 off the face)
    Vec3 point = Vec3::Zero();  ///< sum xi_k x_k
    bool in_face = false;       ///< the projection of p lies inside the triangle
};

/// face_tolerance: the projection counts as inside while every weight is >= -face_tolerance
/// (theory.md §8.1: 0.02); it is then the projection itself, weights unclipped.
inline TriangleClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                                      const Vec3& c, Real face_tolerance = 0.02) {
    TriangleClosestPoint r;
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    // Projection: solve [ab ac]^T [ab ac] (v, w) = [ab ac]^T ap.
    const Real d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
    const Real d20 = ap.dot(ab), d21 = ap.dot(ac);
    const Real det = d00 * d11 - d01 * d01;
    if (det > 0) {
        const Real v = (d11 * d20 - d01 * d21) / det;
        const Real w = (d00 * d21 - d01 * d20) / det;
        const Real u = 1 - v - w;
        if (u >= -face_tolerance && v >= -face_tolerance && w >= -face_tolerance) {
            r.xi = {u, v, w};
            r.point = u * a + v * b + w * c;
            r.in_face = true;
            return r;
        }
    }
    // Outside the face: the nearest point of the three edges (segments).
    Real best = -1;
    const std::array<const Vec3*, 3> x{&a, &b, &c};
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const Vec3& s0 = *x[static_cast<std::size_t>(i)];
        const Vec3& s1 = *x[static_cast<std::size_t>(j)];
        const Vec3 e = s1 - s0;
        const Real len2 = e.squaredNorm();
        const Real t = len2 > 0 ? std::clamp((p - s0).dot(e) / len2, Real(0), Real(1)) : Real(0);
        const Vec3 q = s0 + t * e;
        const Real d2 = (p - q).squaredNorm();
        if (best < 0 || d2 < best) {
            best = d2;
            r.xi = {0, 0, 0};
            r.xi[static_cast<std::size_t>(i)] = 1 - t;
            r.xi[static_cast<std::size_t>(j)] = t;
            r.point = q;
        }
    }
    return r;
}

}  // namespace fpmshell
