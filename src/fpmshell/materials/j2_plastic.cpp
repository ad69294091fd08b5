#include "fpmshell/materials/j2_plastic.hpp"

#include <cmath>
#include <limits>

namespace fpmshell {
namespace {

constexpr int k_max_iterations = 100;

/// xi^T P xi (§7.1) = (x11 + x22)^2 / 6 + (x22 - x11)^2 / 2 + 2 x12^2, i.e. 2 J2.
Real p_norm2(const Voigt3& x) {
    const Real s = x(0) + x(1), d = x(1) - x(0);
    return s * s / 6.0 + 0.5 * d * d + 2.0 * x(2) * x(2);
}

}  // namespace

Real effective_strain_rate(const Voigt3& d_eps, Real dt) {
    if (!(dt > 0)) return 0;
    const Real e11 = d_eps(0), e22 = d_eps(1), e12 = 0.5 * d_eps(2);
    return (2.0 / std::sqrt(3.0)) * std::sqrt(std::max(Real{0}, e11 * e11 + e22 * e22 + e11 * e22 + e12 * e12)) / dt;
}

J2Plastic::J2Plastic(Real youngs_modulus, Real poisson_ratio, const FlowStress& flow,
                     const RateFactor& rate, Real hardening_mix)
    : e_(youngs_modulus), nu_(poisson_ratio), g_(youngs_modulus / (2.0 * (1.0 + poisson_ratio))),
      flow_(flow), rate_(rate), beta_(hardening_mix) {
    const Real f = e_ / (1.0 - nu_ * nu_);
    c_ << f, f * nu_, 0, f * nu_, f, 0, 0, 0, f * (1.0 - nu_) * 0.5;
}

Real J2Plastic::yield_radius(Real alpha, Real r) const {
    // §7.4 mixed hardening with a nonlinear curve: kappa = sigma_f(0) + beta (sigma_f(alpha) - sigma_f(0))
    const Real f0 = flow_.value(0);
    return r * (f0 + beta_ * (flow_.value(alpha) - f0));
}

J2Plastic::Radius J2Plastic::radius_and_slope(Real alpha) const {
    const Real f0 = flow_.value(0);
    const FlowStress::ValueSlope f = flow_.value_and_slope(alpha);
    return {f0 + beta_ * (f.value - f0), f.slope};
}

void J2Plastic::update(const MaterialPoint& old_state, const Voigt3& d_eps, Real dt,
                       MaterialPoint& new_state) const {
    const Real alpha_n = old_state.plastic_strain;
    const Voigt3 sigma_n = old_state.stress;  // old_state may be new_state: copy what is read late
    const Real plastic_work_n = old_state.plastic_work;
    // kappa / R and sigma_f' at alpha_n, stored by the last plastic step (flow curve at alpha = 0
    // before the first one)
    const Real flow_radius_n = alpha_n > 0 ? old_state.flow_radius : flow_.value(0);
    const Real flow_slope_n = alpha_n > 0 ? old_state.flow_slope : -1.0;  // -1: not yet known
    const Voigt3 b_n = old_state.back_stress;
    Real rate = old_state.strain_rate;
    Real r = 1;
    if (rate_.active()) {
        rate = k_rate_filter * effective_strain_rate(d_eps, dt) + (1.0 - k_rate_filter) * rate;
        r = rate_.value(rate);  // frozen during the return (§7.4 option a)
    }
    // 1 trial state
    const Voigt3 sigma_tr = sigma_n + c_ * d_eps;
    const Voigt3 xi_tr = sigma_tr - b_n;
    const Real kappa_n = r * flow_radius_n;
    const Real third_k2 = kappa_n * kappa_n / 3.0;
    const Real f_tr = 0.5 * p_norm2(xi_tr) - third_k2;
    new_state.strain_rate = rate;
    if (f_tr <= k_yield_tolerance * third_k2) {
        new_state.stress = sigma_tr;
        new_state.back_stress = b_n;
        new_state.plastic_strain = alpha_n;
        new_state.plastic_work = plastic_work_n;
        new_state.flow_radius = flow_radius_n;
        new_state.flow_slope = flow_slope_n;
        return;
    }
    // 2 constants; H_k frozen at alpha_n (§7.4)
    const Real slope_n = flow_slope_n >= 0 ? flow_slope_n : flow_.slope(alpha_n);
    const Real h_k = (1.0 - beta_) * r * slope_n;
    const Real s_tr = xi_tr(0) + xi_tr(1), d_tr = xi_tr(1) - xi_tr(0);
    const Real a1_sq = s_tr * s_tr / 6.0;                              // A1
    const Real a2_sq = 0.5 * d_tr * d_tr + 2.0 * xi_tr(2) * xi_tr(2);  // A2
    const Real a1 = e_ / (3.0 * (1.0 - nu_)) + (2.0 / 3.0) * h_k;
    const Real a2 = 2.0 * g_ + (2.0 / 3.0) * h_k;
    const Real sqrt23 = std::sqrt(2.0 / 3.0);
    // 3 F(dgamma) = f_bar^2 / 2 - kappa(alpha(dgamma))^2 / 3, strictly decreasing; Newton kept
    // inside a bracket [lo, hi] with bisection as the fallback. The upper end is found only
    // when needed: Newton from the left of the root of a decreasing F moves right, and the
    // first iterate past the root closes the bracket.
    struct Eval {
        Real f, df;
    };
    Radius last{flow_radius_n, slope_n};  // the flow curve at the last dgamma evaluated
    auto eval = [&](Real dg) {
        const Real q1 = 1.0 / (1.0 + a1 * dg), q2 = 1.0 / (1.0 + a2 * dg);
        const Real fb2 = a1_sq * q1 * q1 + a2_sq * q2 * q2;
        const Real fb = std::sqrt(fb2);
        const Real dfb2 = -2.0 * a1_sq * a1 * q1 * q1 * q1 - 2.0 * a2_sq * a2 * q2 * q2 * q2;
        const Real alpha = alpha_n + sqrt23 * dg * fb;
        const Real dalpha = sqrt23 * (fb + (fb > 0 ? dg * dfb2 / (2.0 * fb) : 0.0));
        last = radius_and_slope(alpha);
        const Real kappa = r * last.radius, dkappa = r * beta_ * last.slope;
        return Eval{0.5 * fb2 - kappa * kappa / 3.0, 0.5 * dfb2 - (2.0 / 3.0) * kappa * dkappa * dalpha};
    };
    const Real first_guess = f_tr / (third_k2 * std::min(a1, a2));
    Real lo = 0, hi = std::numeric_limits<Real>::infinity();
    Real dg = 0;
    // F at dgamma = 0 from what is known already (the flow curve is not evaluated again)
    Eval ev{f_tr, -(a1_sq * a1 + a2_sq * a2) -
                      (2.0 / 3.0) * kappa_n * (r * beta_ * slope_n) * sqrt23 * std::sqrt(a1_sq + a2_sq)};
    bool converged = false;
    for (int it = 0; it < k_max_iterations; ++it) {
        if (it > 0) ev = eval(dg);
        if (std::abs(ev.f) < k_yield_tolerance * third_k2) {
            converged = true;
            break;
        }
        if (ev.f > 0) lo = dg; else hi = dg;
        Real next = ev.df < 0 ? dg - ev.f / ev.df : -1.0;
        if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : std::max(2.0 * lo, first_guess);
        dg = next;
    }
    // 4 update
    const Real s = s_tr / (1.0 + a1 * dg), d = d_tr / (1.0 + a2 * dg);
    const Voigt3 xi(0.5 * (s - d), 0.5 * (s + d), xi_tr(2) / (1.0 + a2 * dg));
    new_state.back_stress = b_n + ((2.0 / 3.0) * h_k * dg) * xi;
    new_state.stress = new_state.back_stress + xi;
    new_state.plastic_strain = alpha_n + sqrt23 * dg * std::sqrt(p_norm2(xi));
    // the flow curve at the converged dgamma is at hand (alpha(dgamma) above, to rounding)
    if (!converged) last = radius_and_slope(new_state.plastic_strain);
    new_state.flow_radius = last.radius;
    new_state.flow_slope = last.slope;
    // d_eps_p = dgamma P xi (engineering shear). Dissipation by the trapezoidal rule, like the
    // element's strain work: then strain work - plastic work = the exact change of the elastic
    // energy 1/2 sigma C^-1 sigma, never negative whatever the increment.
    const Voigt3 p_xi((2.0 * xi(0) - xi(1)) / 3.0, (2.0 * xi(1) - xi(0)) / 3.0, 2.0 * xi(2));
    new_state.plastic_work = plastic_work_n + dg * (0.5 * (sigma_n + new_state.stress)).dot(p_xi);
}

}  // namespace fpmshell
