// Fracture by particle separation (theory.md §7.7): the mesh separates along element edges
// that have opened. A particle whose fan of elements the open edges cut into two or more groups
// (the elements joined through its closed edges) becomes one particle per group: the group of
// its lowest element keeps it, each other group takes a new particle. Nothing is deleted: the
// elements stay, their corners renumbered, and the mass is split exactly.
//
// This is the topology of a split; the solver's use of it (when edges open, how its arrays
// follow) is its own concern.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// An edge between two particles, a < b.
struct MeshEdge {
    Index a = 0, b = 0;
    friend bool operator==(const MeshEdge&, const MeshEdge&) = default;
    friend auto operator<=>(const MeshEdge&, const MeshEdge&) = default;
};
[[nodiscard]] inline MeshEdge mesh_edge(Index p, Index q) {
    return p < q ? MeshEdge{p, q} : MeshEdge{q, p};
}

/// An open side, as the two elements that shared it (first < second): the same pair whatever
/// the particles' numbering after splits.
using ElementPair = std::pair<Index, Index>;

/// The sides of `sides` whose two elements still share two particles of `triangles`, as
/// MeshEdges (those already apart drop out).
[[nodiscard]] std::vector<MeshEdge> unsplit_edges(
    const std::vector<std::array<Index, 3>>& triangles, std::span<const ElementPair> sides);

/// What a run's separations were: the sides in the order they opened, and for each
/// separation the number of sides opened before it (a restart file's record, from which
/// replay_separations makes the run's mesh again).
struct SeparationHistory {
    std::vector<ElementPair> opened;
    std::vector<std::uint64_t> splits;
};

/// One particle split: `parent` keeps the elements of its first group, and new particle
/// `children[k]` takes group k + 1 (each group's elements ascending, the groups in the order
/// of their lowest element).
struct ParticleSplit {
    Index parent = 0;
    std::vector<Index> children;
    std::vector<std::vector<Index>> groups;  ///< groups[0] the parent's
};

struct Separation {
    /// The triangles with the corners of the split particles renumbered.
    std::vector<std::array<Index, 3>> triangles;
    /// The particles split, ascending in parent; the new particles numbered from n_particles
    /// on in that order (a split's children consecutive).
    std::vector<ParticleSplit> splits;
    /// Per new particle (n_particles + k), its parent.
    std::vector<Index> parent_of_new;
};

/// The split of the mesh `triangles` (over n_particles particles) along `open` edges (any
/// order, repeats allowed; an edge of no two elements, or already apart, changes nothing).
/// Deterministic: the result depends on the mesh and the set of open edges alone.
[[nodiscard]] Separation separate_along_edges(const std::vector<std::array<Index, 3>>& triangles,
                                              std::size_t n_particles,
                                              std::span<const MeshEdge> open);

/// `whole` (a particle's mass or rotary inertia) cut into its groups' parts: part k + 1 is close
/// to shares[k] (group k + 1's share, for k < shares.size()), part 0 the rest; the parts add up
/// to `whole` exactly (in real numbers: each cut is exact by Sterbenz's lemma), so that an
/// exact sum over the particles keeps its bits. Shares must be >= 0 and sum to at most whole
/// (up to rounding; a part is never negative).
[[nodiscard]] std::vector<Real> split_exactly(Real whole, std::span<const Real> shares);

}  // namespace fpmshell
