#include "fpmshell/materials/plastic_damage/plastic_damage_law.hpp"

#include <string>

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/lsdyna/deck_translator.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/materials/plastic_damage/plastic_damage.hpp"
#include "fpmshell/materials/tabulated/tabulated_law.hpp"
#include "fpmshell/solver/element_group.hpp"

namespace fpmshell {

namespace {

/// The tabulated law's keys and `damage: {start, rupture}`.
void read_plastic_damage(const YamlMap& keys, Material& m) {
    PlasticDamageParameters p;
    p.j2 = tabulated_parameters(keys);
    const YamlMap d = keys.at("damage", "{start, rupture}").map({"start", "rupture"});
    p.start = d.at("start", "the plastic strain where damage starts, >= 0").non_negative();
    const YamlValue rupture = d.at("rupture", "the plastic strain of rupture, above start");
    p.rupture = rupture.positive();
    if (!(p.rupture > p.start))
        rupture.fail("must be above start (" + std::to_string(p.start) + "), got " +
                     rupture.describe());
    m.parameters = p;
}

std::unique_ptr<ElementGroup> make_plastic_damage_group(const Model& model, std::size_t section) {
    const Material& m = model.materials[static_cast<std::size_t>(model.sections[section].material)];
    const auto& p = std::any_cast<const PlasticDamageParameters&>(m.parameters);
    return std::make_unique<MaterialGroup<PlasticDamage>>(
        PlasticDamage(J2Plastic(m.youngs_modulus, m.poisson_ratio, p.j2.flow, p.j2.rate,
                                p.j2.hardening_mix, p.j2.normal_anisotropy, p.j2.thermal),
                      p.start, p.rupture),
        model, section);
}

/// *MAT_PLASTICITY_WITH_DAMAGE: MID, RO, E, PR, SIGY, ETAN, EPPF, TDEL; C, P, LCSS, LCSR,
/// EPPFR, VP, LCDM, NUMINT; EPS1..EPS8; ES1..ES8. The flow curve as *MAT_024's (LCSS or the
/// points, else SIGY and ETAN as a two-point curve); rupture erodes (NUMINT points).
void mat_plasticity_with_damage(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, SIGY, ETAN, EPPF, TDEL");
    const deck::Card g = card.optional(1);
    const deck::Card eps = card.optional(2), es = card.optional(3);
    card.id(f);
    card.plastic();
    const Real e = f.real(2, "E"), sigy = f.real(4, "SIGY"), etan = f.real(5, "ETAN");
    const Real start = f.real(6, "EPPF", 1e12), rupture = g.real(4, "EPPFR", 1e14);
    if (start < 0) f.fail("EPPF must be >= 0");
    if (!(rupture > start)) g.fail("EPPFR must be above EPPF");
    const long long lcss = g.id(2, "LCSS");
    if (g.id(6, "LCDM") != 0) g.fail("LCDM (a nonlinear damage curve) is not supported");
    if (g.real(5, "VP") != 0) card.note(g, "VP = 1 read as the scaled yield stress (VP = 0)");
    card.deletion_time_step(f, 7, "TDEL");
    card.key("type: plastic_damage");
    card.elastic(f, e, f.real(3, "PR"));
    card.flow_curve_id(lcss);
    if (lcss == 0) {
        std::vector<deck::Point2> points = deck::MaterialCard::curve_of(eps, es);
        if (points.size() < 2) {  // SIGY and ETAN: the bilinear curve against plastic strain
            if (!(sigy > 0)) f.fail("SIGY must be > 0 without a flow curve");
            if (!(etan < e)) f.fail("ETAN must be below E");
            const Real h = etan > 0 ? e * etan / (e - etan) : 0.0;
            points = {{0.0, sigy}, {1.0, sigy + h}};
        }
        card.key("flow_curve: " + deck::MaterialCard::points_text(points));
    }
    const Real c = g.real(0, "C"), p = g.real(1, "P");
    if (c > 0 || p > 0)
        card.key("cowper_symonds: {D: " + deck::num(c) + ", q: " + deck::num(p) + "}");
    if (const long long lcsr = g.id(3, "LCSR"); lcsr != 0) {  // as *MAT_024's
        if (c > 0 || p > 0) g.fail("give C, P (Cowper-Symonds) or LCSR (a rate curve), not both");
        card.rate_curve_id(lcsr);
    }
    card.key("damage: {start: " + deck::num(start) + ", rupture: " + deck::num(rupture) + "}");
    if (rupture < 1e13) {  // the default EPPFR: no rupture
        card.failure("plastic_strain: " + deck::num(rupture));
        if (const long long numint = g.id(7, "NUMINT"); numint > 0) card.failure_points(numint);
    }
}

/// *MAT_PLASTICITY_WITH_DAMAGE_ORTHO: the same cards; its damage read as isotropic.
void mat_plasticity_with_damage_ortho(deck::MaterialCard& card) {
    mat_plasticity_with_damage(card);
    card.note(card.required(0, "MID"),
              "the damage of *MAT_082 is read as isotropic (*MAT_081's): the same in every "
              "direction of the sheet");
}

}  // namespace

MaterialLaw plastic_damage_law() {
    return {"plastic_damage",
            true,
            {"flow_curve", "flow_curves", "hardening_mix", "cowper_symonds", "rate_scaling",
             "normal_anisotropy", "damage"},
            read_plastic_damage,
            make_plastic_damage_group,
            {{{"MAT_PLASTICITY_WITH_DAMAGE", "MAT_081"}, mat_plasticity_with_damage},
             {{"MAT_PLASTICITY_WITH_DAMAGE_ORTHO", "MAT_082"}, mat_plasticity_with_damage_ortho}}};
}

}  // namespace fpmshell
