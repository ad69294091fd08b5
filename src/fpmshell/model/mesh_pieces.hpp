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
/// of no triangle is a piece alone). `separated_from` (Model::separated_from; empty: none)
/// joins each particle to the one it was split from: the pieces of the mesh before its cracks
/// (theory.md §7.7), whose faces start together.
[[nodiscard]] inline std::vector<Index> mesh_pieces(
    std::size_t n_particles, const std::vector<std::array<Index, 3>>& triangles,
    const std::vector<Index>& separated_from = {}) {
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
    const auto join = [&](Index p, Index q) {
        const Index a = find(p), b = find(q);
        if (a != b) root[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    };
    for (const auto& t : triangles)
        for (std::size_t k = 1; k < 3; ++k) join(t[0], t[k]);
    for (std::size_t p = 0; p < separated_from.size(); ++p)
        join(static_cast<Index>(p), separated_from[p]);
    for (std::size_t p = 0; p < n_particles; ++p) root[p] = find(static_cast<Index>(p));
    return root;
}

}  // namespace fpmshell
