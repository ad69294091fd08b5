#include "fpmshell/materials/bilinear/bilinear_law.hpp"

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

/// The flow curve sigma_y + E_t eps past yield, as a plastic modulus against the plastic
/// strain: H = E E_t / (E - E_t).
FlowStress bilinear_flow(Real youngs_modulus, Real yield_stress, Real tangent_modulus) {
    FlowStress flow;
    flow.yield_stress = yield_stress;
    flow.hardening = tangent_modulus > 0
                         ? youngs_modulus * tangent_modulus / (youngs_modulus - tangent_modulus)
                         : 0.0;
    return flow;
}

void read_bilinear(const YamlMap& keys, Material& m) {
    J2Parameters p;
    read_j2_common(keys, p);
    const Real yield_stress =
        keys.at("yield_stress", "the initial yield stress, a number > 0").positive();
    Real tangent = 0;
    if (const auto et = keys.find("tangent_modulus")) {
        tangent = et->non_negative();
        if (!(tangent < m.youngs_modulus))
            et->fail(
                "must be below youngs_modulus (the slope of the bilinear curve past yield; 0 = "
                "perfectly plastic), got " +
                et->describe());
    }
    p.flow = bilinear_flow(m.youngs_modulus, yield_stress, tangent);
    read_cowper_symonds(keys, p);
    set_j2_parameters(m, "j2_plastic", p);
}

/// *MAT_PLASTIC_KINEMATIC: MID, RO, E, PR, SIGY, ETAN, BETA; SRC, SRP, FS, VP.
void mat_plastic_kinematic(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, SIGY, ETAN, BETA");
    const deck::Card g = card.optional(1);
    card.id(f);
    card.plastic();
    card.key("type: j2_plastic");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    card.key("yield_stress: " + deck::num(f.real(4, "SIGY")));
    card.key("tangent_modulus: " + deck::num(f.real(5, "ETAN")));
    card.key("hardening_mix: " + deck::num(f.real(6, "BETA")));
    const Real src = g.real(0, "SRC"), srp = g.real(1, "SRP");
    if (src > 0 || srp > 0)
        card.key("cowper_symonds: {D: " + deck::num(src) + ", q: " + deck::num(srp) + "}");
    card.failure_strain(g, 2, "FS");
    if (g.real(3, "VP") != 0) card.note(g, "VP = 1 read as the scaled yield stress (VP = 0)");
}

}  // namespace

J2Parameters& make_bilinear(Material& m, Real yield_stress, Real tangent_modulus) {
    J2Parameters p;
    p.flow = bilinear_flow(m.youngs_modulus, yield_stress, tangent_modulus);
    return set_j2_parameters(m, "j2_plastic", p);
}

MaterialLaw bilinear_law() {
    return {"j2_plastic",
            true,
            {"yield_stress", "tangent_modulus", "hardening_mix", "cowper_symonds", "rate_scaling",
             "normal_anisotropy"},
            read_bilinear,
            make_j2_group,
            {{{"MAT_PLASTIC_KINEMATIC", "MAT_003"}, mat_plastic_kinematic}}};
}

}  // namespace fpmshell
