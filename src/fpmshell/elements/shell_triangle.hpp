// Internal forces of the FPM shell triangle over one path element (theory.md §3-§5):
// CST membrane + rotation-only bending (BCIZ or DKT), stresses integrated at in-plane x
// thickness points through a material, out-of-plane nodal forces from element equilibrium,
// and the forward rotation of the local force system into the current configuration.
#pragma once

#include <array>
#include <span>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/elements/reverse_motion.hpp"
#include "fpmshell/elements/triangle_shape.hpp"
#include "fpmshell/materials/material_point.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// Integration layout of a section: points are stored [inplane g][thickness k].
struct ShellRule {
    Real thickness = 0;
    std::span<const TrianglePoint> inplane;
    std::span<const ThicknessPoint> through;
    BendingKernel bending = BendingKernel::Bciz;

    [[nodiscard]] int n_points() const {
        return static_cast<int>(inplane.size() * through.size());
    }
};

/// What one element returns for one step.
struct ShellTriangleLoads {
    std::array<Vec3, 3> force;   ///< internal (resisting) nodal forces, global frame, t_n
    std::array<Vec3, 3> moment;  ///< internal nodal moments, global frame, t_n
    Real strain_work = 0;        ///< work of the stresses over the step (trapezoidal), energy.csv
    Real damping_work = 0;       ///< work of the viscous (stiffness-damping) stresses
    Real plastic_work = 0;       ///< plastic dissipation over the step (part of strain_work)
    Real thickness_strain = 0;   ///< d eps_33 averaged over the points (theory.md §3.4)
    Voigt3 membrane_force = Voigt3::Zero();  ///< N averaged over the element, local frame
    Voigt3 membrane_resultant = Voigt3::Zero();  ///< the same plus the viscous part: what the
                                                 ///< membrane nodal forces are made of
    Voigt3 bending_moment = Voigt3::Zero();  ///< M averaged over the element, local frame
};

/// Curvature matrix of the chosen bending kernel at area coordinates L.
[[nodiscard]] inline Mat36 bending_b(BendingKernel kernel, const TriangleShape& s,
                                     const std::array<Real, 3>& L) {
    return kernel == BendingKernel::Dkt ? bending_b_dkt(s, L) : bending_b_bciz(s, L);
}

/// Element loads from the reversed path element rt.
/// points: the element's material points (old state in, new state out).
/// viscous_rate: a_s / dt_{n-1/2} (theory.md §6.5), 0 without stiffness damping.
/// dt: duration of the path element, for rate-dependent materials (0: no rate).
/// thickness: the element's thickness at the start of the step (rule.thickness if <= 0).
/// smoothed_membrane: when given, the membrane strain increment to use instead of the CST
/// one (smoothed over the element's neighbours); the element's own membrane nodal forces are
/// then own_share times A B_m^T N, the rest goes to the neighbours (shell_elements.cpp).
template <class Material>
ShellTriangleLoads shell_triangle_loads(const ReversedTriangle& rt, const ShellRule& rule,
                                        const Material& material,
                                        std::span<MaterialPoint> points, Real viscous_rate,
                                        Real dt = 0, Real thickness = 0,
                                        const Voigt3* smoothed_membrane = nullptr, Real own_share = 1) {
    ShellTriangleLoads out;
    const TriangleShape shape(rt.x2, rt.x3, rt.y3);
    const Mat36 bm = membrane_b(shape);
    const bool dkt = rule.bending == BendingKernel::Dkt;
    const DktShape dkt_s = dkt ? dkt_shape(shape) : DktShape{};  // once per element (§4.7)
    Eigen::Matrix<Real, 6, 1> u_vec, th_vec;
    for (int i = 0; i < 3; ++i) {
        u_vec.segment<2>(2 * i) = rt.u[i];
        th_vec.segment<2>(2 * i) = rt.theta[i];
    }
    const Voigt3 d_eps_m = smoothed_membrane ? *smoothed_membrane : Voigt3(bm * u_vec);  // §3.1
    const Real h = thickness > 0 ? thickness : rule.thickness, half_h = 0.5 * h;
    // §3.4: d eps_33 = -(d eps_11 + d eps_22) + (1 - 2 nu) / E (d sigma_11 + d sigma_22), i.e.
    // -nu/(1-nu) of the elastic and -1 times the plastic in-plane dilatation.
    const Real thickness_factor = (1.0 - 2.0 * material.poisson_ratio()) / material.youngs_modulus();
    const Mat3& c = material.stiffness();

    Voigt3 n_weighted = Voigt3::Zero();  // sum of A w_g N_g: B_m is constant over the CST
    // §4.3 The curvature matrix of both kernels is linear in the area coordinates,
    // B(L) = sum_i L_i B(e_i): it is evaluated at the three corners only, and the curvature
    // and the moment loads of any number of points follow from the corner values.
    std::array<Mat36, 3> b_corner;
    std::array<Voigt3, 3> kappa_corner, m_corner;  // B(e_i) theta; sum_g A w_g L_gi M_g
    for (std::size_t i = 0; i < 3; ++i) {
        std::array<Real, 3> corner{0, 0, 0};
        corner[i] = 1;
        b_corner[i] = dkt ? bending_b_dkt(dkt_s, corner) : bending_b_bciz(shape, corner);
        kappa_corner[i] = b_corner[i] * th_vec;
        m_corner[i].setZero();
    }
    const int nk = static_cast<int>(rule.through.size());
    int g = 0;
    for (const TrianglePoint& ip : rule.inplane) {
        const Voigt3 d_kappa = ip.L[0] * kappa_corner[0] + ip.L[1] * kappa_corner[1] + ip.L[2] * kappa_corner[2];
        Voigt3 n_g = Voigt3::Zero(), m_g = Voigt3::Zero();
        Real work_g = 0, plastic_g = 0;
        for (int k = 0; k < nk; ++k) {
            const ThicknessPoint& tp = rule.through[static_cast<std::size_t>(k)];
            const Real z = tp.zeta * half_h;
            const Voigt3 d_eps = d_eps_m + z * d_kappa;  // §4.4
            MaterialPoint& mp = points[static_cast<std::size_t>(g * nk + k)];
            const Voigt3 sigma_old = mp.stress;
            const Real plastic_old = mp.plastic_work;
            material.update(mp, d_eps, dt, mp);  // old and new may alias: update reads first
            const Real wz = half_h * tp.weight;
            plastic_g += wz * (mp.plastic_work - plastic_old);
            out.thickness_strain += 0.5 * ip.weight * tp.weight *
                                    (thickness_factor * (mp.stress(0) + mp.stress(1) - sigma_old(0) - sigma_old(1)) -
                                     d_eps(0) - d_eps(1));
            n_g += wz * mp.stress;  // §3.2 resultants
            m_g += (wz * z) * mp.stress;
            work_g += wz * 0.5 * (sigma_old + mp.stress).dot(d_eps);
        }
        out.membrane_force += ip.weight * n_g;
        out.bending_moment += ip.weight * m_g;
        if (viscous_rate > 0) {  // §6.5 viscous resultants, force evaluation only
            const Voigt3 n_v = viscous_rate * h * (c * d_eps_m);
            const Voigt3 m_v = viscous_rate * (h * h * h / 12.0) * (c * d_kappa);
            out.damping_work += rt.area * ip.weight * (n_v.dot(d_eps_m) + m_v.dot(d_kappa));
            n_g += n_v;
            m_g += m_v;
        }
        const Real wa = rt.area * ip.weight;
        n_weighted += wa * n_g;
        out.membrane_resultant += ip.weight * n_g;
        for (std::size_t i = 0; i < 3; ++i) m_corner[i] += (wa * ip.L[i]) * m_g;
        out.strain_work += rt.area * ip.weight * work_g;
        out.plastic_work += rt.area * ip.weight * plastic_g;
        ++g;
    }
    const Eigen::Matrix<Real, 6, 1> f_m = own_share * (bm.transpose() * n_weighted);  // §3.3
    const Eigen::Matrix<Real, 6, 1> m_b = b_corner[0].transpose() * m_corner[0] +  // §4.5
                                          b_corner[1].transpose() * m_corner[1] +
                                          b_corner[2].transpose() * m_corner[2];
    // §4.6 eq. 4.6b: the moments the particles take, less their part about each node's drill
    // axis (the rotation the node has from the element, eq. 2.6c).
    std::array<Vec3, 3> m_node;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto k = 2 * static_cast<Eigen::Index>(i);
        const Vec3 m(m_b(k), m_b(k + 1), 0.0);
        m_node[i] = m - m.dot(rt.drill_local[i]) * rt.drill_local[i];
    }
    // §4.6 eq. 4.6a out-of-plane forces from the equilibrium of the element (node-1-origin
    // frame); eq. 4.6c the in-plane couple on side 1-2 that balances the moments' drilling part.
    const Real sum_mx = m_node[0].x() + m_node[1].x() + m_node[2].x();
    const Real sum_my = m_node[0].y() + m_node[1].y() + m_node[2].y();
    const Real sum_mz = m_node[0].z() + m_node[1].z() + m_node[2].z();
    const Real f3z = -sum_mx / rt.y3;
    const Real f2z = (sum_my - rt.x3 * f3z) / rt.x2;
    const Real f1z = -f2z - f3z;
    const std::array<Real, 3> fz{f1z, f2z, f3z};
    const Real f_couple = sum_mz / rt.x2;
    const std::array<Real, 3> fy_couple{f_couple, -f_couple, 0.0};
    // §5 forward rotation: global = T_t^T local.
    const Mat3 to_global = rt.frame_current.transpose();
    for (std::size_t i = 0; i < 3; ++i) {
        const auto k = 2 * static_cast<Eigen::Index>(i);
        out.force[i] = to_global * Vec3(f_m(k), f_m(k + 1) + fy_couple[i], fz[i]);
        out.moment[i] = to_global * m_node[i];
    }
    return out;
}

}  // namespace fpmshell
