#include "fpmshell/elements/reverse_motion.hpp"

#include <cmath>

#include "fpmshell/core/rotation.hpp"

namespace fpmshell {

ReversedTriangle reverse_motion(const std::array<Vec3, 3>& base, const std::array<Vec3, 3>& current,
                                const std::array<Vec3, 3>& dtheta,
                                const std::array<Vec3, 3>& drill_axis) {
    ReversedTriangle out;
    // §2.1 reverse translation by the motion of node 1.
    const Vec3 a2 = base[1] - base[0], a3 = base[2] - base[0];
    const Vec3 r2 = current[1] - current[0], r3 = current[2] - current[0];
    const Vec3 na_raw = a2.cross(a3), n_raw = r2.cross(r3);
    const Real lmax2 = std::max({a2.squaredNorm(), a3.squaredNorm(), (a3 - a2).squaredNorm()});
    if (na_raw.norm() <= 1e-12 * lmax2 || n_raw.norm() <= 1e-12 * lmax2) {
        out.degenerate = true;
        out.frame_current = Mat3::Identity();
        return out;
    }
    const Vec3 na = na_raw.normalized(), n = n_raw.normalized();
    out.area = 0.5 * na_raw.norm();
    out.area_ratio = n_raw.norm() / na_raw.norm();
    out.normal_cosine = na.dot(n);
    // §2.2 reverse out-of-plane rotation R_op = R_{na -> n}. The trig-free form is used while
    // the tilt is below ~154 deg; beyond it (only in kernel tests: a stable step never tilts an
    // element that much) the axis-angle form, with any in-plane axis for an exact flip.
    Mat3 r_op;
    if (out.normal_cosine > -0.9) {
        r_op = minimal_rotation(na, n);
    } else {
        const Vec3 v = na.cross(n);
        const Real s = v.norm();
        const Vec3 axis = s > 1e-12 ? Vec3(v / s) : Vec3(a2.normalized());
        r_op = rotation_matrix(std::atan2(s, out.normal_cosine) * axis);
    }
    const Vec3 r2p = r_op.transpose() * r2, r3p = r_op.transpose() * r3;
    // §2.3 reverse in-plane rotation about na bringing edge 1->2 back onto the base edge.
    const Real theta_ip = small_angle_atan2(na.dot(a2.cross(r2p)), a2.dot(r2p));
    const Mat3 r_ip = rotation_matrix(theta_ip * na);
    const Vec3 r2pp = r_ip.transpose() * r2p, r3pp = r_ip.transpose() * r3p;
    // §2.5 deformation frame on the base configuration.
    const Vec3 ex = a2.normalized(), ez = na, ey = ez.cross(ex);
    Mat3 t_a;
    t_a.row(0) = ex.transpose();
    t_a.row(1) = ey.transpose();
    t_a.row(2) = ez.transpose();
    out.x2 = a2.norm();
    out.x3 = ex.dot(a3);
    out.y3 = ey.dot(a3);
    // §2.4 deformation displacements in the local frame.
    const Vec3 u2 = t_a * (r2pp - a2), u3 = t_a * (r3pp - a3);
    out.u[0] = Vec2::Zero();
    out.u[1] = u2.head<2>();
    out.u[2] = u3.head<2>();
    // §2.6 deformation rotations, exact form: phi_i = log(R_r^T R(dtheta~_i)) (eq. 2.6b) with
    // dtheta~_i = dtheta_i + ((omega_r - dtheta_i) . d_i) d_i (eq. 2.6c): a node whose rotation
    // about its drill axis d_i is no degree of freedom takes the element's rigid rotation
    // omega_r = log(R_r) about it, so that a rigid rotation leaves phi_i = 0 on a curved shell.
    const Mat3 r_r = r_op * r_ip;
    const Vec3 omega_r = rotation_vector(r_r);
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3 dtheta_node =
            dtheta[i] + (omega_r - dtheta[i]).dot(drill_axis[i]) * drill_axis[i];
        const Vec3 phi = rotation_vector(r_r.transpose() * rotation_matrix(dtheta_node));
        out.theta[i] = (t_a * phi).head<2>();  // drilling component discarded
        out.drill_local[i] = t_a * drill_axis[i];
    }
    // §2.7 convected current frame T_t = T_a R_r^T.
    out.frame_current = t_a * r_r.transpose();
    return out;
}

}  // namespace fpmshell
