// The named things of a model being read (sets, curves, materials, rigid bodies), looked up by
// the name a YAML value gives. An unknown name fails at that value with the names the model
// defines and, for a near miss, a "did you mean".
#pragma once

#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// Members of the node set that v names.
[[nodiscard]] const std::vector<Index>& named_node_set(const Model& model, const YamlValue& v);

/// Members of the element set that v names; a node set or an empty element set fails.
[[nodiscard]] const std::vector<Index>& named_element_set(const Model& model, const YamlValue& v);

/// Index in model.curves of the curve that v names.
[[nodiscard]] Index named_curve(const Model& model, const YamlValue& v);

/// Index of the curve under the key `curve` of m, -1 without one.
[[nodiscard]] Index optional_curve(const Model& model, const YamlMap& m);

/// Index in model.materials of the material that v names.
[[nodiscard]] Index named_material(const Model& model, const YamlValue& v);

/// Index in model.rigid_bodies of the rigid body that v names (contact bodies,
/// control.end_when_body_stops).
[[nodiscard]] Index named_rigid_body(const Model& model, const YamlValue& v);

}  // namespace fpmshell
