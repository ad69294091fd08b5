// Name lookups of the model reader (see model_names.hpp).
#include "fpmshell/io/model_names.hpp"

#include <map>
#include <string>

namespace fpmshell {
namespace {

std::vector<std::string> names_of(const std::map<std::string, std::vector<Index>>& sets) {
    std::vector<std::string> names;
    for (const auto& [name, members] : sets) names.push_back(name);
    return names;
}

/// Index of the item of `items` (anything with a `name`) that v names; otherwise fails with
/// "unknown KIND 'x' (did you mean 'y'?)" followed by `listing` and the names there are.
template <class Named>
Index index_by_name(const std::vector<Named>& items, const YamlValue& v, const std::string& kind,
                    const std::string& listing) {
    const std::string name = v.name();
    std::vector<std::string> names;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].name == name) return static_cast<Index>(i);
        names.push_back(items[i].name);
    }
    v.fail("unknown " + kind + " '" + name + "'" + did_you_mean(name, names) + listing +
           join_names(names));
}

}  // namespace

const std::vector<Index>& named_node_set(const Model& model, const YamlValue& v) {
    const std::string name = v.name();
    const auto it = model.node_sets.find(name);
    if (it == model.node_sets.end()) {
        const auto names = names_of(model.node_sets);
        v.fail("unknown node set '" + name + "'" + did_you_mean(name, names) +
               "; the model defines the node sets " + join_names(names));
    }
    return it->second;
}

const std::vector<Index>& named_element_set(const Model& model, const YamlValue& v) {
    const std::string name = v.name();
    const auto it = model.element_sets.find(name);
    const auto names = names_of(model.element_sets);
    if (it == model.element_sets.end()) {
        if (model.node_sets.count(name) != 0)
            v.fail("'" + name +
                   "' is a node set, not an element set; the model defines the "
                   "element sets " +
                   join_names(names));
        v.fail("unknown element set '" + name + "'" + did_you_mean(name, names) +
               "; the model defines the element sets " + join_names(names));
    }
    if (it->second.empty())
        v.fail("the element set '" + name +
               "' contains no element (a near/plane set holds only the elements whose three "
               "nodes are all in it); use a box set or a mesh set");
    return it->second;
}

Index named_curve(const Model& model, const YamlValue& v) {
    if (model.curves.empty())
        v.fail("unknown curve '" + v.name() +
               "'; the model defines no curves (add them under `curves`)");
    return index_by_name(model.curves, v, "curve", "; the model defines the curves ");
}

Index optional_curve(const Model& model, const YamlMap& m) {
    const auto c = m.find("curve");
    return c ? named_curve(model, *c) : -1;
}

Index named_material(const Model& model, const YamlValue& v) {
    return index_by_name(model.materials, v, "material", "; the model defines the materials ");
}

Index named_rigid_body(const Model& model, const YamlValue& v) {
    if (model.rigid_bodies.empty()) v.fail("the model has no rigid_bodies; define the body first");
    return index_by_name(model.rigid_bodies, v, "rigid body", "; the bodies are ");
}

}  // namespace fpmshell
