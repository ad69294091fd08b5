#include "fpmshell/materials/power_law/power_law_law.hpp"

#include <cmath>

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

/// sigma = k (eps_0 + eps_p)^n; eps_0 from the yield stress, (sigma_y / k)^(1/n), or without
/// it where the elastic line E eps meets k eps^n (n < 1), as LS-DYNA's
/// *MAT_POWER_LAW_PLASTICITY.
void read_power_law(const YamlMap& keys, Material& m) {
    J2Parameters p;
    read_j2_common(keys, p);
    FlowStress& flow = p.flow;
    flow.kind = FlowStress::Kind::PowerLaw;
    flow.b = keys.at("k", "the strength coefficient k, a number > 0").positive();
    const YamlValue n = keys.at("n", "the hardening exponent n, a number > 0");
    flow.n = n.positive();
    if (const auto sy = keys.find("yield_stress")) {
        flow.strain_offset = std::pow(sy->positive() / flow.b, 1.0 / flow.n);
    } else {
        if (!(flow.n < 1))
            n.fail(
                "must be below 1 without a yield_stress (the elastic line E eps meets k eps^n "
                "only then); give yield_stress, got " +
                n.describe());
        flow.strain_offset = std::pow(flow.b / m.youngs_modulus, 1.0 / (1.0 - flow.n));
    }
    if (!(flow.strain_offset > 0 && std::isfinite(flow.strain_offset)))
        keys.at("k", "").fail(
            "gives no finite elastic strain at yield with this n and yield stress");
    read_cowper_symonds(keys, p);
    set_j2_parameters(m, "power_law", p);
}

/// *MAT_POWER_LAW_PLASTICITY: MID, RO, E, PR, K, N, SRC, SRP; SIGY, VP, EPSF.
void mat_power_law(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, K, N, SRC, SRP");
    const deck::Card g = card.optional(1);
    card.id(f);
    card.plastic();
    card.key("type: power_law");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    card.key("k: " + deck::num(f.real(4, "K")));
    card.key("n: " + deck::num(f.real(5, "N")));
    const Real src = f.real(6, "SRC"), srp = f.real(7, "SRP");
    if (src > 0 || srp > 0)
        card.key("cowper_symonds: {D: " + deck::num(src) + ", q: " + deck::num(srp) + "}");
    // LS-DYNA takes SIGY as the initial yield stress only above 0.02, else the strain at
    // yield from the elastic line
    const Real sigy = g.real(0, "SIGY");
    if (sigy > 0.02) card.key("yield_stress: " + deck::num(sigy));
    if (g.real(1, "VP") != 0) card.note(g, "VP = 1 read as the scaled yield stress (VP = 0)");
    card.failure_strain(g, 2, "EPSF");
}

}  // namespace

MaterialLaw power_law_law() {
    return {"power_law",
            true,
            {"k", "n", "yield_stress", "hardening_mix", "cowper_symonds", "rate_scaling",
             "normal_anisotropy"},
            read_power_law,
            make_j2_group,
            {{{"MAT_POWER_LAW_PLASTICITY", "MAT_018"}, mat_power_law}}};
}

}  // namespace fpmshell
