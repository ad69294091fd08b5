#include "fpmshell/materials/j2/j2_plastic.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fpmshell {

J2Plastic::J2Plastic(Real youngs_modulus, Real poisson_ratio, const FlowStress& flow,
                     const RateFactor& rate, Real hardening_mix, Real normal_anisotropy,
                     const ThermalSoftening& thermal)
    : e_(youngs_modulus),
      nu_(poisson_ratio),
      flow_(flow),
      rate_(rate),
      thermal_(thermal),
      beta_(hardening_mix) {
    const Real f = e_ / (1.0 - nu_ * nu_);
    c_ << f, f * nu_, 0, f * nu_, f, 0, 0, 0, f * (1.0 - nu_) * 0.5;
    constants_.c11 = c_(0, 0);
    constants_.c12 = c_(0, 1);
    constants_.c33 = c_(2, 2);
    constants_.bulk_term = e_ / (3.0 * (1.0 - nu_));
    constants_.two_g = 2.0 * (e_ / (2.0 * (1.0 + nu_)));
    if (normal_anisotropy != 1.0) {  // eq. 7.1-3: Hill's P in the (s, d, shear) axes of C
        const Real r = normal_anisotropy, third = 1.0 / (3.0 * (1.0 + r));
        constants_.p_sum = third;
        constants_.p_diff = (1.0 + 2.0 * r) * third;
        constants_.p_shear = 4.0 * (1.0 + 2.0 * r) * third;
        // A1, A2: the eigenvalues of C P, E / (1 - nu) 2 p_sum and 2 G 2 p_diff
        constants_.bulk_term = e_ / (1.0 - nu_) * (2.0 * constants_.p_sum);
        constants_.two_g = 2.0 * (e_ / (2.0 * (1.0 + nu_))) * (2.0 * constants_.p_diff);
        constants_.anisotropic = true;
    }
    constants_.beta = beta_;
    constants_.tolerance = k_yield_tolerance;
    if (thermal_.active && (rate_.selects_curve() || flow_.kind != FlowStress::Kind::JohnsonCook))
        throw std::invalid_argument(
            "J2Plastic: thermal softening is Johnson-Cook's, on its own flow curve");
    if (rate_.selects_curve() && (flow_.kind != FlowStress::Kind::Tabulated || beta_ != 1.0 ||
                                  rate_.table_rates.size() != flow_.table.size()))
        throw std::invalid_argument(
            "J2Plastic: a rate table needs a tabulated flow curve per rate and isotropic "
            "hardening");
    constants_.flow = flow_;
    constants_.rate_table = rate_.selects_curve();
    constants_.flow_radius0 = flow_.value(0);
    constants_.flow_slope0 = flow_.slope(0);
    if (flow_.kind == FlowStress::Kind::JohnsonCook && flow_.n > 0.0)
        set_inverse_power_series(constants_, flow_.n);
}

Real J2Plastic::yield_radius(Real alpha, Real r) const {
    // §7.4 mixed hardening with a nonlinear curve: kappa = sigma_f(0) + beta (sigma_f(alpha) -
    // sigma_f(0))
    if (rate_.selects_curve()) return flow_.table.at(alpha, r).value;  // r: the position
    const Real f0 = flow_.value(0);
    return r * (f0 + beta_ * (flow_.value(alpha) - f0));
}

void J2Plastic::update(const MaterialPoint& old_state, const Voigt3& d_eps, Real dt,
                       MaterialPoint& new_state) const {
    // old_state may be new_state: everything is read before anything is written
    Real rate = old_state.strain_rate;
    Real r = 1;
    if (rate_.active()) {
        rate = k_rate_filter * effective_strain_rate<Real>({d_eps(0), d_eps(1), d_eps(2)}, dt) +
               (1.0 - k_rate_filter) * rate;
        r = rate_.value(rate);  // frozen during the return (§7.4 option a)
    }
    // eq. 7.4-2 at the temperature of the step's start, frozen during the return as R
    if (thermal_.active) r *= thermal_.factor(old_state.plastic_work);
    const J2PointState<Real> old{
        {old_state.stress(0), old_state.stress(1), old_state.stress(2)},
        {old_state.back_stress(0), old_state.back_stress(1), old_state.back_stress(2)},
        old_state.plastic_strain,
        old_state.flow_radius,
        old_state.flow_slope};
    const Real plastic_work_n = old_state.plastic_work;
    const J2Return<Real> ret =
        j2_return_mapping(constants_, old, {d_eps(0), d_eps(1), d_eps(2)}, r, true);
    const J2PointState<Real>& next = ret.state;
    new_state.stress = Voigt3(next.stress[0], next.stress[1], next.stress[2]);
    new_state.back_stress = Voigt3(next.back_stress[0], next.back_stress[1], next.back_stress[2]);
    new_state.plastic_strain = next.plastic_strain;
    new_state.plastic_work = plastic_work_n + ret.plastic_work;
    new_state.strain_rate = rate;
    new_state.flow_radius = next.flow_radius;
    new_state.flow_slope = next.flow_slope;
}

}  // namespace fpmshell
