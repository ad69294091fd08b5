#include "fpmshell/failure/tabulated/tabulated_failure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

Real TabulatedFailure::rate_factor(Real rate) const {
    if (p_.rate_scaling.empty()) return 1.0;
    // a rate of 0 (a point that does not flow) lies below every logarithm: the first factor
    return interpolate(
        p_.rate_scaling,
        p_.log_rates ? (rate > 0 ? std::log(rate) : -std::numeric_limits<Real>::infinity()) : rate);
}

Real TabulatedFailure::damage(Real indicator) const { return std::pow(indicator, p_.exponent); }

Real TabulatedFailure::fading(Real damage, Real critical_damage, Real element_size) const {
    if (!(damage > critical_damage)) return 0.0;
    const Real m = interpolate(p_.fading->exponent, element_size);
    return std::min(std::pow((damage - critical_damage) / (1.0 - critical_damage), m), 1.0);
}

// eq. 7.6-3 at the state after the step, lane by lane for the tables; with fading, eq. 7.6-6
// on each flowing lane too. The state: F, the plastic strain at the last step
// (damage_accumulation), then with fading the instability measure (1 once unstable), D_c, the
// fading w of the next step and the element's w of the last one. A point's numbers change only in a
// step it flows in: judging twice changes nothing.
bool TabulatedFailure::judge(const FailurePacks& in, Real dt, RealPack* state,
                             MaskOf<RealPack>* failed) const {
    return accumulate_damage(
        in, state, failed,
        [&](std::size_t j, const RealPack& d_alpha, const MaskOf<RealPack>& flowing) {
            const RealPack eta =
                stress_triaxiality(in.stress[0][j], in.stress[1][j], in.stress[2][j]);
            RealPack eps(1.0);
            for (int l = 0; l < k_lanes; ++l) {
                if (!lane(flowing, l)) continue;
                const Real size = lane(in.element_size, l);
                // the factor of the point's plastic strain rate over the step (LCSRS's)
                const Real rate_scale = p_.rate_scaling.empty()
                                            ? Real(1)
                                            : rate_factor(dt > 0 ? lane(d_alpha, l) / dt : Real(0));
                set_lane(eps, l, failure_strain(lane(eta, l), size) * rate_scale);
                if (p_.fading)  // F after the step, as accumulate_damage will sum it
                    fade(state, in.m, j, l, lane(state[j], l) + lane(d_alpha, l) / lane(eps, l),
                         lane(d_alpha, l), lane(eta, l), size, rate_scale);
            }
            return eps;
        });
}

void TabulatedFailure::fade(RealPack* state, std::size_t m, std::size_t j, int l, Real indicator,
                            Real d_alpha, Real eta, Real element_size, Real rate_scale) const {
    const Fading& f = *p_.fading;
    RealPack *instability = state + 2 * m, *critical = state + 3 * m, *next = state + 4 * m;
    const Real D = damage(std::min(indicator, 1.0));
    Real measure = lane(instability[j], l);
    if (measure < 1.0) {  // not yet unstable
        Real d_c = D;
        if (f.critical_strain.empty()) {
            measure = D >= f.critical_damage ? 1.0 : 0.0;
            d_c = f.critical_damage;
        } else {
            measure += d_alpha / (interpolate(f.critical_strain, eta) *
                                  (f.rate_scaled ? rate_scale : Real(1)));
        }
        set_lane(instability[j], l, std::min(measure, 1.0));
        if (measure >= 1.0) set_lane(critical[j], l, d_c);
    }
    if (measure >= 1.0) set_lane(next[j], l, fading(D, lane(critical[j], l), element_size));
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

/// A number > 0 as the one point {0, y}, or `[[x, y], ...]`.
std::vector<std::pair<Real, Real>> read_points_or_constant(const YamlValue& v, const char* what) {
    if (v.is_scalar()) return {{0.0, v.positive()}};
    return read_points(v, what);
}

/// `fading: {critical_strain | critical_damage, exponent}`.
TabulatedFailureParameters::Fading read_fading(const YamlValue& v) {
    const YamlMap m = v.map({"critical_strain", "critical_damage", "exponent", "rate_scaled"});
    TabulatedFailureParameters::Fading f;
    if (m.count({"critical_strain", "critical_damage"}) > 1)
        v.fail("takes critical_strain or critical_damage, not both");
    if (const auto c = m.find("critical_strain"))
        f.critical_strain =
            read_points_or_constant(*c, "[triaxiality, critical plastic strain] points");
    if (const auto d = m.find("critical_damage")) {
        f.critical_damage = d->non_negative();
        if (!(f.critical_damage < 1)) d->fail("must be below 1, got " + d->describe());
    }
    if (const auto e = m.find("exponent"))
        f.exponent = read_points_or_constant(*e, "[element size, fading exponent] points");
    f.rate_scaled = m.choice_or("rate_scaled", {"true", "false"}, "true") == "true";
    return f;
}

/// `tabulated: {failure_strain: [[eta, eps_f], ...], regularization: [[size, factor], ...],
/// exponent, fading: {...}}`.
std::any read_tabulated(const YamlValue& v, const Material& /*material*/) {
    const YamlMap m = v.map({"failure_strain", "regularization", "exponent", "fading",
                             "rate_scaling", "log_rate_scaling"});
    TabulatedFailureParameters p;
    p.failure_strain = read_points(m.at("failure_strain", "[[triaxiality, failure strain], ...]"),
                                   "[triaxiality, failure strain] points");
    if (const auto r = m.find("regularization"))
        p.regularization = read_points(*r, "[element size, factor] points");
    if (const auto n = m.find("exponent")) {
        p.exponent = n->positive();
        if (p.exponent < 1) n->fail("must be >= 1 (GISSMO's DMGEXP), got " + n->describe());
    }
    if (const auto f = m.find("fading")) p.fading = read_fading(*f);
    if (m.count({"rate_scaling", "log_rate_scaling"}) > 1)
        v.fail("takes rate_scaling or log_rate_scaling, not both");
    if (const auto r = m.find("rate_scaling"))
        p.rate_scaling = read_points(*r, "[plastic strain rate, factor] points");
    if (const auto r = m.find("log_rate_scaling")) {
        p.rate_scaling = read_points(*r, "[ln of the plastic strain rate, factor] points");
        p.log_rates = true;
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
    // LCSRS: the failure strain's factor against the plastic strain rate (a first rate < 0: the
    // rates are logarithms); > 0 scales ECRIT too, < 0 not
    std::string rate;
    const long long lcsrs = h.id(0, "LCSRS");
    if (lcsrs != 0) {
        const long long id = lcsrs < 0 ? -lcsrs : lcsrs;
        rate = (card.curve_first_abscissa(h, id, "LCSRS") < 0 ? ", log_rate_scaling: "
                                                              : ", rate_scaling: ") +
               card.curve_points(h, id, "LCSRS");
    }
    card.failure(tabulated_deck_failure(card, g, 0, rate, lcsrs >= 0));
    if (numfip > 0) card.failure_points(static_cast<long long>(std::llround(numfip)));
    if (numfip < 0) card.failure_layers(f, 4, "NUMFIP");  // a percentage of the layers
    for (std::size_t k = 1; k < 8; ++k)
        if (h.real(k, "SHRF, BIAXF, LCDLIM, MIDFAIL, HISVN, SOFT, LP2BI") != 0) {
            card.note(h, "SHRF, BIAXF, LCDLIM, MIDFAIL, HISVN, SOFT, LP2BI ignored (not modelled)");
            break;
        }
}

}  // namespace

// LS-DYNA couples the damage to the stress in every GISSMO: ECRIT 0 takes the instability at
// D = DCRIT (blank: 0, coupled from the start), FADEXP blank is 1.
std::string tabulated_deck_failure(deck::FailureCard& card, const deck::Card& c,
                                   std::size_t lcsdg_at, const std::string& rate,
                                   bool critical_rate_scaled) {
    const std::size_t ecrit_at = lcsdg_at + 1, dmgexp_at = lcsdg_at + 2, dcrit_at = lcsdg_at + 3,
                      fadexp_at = lcsdg_at + 4, lcregd_at = lcsdg_at + 5;
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
    t += rate;
    std::string fading = "fading: {";
    const Real ecrit = c.real(ecrit_at, "ECRIT");
    if (ecrit < 0) {
        fading += "critical_strain: " +
                  card.curve_points(c, static_cast<long long>(std::llround(-ecrit)), "ECRIT");
    } else if (ecrit > 0) {
        fading += "critical_strain: " + deck::num(ecrit);
    } else {
        const Real dcrit = c.real(dcrit_at, "DCRIT");
        if (dcrit < 0 || dcrit >= 1) c.fail("DCRIT must be in [0, 1)");
        fading += "critical_damage: " + deck::num(dcrit);
    }
    const Real fadexp = c.real(fadexp_at, "FADEXP", 1.0);
    if (fadexp < 0)
        fading += ", exponent: " +
                  card.curve_points(c, static_cast<long long>(std::llround(-fadexp)), "FADEXP");
    else
        fading += ", exponent: " + deck::num(fadexp == 0 ? 1.0 : fadexp);
    if (!rate.empty() && !critical_rate_scaled) fading += ", rate_scaled: false";
    return t + ", " + fading + "}}";
}

FailureCriterion tabulated_criterion() {
    return {"tabulated",
            read_tabulated,
            make_tabulated,
            {{{"MAT_ADD_DAMAGE_GISSMO"}, mat_add_damage_gissmo}}};
}

}  // namespace fpmshell
