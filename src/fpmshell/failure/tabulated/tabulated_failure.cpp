#include "fpmshell/failure/tabulated/tabulated_failure.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fpmshell/failure/damage_accumulation.hpp"
#include "fpmshell/failure/stress_triaxiality.hpp"
#include "fpmshell/io/lsdyna/deck_failure_card.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

/// The piecewise-linear function through the points, flat past its ends.
Real interpolate(const std::vector<std::pair<Real, Real>>& points, Real x) {
    if (x <= points.front().first) return points.front().second;
    if (x >= points.back().first) return points.back().second;
    const auto above = std::upper_bound(points.begin(), points.end(), x,
                                        [](Real v, const auto& p) { return v < p.first; });
    const auto& [x1, y1] = *above;
    const auto& [x0, y0] = *(above - 1);
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

}  // namespace

Real TabulatedFailure::failure_strain(Real eta, Real element_size) const {
    const Real factor =
        p_.regularization.empty() ? 1.0 : interpolate(p_.regularization, element_size);
    return interpolate(p_.failure_strain, eta) * factor;
}

Real TabulatedFailure::damage(Real indicator) const { return std::pow(indicator, p_.exponent); }

// eq. 7.6-3 at the state after the step, lane by lane for the tables.
bool TabulatedFailure::judge(const FailurePacks& in, Real /*dt*/, RealPack* state,
                             MaskOf<RealPack>* failed) const {
    return accumulate_damage(
        in, state, failed,
        [&](std::size_t j, const RealPack& /*d_alpha*/, const MaskOf<RealPack>& flowing) {
            const RealPack eta =
                stress_triaxiality(in.stress[0][j], in.stress[1][j], in.stress[2][j]);
            RealPack eps(1.0);
            for (int l = 0; l < k_lanes; ++l)
                if (lane(flowing, l))
                    set_lane(eps, l, failure_strain(lane(eta, l), lane(in.element_size, l)));
            return eps;
        });
}

namespace {

/// `[[x, y], ...]`, x increasing, y > 0.
std::vector<std::pair<Real, Real>> read_points(const YamlValue& v, const char* what) {
    const auto items = v.list(what);
    if (items.empty()) v.fail(std::string("expected at least one point of ") + what);
    std::vector<std::pair<Real, Real>> points;
    for (const YamlValue& item : items) {
        const auto xy = item.list_of(2, "a point", "an [x, y] pair");
        const Real x = xy[0].real(), y = xy[1].positive();
        if (!points.empty() && !(x > points.back().first))
            xy[0].fail("must increase along the list, got " + xy[0].describe());
        points.emplace_back(x, y);
    }
    return points;
}

/// `tabulated: {failure_strain: [[eta, eps_f], ...], regularization: [[size, factor], ...],
/// exponent}`.
std::any read_tabulated(const YamlValue& v, const Material& /*material*/) {
    const YamlMap m = v.map({"failure_strain", "regularization", "exponent"});
    TabulatedFailureParameters p;
    p.failure_strain = read_points(m.at("failure_strain", "[[triaxiality, failure strain], ...]"),
                                   "[triaxiality, failure strain] points");
    if (const auto r = m.find("regularization"))
        p.regularization = read_points(*r, "[element size, factor] points");
    if (const auto n = m.find("exponent")) {
        p.exponent = n->positive();
        if (p.exponent < 1) n->fail("must be >= 1 (GISSMO's DMGEXP), got " + n->describe());
    }
    return p;
}

std::unique_ptr<PointFailure> make_tabulated(const std::any& parameters,
                                             const Material& /*material*/) {
    return std::make_unique<TabulatedFailure>(
        std::any_cast<const TabulatedFailureParameters&>(parameters));
}

/// *MAT_ADD_DAMAGE_GISSMO: card 1: MID, -, DTYP, REFSZ, NUMFIP, VOLFRAC, TETSF; card 2: LCSDG,
/// ECRIT, DMGEXP, DCRIT, FADEXP, LCREGD, INSTF, LCSOFT; card 3: LCSRS, SHRF, BIAXF, LCDLIM,
/// MIDFAIL, HISVN, SOFT, LP2BI. Its failure strain against triaxiality (LCSDG), DMGEXP, its
/// regularization (LCREGD) and NUMFIP (LS-DYNA's default 1) on the material MID.
void mat_add_damage_gissmo(deck::FailureCard& card) {
    const deck::Card f = card.required(0, "MID, -, DTYP, REFSZ, NUMFIP");
    const deck::Card g = card.required(1, "LCSDG, ECRIT, DMGEXP, DCRIT, FADEXP, LCREGD");
    const deck::Card h = card.optional(2);
    card.material(f);
    const long long dtyp = f.id(2, "DTYP");
    if (dtyp / 10 != 0)
        f.fail("DTYP " + std::to_string(dtyp) +
               ": damage driven by another history variable than the plastic strain is not "
               "supported");
    if (dtyp % 10 == 0) {
        card.note(f, "DTYP 0: damage without failure, which changes nothing here: ignored");
        return;
    }
    const Real numfip = f.real(4, "NUMFIP", 1.0);
    if (numfip < 0) f.fail("NUMFIP < 0 (a percentage of layers) is not supported");
    card.failure(tabulated_deck_failure(card, g, 0, 2, 5));
    if (numfip > 0) card.failure_points(static_cast<long long>(std::llround(numfip)));
    card.note(g,
              "ECRIT, DCRIT, FADEXP: the damage is not coupled to the stress (no fading): a point "
              "carries its stress until its element erodes at D = 1");
    for (std::size_t k = 0; k < 8; ++k)
        if (h.real(k, "LCSRS, SHRF, BIAXF, LCDLIM, MIDFAIL, HISVN, SOFT, LP2BI") != 0) {
            card.note(h,
                      "LCSRS, SHRF, BIAXF, LCDLIM, MIDFAIL, HISVN, SOFT, LP2BI ignored (not "
                      "modelled)");
            break;
        }
}

}  // namespace

std::string tabulated_deck_failure(deck::FailureCard& card, const deck::Card& c,
                                   std::size_t lcsdg_at, std::size_t dmgexp_at,
                                   std::size_t lcregd_at) {
    const long long lcsdg = c.id(lcsdg_at, "LCSDG");
    if (lcsdg <= 0)
        c.fail("LCSDG must be a *DEFINE_CURVE of the failure strain against triaxiality");
    std::string t = "tabulated: {failure_strain: " + card.curve_points(c, lcsdg, "LCSDG");
    const Real dmgexp = c.real(dmgexp_at, "DMGEXP", 1.0);
    t += ", exponent: " + deck::num(dmgexp == 0 ? 1.0 : dmgexp);
    if (const long long lcregd = c.id(lcregd_at, "LCREGD"); lcregd != 0) {
        if (lcregd < 0) c.fail("LCREGD < 0 (a table over triaxiality) is not supported");
        t += ", regularization: " + card.curve_points(c, lcregd, "LCREGD");
    }
    return t + "}";
}

FailureCriterion tabulated_criterion() {
    return {"tabulated",
            read_tabulated,
            make_tabulated,
            {{{"MAT_ADD_DAMAGE_GISSMO"}, mat_add_damage_gissmo}}};
}

}  // namespace fpmshell
