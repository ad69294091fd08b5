// Rotation algebra (theory.md §1.4), written once for a scalar type T (core/simd.hpp): the path
// element (elements/path_element.hpp) runs it on one element (T = Real) or on k_lanes elements
// (T = RealPack); the particle update and the output use the Eigen forms at the end.
//   - The small-angle series (every rotation of a stable step is below 0.01 rad) hold for any
//     T; their callers check the bounds.
//   - The forms for any angle (trigonometric, near pi) are written for T = Real.
#pragma once

#include <algorithm>
#include <cmath>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// R(phi) = (1 - b t^2) I + a [phi]x + b phi phi^T for t^2 = |phi|^2, a = sin t / t,
/// b = (1 - cos t)/t^2 ([phi]x^2 = phi phi^T - t^2 I): 20 flops where the skew-matrix
/// product takes 45.
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> rotation_matrix_of(const V3<T>& phi, const T& t2, const T& a,
                                                       const T& b) {
    const T d = 1.0 - b * t2;
    const T bxy = b * phi.x * phi.y, bxz = b * phi.x * phi.z, byz = b * phi.y * phi.z;
    return {{V3<T>{d + b * phi.x * phi.x, bxy - a * phi.z, bxz + a * phi.y},
             V3<T>{bxy + a * phi.z, d + b * phi.y * phi.y, byz - a * phi.x},
             V3<T>{bxz - a * phi.y, byz + a * phi.x, d + b * phi.z * phi.z}}};
}

/// R(phi) by the series of a and b, for t^2 = |phi|^2 < 1e-4 (next terms < 1e-21).
/// Multiplications by the reciprocal constants, not divisions: a pack division occupies the
/// divider for about 16 cycles.
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> rotation_matrix_series(const V3<T>& phi, const T& t2) {
    const T a = 1.0 - t2 * (1.0 / 6.0) * (1.0 - t2 * (1.0 / 20.0) * (1.0 - t2 * (1.0 / 42.0)));
    const T b = 0.5 - t2 * (1.0 / 24.0) * (1.0 - t2 * (1.0 / 30.0) * (1.0 - t2 * (1.0 / 56.0)));
    return rotation_matrix_of(phi, t2, a, b);
}

/// R(phi) for any angle.
[[nodiscard]] inline M3<Real> rotation_matrix(const V3<Real>& phi) {
    const Real t2 = squared_norm(phi);
    if (t2 < 1e-4) return rotation_matrix_series(phi, t2);
    const Real t = std::sqrt(t2);
    return rotation_matrix_of(phi, t2, std::sin(t) / t, (1.0 - std::cos(t)) / t2);
}

/// The axial vector w = (R32 - R23, R13 - R31, R21 - R12) = 2 sin(theta) e, and cos(theta).
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> axial_vector(const M3<T>& r) {
    return {r.row[2].y - r.row[1].z, r.row[0].z - r.row[2].x, r.row[1].x - r.row[0].y};
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE T rotation_cosine(const M3<T>& r) {
    return (r.row[0].x + r.row[1].y + r.row[2].z - 1.0) * 0.5;
}

/// log(R) = theta / (2 sin theta) w by the series of asin(s)/s in s^2 = sin^2 theta, where
/// cos theta > 0 and s^2 < 1e-4 (next term < 1e-17).
template <class T>
[[nodiscard]] FPMSHELL_INLINE V3<T> rotation_vector_series(const V3<T>& w, const T& s2) {
    return (0.5 * (1.0 + s2 * (1.0 / 6.0 + s2 * (3.0 / 40.0 + s2 * (5.0 / 112.0))))) * w;
}

/// log(R) for any rotation; accurate for angles < pi - 1e-6, near pi the axis is taken from
/// the symmetric part.
[[nodiscard]] inline V3<Real> rotation_vector(const M3<Real>& r) {
    const Real c = std::clamp(rotation_cosine(r), Real(-1), Real(1));
    const V3<Real> w = axial_vector(r);
    const Real s2 = 0.25 * squared_norm(w);
    if (c > 0 && s2 < 1e-4) return rotation_vector_series(w, s2);
    const Real s = std::sqrt(s2);
    const Real theta = std::atan2(s, c);
    if (c > -0.99) return (theta / (2.0 * std::sin(theta))) * w;
    // Near pi: R + R^T = 2 cos I + 2 (1 - cos) e e^T; the axis is the column of
    // S = (R + R^T)/2 - cos I with the largest diagonal entry, its sign from w.
    const auto entry = [&](std::size_t i, std::size_t j) { return component(r.row[i], j); };
    std::size_t k = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (entry(i, i) - c > entry(k, k) - c) k = i;
    const auto s_ik = [&](std::size_t i) {
        return 0.5 * (entry(i, k) + entry(k, i)) - (i == k ? c : 0.0);
    };
    const Real scale = std::sqrt(std::max(s_ik(k), Real(1e-300)));
    V3<Real> e{s_ik(0) / scale, s_ik(1) / scale, s_ik(2) / scale};
    const Real length = std::sqrt(squared_norm(e));
    e = {e.x / length, e.y / length, e.z / length};
    if (dot(e, w) < 0) e = Real(-1) * e;
    return theta * e;
}

/// Minimal rotation taking unit vector a to unit vector b (a.b > -1): I + [v]x + [v]x^2/(1+c)
/// with v = a x b, c = a.b ([v]x^2 = v v^T - |v|^2 I, written out as rotation_matrix_of).
template <class T>
[[nodiscard]] FPMSHELL_INLINE M3<T> minimal_rotation(const V3<T>& a, const V3<T>& b) {
    const V3<T> v = cross(a, b);
    const T f = 1.0 / (1.0 + dot(a, b));
    const T d = 1.0 - f * squared_norm(v);
    const T fxy = f * v.x * v.y, fxz = f * v.x * v.z, fyz = f * v.y * v.z;
    return {{V3<T>{d + f * v.x * v.x, fxy - v.z, fxz + v.y},
             V3<T>{fxy + v.z, d + f * v.y * v.y, fyz - v.x},
             V3<T>{fxz - v.y, fyz + v.x, d + f * v.z * v.z}}};
}

/// atan(t) by its series for |t| < 0.01 (next term < 1e-19).
template <class T>
[[nodiscard]] FPMSHELL_INLINE T atan_series(const T& t) {
    const T t2 = t * t;
    return t * (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0))));
}

/// atan2(y, x): the series for x > 0 and |y| < 0.01 x (the in-plane rotation of a path element
/// in a stable step), std::atan2 otherwise.
[[nodiscard]] inline Real small_angle_atan2(Real y, Real x) {
    if (x > 0 && std::abs(y) < 0.01 * x) return atan_series(y / x);
    return std::atan2(y, x);
}

// ---- the Eigen forms (particle rotations, output, tests) ----

/// R(phi) for any angle.
[[nodiscard]] inline Mat3 rotation_matrix(const Vec3& phi) {
    return to_mat3(rotation_matrix(to_v3(phi)));
}

/// log(R) for any rotation (see rotation_vector above).
[[nodiscard]] inline Vec3 rotation_vector(const Mat3& r) {
    return to_vec3(rotation_vector(to_m3(r)));
}

/// The unit quaternion of the rotation vector phi: (cos t/2, sin(t/2)/t phi), t = |phi|
/// (theory.md §1.4). The accumulated rotation of a particle is kept as one (32 bytes against
/// the 72 of a matrix, and 16 multiplications per step's update against 27).
[[nodiscard]] inline Quat rotation_quaternion(const Vec3& phi) {
    const Real t2 = phi.squaredNorm();
    Real c, s;
    if (t2 < 1e-4) {  // t < 0.01 (every step of a stable run): series, next terms < 1e-22
        c = 1.0 - t2 * (1.0 / 8.0) * (1.0 - t2 * (1.0 / 48.0) * (1.0 - t2 * (1.0 / 120.0)));
        s = 0.5 *
            (1.0 - t2 * (1.0 / 24.0) * (1.0 - t2 * (1.0 / 80.0) * (1.0 - t2 * (1.0 / 168.0))));
    } else {
        const Real t = std::sqrt(t2);
        c = std::cos(0.5 * t);
        s = std::sin(0.5 * t) / t;
    }
    return Quat(c, s * phi.x(), s * phi.y(), s * phi.z());
}

/// Rotation vector of a quaternion (normalised first: the product of many steps' increments
/// drifts from unit length by rounding).
[[nodiscard]] inline Vec3 rotation_vector(const Quat& q) {
    return rotation_vector(q.normalized().toRotationMatrix());
}

}  // namespace fpmshell
