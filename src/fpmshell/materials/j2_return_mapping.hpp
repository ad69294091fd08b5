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

#include "fpmshell/core/simd.hpp"
#include "fpmshell/materials/flow_stress.hpp"

namespace fpmshell {

/// Newton iterations before the return mapping gives up and keeps its last iterate.
inline constexpr int k_max_return_iterations = 100;

/// What the return mapping needs of a J2 material (J2Plastic holds one).
struct J2ReturnConstants {
    Real c11 = 0, c12 = 0,
         c33 = 0;        ///< plane-stress C: [[c11, c12, 0], [c12, c11, 0], [0, 0, c33]]
    Real bulk_term = 0;  ///< E / (3 (1 - nu)), the A1 coefficient of §7.3 without H_k
    Real two_g = 0;      ///< 2 G, the A2 coefficient without H_k
    Real beta = 1;       ///< hardening mix of §7.2: 1 isotropic, 0 kinematic
    Real tolerance = 0;  ///< J2Plastic::k_yield_tolerance
    FlowStress flow;
    Real flow_radius0 = 0;  ///< sigma_f(0)
};

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
    MaskOf<T> yielded;  ///< lanes whose trial state was outside the yield surface
};

namespace j2_detail {

/// x^T P x (§7.1) = (x11 + x22)^2 / 6 + (x22 - x11)^2 / 2 + 2 x12^2, i.e. 2 J2.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T p_norm2(const std::array<T, 3>& x) {
    const T s = x[0] + x[1], d = x[1] - x[0];
    return s * s * (1.0 / 6.0) + 0.5 * d * d + 2.0 * x[2] * x[2];
}

template <class T>
struct Radius {
    T radius;  ///< kappa(alpha) / R = sigma_f(0) + beta (sigma_f(alpha) - sigma_f(0)), §7.4
    T slope;   ///< sigma_f'(alpha)
};

/// kappa / R and sigma_f' at alpha on the lanes of `lanes` (the others are left at 0). A linear
/// curve is pack arithmetic; a Johnson-Cook one takes one power per lane.
template <class T>
[[nodiscard]] FPMSHELL_INLINE Radius<T> radius_and_slope(const J2ReturnConstants& c, const T& alpha,
                                                         const MaskOf<T>& lanes) {
    const Real f0 = c.flow_radius0;
    if (c.flow.kind == FlowStress::Kind::Linear)
        return {f0 + c.beta * ((c.flow.yield_stress + c.flow.hardening * alpha) - f0),
                T(c.flow.hardening)};
    Radius<T> out{T(0.0), T(0.0)};
    for (int l = 0; l < lanes_of<T>; ++l) {
        if (!lane(lanes, l)) continue;
        const FlowStress::ValueSlope f = c.flow.value_and_slope(lane(alpha, l));
        set_lane(out.radius, l, f0 + c.beta * (f.value - f0));
        set_lane(out.slope, l, f.slope);
    }
    return out;
}

/// sigma_f'(alpha) on the lanes of `lanes`.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T flow_slope(const J2ReturnConstants& c, const T& alpha,
                                           const MaskOf<T>& lanes) {
    if (c.flow.kind == FlowStress::Kind::Linear) return T(c.flow.hardening);
    T out = 0.0;
    for (int l = 0; l < lanes_of<T>; ++l)
        if (lane(lanes, l)) set_lane(out, l, c.flow.slope(lane(alpha, l)));
    return out;
}

}  // namespace j2_detail

/// §7.3 on the lanes of `lanes`: the trial state from the old one and the strain increment
/// d_eps (engineering shear), the elastic check, and where it fails the return along the
/// plane-stress projection. r: the rate factor R >= 1 of each lane (§7.4). A lane outside
/// `lanes` returns its trial state.
template <class T>
[[nodiscard]] J2Return<T> j2_return_mapping(const J2ReturnConstants& c, const J2PointState<T>& old,
                                            const std::array<T, 3>& d_eps, const T& r,
                                            const MaskOf<T>& lanes) {
    using namespace j2_detail;
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
    const std::array<T, 3> xi_tr{sigma_tr[0] - old.back_stress[0], sigma_tr[1] - old.back_stress[1],
                                 sigma_tr[2] - old.back_stress[2]};
    const T kappa_n = r * flow_radius_n;
    const T third_k2 = kappa_n * kappa_n * (1.0 / 3.0);
    const T f_tr = 0.5 * p_norm2(xi_tr) - third_k2;
    J2Return<T> out{{sigma_tr, old.back_stress, alpha_n, flow_radius_n, flow_slope_n},
                    T(0.0),
                    lanes && (f_tr > c.tolerance * third_k2)};
    const MaskOf<T> yielding = out.yielded;
    if (!any_lane(yielding)) return out;

    // 2 constants; H_k frozen at alpha_n (§7.4)
    const MaskOf<T> slope_unknown = yielding && (flow_slope_n < 0.0);
    const T slope_n =
        any_lane(slope_unknown)
            ? select(slope_unknown, flow_slope(c, alpha_n, slope_unknown), flow_slope_n)
            : flow_slope_n;
    const T h_k = (1.0 - c.beta) * r * slope_n;
    const T s_tr = xi_tr[0] + xi_tr[1], d_tr = xi_tr[1] - xi_tr[0];
    const T a1_sq = s_tr * s_tr * (1.0 / 6.0);                      // A1
    const T a2_sq = 0.5 * d_tr * d_tr + 2.0 * xi_tr[2] * xi_tr[2];  // A2
    const T a1 = c.bulk_term + (2.0 / 3.0) * h_k;
    const T a2 = c.two_g + (2.0 / 3.0) * h_k;
    const Real sqrt23 = std::sqrt(2.0 / 3.0);
    const T r_beta = r * c.beta;

    // 3 F(dgamma) = f_bar^2 / 2 - kappa(alpha(dgamma))^2 / 3, strictly decreasing; Newton kept
    // inside a bracket [lo, hi] with bisection as the fallback. The upper end is found only
    // when needed: Newton from the left of the root of a decreasing F moves right, and the
    // first iterate past the root closes the bracket.
    Radius<T> last{flow_radius_n, slope_n};  // the flow curve at the last dgamma evaluated
    T f = f_tr;                              // F and F' at dgamma = 0 from what is known already
    T df = -(a1_sq * a1 + a2_sq * a2) -
           (2.0 / 3.0) * kappa_n * (r_beta * slope_n) * sqrt23 * sqrt(a1_sq + a2_sq);
    const T first_guess = f_tr / (third_k2 * select(a1 < a2, a1, a2));
    const Real infinity = std::numeric_limits<Real>::infinity();
    T lo = 0.0, hi = infinity, dg = 0.0;
    MaskOf<T> open = yielding;  // lanes still iterating
    MaskOf<T> converged = !yielding;
    for (int it = 0; it < k_max_return_iterations; ++it) {
        if (it > 0) {
            // q_i = 1 / (1 + a_i dgamma) with one division: the Newton step is a chain of
            // dependent divisions and square roots, whose latency sets the cost of a return
            const T u1 = 1.0 + a1 * dg, u2 = 1.0 + a2 * dg;
            const T inv_u1u2 = 1.0 / (u1 * u2);
            const T q1 = u2 * inv_u1u2, q2 = u1 * inv_u1u2;
            const T fb2 = a1_sq * q1 * q1 + a2_sq * q2 * q2;
            const T fb = sqrt(fb2);
            const T dfb2 = -2.0 * a1_sq * a1 * q1 * q1 * q1 - 2.0 * a2_sq * a2 * q2 * q2 * q2;
            const T alpha = alpha_n + sqrt23 * dg * fb;
            const T dalpha = sqrt23 * (fb + select(fb > 0.0, dg * dfb2 / (2.0 * fb), T(0.0)));
            const Radius<T> at = radius_and_slope(c, alpha, open);
            const T kappa = r * at.radius, dkappa = r_beta * at.slope;
            f = select(open, 0.5 * fb2 - kappa * kappa * (1.0 / 3.0), f);
            df = select(open, 0.5 * dfb2 - (2.0 / 3.0) * kappa * dkappa * dalpha, df);
            last.radius = select(open, at.radius, last.radius);
            last.slope = select(open, at.slope, last.slope);
        }
        const MaskOf<T> done = open && (abs(f) < c.tolerance * third_k2);
        converged = converged || done;
        open = open && !done;
        if (!any_lane(open)) break;
        const MaskOf<T> above = f > 0.0;
        lo = select(open && above, dg, lo);
        hi = select(open && !above, dg, hi);
        T next = select(df < 0.0, dg - f / df, T(-1.0));
        const T bisect = select(hi < infinity, 0.5 * (lo + hi), max(2.0 * lo, first_guess));
        next = select((next > lo) && (next < hi), next, bisect);
        dg = select(open, next, dg);
    }

    // 4 update
    const T u1 = 1.0 + a1 * dg, u2 = 1.0 + a2 * dg;
    const T inv_u1u2 = 1.0 / (u1 * u2);
    const T s = s_tr * (u2 * inv_u1u2), d = d_tr * (u1 * inv_u1u2);
    const std::array<T, 3> xi{0.5 * (s - d), 0.5 * (s + d), xi_tr[2] * (u1 * inv_u1u2)};
    const T hardening_step = (2.0 / 3.0) * h_k * dg;
    J2PointState<T> next;
    for (std::size_t k = 0; k < 3; ++k) {
        next.back_stress[k] = old.back_stress[k] + hardening_step * xi[k];
        next.stress[k] = next.back_stress[k] + xi[k];
    }
    next.plastic_strain = alpha_n + sqrt23 * dg * sqrt(p_norm2(xi));
    // the flow curve at the converged dgamma is at hand (alpha(dgamma) above, to rounding)
    const MaskOf<T> unconverged = yielding && !converged;
    if (any_lane(unconverged)) {
        const Radius<T> at = radius_and_slope(c, next.plastic_strain, unconverged);
        last.radius = select(unconverged, at.radius, last.radius);
        last.slope = select(unconverged, at.slope, last.slope);
    }
    next.flow_radius = last.radius;
    next.flow_slope = last.slope;
    // d_eps_p = dgamma P xi (engineering shear). Dissipation by the trapezoidal rule, like the
    // element's strain work: then strain work - plastic work = the exact change of the elastic
    // energy 1/2 sigma C^-1 sigma, never negative whatever the increment.
    const std::array<T, 3> p_xi{(2.0 * xi[0] - xi[1]) * (1.0 / 3.0),
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

}  // namespace fpmshell
