// The `materials` and `sections` blocks of the model file (see model_blocks.hpp).
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"
#include "fpmshell/materials/flow_table.hpp"
#include "fpmshell/model/enclosed_solid.hpp"
#include "fpmshell/model/rigid_inertia_shares.hpp"

namespace fpmshell {
namespace {

std::string fmt_real(Real x) { return fmt::format("{:g}", x); }

/// `[[plastic strain, flow stress], ...]`: two points at least, from plastic strain 0, the
/// strains increasing, the stresses > 0 and not decreasing (the return mapping brackets its
/// solution on a curve that does not soften, theory.md §7.3a).
FlowCurvePoints read_flow_curve(const YamlValue& v) {
    FlowCurvePoints curve;
    const auto points = v.list("[plastic strain, flow stress] pairs");
    if (points.size() < 2)
        v.fail(
            "a flow curve needs at least two [plastic strain, flow stress] pairs, e.g. [[0, "
            "250e6], [0.2, 400e6]]");
    std::string previous_strain, previous_stress;
    for (const YamlValue& p : points) {
        const auto es = p.list_of(2, "two numbers [plastic strain, flow stress]",
                                  "a pair [plastic strain, flow stress]");
        const Real strain = es[0].real(), stress = es[1].real();
        if (curve.strain.empty()) {
            if (strain != 0.0)
                es[0].fail("the first point of a flow curve must be at plastic strain 0, got " +
                           es[0].describe());
            if (!(stress > 0.0))
                es[1].fail(
                    "the initial yield stress (the flow stress at plastic strain 0) must "
                    "be > 0, got " +
                    es[1].describe());
        } else {
            if (!(strain > curve.strain.back()))
                es[0].fail("the plastic strains of a flow curve must increase strictly, but " +
                           es[0].describe() + " follows " + previous_strain);
            if (!(stress >= curve.stress.back()))
                es[1].fail(
                    "the flow stress must not decrease along the curve (softening is not "
                    "supported), but " +
                    es[1].describe() + " follows " + previous_stress);
        }
        previous_strain = es[0].describe();
        previous_stress = es[1].describe();
        curve.strain.push_back(strain);
        curve.stress.push_back(stress);
    }
    return curve;
}

/// The first point where curve `high` lies below curve `low` (eq. 7.2-4: piecewise linear,
/// each extended past its last point), or a negative strain where it never does: the
/// difference is piecewise linear, so its breakpoints and its slope past the last decide.
Real first_crossing(const FlowCurvePoints& low, const FlowCurvePoints& high) {
    const PiecewiseLinearCurve a(low.strain, low.stress), b(high.strain, high.stress);
    std::vector<Real> at = low.strain;
    at.insert(at.end(), high.strain.begin(), high.strain.end());
    std::sort(at.begin(), at.end());
    for (Real alpha : at)
        if (b.at(alpha).value < a.at(alpha).value) return alpha;
    if (b.at(at.back()).slope < a.at(at.back()).slope) return at.back() + 1.0;  // past both
    return -1.0;
}

/// `flow_curves: [{strain_rate: r, points: [...]}, ...]`: the rates >= 0 and increasing, each
/// curve on or above the one before it (the element's trial check takes the first curve's
/// radius as a lower bound of every other, elements/elastic_triangle_block.hpp).
void read_flow_curves(const YamlValue& v, Material& mat) {
    const auto items = v.list("flow curves at increasing strain rates");
    if (items.empty())
        v.fail(
            "expected at least one {strain_rate: ..., points: [[plastic strain, flow stress], "
            "...]}");
    for (const YamlValue& item : items) {
        const YamlMap m = item.map({"strain_rate", "points"});
        const YamlValue rate = m.at("strain_rate", "the strain rate of this curve, a number >= 0");
        FlowCurvePoints curve =
            read_flow_curve(m.at("points", "[plastic strain, flow stress] pairs"));
        curve.strain_rate = rate.non_negative();
        if (!mat.flow_curves.empty()) {
            const FlowCurvePoints& below = mat.flow_curves.back();
            if (!(curve.strain_rate > below.strain_rate))
                rate.fail("the strain rates of the flow curves must increase, but " +
                          rate.describe() + " follows " + fmt_real(below.strain_rate));
            const Real crossing = first_crossing(below, curve);
            if (crossing >= 0.0)
                item.fail("the curve at strain rate " + rate.describe() +
                          " lies below the one at strain rate " + fmt_real(below.strain_rate) +
                          " near plastic strain " + fmt_real(crossing) +
                          "; the curves must not cross (a higher rate, a flow stress at least "
                          "as high)");
        }
        mat.flow_curves.push_back(std::move(curve));
    }
}

/// power_law (eq. 7.2-6): sigma = k (eps_0 + eps_p)^n; eps_0 from the yield stress,
/// (sigma_y / k)^(1/n), or without it where the elastic line E eps meets k eps^n (n < 1), as
/// LS-DYNA's *MAT_POWER_LAW_PLASTICITY.
void read_power_law(const YamlMap& m, Material& mat) {
    mat.power_k = m.at("k", "the strength coefficient k, a number > 0").positive();
    const YamlValue n = m.at("n", "the hardening exponent n, a number > 0");
    mat.power_n = n.positive();
    if (const auto sy = m.find("yield_stress")) {
        mat.yield_stress = sy->positive();
        mat.power_strain_offset = std::pow(mat.yield_stress / mat.power_k, 1.0 / mat.power_n);
    } else {
        if (!(mat.power_n < 1))
            n.fail(
                "must be below 1 without a yield_stress (the elastic line E eps meets k eps^n "
                "only then); give yield_stress, got " +
                n.describe());
        mat.power_strain_offset =
            std::pow(mat.power_k / mat.youngs_modulus, 1.0 / (1.0 - mat.power_n));
        mat.yield_stress = mat.youngs_modulus * mat.power_strain_offset;
    }
    if (!(mat.power_strain_offset > 0 && std::isfinite(mat.power_strain_offset)))
        m.at("k", "").fail("gives no finite elastic strain at yield with this n and yield stress");
}

/// johnson_cook's `thermal_softening: {m, melt_temperature, room_temperature, specific_heat,
/// taylor_quinney}` (theory.md eq. 7.4-2).
void read_thermal_softening(const YamlValue& v, Material& mat) {
    const YamlMap t =
        v.map({"m", "melt_temperature", "room_temperature", "specific_heat", "taylor_quinney"});
    mat.thermal = true;
    mat.jc_m = t.at("m", "the exponent m of T*, a number > 0").positive();
    mat.room_temperature =
        t.at("room_temperature", "the temperature T_r the material starts at").real();
    const YamlValue melt = t.at("melt_temperature", "the melting temperature T_m > T_r");
    mat.melt_temperature = melt.real();
    if (!(mat.melt_temperature > mat.room_temperature))
        melt.fail("must be above room_temperature (" + fmt_real(mat.room_temperature) + "), got " +
                  melt.describe());
    mat.specific_heat =
        t.at("specific_heat", "the specific heat c_p (energy per mass and degree), a number > 0")
            .positive();
    if (const auto chi = t.find("taylor_quinney")) {
        mat.taylor_quinney = chi->positive();
        if (mat.taylor_quinney > 1)
            chi->fail("is the fraction of the plastic work that heats, in (0, 1]; got " +
                      chi->describe());
    }
}

/// A plastic material's `failure: {plastic_strain, points}` (theory.md §7.6).
void read_failure(const YamlValue& v, Material& mat) {
    const YamlMap f = v.map({"plastic_strain", "points"});
    mat.failure.plastic_strain =
        f.at("plastic_strain", "the plastic strain at which a point fails, a number > 0")
            .positive();
    if (const auto n = f.find("points"))
        mat.failure.points = static_cast<int>(n->integer(1, 7 * k_max_thickness_points));
}

}  // namespace

void read_materials(const YamlValue& v, Model& model) {
    const YamlMap all = v.open_map("material names to material definitions");
    if (all.entries().empty())
        v.fail(
            "at least one material is required, e.g. steel: {type: elastic, density: "
            "7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}");
    for (const auto& [name, def] : all.entries()) {
        if (!def.is_map() && !def.is_null())
            def.fail(
                "expected a map of material constants such as {type: elastic, density: "
                "..., youngs_modulus: ..., poisson_ratio: ...}, got " +
                def.describe());
        const YamlMap any = def.open_map("material constants");
        const YamlValue type = any.at("type", "elastic");
        const std::string t = type.choice(
            {"elastic", "j2_plastic", "johnson_cook", "tabulated", "power_law", "rigid"});
        std::vector<std::string> keys{"type", "density", "youngs_modulus", "poisson_ratio"};
        if (t == "rigid") keys.push_back("fix");
        if (t == "elastic" || t == "rigid") {
            for (const auto& [key, value] : any.entries())
                for (const char* plastic :
                     {"yield_stress", "tangent_modulus", "hardening_mix", "cowper_symonds", "A",
                      "B", "n", "C", "reference_strain_rate", "thermal_softening", "flow_curve",
                      "flow_curves", "k", "normal_anisotropy", "failure"})
                    if (key == plastic)
                        value.fail(
                            "belongs to plastic materials (type: j2_plastic, johnson_cook, "
                            "tabulated or power_law); remove it or change the type");
        } else if (t == "j2_plastic") {
            keys.insert(keys.end(),
                        {"yield_stress", "tangent_modulus", "hardening_mix", "cowper_symonds"});
        } else if (t == "tabulated") {
            keys.insert(keys.end(),
                        {"flow_curve", "flow_curves", "hardening_mix", "cowper_symonds"});
        } else if (t == "power_law") {
            keys.insert(keys.end(), {"k", "n", "yield_stress", "hardening_mix", "cowper_symonds"});
        } else {
            if (const auto cs = any.find("cowper_symonds"))
                cs->fail("is a rate factor for j2_plastic; johnson_cook has its own rate term C");
            keys.insert(keys.end(), {"A", "B", "n", "C", "reference_strain_rate", "hardening_mix",
                                     "thermal_softening"});
        }
        if (t != "elastic" && t != "rigid") {
            keys.push_back("normal_anisotropy");
            keys.push_back("failure");
        }
        const YamlMap m = def.map(keys);
        Material mat;
        mat.name = name;
        mat.rigid = t == "rigid";  // elastic constants, rigid motion (model.hpp)
        if (const auto fix = m.find("fix")) mat.rigid_fixed = fixed_dofs(*fix);
        mat.type = t == "elastic" || mat.rigid ? MaterialType::Elastic
                   : t == "j2_plastic"         ? MaterialType::J2Plastic
                   : t == "tabulated"          ? MaterialType::Tabulated
                   : t == "power_law"          ? MaterialType::PowerLaw
                                               : MaterialType::JohnsonCook;
        mat.density = m.at("density", "a number > 0").positive();
        mat.youngs_modulus = m.at("youngs_modulus", "a number > 0").positive();
        const YamlValue nu = m.at("poisson_ratio", "a number in (-1, 0.5)");
        mat.poisson_ratio = nu.real();
        if (!(mat.poisson_ratio > -1 && mat.poisson_ratio < 0.5))
            nu.fail("must be greater than -1 and less than 0.5, got " + nu.describe());
        if (mat.plastic()) {
            if (const auto r = m.find("normal_anisotropy"))  // Hill's R (eq. 7.1-3)
                mat.normal_anisotropy = r->positive();
            if (const auto f = m.find("failure")) read_failure(*f, mat);
            if (const auto mix = m.find("hardening_mix")) {
                mat.hardening_mix = mix->real();
                if (!(mat.hardening_mix >= 0 && mat.hardening_mix <= 1))
                    mix->fail("must be in [0, 1] (1 isotropic, 0 kinematic hardening), got " +
                              mix->describe());
            }
        }
        if (mat.type == MaterialType::J2Plastic) {
            mat.yield_stress =
                m.at("yield_stress", "the initial yield stress, a number > 0").positive();
            if (const auto et = m.find("tangent_modulus")) {
                mat.tangent_modulus = et->non_negative();
                if (!(mat.tangent_modulus < mat.youngs_modulus))
                    et->fail(
                        "must be below youngs_modulus (the slope of the bilinear curve past "
                        "yield; 0 = perfectly plastic), got " +
                        et->describe());
            }
        }
        if (mat.type == MaterialType::Tabulated) {
            const auto one = m.find("flow_curve"), table = m.find("flow_curves");
            if (one && table)
                table->fail(
                    "give either flow_curve (one curve) or flow_curves (one per strain "
                    "rate), not both");
            if (table) {
                read_flow_curves(*table, mat);
                if (mat.flow_curves.size() > 1) {
                    if (const auto cs = m.find("cowper_symonds"))
                        cs->fail(
                            "cannot be combined with flow_curves: the curves at their "
                            "strain rates give the rate dependence");
                    if (const auto mix = m.find("hardening_mix"); mix && mat.hardening_mix != 1.0)
                        mix->fail(
                            "must be 1 (isotropic) with flow_curves at several strain "
                            "rates, as in LS-DYNA's *MAT_024");
                }
            } else {
                mat.flow_curves.push_back(read_flow_curve(
                    m.at("flow_curve",
                         "a list of [plastic strain, flow stress] pairs (or flow_curves)")));
            }
        }
        if (mat.type == MaterialType::PowerLaw) read_power_law(m, mat);
        if (mat.type == MaterialType::J2Plastic || mat.type == MaterialType::Tabulated ||
            mat.type == MaterialType::PowerLaw) {
            if (const auto cs = m.find("cowper_symonds")) {
                const YamlMap c = cs->map({"D", "q"});
                mat.cowper_symonds = true;
                mat.cs_d = c.at("D", "the Cowper-Symonds rate constant D [1/time], a number > 0")
                               .positive();
                mat.cs_q = c.at("q", "the Cowper-Symonds exponent q, a number > 0").positive();
            }
        }
        if (mat.type == MaterialType::JohnsonCook) {
            mat.jc_a = m.at("A", "the Johnson-Cook yield stress A, a number > 0").positive();
            mat.jc_b =
                m.at("B", "the Johnson-Cook hardening modulus B, a number >= 0").non_negative();
            mat.jc_n = m.at("n", "the Johnson-Cook hardening exponent n, a number > 0").positive();
            mat.jc_c = m.non_negative_or("C", 0.0);
            mat.reference_strain_rate = m.positive_or("reference_strain_rate", 1.0);
            if (const auto th = m.find("thermal_softening")) read_thermal_softening(*th, mat);
        }
        model.materials.push_back(mat);
    }
}

/// A section's points through the thickness: `thickness_points` and `thickness_rule`
/// (model-format.md; theory.md §4.5). Without a rule, 1 or 2 points are Gauss, 3 or more Lobatto.
void read_thickness_rule(const YamlMap& m, Section& s) {
    const auto tp = m.find("thickness_points");
    if (tp) s.thickness_points = static_cast<int>(tp->integer(1, k_max_thickness_points));
    const auto rule = m.find("thickness_rule");
    if (!rule) return;
    if (rule->is_list()) {
        // a user rule: [zeta, fraction of the thickness] per point, as *INTEGRATION_SHELL's S, WF
        const std::vector<YamlValue> points = rule->list("[zeta, weight] pairs");
        if (points.empty() || points.size() > static_cast<std::size_t>(k_max_thickness_points))
            rule->fail("expected 1 to 10 [zeta, weight] points, got " +
                       std::to_string(points.size()));
        Real sum = 0;
        for (const YamlValue& p : points) {
            const std::vector<YamlValue> pair =
                p.list_of(2, "a point", "a [zeta, weight] pair such as [0.5, 0.25]");
            const Real zeta = pair[0].real(), weight = pair[1].positive();
            if (zeta < -1 || zeta > 1)
                pair[0].fail("zeta must lie in [-1, 1], got " + pair[0].describe());
            s.thickness_user_points.emplace_back(zeta, 2 * weight);
            sum += weight;
        }
        // weights are fractions of the thickness: they must add up to it (rounding of 1e-6)
        if (std::abs(sum - 1) > 1e-6)
            rule->fail(
                fmt::format("the weights must sum to 1 (fractions of the thickness), got {}", sum));
        if (tp && tp->integer(1, k_max_thickness_points) != static_cast<long long>(points.size()))
            tp->fail("thickness_points differs from the number of points of thickness_rule");
        s.thickness_points = static_cast<int>(points.size());
        s.thickness_rule = ThicknessRule::User;
        return;
    }
    if (rule->choice({"gauss", "lobatto"}) == "gauss") {
        s.thickness_rule = ThicknessRule::Gauss;
    } else {
        if (s.thickness_points < 3)
            (tp ? *tp : *rule)
                .fail("a Lobatto rule has 3 to 10 points through the thickness, got " +
                      std::to_string(s.thickness_points));
        s.thickness_rule = ThicknessRule::Lobatto;
    }
}

namespace {

/// A rigid section's `inertia` (LS-DYNA's *PART_INERTIA; eq. 6.11-8 for `enclosed`): its
/// body's mass, centre and tensor [Ixx, Ixy, Ixz, Iyy, Iyz, Izz] about the centre, or those of
/// the solid its closed faces enclose.
void read_rigid_inertia(const YamlValue& v, const Model& model, const std::vector<Index>& elements,
                        Section& s) {
    const Material& mat = model.materials[static_cast<std::size_t>(s.material)];
    if (!mat.rigid) v.fail("inertia is given to sections of a rigid material only (`type: rigid`)");
    s.has_inertia = true;
    if (v.is_scalar()) {
        (void)v.choice({"enclosed"});  // the one word; a map gives the numbers
        std::vector<std::array<Index, 3>> faces;
        faces.reserve(elements.size());
        for (const Index e : elements)
            faces.push_back(model.triangles[static_cast<std::size_t>(e)]);
        if (const auto open = open_surface_edge(faces))
            v.fail(
                "`enclosed` needs the section's faces to close a solid, each edge shared by two "
                "of them oriented the same way round; " +
                *open);
        s.inertia = enclosed_solid_inertia(faces, model.nodes, mat.density);
        if (!(s.inertia.mass > 0)) v.fail("the faces enclose no volume (or the density is 0)");
        return;
    }
    const YamlMap m = v.map({"mass", "centre", "tensor"});
    s.inertia.mass = m.at("mass", "a number > 0").positive();
    s.inertia.centre = m.at("centre", "[x, y, z]").vec3();
    const auto items = m.at("tensor", "[Ixx, Ixy, Ixz, Iyy, Iyz, Izz]")
                           .list_of(6, "a component", "[Ixx, Ixy, Ixz, Iyy, Iyz, Izz]");
    const Real ixx = items[0].real(), ixy = items[1].real(), ixz = items[2].real();
    const Real iyy = items[3].real(), iyz = items[4].real(), izz = items[5].real();
    s.inertia.tensor << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(s.inertia.tensor);
    const Vec3 principal = eigen.eigenvalues();  // ascending
    // a body's principal moments are positive, each at most the sum of the other two
    if (!(principal[0] > 0) || principal[2] > principal[0] + principal[1] + 1e-9 * principal[2])
        m.at("tensor").fail(fmt::format(
            "the principal moments {:.6g}, {:.6g}, {:.6g} are not those of a body (each must be "
            "positive and at most the sum of the other two)",
            principal[0], principal[1], principal[2]));
}

}  // namespace

void read_sections(const YamlValue& v, Model& model) {
    const auto items = v.list("sections");
    if (items.empty())
        v.fail(
            "at least one section is required, e.g. - {elements: all, material: steel, "
            "thickness: 1.0}");
    model.element_section.assign(model.triangles.size(), -1);
    std::vector<std::pair<Index, YamlValue>> given_inertia;  // checked once every section is in
    for (const YamlValue& item : items) {
        const YamlMap m = item.map({"elements", "material", "thickness", "thickness_points",
                                    "thickness_rule", "inplane_points", "inertia"});
        const auto& elements =
            named_element_set(model, m.at("elements", "an element set name such as all"));
        Section s;
        s.material = named_material(model, m.at("material", "a material name"));
        if (model.materials[static_cast<std::size_t>(s.material)].plastic()) {
            s.thickness_points = 5;  // Lobatto: the surfaces yield first (theory.md §7.5)
            s.inplane_points = 3;    // docs/option-studies.md: 7 changes no tested row by > 0.4 %
        }
        const auto inertia = m.find("inertia");
        // the faces of a rigid solid have no thickness of their own (their contact has none)
        s.thickness = inertia ? m.at("thickness", "a number >= 0").non_negative()
                              : m.at("thickness", "a number > 0").positive();
        read_thickness_rule(m, s);
        if (inertia) read_rigid_inertia(*inertia, model, elements, s);
        if (const auto ip = m.find("inplane_points")) {
            const long long n = ip->integer(3, 7);
            if (n != 3 && n != 7)
                ip->fail("expected 3 or 7 in-plane integration points, got " + ip->describe());
            s.inplane_points = static_cast<int>(n);
        }
        const auto index = static_cast<Index>(model.sections.size());
        if (inertia) given_inertia.emplace_back(index, *inertia);
        model.sections.push_back(s);
        for (const Index e : elements) model.element_section[static_cast<std::size_t>(e)] = index;
    }
    const auto missing =
        std::find(model.element_section.begin(), model.element_section.end(), Index{-1});
    if (missing != model.element_section.end()) {
        const auto e = missing - model.element_section.begin();
        const auto n_missing = std::count(missing, model.element_section.end(), Index{-1});
        v.fail("element " + std::to_string(e + 1) + " (and " + std::to_string(n_missing - 1) +
               " more) has no section; every element needs one, e.g. start with an entry "
               "for `elements: all`");
    }
    for (const auto& [index, value] : given_inertia)  // eq. 6.11-9
        if (const auto problem = rigid_inertia_shares(model, index).problem)
            value.fail("the section's particles cannot carry its inertia: " + *problem);
    auto rigid = [&](Index s) {
        return model
            .materials[static_cast<std::size_t>(
                model.sections[static_cast<std::size_t>(s)].material)]
            .rigid;
    };
    if (!model.element_section.empty() &&
        std::all_of(model.element_section.begin(), model.element_section.end(), rigid))
        v.fail(
            "every element is in a section of a rigid material: nothing is left to deform or to "
            "set the time step; give at least one section a deformable material");
}

}  // namespace fpmshell
