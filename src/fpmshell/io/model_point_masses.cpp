// `masses` and the sections' `area_mass` (model-format.md; theory.md §6.1): masses lumped on
// particles as Model::point_masses. On nodes: each gains `mass`, or they share `total` equally
// (LS-DYNA's *ELEMENT_MASS, _NODE_SET). On elements: `total`, or what `final` leaves above the
// elements' own mass, spread by area (*ELEMENT_MASS_PART's area-weighted distribution), a third
// of each element's share on each corner; a section's mass per unit area likewise (MAREA).
#include <fmt/format.h>

#include "fpmshell/io/model_blocks.hpp"
#include "fpmshell/io/model_names.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

Real element_area(const Model& model, Index e) {
    const auto& t = model.triangles[static_cast<std::size_t>(e)];
    const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
    const Vec3& b = model.nodes[static_cast<std::size_t>(t[1])];
    const Vec3& c = model.nodes[static_cast<std::size_t>(t[2])];
    return 0.5 * (b - a).cross(c - a).norm();
}

/// The elements' own mass: their sections' density x thickness plus area mass, times area.
Real own_mass(const Model& model, const std::vector<Index>& elements) {
    Real mass = 0;
    for (const Index e : elements) {
        const Section& s = model.sections[static_cast<std::size_t>(
            model.element_section[static_cast<std::size_t>(e)])];
        const Real density = model.materials[static_cast<std::size_t>(s.material)].density;
        mass += (density * s.thickness + s.area_mass) * element_area(model, e);
    }
    return mass;
}

/// `mass_per_area` on `elements`: a third of each element's share on each of its corners, in
/// element order.
PointMass by_area(const Model& model, const std::vector<Index>& elements, Real mass_per_area) {
    PointMass pm;
    for (const Index e : elements) {
        const Real corner = mass_per_area * element_area(model, e) / 3.0;
        for (const Index p : model.triangles[static_cast<std::size_t>(e)]) {
            pm.nodes.push_back(p);
            pm.masses.push_back(corner);
        }
    }
    return pm;
}

}  // namespace

void add_area_masses(Model& model) {
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        if (!(model.sections[s].area_mass > 0)) continue;
        std::vector<Index> elements;
        for (std::size_t e = 0; e < model.element_section.size(); ++e)
            if (model.element_section[e] == static_cast<Index>(s))
                elements.push_back(static_cast<Index>(e));
        model.point_masses.push_back(by_area(model, elements, model.sections[s].area_mass));
    }
}

void read_point_masses(const YamlValue& v, Model& model) {
    for (const YamlValue& item : v.list("point masses")) {
        const YamlMap m = item.map({"nodes", "elements", "mass", "total", "final"});
        if (m.count({"nodes", "elements"}) != 1)
            item.fail(
                "a mass needs exactly one of `nodes` (a node set: point masses) and `elements` "
                "(an element set: a mass spread by area)");
        if (const auto nodes = m.find("nodes")) {
            PointMass pm;
            pm.nodes = named_node_set(model, *nodes);
            if (pm.nodes.empty()) nodes->fail("the set has no particles to carry the mass");
            if (m.count({"mass", "total"}) != 1 || m.count({"final"}) != 0)
                item.fail(
                    "a mass on nodes needs exactly one of `mass` (each particle of the set gains "
                    "it) and `total` (shared equally by the set's particles)");
            const Real each =
                m.find("mass") ? m.at("mass", "").positive()
                               : m.at("total", "").positive() / static_cast<Real>(pm.nodes.size());
            pm.masses.assign(pm.nodes.size(), each);
            model.point_masses.push_back(std::move(pm));
            continue;
        }
        const YamlValue elements = m.at("elements", "");
        const std::vector<Index>& set = named_element_set(model, elements);
        Real area = 0;
        for (const Index e : set) area += element_area(model, e);
        if (!(area > 0)) elements.fail("the set has no area to spread the mass over");
        if (m.count({"total", "final"}) != 1 || m.count({"mass"}) != 0)
            item.fail(
                "a mass on elements needs exactly one of `total` (the mass added, spread by area) "
                "and `final` (the elements' mass once it is added)");
        Real added = 0;
        if (m.find("total")) {
            added = m.at("total", "").positive();
        } else {
            const YamlValue final_value = m.at("final", "");
            const Real own = own_mass(model, set);
            added = final_value.positive() - own;
            if (added < 0)
                final_value.fail(fmt::format(
                    "the elements already weigh {:.6g}, more than the final mass", own));
        }
        model.point_masses.push_back(by_area(model, set, added / area));
    }
}

}  // namespace fpmshell
