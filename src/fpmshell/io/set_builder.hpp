// Geometric node and element sets (model-format.md `sets`): near a point, on a plane, in a box.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/mesh/mesh_data.hpp"

namespace fpmshell {

/// Length of the diagonal of the bounding box of `nodes` (0 for no node).
[[nodiscard]] Real model_size(const std::vector<Vec3>& nodes);

/// Nodes within `tolerance` of `point`; without a tolerance the single closest node (the lowest
/// index on a tie). Sorted.
[[nodiscard]] std::vector<Index> nodes_near(const std::vector<Vec3>& nodes, const Vec3& point,
                                            std::optional<Real> tolerance);

/// Nodes at distance <= tolerance from the plane through `point` with normal `normal`
/// (any length > 0). Sorted.
[[nodiscard]] std::vector<Index> nodes_on_plane(const std::vector<Vec3>& nodes, const Vec3& point,
                                                const Vec3& normal, Real tolerance);

/// Nodes inside the box [lo - tolerance, hi + tolerance] (bounds included). Sorted.
[[nodiscard]] std::vector<Index> nodes_in_box(const std::vector<Vec3>& nodes, const Vec3& lo,
                                              const Vec3& hi, Real tolerance);

/// Elements whose three nodes all belong to the sorted `node_set`. Sorted.
[[nodiscard]] std::vector<Index> elements_within(const std::vector<std::array<Index, 3>>& triangles,
                                                 const std::vector<Index>& node_set,
                                                 std::size_t n_nodes);

/// Elements whose centroid is inside [lo - tolerance, hi + tolerance]. Sorted.
[[nodiscard]] std::vector<Index> elements_in_box(const std::vector<Vec3>& nodes,
                                                 const std::vector<std::array<Index, 3>>& triangles,
                                                 const Vec3& lo, const Vec3& hi, Real tolerance);

/// Reads the `sets` map and adds each set to mesh.node_sets and mesh.element_sets. Each entry
/// has exactly one of `near: [x,y,z]`, `plane: {point, normal}`, `box: [[lo], [hi]]`, and an
/// optional `tolerance` (near: none = the single closest node; plane: default 1e-6 x model size;
/// box: default 1e-9 x model size, widening the box). The element set of a box holds the
/// elements whose centroid is inside; that of near/plane the elements whose three nodes are in
/// the node set (possibly none). An empty node set, a name already used by the mesh, or the
/// name `all` is an InputError.
void add_user_sets(const YamlValue& sets, MeshData& mesh);

}  // namespace fpmshell
