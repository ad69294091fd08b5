// The shell triangle (DKT or BCIZ bending), theory.md §2-§5, written once for a scalar type T
// (core/simd.hpp): with T = RealPack it computes k_lanes elements at once, one per SIMD lane;
// with T = Real it is the general element (shell_triangle.hpp).
//   - local_triangle_loads: the loads of a path element given in its local frame (§3.1 CST
//     or the smoothed membrane strain, §4.3 / §4.7 curvatures, the points' stresses through
//     the thickness, §3.3 / §4.5 / §4.6 nodal loads, §5 forward rotation). The points are a
//     linear elastic section's, a J2 section's (the trial check of §7.3 step 1 on every point
//     at once; the points that yield go, all together, to the caller's return mapping), or
//     any material's through its own point update (the general element).
//   - elastic_triangle_loads: the path element (path_element.hpp) with the small-angle series
//     of its rotations, then local_triangle_loads: for the path elements of a stable step,
//       - every rotation of the step (nodal increments, in-plane and relative rotations) is
//         below 0.01 rad,
//       - the element is not degenerate, not tilted by more than 90 deg, and keeps its area
//         within a factor of 2.
//     A lane outside these bounds is reported in `valid` and the caller computes that element
//     with the general element: the same path element with the rotations for any angle
//     (reverse_motion.hpp), which also reports the failures of §2.8. A J2 point whose trial
//     state yields is handed to the caller's return mapping, or, without one, also makes its
//     lane invalid. Within the bounds a lane gives the general element's result up to the
//     rounding of the series against the trigonometric forms and of the FMA contractions.
#pragma once

#include <array>
#include <span>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/elements/bciz_curvature.hpp"
#include "fpmshell/elements/cst_membrane.hpp"
#include "fpmshell/elements/dkt_curvature.hpp"
#include "fpmshell/elements/path_element.hpp"
#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/materials/j2/flow_stress.hpp"
#include "fpmshell/materials/j2/strain_rate.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// The constants of a linear elastic section with its integration rule.
struct ElasticSectionConstants {
    Real c11 = 0, c12 = 0,
         c33 = 0;               ///< plane-stress C: [[c11, c12, 0], [c12, c11, 0], [0, 0, c33]]
    Real thickness_factor = 0;  ///< (1 - 2 nu) / E, §3.4
    std::span<const TrianglePoint> inplane;
    std::span<const ThicknessPoint> through;
    BendingKernel bending = BendingKernel::Dkt;  ///< the curvature matrix: §4.7 DKT or §4.3 BCIZ
};

/// The yield surfaces of the points of a J2 section at the start of the step, [g][k].
/// A rate-dependent section's yield radius is R(rate) kappa_n with R >= 1 (§7.4): the check
/// first uses R = 1, a surface inside the true one, which a point well inside passes without
/// any logarithm or power; only the lanes outside it evaluate their R. A table of flow curves
/// at increasing rates (eq. 7.2-5) works alike: kappa_n is the first curve's, and a lane outside
/// it is checked against the curve of its rate. The filtered strain rate, part of the point's
/// state, is updated.
template <class T>
struct YieldSurfaces {
    const T* back_stress;              ///< b, 3 components per point (§7.2)
    const T* third_k2;                 ///< (kappa_n / R)^2 / 3 per point (§7.3)
    Real tolerance;                    ///< J2Plastic::k_yield_tolerance
    const RateFactor* rate = nullptr;  ///< rate-dependent sections: R(rate), §7.4
    const T* strain_rate = nullptr;    ///< the filtered rate per point, old
    T* new_strain_rate = nullptr;      ///< and new (§7.4 option a)
    Real dt = 0;                       ///< duration of the path element (0: no rate)
    Real rate_filter = 0;              ///< J2Plastic::k_rate_filter
    /// a rate table (RateFactor::selects_curve): its curves, and alpha_n per point
    const FlowTable* table = nullptr;
    const T* plastic_strain = nullptr;
};

/// No return mapping: a lane with a yielding point is reported invalid instead.
struct NoReturnMapping {};

/// The largest number of points of a section the block kernel takes (7 in-plane x 10 through
/// the thickness, the largest rules of quadrature.hpp).
inline constexpr std::size_t k_max_block_points = 7 * k_max_thickness_points;

/// The stresses of the points follow from the elastic trial (and, in a J2 section, the
/// yield check and return mapping) inside the kernel.
struct ElasticPoints {};

/// The smoothed membrane (membrane_smoothing.hpp): the strain increment to use instead of the
/// CST one, and the element's own share of its membrane nodal forces.
template <class T>
struct SmoothedMembrane {
    std::array<T, 3> strain;
    Real own_share = 1;
};

/// The fading of the points' stress by their damage (theory.md eq. 7.6-6; GISSMO's FADEXP), one
/// number per point: the nominal stress (1 - w) sigma is what the element integrates, sigma the
/// stress of the law. next[p]: w for the new stress; applied[p]: the w the old stress was
/// integrated with, set to next[p] on the valid lanes (the work over the step is the trapezoid
/// of the stresses the particles took).
template <class T>
struct StressFading {
    const T* next = nullptr;
    T* applied = nullptr;
};

/// What one lane returns (the quantities of ShellTriangleLoads an elastic element has).
template <class T>
struct ElasticTriangleLoads {
    std::array<V3<T>, 3> force, moment;  ///< internal nodal loads, global frame, t_n
    T strain_work, damping_work, plastic_work, thickness_strain;
    std::array<T, 3> membrane_force, bending_moment;  ///< N, M averaged over the element
    std::array<T, 3> membrane_resultant;  ///< smoothed membrane only: N plus its viscous part
    T characteristic_length;              ///< L_c = 2A / l_max of the current triangle (§6.4)
    T current_area;                       ///< A of the current triangle (eq. 6.4-2)
    MaskOf<T> valid;                      ///< lanes inside the bounds above
};

/// The value at area coordinates L of a field linear in L with corner values corner[i] (the
/// curvature increment: §4.3, §4.7).
template <class T>
[[nodiscard]] FPMSHELL_INLINE std::array<T, 3> interpolate(
    const std::array<Real, 3>& L, const std::array<std::array<T, 3>, 3>& corner) {
    std::array<T, 3> v;
    for (std::size_t r = 0; r < 3; ++r)
        v[r] = L[0] * corner[0][r] + L[1] * corner[1][r] + L[2] * corner[2][r];
    return v;
}

/// Loads of the path element `e` (§3-§5) with the section's points, lanes `valid`:
/// arguments as elastic_triangle_loads. update: ElasticPoints, or the general point update
/// update(point, d_eps, sigma) -> plastic work per unit volume, which turns the stress sigma
/// (3 components, old in, new out) by the strain increment d_eps. smoothed: the smoothed
/// membrane (nullptr: the CST). With Fades, fading (not null) fades the points' stress.
template <class T, class ReturnMapping = NoReturnMapping, class PointUpdate = ElasticPoints,
          bool Fades = false>
[[nodiscard]] FPMSHELL_INLINE ElasticTriangleLoads<T> local_triangle_loads(
    const LocalTriangle<T>& e, MaskOf<T> valid, const ElasticSectionConstants& sec,
    const T& thickness, T* stress, Real viscous_rate, const YieldSurfaces<T>* yield = nullptr,
    const ReturnMapping& return_mapping = {}, const PointUpdate& update = {},
    const SmoothedMembrane<T>* smoothed = nullptr, const StressFading<T>* fading = nullptr) {
    constexpr bool elastic_points = std::is_same_v<PointUpdate, ElasticPoints>;
    ElasticTriangleLoads<T> out;
    const T &x2 = e.x2, &x3 = e.x3, &y3 = e.y3, &inv_x2 = e.inv_x2, &area = e.area;
    const std::array<T, 3>&ux = e.ux, &uy = e.uy;
    const std::array<T, 6>& th = e.th;
    const std::array<V3<T>, 3>& drill_local = e.drill_local;
    const M3<T>& frame_current = e.frame_current;
    // ---- §3.1 CST ----
    const T inv_two_area = 1.0 / (x2 * y3);
    const CstGradients<T> cst = cst_gradients(x2, x3, y3, inv_two_area);
    const std::array<T, 3> d_eps_m = smoothed ? smoothed->strain : cst_strain(cst, ux, uy);

    // ---- §4.7 DKT or §4.3 BCIZ at the three corners (the curvature matrix is linear in L) ----
    std::array<std::array<std::array<T, 6>, 3>, 3> corner;  // B(e_i), rows kxx, kyy, kxy
    if (sec.bending == BendingKernel::Bciz) {
        const std::array<T, 3> b{-y3, y3, T(0.0)}, c{x3 - x2, -x3, x2};  // TriangleShape's b, c
        const T f = -(inv_two_area * inv_two_area);
        for (std::size_t i = 0; i < 3; ++i) {
            std::array<Real, 3> L{0.0, 0.0, 0.0};
            L[i] = 1.0;
            corner[i] = bciz_curvature(L, b, c, f);
        }
    } else {
        const DktSides<T> sides = dkt_sides(x2, x3, y3);
        static constexpr std::array<DktDerivatives, 3> k_corner_derivatives{
            dkt_derivatives({1.0, 0.0, 0.0}), dkt_derivatives({0.0, 1.0, 0.0}),
            dkt_derivatives({0.0, 0.0, 1.0})};
        for (std::size_t i = 0; i < 3; ++i)
            corner[i] = dkt_curvature(k_corner_derivatives[i], sides, x2, x3, y3, inv_two_area);
    }
    std::array<std::array<T, 3>, 3> kappa_corner, m_corner;
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t r = 0; r < 3; ++r) {
            const auto& row = corner[i][r];
            kappa_corner[i][r] = row[0] * th[0] + row[1] * th[1] + row[2] * th[2] + row[3] * th[3] +
                                 row[4] * th[4] + row[5] * th[5];
            m_corner[i][r] = T(0.0);
        }
    }

    // ---- §3.2, §4.4-§4.5, §7.3 the points: trial states, return mapping, integration ----
    const T h = thickness, half_h = 0.5 * h;
    const std::size_t nk = sec.through.size();
    const std::size_t n_points = sec.inplane.size() * nk;
    // pass 1: the strain increment and the trial stress of every point (elastic sections: the
    // new stress) and, in a J2 section, the check of §7.3 step 1
    std::array<std::array<T, 3>, k_max_block_points> d_eps, old;
    std::array<MaskOf<T>, k_max_block_points> yielding;
    std::array<T, k_max_block_points> rate_factor;     // R of §7.4 (1 where not evaluated)
    std::array<T, k_max_block_points> d_plastic_work;  // per unit volume, per point
    MaskOf<T> any_yielding = !valid && valid;          // no lane
    for (std::size_t g = 0, point = 0; g < sec.inplane.size(); ++g) {
        const TrianglePoint& ip = sec.inplane[g];
        const std::array<T, 3> d_kappa = interpolate(ip.L, kappa_corner);
        for (std::size_t k = 0; k < nk; ++k, ++point) {
            const T z = sec.through[k].zeta * half_h;
            const std::array<T, 3> de{d_eps_m[0] + z * d_kappa[0], d_eps_m[1] + z * d_kappa[1],
                                      d_eps_m[2] + z * d_kappa[2]};
            d_eps[point] = de;
            if constexpr (!elastic_points) {  // the general update: every point may yield
                T* sigma = stress + 3 * point;
                old[point] = {sigma[0], sigma[1], sigma[2]};
                d_plastic_work[point] = update(point, de, sigma);
                yielding[point] = valid;
                any_yielding = valid;
                continue;
            }
            const std::array<T, 3> d_sigma{sec.c11 * de[0] + sec.c12 * de[1],
                                           sec.c12 * de[0] + sec.c11 * de[1], sec.c33 * de[2]};
            T* sigma = stress + 3 * point;
            old[point] = {sigma[0], sigma[1], sigma[2]};
            for (std::size_t r = 0; r < 3; ++r) sigma[r] = old[point][r] + d_sigma[r];
            rate_factor[point] = 1.0;
            if (!yield) continue;
            // §7.3 step 1: f_tr = xi^T P xi / 2 - kappa^2 / 3 <= tol kappa^2 / 3
            const T* b = yield->back_stress + 3 * point;
            const T xs = (sigma[0] - b[0]) + (sigma[1] - b[1]),
                    xd = (sigma[1] - b[1]) - (sigma[0] - b[0]);
            const T x12 = sigma[2] - b[2];
            const T half_p2 = 0.5 * (xs * xs * (1.0 / 6.0) + 0.5 * xd * xd + 2.0 * x12 * x12);
            const T k2 = yield->third_k2[point];
            MaskOf<T> inside = (half_p2 - k2 <= yield->tolerance * k2);
            if (yield->rate) {  // the filtered rate (§7.4 a)
                const T rate = effective_strain_rate(de, yield->dt);
                const T new_rate = yield->rate_filter * rate +
                                   (1.0 - yield->rate_filter) * yield->strain_rate[point];
                yield->new_strain_rate[point] = new_rate;
                // A lane outside the R = 1 surface is checked against its own R(rate) >= 1:
                // one logarithm or power per pack with such a lane, none for the points well
                // inside.
                const MaskOf<T> outside = !inside && valid;
                if (any_lane(outside)) {
                    rate_factor[point] =
                        select(outside, yield->rate->value(new_rate), rate_factor[point]);
                    T k2_rate;
                    if (yield->table) {  // the radius of the curve at the rate's position
                        const T kappa = table_flow(*yield->table, yield->plastic_strain[point],
                                                   rate_factor[point])
                                            .value;
                        k2_rate = kappa * kappa * (1.0 / 3.0);
                    } else {
                        k2_rate = rate_factor[point] * rate_factor[point] * k2;
                    }
                    inside = inside || (half_p2 - k2_rate <= yield->tolerance * k2_rate);
                }
            }
            yielding[point] = !inside && valid;
            any_yielding = any_yielding || yielding[point];
        }
    }
    // pass 2: §7.3 steps 2-4 on every yielding point of every lane; without a return mapping
    // such a lane is left to the scalar element
    const bool plastic = (yield || !elastic_points) && any_lane(any_yielding);
    if constexpr (!elastic_points) {
    } else if constexpr (std::is_same_v<ReturnMapping, NoReturnMapping>) {
        if (plastic) valid = valid && !any_yielding;
    } else if (plastic) {
        d_plastic_work.fill(T(0.0));
        return_mapping(n_points, yielding.data(), d_eps.data(), rate_factor.data(), stress,
                       d_plastic_work.data());
    }
    // eq. 7.6-6: the nominal stresses the particles take, where the points fade (a variant of
    // its own: the kernel without fading keeps its code, and its results their bits)
    [[maybe_unused]] std::array<T, 3 * k_max_block_points> faded;
    [[maybe_unused]] std::array<std::array<T, 3>, k_max_block_points> old_faded;
    if constexpr (Fades) {
        for (std::size_t p = 0; p < n_points; ++p) {
            const T kept = 1.0 - fading->next[p], kept_old = 1.0 - fading->applied[p];
            for (std::size_t r = 0; r < 3; ++r) {
                faded[3 * p + r] = kept * stress[3 * p + r];
                old_faded[p][r] = kept_old * old[p][r];
            }
            if constexpr (std::is_same_v<T, Real>)
                fading->applied[p] = valid ? fading->next[p] : fading->applied[p];
            else
                stdx::where(valid, fading->applied[p]) = fading->next[p];
        }
    }
    // pass 3: through-thickness integration
    std::array<T, 3> n_weighted{T(0.0), T(0.0), T(0.0)};
    if (smoothed) out.membrane_resultant = {T(0.0), T(0.0), T(0.0)};
    out.strain_work = out.damping_work = out.plastic_work = out.thickness_strain = T(0.0);
    for (std::size_t r = 0; r < 3; ++r) out.membrane_force[r] = out.bending_moment[r] = T(0.0);
    for (std::size_t g = 0, point = 0; g < sec.inplane.size(); ++g) {
        const TrianglePoint& ip = sec.inplane[g];
        const std::array<T, 3> d_kappa = interpolate(ip.L, kappa_corner);
        std::array<T, 3> n_g{T(0.0), T(0.0), T(0.0)}, m_g{T(0.0), T(0.0), T(0.0)};
        T work_g = 0.0, plastic_g = 0.0;
        for (std::size_t k = 0; k < nk; ++k, ++point) {
            const ThicknessPoint& tp = sec.through[k];
            const T z = tp.zeta * half_h;
            const T* sigma = stress + 3 * point;
            const std::array<T, 3>& de = d_eps[point];
            const std::array<T, 3>& o = old[point];
            const T wz = half_h * tp.weight;
            if (plastic) plastic_g += wz * select(yielding[point], d_plastic_work[point], T(0.0));
            out.thickness_strain +=
                (0.5 * ip.weight * tp.weight) *
                (sec.thickness_factor * ((sigma[0] - o[0]) + (sigma[1] - o[1])) - de[0] - de[1]);
            if constexpr (Fades) sigma = faded.data() + 3 * point;  // what the particles take
            const std::array<T, 3>& o_taken = Fades ? old_faded[point] : o;
            const T wzz = wz * z;
            for (std::size_t r = 0; r < 3; ++r) {
                n_g[r] += wz * sigma[r];
                m_g[r] += wzz * sigma[r];
            }
            work_g += wz * 0.5 *
                      ((o_taken[0] + sigma[0]) * de[0] + (o_taken[1] + sigma[1]) * de[1] +
                       (o_taken[2] + sigma[2]) * de[2]);
        }
        for (std::size_t r = 0; r < 3; ++r) {
            out.membrane_force[r] += ip.weight * n_g[r];
            out.bending_moment[r] += ip.weight * m_g[r];
        }
        if (viscous_rate > 0) {  // §6.5 viscous resultants
            const T fn = viscous_rate * h, fm = viscous_rate * (h * h * h * (1.0 / 12.0));
            const std::array<T, 3> n_v{fn * (sec.c11 * d_eps_m[0] + sec.c12 * d_eps_m[1]),
                                       fn * (sec.c12 * d_eps_m[0] + sec.c11 * d_eps_m[1]),
                                       fn * (sec.c33 * d_eps_m[2])};
            const std::array<T, 3> m_v{fm * (sec.c11 * d_kappa[0] + sec.c12 * d_kappa[1]),
                                       fm * (sec.c12 * d_kappa[0] + sec.c11 * d_kappa[1]),
                                       fm * (sec.c33 * d_kappa[2])};
            out.damping_work += area * ip.weight *
                                (n_v[0] * d_eps_m[0] + n_v[1] * d_eps_m[1] + n_v[2] * d_eps_m[2] +
                                 m_v[0] * d_kappa[0] + m_v[1] * d_kappa[1] + m_v[2] * d_kappa[2]);
            for (std::size_t r = 0; r < 3; ++r) {
                n_g[r] += n_v[r];
                m_g[r] += m_v[r];
            }
        }
        if (smoothed)
            for (std::size_t r = 0; r < 3; ++r) out.membrane_resultant[r] += ip.weight * n_g[r];
        const T wa = area * ip.weight;
        for (std::size_t r = 0; r < 3; ++r) {
            n_weighted[r] += wa * n_g[r];
            for (std::size_t i = 0; i < 3; ++i) m_corner[i][r] += (wa * ip.L[i]) * m_g[r];
        }
        out.strain_work += wa * work_g;
        out.plastic_work += wa * plastic_g;
    }

    // ---- §3.3 membrane, §4.5 bending and §4.6 out-of-plane nodal loads ----
    std::array<T, 6> f_m = cst_nodal_forces(cst, n_weighted), m_b;
    if (smoothed)  // the rest goes to the neighbours (solver/shell_elements.cpp)
        for (T& f : f_m) f *= smoothed->own_share;
    for (std::size_t q = 0; q < 6; ++q) {
        T sum = 0.0;
        for (std::size_t i = 0; i < 3; ++i)
            sum += corner[i][0][q] * m_corner[i][0] + corner[i][1][q] * m_corner[i][1] +
                   corner[i][2][q] * m_corner[i][2];
        m_b[q] = sum;
    }
    // eq. 4.6b: the moments the particles take, less their part about each drill axis
    std::array<V3<T>, 3> m_node;
    for (std::size_t i = 0; i < 3; ++i) {
        const V3<T>& d = drill_local[i];
        const T along = m_b[2 * i] * d.x + m_b[2 * i + 1] * d.y;
        m_node[i] = V3<T>{m_b[2 * i] - along * d.x, m_b[2 * i + 1] - along * d.y, -(along * d.z)};
    }
    const T sum_mx = m_node[0].x + m_node[1].x + m_node[2].x,
            sum_my = m_node[0].y + m_node[1].y + m_node[2].y;
    const T sum_mz = m_node[0].z + m_node[1].z + m_node[2].z;
    const T f3z = -sum_mx * (x2 * inv_two_area);  // 1 / y3 = x2 / (x2 y3); eq. 4.6a
    const T f2z = (sum_my - x3 * f3z) * inv_x2;
    const T f1z = -f2z - f3z;
    const std::array<T, 3> fz{f1z, f2z, f3z};
    const T f_couple = sum_mz * inv_x2;  // eq. 4.6c
    const std::array<T, 3> fy_couple{f_couple, -f_couple, T(0.0)};
    // §5 forward rotation: global = T_t^T local.
    for (std::size_t i = 0; i < 3; ++i) {
        out.force[i] =
            transpose_times(frame_current, V3<T>{f_m[2 * i], f_m[2 * i + 1] + fy_couple[i], fz[i]});
        out.moment[i] = transpose_times(frame_current, m_node[i]);
    }
    out.valid = valid;
    return out;
}

/// Elastic step of the triangle on one path element per lane (theory.md §2-§5).
/// stress: the section's points [g][k], 3 components each, old in, new out (only meaningful
/// on valid lanes). thickness: h at the start of the step. viscous_rate as shell_triangle_loads.
/// yield: for a J2 section, the yield surfaces of the trial check.
/// return_mapping(n_points, yielding, d_eps, r, stress, d_plastic_work): called once, when
/// some point's trial stress is outside its yield surface on some lanes with a valid path
/// element; per point: the mask `yielding`, the strain increment and the rate factor R of
/// every lane, and the trial stress in `stress`. It runs §7.3 steps 2-4 on the yielding
/// (point, lane) pairs (materials/j2/j2_return_mapping.hpp), keeps their history, and writes
/// their new stress into `stress` and their plastic work per unit volume into d_plastic_work.
/// Without one (NoReturnMapping) such a lane is reported invalid instead.
/// With Fades, fading (not null): the fading of the points' stress by their damage (eq. 7.6-6).
template <class T, class ReturnMapping = NoReturnMapping, bool Fades = false>
[[nodiscard]] ElasticTriangleLoads<T> elastic_triangle_loads(
    const TriangleMotion<T>& m, const ElasticSectionConstants& sec, const T& thickness, T* stress,
    Real viscous_rate, const YieldSurfaces<T>* yield = nullptr,
    const ReturnMapping& return_mapping = {}, const StressFading<T>* fading = nullptr) {
    LocalTriangle<T> local;  // filled in place: a copy of its packs costs the kernel a few per cent
    PathElementChecks<T> checks;
    const MaskOf<T> valid = path_element<SeriesRotations>(m, local, checks);  // §2
    ElasticTriangleLoads<T> out = local_triangle_loads<T, ReturnMapping, ElasticPoints, Fades>(
        local, valid, sec, thickness, stress, viscous_rate, yield, return_mapping, ElasticPoints{},
        nullptr, fading);
    out.characteristic_length = checks.characteristic_length;
    out.current_area = checks.area_ratio * local.area;
    return out;
}

}  // namespace fpmshell
