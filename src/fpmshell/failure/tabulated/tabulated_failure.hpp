// Damage on a failure strain tabulated against the stress triaxiality, regularized by the
// element size (theory.md eq. 7.6-3; LS-DYNA's GISSMO of *MAT_ADD_EROSION, its LCSDG, DMGEXP
// and LCREGD; OpenRadioss /FAIL/TAB): F = sum d alpha / (eps_f(eta) r(l_e)), the damage
// D = F^n (n = DMGEXP: D accumulates as n D^(1 - 1/n) d alpha / eps_f), failure at D = 1, i.e. at
// F = 1 whatever n. eps_f and the factor r are piecewise linear, flat past their ends; l_e is
// the element's initial size sqrt(2 A_0). Its state per point: F and the plastic strain at the
// last step. (GISSMO's coupling of D to the stress past ECRIT, its fading, is not modelled: a
// point carries its stress until its element erodes.)
#pragma once

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
    Real exponent = 1;  ///< n >= 1
};

class TabulatedFailure final : public PointFailure {
public:
    explicit TabulatedFailure(TabulatedFailureParameters p) : p_(std::move(p)) {}

    [[nodiscard]] std::size_t state_fields() const override { return 2; }
    [[nodiscard]] bool reads_point() const override { return true; }
    bool judge(const FailurePacks& in, Real dt, RealPack* state,
               MaskOf<RealPack>* failed) const override;

    /// eps_f(eta) r(size).
    [[nodiscard]] Real failure_strain(Real eta, Real element_size) const;
    /// The damage D = F^n of a point of indicator F.
    [[nodiscard]] Real damage(Real indicator) const;

private:
    TabulatedFailureParameters p_;
};

[[nodiscard]] FailureCriterion tabulated_criterion();

namespace deck {
class Card;
}
/// The `tabulated: {...}` of a GISSMO card c: LCSDG, DMGEXP and LCREGD at those fields
/// (*MAT_ADD_DAMAGE_GISSMO's card 2; *MAT_ADD_EROSION's card 3 with IDAM 1).
[[nodiscard]] std::string tabulated_deck_failure(deck::FailureCard& card, const deck::Card& c,
                                                 std::size_t lcsdg_at, std::size_t dmgexp_at,
                                                 std::size_t lcregd_at);

}  // namespace fpmshell
