// The path element of a triangle (theory.md §2), written once for a scalar type T
// (core/simd.hpp): the fictitious reverse translation (§2.1), out-of-plane (§2.2) and in-plane
// (§2.3) rotation between the base configuration (t_{n-1}) and the current one (t_n), leaving
// the pure deformation displacements (§2.4) and rotations (§2.6) in the deformation frame of
// the base configuration (§2.5), and the convected current frame (§2.7).
// Its rotations come from a policy:
//   - SeriesRotations (any T; the SIMD blocks, T = RealPack): the small-angle series of
//     core/rotation.hpp, with the lanes where every rotation of the step is below 0.01 rad;
//   - ExactRotations (T = Real; the general element): any rotation.
#pragma once

#include <array>

#include "fpmshell/core/rotation.hpp"
#include "fpmshell/core/simd.hpp"

namespace fpmshell {

/// One path element per lane: node positions at t_{n-1} and t_n, nodal rotation increments
/// (global rotation vectors) and the nodes' drill axes: per node, the unit axis about which its
/// rotation is not a degree of freedom (the particle normal of the step; zero where the
/// increment is complete: kinks, prescribed rotations, a single element's test).
template <class T>
struct TriangleMotion {
    std::array<V3<T>, 3> base, current, dtheta, drill_axis;
};

/// The path element in its local frame (§2.4-§2.7): node 1 at the origin, node 2 on x.
template <class T>
struct LocalTriangle {
    T x2, x3, y3;             ///< base local coordinates (x1 = y1 = y2 = 0), y3 > 0
    T inv_x2;                 ///< 1 / x2
    T area;                   ///< A_a, base area
    std::array<T, 3> ux, uy;  ///< deformation displacements (u_1 = 0), §2.4
    std::array<T, 6> th;      ///< deformation rotations [thx1 thy1 thx2 thy2 thx3 thy3], §2.6
    std::array<V3<T>, 3> drill_local;  ///< the drill axes in the local frame (eq. 4.6b)
    M3<T> frame_current;               ///< T_t: local -> global is T_t^T, §2.7
};

/// What the path element says of itself besides its local triangle.
template <class T>
struct PathElementChecks {
    T normal_cosine;  ///< n_a . n
    T area_ratio;     ///< current / base area
    /// Lanes whose path element a stable step can produce (§2.8): neither triangle degenerate,
    /// the normal tilted by less than 90 deg, the area kept within a factor of 2.
    MaskOf<T> within_step_bounds;
    T characteristic_length;  ///< L_c = 2A / l_max of the current triangle (§6.4)
};

/// L_c = 2A / l_max (§6.4) of the triangle p0 p1 p2 whose doubled area is two_area.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T characteristic_length(const T& two_area, const V3<T>& p0,
                                                      const V3<T>& p1, const V3<T>& p2) {
    const T lmax2 = max(max(squared_norm(p1 - p0), squared_norm(p2 - p1)), squared_norm(p0 - p2));
    return two_area / sqrt(lmax2);
}
template <class T>
[[nodiscard]] FPMSHELL_INLINE T characteristic_length(const V3<T>& p0, const V3<T>& p1,
                                                      const V3<T>& p2) {
    return characteristic_length(sqrt(squared_norm(cross(p1 - p0, p2 - p0))), p0, p1, p2);
}

/// The small-angle series of core/rotation.hpp; each narrows `valid` to the lanes where it holds.
struct SeriesRotations {
    /// R_{a -> b} of two unit normals (§2.2), for a tilt below 90 deg.
    template <class T>
    [[nodiscard]] FPMSHELL_INLINE static M3<T> tilt(const V3<T>& a, const V3<T>& b, const T&,
                                                    const V3<T>&) {
        return minimal_rotation(a, b);
    }
    /// atan2(y, x) where x > 0 and |y| < 0.01 x.
    template <class T>
    [[nodiscard]] FPMSHELL_INLINE static T angle(const T& y, const T& x, MaskOf<T>& valid) {
        valid = valid && (x > 0.0) && (abs(y) < 0.01 * x);
        return atan_series(y / x);
    }
    /// R(phi) where |phi|^2 < 1e-4.
    template <class T>
    [[nodiscard]] FPMSHELL_INLINE static M3<T> matrix(const V3<T>& phi, MaskOf<T>& valid) {
        const T t2 = squared_norm(phi);
        valid = valid && (t2 < 1e-4);
        return rotation_matrix_series(phi, t2);
    }
    /// log(R) where cos > 0 and sin^2 < 1e-4.
    template <class T>
    [[nodiscard]] FPMSHELL_INLINE static V3<T> vector(const M3<T>& r, MaskOf<T>& valid) {
        const T c = rotation_cosine(r);
        const V3<T> w = axial_vector(r);
        const T s2 = 0.25 * squared_norm(w);
        valid = valid && (c > 0.0) && (s2 < 1e-4);
        return rotation_vector_series(w, s2);
    }
};

/// The forms of core/rotation.hpp for any rotation (T = Real); `valid` is left as it is.
struct ExactRotations {
    /// R_{a -> b}: the trig-free form while the tilt is below ~154 deg; beyond it (only in
    /// kernel tests: a stable step never tilts an element that much) the axis-angle form, with
    /// the in-plane axis `fallback_axis` for an exact flip.
    [[nodiscard]] static M3<Real> tilt(const V3<Real>& a, const V3<Real>& b, Real cosine,
                                       const V3<Real>& fallback_axis) {
        if (cosine > -0.9) return minimal_rotation(a, b);
        const V3<Real> v = cross(a, b);
        const Real s = std::sqrt(squared_norm(v));
        const V3<Real> axis = s > 1e-12
                                  ? (1.0 / s) * v
                                  : (1.0 / std::sqrt(squared_norm(fallback_axis))) * fallback_axis;
        return rotation_matrix(std::atan2(s, cosine) * axis);
    }
    [[nodiscard]] static Real angle(Real y, Real x, bool&) { return small_angle_atan2(y, x); }
    [[nodiscard]] static M3<Real> matrix(const V3<Real>& phi, bool&) {
        return rotation_matrix(phi);
    }
    [[nodiscard]] static V3<Real> vector(const M3<Real>& r, bool&) { return rotation_vector(r); }
};

/// The path element of `m` (§2.1-§2.7) into `local`, its checks into `checks`; returns the
/// lanes within the step bounds (§2.8) and, with SeriesRotations, within the series' bounds.
/// Lanes outside them hold meaningless values. Frame: global in, element-local out.
template <class Rotations, class T>
[[nodiscard]] FPMSHELL_INLINE MaskOf<T> path_element(const TriangleMotion<T>& m,
                                                     LocalTriangle<T>& local,
                                                     PathElementChecks<T>& checks) {
    // §2.1 reverse translation by the motion of node 1
    const V3<T> a2 = m.base[1] - m.base[0], a3 = m.base[2] - m.base[0];
    const V3<T> r2 = m.current[1] - m.current[0], r3 = m.current[2] - m.current[0];
    const V3<T> na_raw = cross(a2, a3), n_raw = cross(r2, r3);
    const T lmax2 = max(max(squared_norm(a2), squared_norm(a3)), squared_norm(a3 - a2));
    const T na_norm = sqrt(squared_norm(na_raw)), n_norm = sqrt(squared_norm(n_raw));
    const MaskOf<T> not_degenerate = (na_norm > 1e-12 * lmax2) && (n_norm > 1e-12 * lmax2);
    if constexpr (std::is_same_v<T, Real>) {
        if (!not_degenerate) {
            checks = {0.0, 0.0, false, 0.0};
            return false;
        }
    }
    const T inv_na_norm = 1.0 / na_norm;
    const T inv_n_norm = 1.0 / n_norm;
    const V3<T> na = inv_na_norm * na_raw, n = inv_n_norm * n_raw;
    local.area = 0.5 * na_norm;
    checks.area_ratio = n_norm * inv_na_norm;
    checks.normal_cosine = dot(na, n);
    checks.within_step_bounds = not_degenerate && (checks.normal_cosine > 0.0) &&
                                (checks.area_ratio > 0.5) && (checks.area_ratio < 2.0);
    checks.characteristic_length = characteristic_length(n_norm, m.current[0], m.current[1],
                                                         m.current[2]);  // §6.4
    MaskOf<T> valid = checks.within_step_bounds;
    // §2.2 reverse out-of-plane rotation R_op = R_{na -> n}
    const M3<T> r_op = Rotations::tilt(na, n, checks.normal_cosine, a2);
    const V3<T> r2p = transpose_times(r_op, r2), r3p = transpose_times(r_op, r3);
    // §2.3 reverse in-plane rotation about na bringing edge 1->2 back onto the base edge
    const T theta_ip = Rotations::angle(dot(na, cross(a2, r2p)), dot(a2, r2p), valid);
    const M3<T> r_ip = Rotations::matrix(theta_ip * na, valid);
    const V3<T> r2pp = transpose_times(r_ip, r2p), r3pp = transpose_times(r_ip, r3p);
    // §2.5 deformation frame on the base configuration
    const T x2 = local.x2 = sqrt(squared_norm(a2));
    const T inv_x2 = local.inv_x2 = 1.0 / x2;
    const V3<T> ex = inv_x2 * a2, ez = na, ey = cross(ez, ex);
    local.x3 = dot(ex, a3);
    local.y3 = dot(ey, a3);
    // §2.4 deformation displacements in the local frame
    const V3<T> d2 = r2pp - a2, d3 = r3pp - a3;
    local.ux = {T(0.0), dot(ex, d2), dot(ex, d3)};
    local.uy = {T(0.0), dot(ey, d2), dot(ey, d3)};
    // §2.6 deformation rotations phi_i = log(R_r^T R(dtheta~_i)) (eq. 2.6b) with
    // dtheta~_i = dtheta_i + ((omega_r - dtheta_i) . d_i) d_i (eq. 2.6c): a node whose rotation
    // about its drill axis d_i is no degree of freedom takes the element's rigid rotation
    // omega_r = log(R_r) about it, so that a rigid rotation leaves phi_i = 0 on a curved shell.
    const M3<T> r_r = r_op * r_ip;
    const V3<T> omega_r = Rotations::vector(r_r, valid);
    for (std::size_t i = 0; i < 3; ++i) {
        const V3<T>& d = m.drill_axis[i];
        local.drill_local[i] = V3<T>{dot(ex, d), dot(ey, d), dot(ez, d)};
        const V3<T> dtheta = m.dtheta[i] + dot(omega_r - m.dtheta[i], d) * d;
        const M3<T> rel = transpose_times(r_r, Rotations::matrix(dtheta, valid));
        const V3<T> phi = Rotations::vector(rel, valid);
        local.th[2 * i] = dot(ex, phi);  // the drilling component is discarded
        local.th[2 * i + 1] = dot(ey, phi);
    }
    // §2.7 convected current frame T_t = T_a R_r^T
    local.frame_current = times_transpose(M3<T>{{ex, ey, ez}}, r_r);
    return valid;
}

}  // namespace fpmshell
