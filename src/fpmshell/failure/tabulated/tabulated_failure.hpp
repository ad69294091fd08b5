// Damage on a failure strain tabulated against the stress triaxiality, regularized by the
// element size (theory.md eq. 7.6-3; LS-DYNA's GISSMO of *MAT_ADD_EROSION, its LCSDG, DMGEXP
// and LCREGD; OpenRadioss /FAIL/TAB): F = sum d alpha / (eps_f(eta) r(l_e)), the damage
// D = F^n (n = DMGEXP: D accumulates as n D^(1 - 1/n) d alpha / eps_f), failure at D = 1, i.e. at
// F = 1 whatever n. eps_f and the factor r are piecewise linear, flat past their ends; l_e is
// the element's initial size sqrt(2 A_0). Its state per point: F and the plastic strain at the
// last step.
// With `fading` (GISSMO's ECRIT, DCRIT, FADEXP; eq. 7.6-6) the damage fades the stress a point
// carries once the material is unstable: from the damage D_c where the instability measure
// sum d alpha / eps_crit(eta) reaches 1 (or where D reaches DCRIT), the point carries
// (1 - w) sigma, w = ((D - D_c) / (1 - D_c))^m; its state then also keeps that sum, D_c, and
// the w of the next step and of the last (solver/shell_elements_erosion.cpp).
// With `rate_scaling` (GISSMO's LCSRS) eps_f, and eps_crit unless told not to, are multiplied by
// a factor of the point's plastic strain rate d alpha / dt (or of its logarithm), piecewise
// linear and flat past its ends.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/failure/failure_criterion.hpp"

namespace fpmshell {

struct TabulatedFailureParameters {
    /// (eta, eps_f) points, eta increasing, eps_f > 0
    std::vector<std::pair<Real, Real>> failure_strain;
    /// (element size, factor) points, sizes increasing, factors > 0; empty: 1
    std::vector<std::pair<Real, Real>> regularization;
    /// (plastic strain rate, factor) points, or (ln of the rate, factor) with log_rates; rates
    /// increasing, factors > 0; empty: 1
    std::vector<std::pair<Real, Real>> rate_scaling;
    bool log_rates = false;
    Real exponent = 1;  ///< n >= 1
    struct Fading {
        /// (eta, eps_crit) points; empty: the instability at D = critical_damage
        std::vector<std::pair<Real, Real>> critical_strain;
        Real critical_damage = 0;  ///< DCRIT, in [0, 1)
        /// m against the element size (one point: a constant m > 0)
        std::vector<std::pair<Real, Real>> exponent{{0.0, 1.0}};
        /// whether rate_scaling's factor scales critical_strain too (GISSMO's LCSRS > 0)
        bool rate_scaled = true;
    };
    std::optional<Fading> fading;
};

class TabulatedFailure final : public PointFailure {
public:
    explicit TabulatedFailure(TabulatedFailureParameters p) : p_(std::move(p)) {}

    [[nodiscard]] std::size_t state_fields() const override { return p_.fading ? 6 : 2; }
    [[nodiscard]] std::size_t fading_field() const override { return p_.fading ? 4 : k_no_field; }
    [[nodiscard]] bool reads_point() const override { return true; }
    bool judge(const FailurePacks& in, Real dt, RealPack* state,
               MaskOf<RealPack>* failed) const override;

    /// eps_f(eta) r(size).
    [[nodiscard]] Real failure_strain(Real eta, Real element_size) const;
    /// rate_scaling's factor at the plastic strain rate `rate` (1 without it).
    [[nodiscard]] Real rate_factor(Real rate) const;
    /// The damage D = F^n of a point of indicator F.
    [[nodiscard]] Real damage(Real indicator) const;
    /// w of eq. 7.6-6 at damage D, D_c the damage at the instability, on an element of that size.
    [[nodiscard]] Real fading(Real damage, Real critical_damage, Real element_size) const;

private:
    using Fading = TabulatedFailureParameters::Fading;
    /// eq. 7.6-6 on lane l of pack j (state: state_fields() x m packs) whose indicator after the
    /// step is `indicator`, of a step of plastic strain d_alpha at triaxiality eta and of
    /// rate_factor rate_scale.
    void fade(RealPack* state, std::size_t m, std::size_t j, int l, Real indicator, Real d_alpha,
              Real eta, Real element_size, Real rate_scale) const;

    TabulatedFailureParameters p_;
};

[[nodiscard]] FailureCriterion tabulated_criterion();

namespace deck {
class Card;
}
/// The `tabulated: {...}` of a GISSMO card c whose fields LCSDG, ECRIT, DMGEXP, DCRIT, FADEXP,
/// LCREGD start at lcsdg_at (*MAT_ADD_DAMAGE_GISSMO's card 2; *MAT_ADD_EROSION's card 3 with
/// IDAM 1); rate: its rate_scaling key (", rate_scaling: ..." or ""), critical_rate_scaled:
/// whether it scales the critical strain too.
[[nodiscard]] std::string tabulated_deck_failure(deck::FailureCard& card, const deck::Card& c,
                                                 std::size_t lcsdg_at, const std::string& rate = "",
                                                 bool critical_rate_scaled = true);

}  // namespace fpmshell
