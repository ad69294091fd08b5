// Step 3 of the plane-stress return mapping (theory.md §7.3): the consistency condition
// f_bar(dgamma) = sqrt(2/3) kappa(alpha(dgamma)) solved for the plastic multiplier dgamma on the
// lanes of a scalar type T (core/simd.hpp), by a bracketed Halley iteration on one of two
// unknowns (§7.3a):
// - dgamma itself, for a linear or tabulated flow curve (and a Johnson-Cook one with n > 1 or
// without
//   isotropic hardening, beta = 0);
// - the flow stress y = sigma_f(alpha_{n+1}), for a Johnson-Cook curve with n <= 1 and
//   beta > 0, where sigma_f'(alpha) = B n alpha^(n-1) is infinite at alpha = 0 but the inverse
//   alpha(y) = ((y - A) / B)^(1/n) is smooth.
// Both iterate on the residual in norm form, Phi = (1 + a_bar dgamma)(f_bar - sqrt(2/3) kappa)
// (eq. 7.3a-1),
// nearly linear in dgamma, and stop on the residual of §7.3, |F| < tol kappa_n^2 / 3.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/simd_math.hpp"
#include "fpmshell/materials/j2/flow_stress.hpp"

namespace fpmshell {

/// Newton iterations before the return mapping gives up and keeps its last iterate.
inline constexpr int k_max_return_iterations = 100;

/// What the return mapping needs of a J2 material (J2Plastic holds one).
struct J2ReturnConstants {
    Real c11 = 0, c12 = 0,
         c33 = 0;        ///< plane-stress C: [[c11, c12, 0], [c12, c11, 0], [0, 0, c33]]
    Real bulk_term = 0;  ///< E / (3 (1 - nu)), the A1 coefficient of §7.3 without H_k
    Real two_g = 0;      ///< 2 G, the A2 coefficient without H_k
    /// xi^T P xi = p_sum s^2 + p_diff d^2 + p_shear xi12^2, s = xi11 + xi22, d = xi22 - xi11
    /// (§7.1: 1/6, 1/2, 2 for von Mises; Hill's normal anisotropy R, eq. 7.1-3: 1 / (3 (1 + R)),
    /// (1 + 2R) / (3 (1 + R)), 4 (1 + 2R) / (3 (1 + R))); bulk_term and two_g then carry the
    /// factors 2 p_sum / (1/3) and 2 p_diff
    Real p_sum = 1.0 / 6.0, p_diff = 0.5, p_shear = 2.0;
    bool anisotropic = false;  ///< R != 1: P xi from the coefficients (von Mises: its own form)
    Real beta = 1;             ///< hardening mix of §7.2: 1 isotropic, 0 kinematic
    Real tolerance = 0;        ///< J2Plastic::k_yield_tolerance
    FlowStress flow;
    /// the rate selects a curve of flow.table (RateFactor::Kind::Table): the r of a point is its
    /// position among the rates, its yield radius that curve's (isotropic hardening only)
    bool rate_table = false;
    Real flow_radius0 = 0;  ///< sigma_f(0)
    Real flow_slope0 = 0;   ///< FlowStress::slope(0) (Johnson-Cook: the slope at alpha = 1e-6)
    /// Johnson-Cook: the binomial coefficients C(1/n, k), k = 0 ... 12, of (1 + d)^(1/n), and
    /// the |d| up to which the series is exact to rounding (FlowStressIteration, §7.3a)
    std::array<Real, 13> inverse_power_series{};
    Real inverse_power_radius = 0;
};

/// The binomial series of (1 + d)^(1/n) (J2ReturnConstants): sets c.inverse_power_series and
/// c.inverse_power_radius for the exponent n > 0.
inline void set_inverse_power_series(J2ReturnConstants& c, Real n) {
    const Real p = 1.0 / n;
    Real coefficient = 1.0;
    for (std::size_t k = 0; k < c.inverse_power_series.size(); ++k) {
        c.inverse_power_series[k] = coefficient;
        coefficient *= (p - static_cast<Real>(k)) / static_cast<Real>(k + 1);
    }
    // the first term left out, C(1/n, 13) d^13, below 1e-17 with a factor 2 for the rest of the
    // tail (whose terms shrink by (k - 1/n) / (k + 1) |d| < 1 each)
    const Real radius = 1.0 / 16.0;
    c.inverse_power_radius =
        coefficient == 0.0
            ? radius
            : std::min(radius, 0.5 * std::pow(1e-17 / std::abs(coefficient), 1.0 / 13.0));
}

namespace j2_detail {

inline constexpr Real k_sqrt23 = 0.816496580927726;  // sqrt(2/3)

/// The trial state of the yielding lanes as step 3 needs it (§7.3 steps 1-2).
template <class T>
struct TrialReturn {
    T a1_sq, a2_sq;   ///< A1, A2
    T a1, a2;         ///< a1, a2 (with H_k)
    T a_bar;          ///< (A1 a1 + A2 a2) / (A1 + A2): f_bar ~ f_bar_tr / (1 + a_bar dgamma)
    T m2;             ///< (A1 a1^2 + A2 a2^2) / (A1 + A2), for Phi'' at dgamma = 0
    T fbar_tr;        ///< sqrt(A1 + A2) = f_bar(0)
    T alpha_n;        ///< alpha_n
    T r;              ///< the rate factor R
    T kappa_n;        ///< R kappa(alpha_n) / R = the yield radius at alpha_n
    T third_k2;       ///< kappa_n^2 / 3, the scale of the convergence test
    T flow_radius_n;  ///< kappa(alpha_n) / R
};

/// The solution of step 3 on each lane.
template <class T>
struct Consistency {
    T dgamma;
    T q1, q2, fbar;  ///< 1 / (1 + a_i dgamma) and f_bar at dgamma, for step 4
    T flow_radius;   ///< kappa / R at the solution, to store (§7.4)
    T flow_slope;    ///< sigma_f' at the solution, to store (the next step's H_k)
    MaskOf<T> converged;
    int evaluations = 0;  ///< evaluations of the residual (the most of any lane)
};

/// f_bar(dgamma) and f_bar f_bar'(dgamma), where f_bar^2 = A1 / (1 + a1 dgamma)^2 +
/// A2 / (1 + a2 dgamma)^2: the Newton steps below are written with f_bar' times f_bar, which
/// needs no division.
template <class T>
struct ReturnedNorm {
    T fbar, fbar_dfbar;
    T q1, q2;  ///< 1 / (1 + a_i dgamma)
    T c1, c2;  ///< A_i q_i^2 (f_bar^2 = c1 + c2)
};
template <class T>
[[nodiscard]] FPMSHELL_INLINE ReturnedNorm<T> returned_norm(const TrialReturn<T>& t, const T& dg) {
    // q_i = 1 / (1 + a_i dgamma) with one division: the iteration is a chain of dependent
    // divisions, square roots and polynomials, whose latency sets the cost of a return
    const T u1 = 1.0 + t.a1 * dg, u2 = 1.0 + t.a2 * dg;
    const T inv_u1u2 = pipelined_reciprocal(u1 * u2);
    const T q1 = u2 * inv_u1u2, q2 = u1 * inv_u1u2;
    const T c1 = t.a1_sq * q1 * q1, c2 = t.a2_sq * q2 * q2;
    return {pipelined_sqrt(c1 + c2), -(c1 * (t.a1 * q1) + c2 * (t.a2 * q2)), q1, q2, c1, c2};
}

/// An upper bound of dgamma (eq. 7.3a-2): with kappa >= kappa_n and f_bar <= f_bar_tr / (1 + a_min
/// dgamma), f_bar reaches sqrt(2/3) kappa before (f_bar_tr / (sqrt(2/3) kappa_n) - 1) / a_min.
template <class T>
[[nodiscard]] FPMSHELL_INLINE T dgamma_upper_bound(const TrialReturn<T>& t) {
    const T g0 = t.fbar_tr - k_sqrt23 * t.kappa_n;
    return g0 * pipelined_reciprocal(k_sqrt23 * t.kappa_n * min(t.a1, t.a2));
}

/// The Johnson-Cook curve on packs: sigma_f(alpha) and sigma_f'(alpha) as
/// FlowStress::value_and_slope gives them (the slope at alpha = 1e-6 below it), one power per
/// lane (two where 0 < alpha < 1e-6).
template <class T>
[[nodiscard]] FPMSHELL_INLINE FlowValue<T> johnson_cook_curve(const J2ReturnConstants& c,
                                                              const T& alpha) {
    const FlowStress& f = c.flow;
    const MaskOf<T> small = alpha < FlowStress::k_slope_floor;
    const T p = vector_pow(max(alpha, T(FlowStress::k_slope_floor)), T(f.n - 1.0));
    T value = f.a + f.b * alpha * p;  // alpha^n = alpha alpha^(n-1)
    if (any_lane(small)) {
        const MaskOf<T> positive = alpha > 0.0;
        const T tiny = select(small && positive, vector_pow(max(alpha, T(1e-300)), T(f.n)), T(0.0));
        value = select(small, f.a + f.b * tiny, value);
    }
    return {value, select(small, T(c.flow_slope0), f.b * f.n * p)};
}

/// The bracketed update shared by both iterations: x between lo and hi, whose residual phi
/// decreases in x; the lanes of `open` take Halley's step (eq. 7.3a-5),
/// -2 Phi Phi' / (2 Phi'^2 - Phi Phi''), where it scales Newton's by a factor in (2/3, 2) (else
/// Newton's; one division either way), or go to the middle of the bracket where the step leaves
/// it.
template <class T>
FPMSHELL_INLINE void halley_in_bracket(const MaskOf<T>& open, const T& phi, const T& dphi,
                                       const T& d2phi, T& x, T& lo, T& hi) {
    const MaskOf<T> above = phi > 0.0;
    lo = select(open && above, x, lo);
    hi = select(open && !above, x, hi);
    const T two_d2 = 2.0 * dphi * dphi, phi_d2 = phi * d2phi;
    const MaskOf<T> halley = (phi_d2 < 0.5 * two_d2) && (phi_d2 > -0.5 * two_d2);
    const T step = select(halley, 2.0 * phi * dphi, phi) *
                   pipelined_reciprocal(select(halley, two_d2 - phi_d2, dphi));
    const T next = x - step;
    x = select(open, select((next > lo) && (next < hi), next, 0.5 * (lo + hi)), x);
}

/// Step 3 by Newton on dgamma, for a flow curve `curve(alpha) -> {sigma_f, sigma_f'}`:
///   f_bar(dgamma) as returned_norm, alpha = alpha_n + sqrt(2/3) dgamma f_bar,
///   kappa = R (sigma_f(0) + beta (sigma_f(alpha) - sigma_f(0))),
///   Phi = (1 + a_bar dgamma)(f_bar - sqrt(2/3) kappa), Phi' by the chain rule,
/// from dgamma = 0 (where Phi and Phi' are known from the trial state and the stored slope)
/// inside the bracket [0, dgamma_upper_bound], bisecting when a Newton iterate leaves it.
/// The constructor takes the first step; each iterate() evaluates Phi once, stops the lanes
/// that have converged and moves the others (solve_in_lockstep runs several at once).
template <class T, class Curve>
class DgammaIteration {
public:
    FPMSHELL_INLINE DgammaIteration(const J2ReturnConstants& c, const TrialReturn<T>& t,
                                    const T& slope_n, const MaskOf<T>& lanes, const Curve& curve)
        : c_(c),
          t_(t),
          curve_(curve),
          r_beta_(t.r * c.beta),
          out_{T(0.0), T(1.0), T(1.0), t.fbar_tr, t.flow_radius_n, slope_n, !lanes, 0},
          open_(lanes),
          lo_(0.0),
          hi_(dgamma_upper_bound(t)),
          dg_(0.0) {
        // Phi, Phi' and Phi'' at dgamma = 0 (f_bar' = -a_bar f_bar_tr there; Phi'' =
        // 3 f_bar_tr (m2 - a_bar^2), m2 = (A1 a1^2 + A2 a2^2) / (A1 + A2), for a curve of
        // sigma_f'' = 0)
        const T phi = t.fbar_tr - k_sqrt23 * t.kappa_n;
        const T dphi =
            -t.a_bar * (k_sqrt23 * t.kappa_n) - (2.0 / 3.0) * r_beta_ * slope_n * t.fbar_tr;
        const T d2phi = 3.0 * t.fbar_tr * (t.m2 - t.a_bar * t.a_bar);
        halley_in_bracket(open_, phi, dphi, d2phi, dg_, lo_, hi_);
    }
    [[nodiscard]] bool open() const { return any_lane(open_); }
    /// One evaluation and step of the open lanes (none changes where no lane is open).
    FPMSHELL_INLINE void iterate() {
        const Real f0 = c_.flow_radius0;
        const TrialReturn<T>& t = t_;
        const ReturnedNorm<T> n = returned_norm(t, dg_);
        const T alpha = t.alpha_n + k_sqrt23 * dg_ * n.fbar;
        const T fbar_dalpha = k_sqrt23 * (n.fbar * n.fbar + dg_ * n.fbar_dfbar);
        const FlowValue<T> at = curve_(alpha);
        const T radius = f0 + c_.beta * (at.value - f0);
        const T kappa = t.r * radius;
        const T g = n.fbar - k_sqrt23 * kappa;
        const T f = 0.5 * g * (n.fbar + k_sqrt23 * kappa);  // F of §7.3
        out_.dgamma = select(open_, dg_, out_.dgamma);
        out_.q1 = select(open_, n.q1, out_.q1);
        out_.q2 = select(open_, n.q2, out_.q2);
        out_.fbar = select(open_, n.fbar, out_.fbar);
        out_.flow_radius = select(open_, radius, out_.flow_radius);
        out_.flow_slope = select(open_, at.slope, out_.flow_slope);
        out_.evaluations += any_lane(open_) ? 1 : 0;
        const MaskOf<T> done = open_ && (abs(f) < c_.tolerance * t.third_k2);
        out_.converged = out_.converged || done;
        open_ = open_ && !done;
        if (!any_lane(open_)) return;  // the usual last round: no step to take
        // Phi f_bar, Phi' f_bar and Phi'' f_bar (Halley's step: f_bar^2 cancels), with
        // f_bar f_bar'' = (f_bar^2)''/2 - (f_bar f_bar')^2 / f_bar^2 and kappa'' from alpha''
        // (sigma_f'' left out: a start for the next step, the bracket keeps it safe)
        const T u = 1.0 + t.a_bar * dg_;
        const T g_fbar = g * n.fbar;
        const T dg_fbar = n.fbar_dfbar - k_sqrt23 * r_beta_ * at.slope * fbar_dalpha;
        const T a1q1 = t.a1 * n.q1, a2q2 = t.a2 * n.q2;
        const T fbar_d2fbar = 3.0 * (n.c1 * a1q1 * a1q1 + n.c2 * a2q2 * a2q2) -
                              n.fbar_dfbar * n.fbar_dfbar * pipelined_reciprocal(n.c1 + n.c2);
        const T fbar_d2alpha = k_sqrt23 * (2.0 * n.fbar_dfbar + dg_ * fbar_d2fbar);
        const T d2g_fbar = fbar_d2fbar - k_sqrt23 * r_beta_ * at.slope * fbar_d2alpha;
        const T phi = u * g_fbar;
        const T dphi = t.a_bar * g_fbar + u * dg_fbar;
        const T d2phi = 2.0 * t.a_bar * dg_fbar + u * d2g_fbar;
        halley_in_bracket(open_, phi, dphi, d2phi, dg_, lo_, hi_);
    }
    [[nodiscard]] const Consistency<T>& result() const { return out_; }

private:
    const J2ReturnConstants& c_;
    TrialReturn<T> t_;
    Curve curve_;
    T r_beta_;
    Consistency<T> out_;
    MaskOf<T> open_;
    T lo_, hi_, dg_;
};

/// Step 3 for a Johnson-Cook curve with n <= 1 and beta > 0, by Newton on the flow stress
/// y = sigma_f(alpha_{n+1}) (theory.md §7.3a, eq. 7.3a-3):
///   alpha(y) = ((y - A) / B)^(1/n),  kappa(y) = R (A + beta (y - A)),
///   dgamma(y) = 3/2 (alpha(y) - alpha_n) / kappa(y)   (alpha = alpha_n + sqrt(2/3) dgamma f_bar
///                                                     with f_bar = sqrt(2/3) kappa),
///   Phi(y) = (1 + a_bar dgamma)(f_bar(dgamma) - sqrt(2/3) kappa), decreasing in y.
/// Bracket [y_n, y_hi]: y_n = sigma_f(alpha_n); y_hi = sigma_f(alpha_n + d_alpha_u), d_alpha_u
/// from dgamma_upper_bound, bounded by the tangent y_n + sigma_f'(alpha_n) d_alpha_u (sigma_f
/// is concave) and evaluated exactly (one power) where the increment can exceed alpha_n.
/// Start: Halley's step from y_n (Phi, Phi' and Phi'' there from the trial state), or y_hi if
/// less; then Halley's steps with Phi'' of eq. 7.3a-7. iterate() as DgammaIteration's.
template <class T>
class FlowStressIteration {
public:
    FPMSHELL_INLINE FlowStressIteration(const J2ReturnConstants& c, const TrialReturn<T>& t,
                                        const MaskOf<T>& lanes)
        : c_(c),
          t_(t),
          lanes_(lanes),
          a_(c.flow.a),
          inv_b_(1.0 / c.flow.b),
          inv_n_(1.0 / c.flow.n),
          r_beta_(t.r * c.beta),
          out_{T(0.0), T(1.0), T(1.0), t.fbar_tr, t.flow_radius_n, T(c.flow_slope0), !lanes, 0},
          open_(lanes) {
        const FlowStress& fl = c.flow;
        const Real a = a_, infinity = std::numeric_limits<Real>::infinity();
        // y_n: the stored radius is A + beta (y_n - A)
        const T y_n = c.beta == 1.0 ? t.flow_radius_n : a + (t.flow_radius_n - a) * (1.0 / c.beta);
        const MaskOf<T> hardened = (t.alpha_n > 0.0) && (y_n > a);
        // dalpha/dy at y_n = alpha_n / (n (y_n - A)) = 1 / sigma_f'(alpha_n), written as the
        // ratio alpha_e / (n y_e): at alpha_n = 0 it is 0 for n < 1 and 1 / B for n = 1
        const T alpha_e = select(hardened, t.alpha_n, T(fl.n == 1.0 ? inv_b_ : 0.0));
        const T y_e = select(hardened, y_n - a, T(1.0));
        // Halley's step from y_n (eqs. 7.3a-4, 7.3a-5), where dgamma = 0, Phi = g0 and (f_bar' =
        // -a_bar f_bar_tr) Phi' = -sqrt(2/3) (3/2 a_bar dalpha/dy + R beta), Phi'' by the chain
        // rule; derivatives in y times s = n (y_n - A), so that dalpha/dy s = alpha_e and
        // d2alpha/dy2 s^2 = (1 - n) alpha_e (0 where not hardened: Newton's step)
        const T g0 = t.fbar_tr - k_sqrt23 * t.kappa_n;
        const T s = fl.n * y_e;
        const T p1 = -k_sqrt23 * (1.5 * t.a_bar * alpha_e + r_beta_ * s);  // Phi' s
        const T inv_kappa_n = pipelined_reciprocal(t.kappa_n);
        const T dg1 = 1.5 * alpha_e * inv_kappa_n;  // dgamma' s
        const T dg2 =
            (select(hardened, T(1.5 * (1.0 - fl.n)) * alpha_e, T(0.0)) - 2.0 * dg1 * s * r_beta_) *
            inv_kappa_n;                                                   // dgamma'' s^2
        const T g1 = -t.a_bar * t.fbar_tr * dg1 - k_sqrt23 * r_beta_ * s;  // g' s
        const T g2 = t.fbar_tr * ((3.0 * t.m2 - t.a_bar * t.a_bar) * dg1 * dg1 - t.a_bar * dg2);
        const T p2 = t.a_bar * (dg2 * g0 + 2.0 * dg1 * g1) + g2;  // Phi'' s^2
        const MaskOf<T> halley = abs(g0 * p2) < p1 * p1;
        const T y_newton =
            y_n - select(halley, 2.0 * g0 * p1, g0) * s *
                      pipelined_reciprocal(select(halley, 2.0 * p1 * p1 - g0 * p2, p1));
        // the upper end of the bracket: d_alpha <= sqrt(2/3) dgamma_upper_bound f_bar_tr, and
        // the tangent of the concave curve at alpha_n lies above it
        const T d_alpha_u = g0 * t.fbar_tr * pipelined_reciprocal(t.kappa_n * min(t.a1, t.a2));
        T y_hi = select(hardened,
                        y_n + (fl.n * y_e) * d_alpha_u *
                                  pipelined_reciprocal(select(hardened, t.alpha_n, T(1.0))),
                        T(infinity));
        const MaskOf<T> steep = lanes && (t.alpha_n < d_alpha_u);
        if (any_lane(steep)) {  // the curve itself, at the tighter bound of f_bar(dgamma_u)
            const T dg_u = dgamma_upper_bound(t);
            const T d_alpha = k_sqrt23 * dg_u * returned_norm(t, dg_u).fbar;
            y_hi =
                select(steep, min(y_hi, a + fl.b * vector_pow(t.alpha_n + d_alpha, T(fl.n))), y_hi);
        }
        lo_ = y_n;
        hi_ = y_hi;
        y_ = min(y_newton, y_hi);
        last_alpha_ = 0.0;
        last_excess_ = 0.0;
        // the series of the first evaluation from (y_n, alpha_n) on the hardened lanes: alpha_n
        // is alpha(y_n) to the convergence tolerance of the last step
        centre_y_ = y_n;
        centre_alpha_ = select(hardened, t.alpha_n, T(0.0));
        centre_inv_excess_ = pipelined_reciprocal(y_e);
        centred_ = hardened;
    }
    [[nodiscard]] bool open() const { return any_lane(open_); }
    /// One evaluation and step of the open lanes (none changes where no lane is open).
    FPMSHELL_INLINE void iterate() {
        const TrialReturn<T>& t = t_;
        const T excess = max(y_ - a_, T(0.0));
        const MaskOf<T> positive = excess > 0.0;
        // alpha(y) = ((y - A) / B)^(1/n): near the last iterate y_k (eq. 7.3a-6; y_n, alpha_n
        // before the first) by the series of alpha_k (1 + d)^(1/n), d = (y - y_k) / (y_k - A),
        // exact to rounding for |d| within inverse_power_radius; else (any lane farther, or at
        // y_k = A) e^(ln x / n)
        const T d = (y_ - centre_y_) * centre_inv_excess_;
        T alpha;
        if (!any_lane(open_ && !(centred_ && abs(d) <= c_.inverse_power_radius)))
            alpha = centre_alpha_ * inverse_power(d);
        else
            alpha = select(
                positive, vector_exp(inv_n_ * vector_log(max(excess * inv_b_, T(1e-300)))), T(0.0));
        const T radius = a_ + c_.beta * (y_ - a_);
        const T kappa = t.r * radius;
        // one division for 1 / kappa and 1 / (y - A)
        const T inv = pipelined_reciprocal(select(positive, excess, T(1.0)) * kappa);
        const T inv_kappa = select(positive, excess, T(1.0)) * inv;
        const T dalpha =
            select(positive, alpha * inv_n_ * (kappa * inv), T(c_.flow.n == 1.0 ? inv_b_ : 0.0));
        const T dg = 1.5 * (alpha - t.alpha_n) * inv_kappa;
        const T ddg = (1.5 * dalpha - dg * r_beta_) * inv_kappa;
        const ReturnedNorm<T> n = returned_norm(t, dg);
        const T g = n.fbar - k_sqrt23 * kappa;
        const T f = 0.5 * g * (n.fbar + k_sqrt23 * kappa);  // F of §7.3
        out_.dgamma = select(open_, dg, out_.dgamma);
        out_.q1 = select(open_, n.q1, out_.q1);
        out_.q2 = select(open_, n.q2, out_.q2);
        out_.fbar = select(open_, n.fbar, out_.fbar);
        out_.flow_radius = select(open_, radius, out_.flow_radius);
        last_alpha_ = select(open_, alpha, last_alpha_);
        last_excess_ = select(open_, excess, last_excess_);
        centre_y_ = y_;
        centre_alpha_ = alpha;
        centre_inv_excess_ = kappa * inv;  // 1 / (y - A) where positive
        centred_ = positive;
        out_.evaluations += any_lane(open_) ? 1 : 0;
        const MaskOf<T> done = open_ && (abs(f) < c_.tolerance * t.third_k2);
        out_.converged = out_.converged || done;
        open_ = open_ && !done;
        if (!any_lane(open_)) return;  // the usual last round: no step to take
        // Phi f_bar, Phi' f_bar and Phi'' f_bar in y for Halley's step (eq. 7.3a-7): Phi = u g,
        // u = 1 + a_bar dgamma, g = f_bar - sqrt(2/3) kappa, kappa'' = 0, with
        //   alpha'' = (1/n - 1) alpha' / (y - A),  dgamma'' = (3/2 alpha'' - 2 dgamma' R beta) /
        //   kappa, f_bar f_bar''(y) = f_bar f_bar_dd dgamma'^2 + f_bar f_bar_d dgamma'', f_bar
        //   f_bar_dd = 3 (A1 a1^2 q1^4 + A2 a2^2 q2^4) - (f_bar f_bar_d)^2 / f_bar^2,
        // 1 / f_bar^2 taken as 3 / (2 kappa^2), its value at the solution: Phi'' only shapes the
        // step, and its error O(g) keeps the step's order (the bracket keeps it safe)
        const T u = 1.0 + t.a_bar * dg;
        const T g_fbar = g * n.fbar;
        const T dg_fbar = n.fbar_dfbar * ddg - k_sqrt23 * r_beta_ * n.fbar;  // g' f_bar
        const T d2alpha = select(positive, (inv_n_ - 1.0) * dalpha * (kappa * inv), T(0.0));
        const T d2dg = (1.5 * d2alpha - 2.0 * ddg * r_beta_) * inv_kappa;
        const T a1q1 = t.a1 * n.q1, a2q2 = t.a2 * n.q2;
        const T fbar_dd = 3.0 * (n.c1 * a1q1 * a1q1 + n.c2 * a2q2 * a2q2) -
                          n.fbar_dfbar * n.fbar_dfbar * (1.5 * inv_kappa * inv_kappa);
        const T d2g_fbar = fbar_dd * ddg * ddg + n.fbar_dfbar * d2dg;  // g'' f_bar
        const T phi = u * g_fbar;
        const T dphi = t.a_bar * ddg * g_fbar + u * dg_fbar;
        const T d2phi = t.a_bar * d2dg * g_fbar + 2.0 * t.a_bar * ddg * dg_fbar + u * d2g_fbar;
        halley_in_bracket(open_, phi, dphi, d2phi, y_, lo_, hi_);
    }
    /// The solution, with sigma_f' = B n alpha^(n-1) = n (y - A) / alpha at the last
    /// evaluation (taken at FlowStress::k_slope_floor below it, as FlowStress::slope does).
    [[nodiscard]] FPMSHELL_INLINE Consistency<T> result() const {
        Consistency<T> out = out_;
        const MaskOf<T> floor = last_alpha_ < FlowStress::k_slope_floor;
        out.flow_slope = select(
            lanes_ && !floor,
            c_.flow.n * last_excess_ * pipelined_reciprocal(select(floor, T(1.0), last_alpha_)),
            out.flow_slope);
        return out;
    }

private:
    const J2ReturnConstants& c_;
    TrialReturn<T> t_;
    MaskOf<T> lanes_;
    Real a_, inv_b_, inv_n_;
    T r_beta_;
    Consistency<T> out_;
    MaskOf<T> open_;
    /// (1 + d)^(1/n) by its binomial series to d^12, Estrin's scheme (as core/simd_math.hpp)
    [[nodiscard]] FPMSHELL_INLINE T inverse_power(const T& d) const {
        const std::array<Real, 13>& c = c_.inverse_power_series;
        const T d2 = d * d, d4 = d2 * d2, d8 = d4 * d4;
        const T q0 = (c[0] + c[1] * d) + d2 * (c[2] + c[3] * d);
        const T q1 = (c[4] + c[5] * d) + d2 * (c[6] + c[7] * d);
        const T q2 = (c[8] + c[9] * d) + d2 * (c[10] + c[11] * d);
        return (q0 + d4 * q1) + d8 * (q2 + d4 * c[12]);
    }

    T lo_, hi_, y_;
    T last_alpha_, last_excess_;  // alpha(y) and y - A at the last evaluation (open lanes)
    // the last evaluation on every lane: y, alpha(y), 1 / (y - A), and whether y > A
    T centre_y_, centre_alpha_, centre_inv_excess_;
    MaskOf<T> centred_;
};

/// Runs the iterations of several independent points in lockstep, one evaluation of each per
/// round, without a branch between them: their chains of dependent divisions, square roots and
/// polynomials overlap on one core, where one alone waits on the latency of each step.
template <class Iteration, std::size_t K>
void solve_in_lockstep(std::array<Iteration, K>& iterations) {
    for (int it = 0; it < k_max_return_iterations; ++it) {
        for (Iteration& i : iterations) i.iterate();
        bool open = false;
        for (const Iteration& i : iterations) open = open || i.open();
        if (!open) return;
    }
}

}  // namespace j2_detail

}  // namespace fpmshell
