// The outer faces of a part meshed with solids (LS-DYNA's *ELEMENT_SOLID: hexahedra, and the
// pentahedra and tetrahedra written as hexahedra with repeated nodes): the faces that belong to
// one solid only, oriented outward. A rigid part of solids is the body these faces enclose
// (theory.md §6.11).
#pragma once

#include <array>
#include <unordered_map>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct SolidElement {
    long long id = 0;
    long long part = 0;
    std::array<long long, 8> nodes{};  ///< N1..N8 (N5..N8 = N4 for a tetrahedron)
    int line = 0;
};

struct SolidFace {
    long long part = 0;
    long long solid = 0;           ///< the solid it bounds
    std::vector<long long> nodes;  ///< 3 or 4, counter-clockwise seen from outside
};

/// The faces of the solids that no other solid of the same part shares, in the solids' order,
/// each oriented outward (its normal away from its solid's centre). A degenerate face (fewer
/// than 3 distinct nodes) is no face.
[[nodiscard]] std::vector<SolidFace> outer_solid_faces(
    const std::vector<SolidElement>& solids, const std::unordered_map<long long, Vec3>& nodes);

}  // namespace fpmshell
