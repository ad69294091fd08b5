// The plane-stress J2 return mapping of theory.md §7.3 (Simo & Taylor 1986), written once for
// a scalar type T (core/simd.hpp): J2Plastic::update runs it on one point (T = Real), the
// element blocks on the same point of k_lanes elements at once (T = RealPack). The Newton
// iteration is masked: every lane keeps its own bracket and iterate and stops changing once it
// has converged, so a lane gives what the scalar iteration gives for that point (to rounding:
// the compiler may contract a*b+c into one FMA in one and not in the other).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/materials/j2/flow_stress.hpp"
#include "fpmshell/materials/j2/j2_consistency.hpp"

namespace fpmshell {

/// The history of one point per lane, as in MaterialPoint (the filtered strain rate is the
/// caller's: it sets the rate factor R, frozen during the return, §7.4 option a).
template <class T>
struct J2PointState {
    std::array<T, 3> stress, back_stress;
    T plastic_strain, flow_radius, flow_slope;
};

/// The new state of a point and its increment of plastic work per unit volume.
template <class T>
struct J2Return {
    J2PointState<T> state;
    T plastic_work;
    MaskOf<T> yielded;    ///< lanes whose trial state was outside the yield surface
    int evaluations = 0;  ///< evaluations of the consistency residual (the most of any lane)
};

namespace j2_detail {

/// x^T P x (§7.1) = (x11 + x22)^2 / 6 + (x22 - x11)^2 / 2 + 2 x12^2, i.e. 2 J2 (von Mises),
/// or with the coefficients of Hill's normal anisotropy (eq. 7.1-3).
template <class T>
[[nodiscard]] FPMSHELL_INLINE T p_norm2(const J2ReturnConstants& c, const std::array<T, 3>& x) {
    const T s = x[0] + x[1], d = x[1] - x[0];
    return s * s * c.p_sum + c.p_diff * d * d + c.p_shear * x[2] * x[2];
}

}  // namespace j2_detail

namespace j2_detail {

/// Steps 1-2 of one point per lane: the trial state, the elastic check, the constants of the
/// return.
template <class T>
struct Trial {
    J2Return<T> out;  ///< the trial state (what a lane that does not yield returns)
    MaskOf<T> yielding;
    TrialReturn<T> t;
    std::array<T, 3> xi_tr;
    T s_tr, d_tr, h_k, slope_n;
};

template <class T>
[[nodiscard]] FPMSHELL_INLINE Trial<T> trial_state(const J2ReturnConstants& c,
                                                   const J2PointState<T>& old,
                                                   const std::array<T, 3>& d_eps, const T& r,
                                                   const MaskOf<T>& lanes) {
    Trial<T> tr;  // set below (zeroing the whole of it costs a pack's return a few per cent)
    const T alpha_n = old.plastic_strain;
    // kappa / R and sigma_f' at alpha_n, stored by the last plastic step (the flow curve at
    // alpha = 0 before the first one; -1: the slope is not known yet)
    const MaskOf<T> hardened = alpha_n > 0.0;
    const T flow_radius_n = select(hardened, old.flow_radius, T(c.flow_radius0));
    const T flow_slope_n = select(hardened, old.flow_slope, T(-1.0));
    // 1 trial state
    const std::array<T, 3> sigma_tr{old.stress[0] + (c.c11 * d_eps[0] + c.c12 * d_eps[1]),
                                    old.stress[1] + (c.c12 * d_eps[0] + c.c11 * d_eps[1]),
                                    old.stress[2] + c.c33 * d_eps[2]};
    tr.xi_tr = {sigma_tr[0] - old.back_stress[0], sigma_tr[1] - old.back_stress[1],
                sigma_tr[2] - old.back_stress[2]};
    // the yield radius at alpha_n: R times the stored one, or on a table the curve of the
    // point's rate (the stored radius is the first curve's, the smallest)
    const T kappa_n = c.rate_table ? table_flow(c.flow.table, alpha_n, r).value : r * flow_radius_n;
    const T third_k2 = kappa_n * kappa_n * (1.0 / 3.0);
    const T f_tr = 0.5 * p_norm2(c, tr.xi_tr) - third_k2;
    // member by member: an aggregate assignment copies the mask through an 8-byte load of the
    // byte just stored, which stalls store forwarding (perf: a tenth of the Johnson-Cook kernel)
    tr.out.state = {sigma_tr, old.back_stress, alpha_n, flow_radius_n, flow_slope_n};
    tr.out.plastic_work = T(0.0);
    tr.yielding = lanes && (f_tr > c.tolerance * third_k2);
    tr.out.yielded = tr.yielding;
    tr.out.evaluations = 0;
    if (!any_lane(tr.yielding)) {  // never read for a result, but defined
        tr.t = TrialReturn<T>{};
        tr.s_tr = tr.d_tr = tr.h_k = tr.slope_n = T(0.0);
        return tr;
    }

    // 2 constants; H_k frozen at alpha_n (§7.4); a point that never yielded has the slope of
    // the flow curve at alpha = 0
    tr.slope_n = select(flow_slope_n < 0.0, T(c.flow_slope0), flow_slope_n);
    tr.h_k = (1.0 - c.beta) * r * tr.slope_n;
    tr.s_tr = tr.xi_tr[0] + tr.xi_tr[1];
    tr.d_tr = tr.xi_tr[1] - tr.xi_tr[0];
    TrialReturn<T>& t = tr.t;
    t.a1_sq = tr.s_tr * tr.s_tr * c.p_sum;                                           // A1
    t.a2_sq = c.p_diff * tr.d_tr * tr.d_tr + c.p_shear * tr.xi_tr[2] * tr.xi_tr[2];  // A2
    t.a1 = c.bulk_term + (2.0 / 3.0) * tr.h_k;
    t.a2 = c.two_g + (2.0 / 3.0) * tr.h_k;
    const T fbar2_tr = t.a1_sq + t.a2_sq;
    t.fbar_tr = pipelined_sqrt(fbar2_tr);
    const T inv_fbar2_tr = pipelined_reciprocal(fbar2_tr);
    t.a_bar = (t.a1_sq * t.a1 + t.a2_sq * t.a2) * inv_fbar2_tr;
    t.m2 = (t.a1_sq * t.a1 * t.a1 + t.a2_sq * t.a2 * t.a2) * inv_fbar2_tr;
    t.alpha_n = alpha_n;
    t.r = c.rate_table ? T(1.0) : r;  // a table's curve is the point's flow curve
    t.kappa_n = kappa_n;
    t.third_k2 = third_k2;
    t.flow_radius_n = flow_radius_n;
    return tr;
}

/// Step 4 from the solution of step 3.
template <class T>
[[nodiscard]] FPMSHELL_INLINE J2Return<T> returned_state(const J2ReturnConstants& c,
                                                         const J2PointState<T>& old,
                                                         const Trial<T>& tr,
                                                         const Consistency<T>& solution) {
    J2Return<T> out = tr.out;
    const MaskOf<T>& yielding = tr.yielding;
    const T dg = solution.dgamma;
    out.evaluations = solution.evaluations;
    // 4 update, with q_i = 1 / (1 + a_i dgamma) and f_bar = sqrt(xi^T P xi) of the last
    // evaluation
    const T s = tr.s_tr * solution.q1, d = tr.d_tr * solution.q2;
    const std::array<T, 3> xi{0.5 * (s - d), 0.5 * (s + d), tr.xi_tr[2] * solution.q2};
    const T hardening_step = (2.0 / 3.0) * tr.h_k * dg;
    J2PointState<T> next;
    for (std::size_t k = 0; k < 3; ++k) {
        next.back_stress[k] = old.back_stress[k] + hardening_step * xi[k];
        next.stress[k] = next.back_stress[k] + xi[k];
    }
    next.plastic_strain = tr.t.alpha_n + k_sqrt23 * dg * solution.fbar;
    // kappa / R; on a table the first curve's radius, that the next step's check reads
    next.flow_radius = c.rate_table ? table_flow(c.flow.table, next.plastic_strain, T(0.0)).value
                                    : solution.flow_radius;
    next.flow_slope = solution.flow_slope;
    // d_eps_p = dgamma P xi (engineering shear). Dissipation by the trapezoidal rule, like the
    // element's strain work: then strain work - plastic work = the exact change of the elastic
    // energy 1/2 sigma C^-1 sigma, never negative whatever the increment.
    const std::array<T, 3> p_xi =
        c.anisotropic ? std::array<T, 3>{c.p_sum * s - c.p_diff * d, c.p_sum * s + c.p_diff * d,
                                         c.p_shear * xi[2]}
                      : std::array<T, 3>{(2.0 * xi[0] - xi[1]) * (1.0 / 3.0),
                                         (2.0 * xi[1] - xi[0]) * (1.0 / 3.0), 2.0 * xi[2]};
    const T work = dg * (0.5 * (old.stress[0] + next.stress[0]) * p_xi[0] +
                         0.5 * (old.stress[1] + next.stress[1]) * p_xi[1] +
                         0.5 * (old.stress[2] + next.stress[2]) * p_xi[2]);
    for (std::size_t k = 0; k < 3; ++k) {
        out.state.stress[k] = select(yielding, next.stress[k], out.state.stress[k]);
        out.state.back_stress[k] = select(yielding, next.back_stress[k], out.state.back_stress[k]);
    }
    out.state.plastic_strain = select(yielding, next.plastic_strain, out.state.plastic_strain);
    out.state.flow_radius = select(yielding, next.flow_radius, out.state.flow_radius);
    out.state.flow_slope = select(yielding, next.flow_slope, out.state.flow_slope);
    out.plastic_work = select(yielding, work, T(0.0));
    return out;
}

/// {f(0), ..., f(K - 1)}
template <std::size_t K, class F>
[[nodiscard]] FPMSHELL_INLINE auto array_of(const F& f) {
    using Value = std::decay_t<decltype(f(std::size_t{0}))>;  // not CTAD: K = 1 of an array
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<Value, K>{f(I)...};
    }
    (std::make_index_sequence<K>{});
}

}  // namespace j2_detail

/// §7.3 on K points per lane at once (their Newton iterations in lockstep, j2_consistency.hpp),
/// each on the lanes of its `lanes`: the trial state from the old one and the strain increment
/// d_eps (engineering shear), the elastic check, and where it fails the return along the
/// plane-stress projection. r: the rate factor R >= 1 of each lane (§7.4). A lane outside
/// `lanes` returns its trial state. A point's result does not depend on the others.
template <class T, std::size_t K>
[[nodiscard]] std::array<J2Return<T>, K> j2_return_mapping_points(
    const J2ReturnConstants& c, const std::array<J2PointState<T>, K>& old,
    const std::array<std::array<T, 3>, K>& d_eps, const std::array<T, K>& r,
    const std::array<MaskOf<T>, K>& lanes) {
    using namespace j2_detail;
    const std::array<Trial<T>, K> tr = array_of<K>(
        [&](std::size_t k) { return trial_state(c, old[k], d_eps[k], r[k], lanes[k]); });
    bool any = false;
    for (const Trial<T>& x : tr) any = any || any_lane(x.yielding);
    if (!any) return array_of<K>([&](std::size_t k) { return tr[k].out; });

    // 3 the consistency condition (§7.3a)
    const FlowStress& fl = c.flow;
    std::array<Consistency<T>, K> solution;
    auto solve = [&](auto make) {
        auto iterations = array_of<K>(make);
        solve_in_lockstep(iterations);
        for (std::size_t k = 0; k < K; ++k) solution[k] = iterations[k].result();
    };
    if (fl.kind == FlowStress::Kind::Linear) {
        auto linear = [&fl](const T& alpha) {
            return FlowValue<T>{fl.yield_stress + fl.hardening * alpha, T(fl.hardening)};
        };
        solve([&](std::size_t k) {
            return DgammaIteration<T, decltype(linear)>(c, tr[k].t, tr[k].slope_n, tr[k].yielding,
                                                        linear);
        });
    } else if (fl.kind == FlowStress::Kind::PowerLaw) {  // a finite slope everywhere
        auto power = [&fl](const T& alpha) {
            const T e = fl.strain_offset + alpha;
            const T p = vector_pow(e, T(fl.n - 1.0));  // e^n = e e^(n-1)
            return FlowValue<T>{fl.b * e * p, fl.b * fl.n * p};
        };
        solve([&](std::size_t k) {
            return DgammaIteration<T, decltype(power)>(c, tr[k].t, tr[k].slope_n, tr[k].yielding,
                                                       power);
        });
    } else if (fl.kind == FlowStress::Kind::Tabulated) {
        solve([&](std::size_t k) {  // the curve of the point's rate (the first without a table)
            return DgammaIteration<T, TableCurveAt<T>>(
                c, tr[k].t, tr[k].slope_n, tr[k].yielding,
                TableCurveAt<T>{&fl.table, c.rate_table ? r[k] : T(0.0)});
        });
    } else if (fl.n <= 1.0 && c.beta > 0.0) {
        solve([&](std::size_t k) { return FlowStressIteration<T>(c, tr[k].t, tr[k].yielding); });
    } else {
        auto curve = [&c](const T& alpha) { return johnson_cook_curve(c, alpha); };
        solve([&](std::size_t k) {
            return DgammaIteration<T, decltype(curve)>(c, tr[k].t, tr[k].slope_n, tr[k].yielding,
                                                       curve);
        });
    }
    return array_of<K>(
        [&](std::size_t k) { return returned_state(c, old[k], tr[k], solution[k]); });
}

/// §7.3 on one point per lane (j2_return_mapping_points with K = 1).
template <class T>
[[nodiscard]] J2Return<T> j2_return_mapping(const J2ReturnConstants& c, const J2PointState<T>& old,
                                            const std::array<T, 3>& d_eps, const T& r,
                                            const MaskOf<T>& lanes) {
    return j2_return_mapping_points<T, 1>(c, {old}, {d_eps}, {r}, {lanes})[0];
}

}  // namespace fpmshell
