#include "fpmshell/materials/johnson_cook/johnson_cook_law.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

FlowStress johnson_cook_flow(Real a, Real b, Real n) {
    FlowStress flow;
    flow.kind = FlowStress::Kind::JohnsonCook;
    flow.a = a;
    flow.b = b;
    flow.n = n;
    return flow;
}

/// `thermal_softening: {m, melt_temperature, room_temperature, specific_heat, taylor_quinney}`
/// (eq. 7.4-2).
ThermalSoftening read_thermal_softening(const YamlValue& v, Real density) {
    const YamlMap t =
        v.map({"m", "melt_temperature", "room_temperature", "specific_heat", "taylor_quinney"});
    const Real m = t.at("m", "the exponent m of T*, a number > 0").positive();
    const Real room = t.at("room_temperature", "the temperature T_r the material starts at").real();
    const YamlValue melt_value = t.at("melt_temperature", "the melting temperature T_m > T_r");
    const Real melt = melt_value.real();
    if (!(melt > room))
        melt_value.fail("must be above room_temperature (" + fmt::format("{:g}", room) + "), got " +
                        melt_value.describe());
    const Real cp =
        t.at("specific_heat", "the specific heat c_p (energy per mass and degree), a number > 0")
            .positive();
    Real chi = 0.9;  // Taylor-Quinney
    if (const auto c = t.find("taylor_quinney")) {
        chi = c->positive();
        if (chi > 1)
            c->fail("is the fraction of the plastic work that heats, in (0, 1]; got " +
                    c->describe());
    }
    return adiabatic_softening(m, melt, room, cp, chi, density);
}

void read_johnson_cook(const YamlMap& keys, Material& mat) {
    J2Parameters p;
    read_j2_common(keys, p);
    const Real a = keys.at("A", "the Johnson-Cook yield stress A, a number > 0").positive();
    const Real b =
        keys.at("B", "the Johnson-Cook hardening modulus B, a number >= 0").non_negative();
    const Real n = keys.at("n", "the Johnson-Cook hardening exponent n, a number > 0").positive();
    p.flow = johnson_cook_flow(a, b, n);
    const Real c = keys.non_negative_or("C", 0.0);
    const Real rate0 = keys.positive_or("reference_strain_rate", 1.0);
    if (c > 0) {
        p.rate.kind = RateFactor::Kind::JohnsonCook;
        p.rate.c = c;
        p.rate.reference_rate = rate0;
    }
    if (const auto th = keys.find("thermal_softening"))
        p.thermal = read_thermal_softening(*th, mat.density);
    set_j2_parameters(mat, "johnson_cook", p);
}

/// *MAT_JOHNSON_COOK: MID, RO, G, E, PR, DTF, VP, RATEOP; A, B, N, C, M, TM, TR, EPSO;
/// CP, PC, SPALL, IT, D1, D2, D3, D4; D5, C2/P, EROD, EFMIN, NUMINT.
void mat_johnson_cook(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, G, E, PR");
    const deck::Card g = card.required(1, "A, B, N, C, M, TM, TR, EPSO");
    const deck::Card h = card.optional(2), i = card.optional(3);
    card.id(f);
    card.plastic();
    Real e = f.real(3, "E");
    const Real shear = f.real(2, "G"), nu = f.real(4, "PR");
    if (e == 0) e = 2.0 * shear * (1.0 + nu);
    card.key("type: johnson_cook");
    card.elastic(f, e, nu);
    if (f.real(7, "RATEOP") != 0) f.fail("RATEOP: only the log-linear rate term (0) is supported");
    if (f.real(6, "VP") != 0) card.note(f, "VP = 1 read as the scaled yield stress (VP = 0)");
    const Real c = g.real(3, "C"), m_exp = g.real(4, "M"), tm = g.real(5, "TM");
    const Real eps0 = g.real(7, "EPSO");
    card.key("A: " + deck::num(g.real(0, "A")));
    card.key("B: " + deck::num(g.real(1, "B")));
    card.key("n: " + deck::num(g.real(2, "N")));
    if (c != 0) {
        if (!(eps0 > 0)) g.fail("EPSO must be > 0 with a rate term C");
        card.key("C: " + deck::num(c));
        card.key("reference_strain_rate: " + deck::num(eps0));
    }
    const Real cp = h.real(0, "CP"), tr = g.real(6, "TR");
    if (m_exp != 0 && tm != 0 && cp != 0) {  // theory.md eq. 7.4-2
        if (!(m_exp > 0)) g.fail("M must be > 0 (the exponent of the homologous temperature)");
        if (!(tm > tr)) g.fail("TM must be above TR (the melting and the room temperature)");
        if (!(cp > 0)) h.fail("CP must be > 0 (the specific heat)");
        card.key("thermal_softening: {m: " + deck::num(m_exp) +
                 ", melt_temperature: " + deck::num(tm) + ", room_temperature: " + deck::num(tr) +
                 ", specific_heat: " + deck::num(cp) + "}");
        card.note(h,
                  "thermal softening by adiabatic heating: 0.9 of the plastic work heats (the "
                  "Taylor-Quinney fraction; the card has no field for it)");
    } else if (m_exp != 0 || tm != 0) {
        card.note(g, "isothermal: the temperature terms (M, TM, TR) need CP > 0 to act");
    }
    // D1..D5: Johnson-Cook damage (failure/johnson_cook), EFMIN its floor, NUMINT the points
    // that erode a shell (0: all through the thickness)
    const Real d[5] = {h.real(4, "D1"), h.real(5, "D2"), h.real(6, "D3"), h.real(7, "D4"),
                       i.real(0, "D5")};
    if (d[0] != 0 || d[1] != 0 || d[2] != 0 || d[3] != 0 || d[4] != 0) {
        std::string damage = "johnson_cook: {D1: " + deck::num(d[0]) + ", D2: " + deck::num(d[1]) +
                             ", D3: " + deck::num(d[2]) + ", D4: " + deck::num(d[3]) +
                             ", D5: " + deck::num(d[4]);
        if (d[3] != 0) {
            if (!(eps0 > 0)) g.fail("EPSO must be > 0 with a rate term D4 of the damage");
            damage += ", reference_strain_rate: " + deck::num(eps0);
        }
        const Real efmin = i.real(3, "EFMIN");
        if (efmin < 0) i.fail("EFMIN must be >= 0 (the lower bound of the failure strain)");
        if (efmin > 0) damage += ", minimum_strain: " + deck::num(efmin);
        card.failure(damage + "}");
        const long long numint = i.id(4, "NUMINT");
        if (numint < 0) i.fail("NUMINT < 0 is not supported (give the number of points, or 0)");
        if (numint > 0) card.failure_points(numint);
        if (i.real(2, "EROD") != 0)
            card.note(i,
                      "EROD != 0 read as 0: an element whose points fail erodes (keeping it with "
                      "no deviatoric stress is not modelled)");
        if (f.real(5, "DTF") != 0)
            card.note(f, "DTF ignored: elements erode by their damage, not by their time step");
        if (h.real(1, "PC") != 0 || h.real(2, "SPALL") != 0)
            card.note(h, "PC, SPALL ignored: a shell in plane stress has no pressure cut-off");
    }
    card.note(f, "its *EOS is irrelevant: a shell is in plane stress");
}

/// *MAT_SIMPLIFIED_JOHNSON_COOK (098): MID, RO, E, PR, VP; A, B, N, C, PSFAIL, SIGMAX, SIGSAT,
/// EPSO. The Johnson-Cook flow stress without temperature, its rate term at EPSO, and failure at
/// the plastic strain PSFAIL (0, blank or its default 1e17: none).
void mat_simplified_johnson_cook(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, VP");
    const deck::Card g = card.required(1, "A, B, N, C, PSFAIL, SIGMAX, SIGSAT, EPSO");
    card.id(f);
    card.plastic();
    card.key("type: johnson_cook");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    if (f.real(4, "VP") != 0) card.note(f, "VP = 1 read as the scaled yield stress (VP = 0)");
    card.key("A: " + deck::num(g.real(0, "A")));
    card.key("B: " + deck::num(g.real(1, "B")));
    card.key("n: " + deck::num(g.real(2, "N")));
    const Real c = g.real(3, "C"), eps0 = g.real(7, "EPSO", 1.0);
    if (c != 0) {
        if (!(eps0 > 0)) g.fail("EPSO must be > 0 with a rate term C");
        card.key("C: " + deck::num(c));
        card.key("reference_strain_rate: " + deck::num(eps0));
    }
    // LS-DYNA's defaults of the caps (1e28) leave the flow stress uncapped
    for (const auto& [k, name] :
         {std::pair{std::size_t{5}, "SIGMAX"}, std::pair{std::size_t{6}, "SIGSAT"}})
        if (g.real(k, name, 1e28) < 1e27)
            g.fail(std::string(name) +
                   " (a cap on the flow stress) is not supported: leave it blank (no cap)");
    card.failure_strain(g, 4, "PSFAIL");
}

}  // namespace

ThermalSoftening adiabatic_softening(Real m, Real melt_temperature, Real room_temperature,
                                     Real specific_heat, Real taylor_quinney, Real density) {
    ThermalSoftening t;
    t.active = true;
    t.m = m;
    t.heating = taylor_quinney / (density * specific_heat * (melt_temperature - room_temperature));
    return t;
}

J2Parameters& make_johnson_cook(Material& m, Real a, Real b, Real n, Real c, Real reference_rate) {
    J2Parameters p;
    p.flow = johnson_cook_flow(a, b, n);
    if (c > 0) {
        p.rate.kind = RateFactor::Kind::JohnsonCook;
        p.rate.c = c;
        p.rate.reference_rate = reference_rate;
    }
    return set_j2_parameters(m, "johnson_cook", p);
}

MaterialLaw johnson_cook_law() {
    return {"johnson_cook",
            true,
            {"A", "B", "n", "C", "reference_strain_rate", "hardening_mix", "thermal_softening",
             "normal_anisotropy"},
            read_johnson_cook,
            make_j2_group,
            {{{"MAT_JOHNSON_COOK", "MAT_015"}, mat_johnson_cook},
             {{"MAT_SIMPLIFIED_JOHNSON_COOK", "MAT_098"}, mat_simplified_johnson_cook}}};
}

}  // namespace fpmshell
