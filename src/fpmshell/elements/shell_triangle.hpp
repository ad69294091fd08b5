// Internal forces of the FPM shell triangle over one path element (theory.md §3-§5), for any
// material: CST membrane + rotation-only bending (BCIZ or DKT), stresses integrated at in-plane
// x thickness points through the material's update, out-of-plane nodal forces from element
// equilibrium, and the forward rotation of the local force system into the current
// configuration. The element itself is elastic_triangle_block.hpp's local_triangle_loads with
// T = Real (the SIMD blocks run the same source on k_lanes elements).
#pragma once

#include <array>
#include <span>
#include <type_traits>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"
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

    [[nodiscard]] int n_points() const { return static_cast<int>(inplane.size() * through.size()); }
};

/// What one element returns for one step.
struct ShellTriangleLoads {
    std::array<Vec3, 3> force;   ///< internal (resisting) nodal forces, global frame, t_n
    std::array<Vec3, 3> moment;  ///< internal nodal moments, global frame, t_n
    Real strain_work = 0;        ///< work of the stresses over the step (trapezoidal), energy.csv
    Real damping_work = 0;       ///< work of the viscous (stiffness-damping) stresses
    Real plastic_work = 0;       ///< plastic dissipation over the step (part of strain_work)
    Real thickness_strain = 0;   ///< d eps_33 averaged over the points (theory.md §3.4)
    Voigt3 membrane_force = Voigt3::Zero();      ///< N averaged over the element, local frame
    Voigt3 membrane_resultant = Voigt3::Zero();  ///< the same plus the viscous part: what the
                                                 ///< membrane nodal forces are made of
    Voigt3 bending_moment = Voigt3::Zero();      ///< M averaged over the element, local frame
};

/// Curvature matrix of the chosen bending kernel at area coordinates L.
[[nodiscard]] inline Mat36 bending_b(BendingKernel kernel, const TriangleShape& s,
                                     const std::array<Real, 3>& L) {
    return kernel == BendingKernel::Dkt ? bending_b_dkt(s, L) : bending_b_bciz(s, L);
}

/// Element loads from the reversed path element rt.
/// points: the element's material points (old state in, new state out), of the material's
/// point type (MaterialPoint unless given).
/// viscous_rate: a_s / dt_{n-1/2} (theory.md §6.5), 0 without stiffness damping.
/// dt: duration of the path element, for rate-dependent materials (0: no rate).
/// thickness: the element's thickness at the start of the step (rule.thickness if <= 0).
/// smoothed_membrane: when given, the membrane strain increment to use instead of the CST
/// one (smoothed over the element's neighbours); the element's own membrane nodal forces are
/// then own_share times A B_m^T N, the rest goes to the neighbours (shell_elements.cpp).
/// fading: the fading of the points' stress by their damage (eq. 7.6-6), nullptr: none.
/// The viscous resultants use the isotropic C of the material (c11, c12, c33).
template <class Material, class Point = MaterialPoint>
ShellTriangleLoads shell_triangle_loads(const ReversedTriangle& rt, const ShellRule& rule,
                                        const Material& material,
                                        std::span<std::type_identity_t<Point>> points,
                                        Real viscous_rate, Real dt = 0, Real thickness = 0,
                                        const Voigt3* smoothed_membrane = nullptr,
                                        Real own_share = 1,
                                        const StressFading<Real>* fading = nullptr) {
    // The element of elastic_triangle_block.hpp on one path element (T = Real), its points
    // turned by the material's own update.
    const Mat3& c = material.stiffness();
    ElasticSectionConstants sec;
    sec.c11 = c(0, 0);
    sec.c12 = c(0, 1);
    sec.c33 = c(2, 2);
    // §3.4: d eps_33 = -(d eps_11 + d eps_22) + (1 - 2 nu) / E (d sigma_11 + d sigma_22)
    sec.thickness_factor = (1.0 - 2.0 * material.poisson_ratio()) / material.youngs_modulus();
    sec.inplane = rule.inplane;
    sec.through = rule.through;
    sec.bending = rule.bending;
    std::array<Real, 3 * k_max_block_points> stress;
    for (std::size_t p = 0; p < points.size(); ++p)
        for (std::size_t r = 0; r < 3; ++r)
            stress[3 * p + r] = points[p].stress(static_cast<Eigen::Index>(r));
    auto update = [&](std::size_t p, const std::array<Real, 3>& d_eps, Real* sigma) {
        Point& mp = points[p];
        Real plastic_old = 0;
        if constexpr (requires { mp.plastic_work; }) plastic_old = mp.plastic_work;
        material.update(mp, Voigt3(d_eps[0], d_eps[1], d_eps[2]), dt, mp);  // old and new may alias
        for (std::size_t r = 0; r < 3; ++r) sigma[r] = mp.stress(static_cast<Eigen::Index>(r));
        if constexpr (requires { mp.plastic_work; }) return mp.plastic_work - plastic_old;
        return plastic_old;  // 0: a law without plastic work
    };
    SmoothedMembrane<Real> smoothed;
    if (smoothed_membrane) {
        smoothed.strain = {(*smoothed_membrane)(0), (*smoothed_membrane)(1),
                           (*smoothed_membrane)(2)};
        smoothed.own_share = own_share;
    }
    const ElasticTriangleLoads<Real> loads =  // eq. 7.6-6: fading, a variant of its own
        fading ? local_triangle_loads<Real, NoReturnMapping, decltype(update), true>(
                     rt.local, true, sec, thickness > 0 ? thickness : rule.thickness, stress.data(),
                     viscous_rate, nullptr, NoReturnMapping{}, update,
                     smoothed_membrane ? &smoothed : nullptr, fading)
               : local_triangle_loads<Real>(rt.local, true, sec,
                                            thickness > 0 ? thickness : rule.thickness,
                                            stress.data(), viscous_rate, nullptr, NoReturnMapping{},
                                            update, smoothed_membrane ? &smoothed : nullptr);
    ShellTriangleLoads out;
    for (std::size_t i = 0; i < 3; ++i) {
        out.force[i] = Vec3(loads.force[i].x, loads.force[i].y, loads.force[i].z);
        out.moment[i] = Vec3(loads.moment[i].x, loads.moment[i].y, loads.moment[i].z);
    }
    out.strain_work = loads.strain_work;
    out.damping_work = loads.damping_work;
    out.plastic_work = loads.plastic_work;
    out.thickness_strain = loads.thickness_strain;
    out.membrane_force =
        Voigt3(loads.membrane_force[0], loads.membrane_force[1], loads.membrane_force[2]);
    out.bending_moment =
        Voigt3(loads.bending_moment[0], loads.bending_moment[1], loads.bending_moment[2]);
    if (smoothed_membrane)
        out.membrane_resultant = Voigt3(loads.membrane_resultant[0], loads.membrane_resultant[1],
                                        loads.membrane_resultant[2]);
    return out;
}

}  // namespace fpmshell
