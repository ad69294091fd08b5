// The mass properties of the solid a closed triangulated surface encloses (theory.md §6.11,
// eq. 6.11-8): a rigid part meshed with solids is its outer faces, and its body's mass, centre
// and inertia are those of the solid inside them, by the divergence theorem over the faces.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// Why the faces do not close a solid, if they do not: an edge that is not shared by exactly two
/// of them running opposite ways (the faces of a solid, oriented outward, meet so). Indices in
/// `faces` are particles; the message names them 1-based.
[[nodiscard]] std::optional<std::string> open_surface_edge(
    const std::vector<std::array<Index, 3>>& faces);

/// Mass, centre and inertia tensor about the centre of the solid of `density` the closed faces
/// enclose (eq. 6.11-8): the sum over the tetrahedra spanned by each face and a reference point.
/// Faces oriented inward give the same solid (the sign of the volume is taken off).
[[nodiscard]] RigidInertia enclosed_solid_inertia(const std::vector<std::array<Index, 3>>& faces,
                                                  const std::vector<Vec3>& nodes, Real density);

}  // namespace fpmshell
