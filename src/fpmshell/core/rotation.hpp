// Rotation algebra used by the reverse motion and the particle update (theory.md §1.4).
#pragma once

#include <algorithm>
#include <cmath>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// R(phi) = I + a [phi]x + b [phi]x^2, a = sin t / t, b = (1 - cos t)/t^2 (theory.md §1.4).
[[nodiscard]] inline Mat3 rotation_matrix(const Vec3& phi) {
    const Real t2 = phi.squaredNorm();
    Real a, b;
    if (t2 < 1e-4) {  // t < 0.01 (every step of a stable run): series, next terms < 1e-21
        // (multiplications by the reciprocal constants: as the block kernel's series)
        a = 1.0 - t2 * (1.0 / 6.0) * (1.0 - t2 * (1.0 / 20.0) * (1.0 - t2 * (1.0 / 42.0)));
        b = 0.5 - t2 * (1.0 / 24.0) * (1.0 - t2 * (1.0 / 30.0) * (1.0 - t2 * (1.0 / 56.0)));
    } else {
        const Real t = std::sqrt(t2);
        a = std::sin(t) / t;
        b = (1.0 - std::cos(t)) / t2;
    }
    // [phi]x^2 = phi phi^T - t^2 I, so R = (1 - b t^2) I + a [phi]x + b phi phi^T: 20 flops
    // where the skew-matrix product takes 45 (this is the hottest function of the step).
    const Real x = phi.x(), y = phi.y(), z = phi.z();
    const Real d = 1.0 - b * t2;
    const Real bxy = b * x * y, bxz = b * x * z, byz = b * y * z;
    Mat3 r;
    r << d + b * x * x, bxy - a * z, bxz + a * y, bxy + a * z, d + b * y * y, byz - a * x,
        bxz - a * y, byz + a * x, d + b * z * z;
    return r;
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

/// Rotation vector of a rotation matrix, log(R) (theory.md §1.4). Accurate for angles < pi - 1e-6;
/// near pi the axis is taken from the symmetric part.
[[nodiscard]] inline Vec3 rotation_vector(const Mat3& r) {
    const Real c = std::clamp((r.trace() - 1.0) * 0.5, Real(-1), Real(1));
    const Vec3 w(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
    const Real s2 = 0.25 * w.squaredNorm();  // sin^2(theta)
    if (c > 0 && s2 < 1e-4) {  // theta / sin(theta) = asin(s)/s series, next term < 1e-17
        return (0.5 * (1.0 + s2 * (1.0 / 6.0 + s2 * (3.0 / 40.0 + s2 * (5.0 / 112.0))))) * w;
    }
    const Real s = std::sqrt(s2);
    const Real theta = std::atan2(s, c);
    if (c > -0.99) return (theta / (2.0 * std::sin(theta))) * w;
    // Near pi: axis from R + R^T = 2 cos I + 2(1 - cos) e e^T, sign from the skew part.
    const Mat3 sym = 0.5 * (r + r.transpose()) - c * Mat3::Identity();
    Eigen::Index k = 0;
    sym.diagonal().maxCoeff(&k);
    Vec3 e = sym.col(k) / std::sqrt(std::max(sym(k, k), Real(1e-300)));
    e.normalize();
    if (e.dot(w) < 0) e = -e;
    return theta * e;
}

/// Rotation vector of a quaternion (normalised first: the product of many steps' increments
/// drifts from unit length by rounding).
[[nodiscard]] inline Vec3 rotation_vector(const Quat& q) {
    return rotation_vector(q.normalized().toRotationMatrix());
}

/// Minimal rotation taking unit vector a to unit vector b (a.b > -1): I + [v]x + [v]x^2/(1+c).
[[nodiscard]] inline Mat3 minimal_rotation(const Vec3& a, const Vec3& b) {
    // [v]x^2 = v v^T - |v|^2 I, written out like rotation_matrix.
    const Vec3 v = a.cross(b);
    const Real c = a.dot(b);
    const Real f = 1.0 / (1.0 + c);
    const Real x = v.x(), y = v.y(), z = v.z();
    const Real d = 1.0 - f * v.squaredNorm();
    const Real fxy = f * x * y, fxz = f * x * z, fyz = f * y * z;
    Mat3 r;
    r << d + f * x * x, fxy - z, fxz + y, fxy + z, d + f * y * y, fyz - x, fxz - y, fyz + x,
        d + f * z * z;
    return r;
}

/// atan2(y, x) for x > 0 and |y| < 0.01 x (the in-plane rotation of a path element in a stable
/// step) by its series, next term < 1e-19; std::atan2 otherwise.
[[nodiscard]] inline Real small_angle_atan2(Real y, Real x) {
    if (x > 0 && std::abs(y) < 0.01 * x) {
        const Real t = y / x, t2 = t * t;
        return t * (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0))));
    }
    return std::atan2(y, x);
}

}  // namespace fpmshell
