// The connected pieces of a mesh: particles joined through the triangles they share a piece
// (a part welded or tied to another is still a piece of its own: constraints are not mesh).
// The self-contact's exclusion (theory.md §8.1, R8) holds only within a piece.
#pragma once

#include <array>
#include <numeric>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Per particle, the index of its piece: the smallest particle index of the piece (a particle
/// of no triangle is a piece alone).
[[nodiscard]] inline std::vector<Index> mesh_pieces(
    std::size_t n_particles, const std::vector<std::array<Index, 3>>& triangles) {
    std::vector<Index> root(n_particles);
    std::iota(root.begin(), root.end(), Index{0});
    auto find = [&](Index p) {
        while (root[static_cast<std::size_t>(p)] != p) {  // path halving
            Index& r = root[static_cast<std::size_t>(p)];
            r = root[static_cast<std::size_t>(r)];
            p = r;
        }
        return p;
    };
    for (const auto& t : triangles)
        for (std::size_t k = 1; k < 3; ++k) {
            const Index a = find(t[0]), b = find(t[k]);
            if (a != b) root[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    for (std::size_t p = 0; p < n_particles; ++p) root[p] = find(static_cast<Index>(p));
    return root;
}

}  // namespace fpmshell
