// The `materials` and `sections` blocks of the model file (see model_blocks.hpp).
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"
#include "fpmshell/materials/material_law.hpp"
#include "fpmshell/model/enclosed_solid.hpp"
#include "fpmshell/model/rigid_inertia_shares.hpp"

namespace fpmshell {
namespace {

/// A plastic material's `failure: {<criterion>: ..., points}` (theory.md §7.6): each
/// criterion of failure/failure_criteria.cpp reads its own value, after the material's law.
void read_failure(const YamlValue& v, Material& mat) {
    std::vector<std::string> keys;
    std::string names;
    for (const FailureCriterion& c : failure_criteria()) {
        keys.push_back(c.name);
        names += (names.empty() ? "" : " or ") + c.name;
    }
    keys.push_back("points");
    keys.push_back("fracture");
    keys.push_back("minimum_time_step");
    keys.push_back("layer_fraction");
    const YamlMap f = v.map(keys);
    for (const auto& [key, value] : f.entries())
        if (const FailureCriterion* c = find_failure_criterion(key))
            mat.failure.criteria.push_back({c->name, c->read(value, mat)});
    // an element erodes below this step, whatever its points (LS-DYNA's TDEL)
    mat.failure.minimum_time_step = f.positive_or("minimum_time_step", 0.0);
    if (!mat.failure.active())
        v.fail("names no failure criterion; give " + names +
               " or minimum_time_step, e.g. {plastic_strain: 0.3}");
    if (const auto n = f.find("points"))
        mat.failure.points = static_cast<int>(n->integer(1, 7 * k_max_thickness_points));
    if (const auto l = f.find("layer_fraction")) {  // LS-DYNA's NUMFIP < 0, as a fraction
        if (f.find("points")) l->fail("give points or layer_fraction, not both");
        mat.failure.layer_fraction = l->positive();
        if (mat.failure.layer_fraction > 1) l->fail("must be at most 1 (every layer)");
    }
    if (const auto kind = f.find("fracture")) {  // theory.md §7.7
        const std::string k = kind->name();
        if (k != "erode" && k != "separate")
            kind->fail("is '" + k +
                       "'; give erode (the failed elements erode) or separate (the "
                       "particles separate along the failed elements' edges)");
        mat.failure.separates = k == "separate";
    }
}

/// Where a key that `law` does not take belongs: the laws that take it, or "" if none does.
std::string owners_of(const std::string& key, const MaterialLaw& law) {
    std::vector<std::string> owners;
    bool all_plastic = true;
    for (const MaterialLaw& other : material_laws()) {
        const bool takes =
            std::find(other.keys.begin(), other.keys.end(), key) != other.keys.end() ||
            (other.plastic && key == "failure");
        if (!takes || other.name == law.name) continue;
        owners.push_back(other.name);
        all_plastic = all_plastic && other.plastic;
    }
    if (owners.empty()) return "";
    std::string list;
    for (std::size_t i = 0; i < owners.size(); ++i)
        list += (i == 0 ? "" : i + 1 == owners.size() ? " or " : ", ") + owners[i];
    return std::string("belongs to ") + (all_plastic ? "plastic materials" : "materials") +
           " (type: " + list + "), not to type " + law.name + "; remove it or change the type";
}

}  // namespace

// Each material's law (materials/material_laws.cpp) reads its own keys; the constants every
// law has are read here.
void read_materials(const YamlValue& v, Model& model) {
    const YamlMap all = v.open_map("material names to material definitions");
    if (all.entries().empty())
        v.fail(
            "at least one material is required, e.g. steel: {type: elastic, density: "
            "7.8e-9, youngs_modulus: 210000, poisson_ratio: 0.3}");
    std::vector<std::string> names;
    for (const MaterialLaw& law : material_laws()) names.push_back(law.name);
    for (const auto& [name, def] : all.entries()) {
        if (!def.is_map() && !def.is_null())
            def.fail(
                "expected a map of material constants such as {type: elastic, density: "
                "..., youngs_modulus: ..., poisson_ratio: ...}, got " +
                def.describe());
        const YamlMap any = def.open_map("material constants");
        const YamlValue type = any.at("type", "elastic");
        const MaterialLaw& law = *find_material_law(type.choice(names));
        std::vector<std::string> keys{"type", "density", "youngs_modulus", "poisson_ratio"};
        keys.insert(keys.end(), law.keys.begin(), law.keys.end());
        if (law.plastic) keys.push_back("failure");
        for (const auto& [key, value] : any.entries())
            if (std::find(keys.begin(), keys.end(), key) == keys.end())
                if (const std::string owners = owners_of(key, law); !owners.empty())
                    value.fail(owners);
        const YamlMap m = def.map(keys);
        Material mat;
        mat.name = name;
        mat.law = law.name;
        mat.plastic_law = law.plastic;
        mat.density = m.at("density", "a number > 0").positive();
        mat.youngs_modulus = m.at("youngs_modulus", "a number > 0").positive();
        const YamlValue nu = m.at("poisson_ratio", "a number in (-1, 0.5)");
        mat.poisson_ratio = nu.real();
        if (!(mat.poisson_ratio > -1 && mat.poisson_ratio < 0.5))
            nu.fail("must be greater than -1 and less than 0.5, got " + nu.describe());
        law.read(m, mat);
        if (law.plastic)
            if (const auto f = m.find("failure")) read_failure(*f, mat);
        model.materials.push_back(std::move(mat));
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
                                    "thickness_rule", "inplane_points", "inertia", "area_mass"});
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
        if (const auto nsm = m.find("area_mass")) {  // §6.1, LS-DYNA's MAREA
            s.area_mass = nsm->non_negative();
            if (inertia && s.area_mass > 0)
                nsm->fail("a section with a given inertia carries its whole mass in it");
        }
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
