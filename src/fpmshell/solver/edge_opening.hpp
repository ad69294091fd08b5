// The edge criterion of fracture by particle separation (theory.md §7.7, eq. 7.7-1): which
// edge a failed element opens. An element of a material with `fracture: separate` fails as an
// eroding one would (its criteria and points, §7.6) but keeps acting; it then opens one of its
// sides, the one across which its membrane force pulls hardest, among the sides it shares with
// another element that reach the crack (an end on a free side: the mesh's boundary or a side
// already open) or whose other element has failed too (the crack's start inside a sheet). An
// element is never cut out of the sheet: it borders two open sides at most (the crack turning
// through its corner) and keeps a closed side. An element
// with no candidate in tension waits for the crack to reach it; one that borders an open side
// has done its part. The sides the failed elements of a step choose open in the order of their
// tractions, largest first, each only where its two elements may still open it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/particle_separation.hpp"

namespace fpmshell {

class EdgeOpening {
public:
    EdgeOpening() = default;
    explicit EdgeOpening(Index n_elements) : open_count_(static_cast<std::size_t>(n_elements), 0) {}

    /// What the criterion reads of the mesh now.
    struct Mesh {
        const std::vector<std::array<Index, 3>>& triangles;
        const MeshTopology& topology;
        const std::vector<Vec3>& x;  ///< the positions of the element loop's step, x^n
        /// per particle, 1 where it never splits (the particles of nodal rigid bodies, spot
        /// welds and ties, whose constraints hold one particle)
        const std::vector<std::uint8_t>& pinned;
        /// whether element e has failed (every rank's failed elements)
        const std::function<bool(Index)>& failed;
    };
    /// Eq. 7.7-1 for failed element e with membrane force `n` (its local frame: corner 0 at the
    /// origin, corner 1 on x): the element across the side it would open and the normal
    /// membrane force across that side; across -1 where it waits.
    struct Choice {
        Index across = -1;
        Real traction = 0;
    };
    [[nodiscard]] Choice side_to_open(const Mesh& mesh, Index e, const Voigt3& n) const;
    /// The sides of `choices` (records [element, across, traction], every rank's) that open: by
    /// traction, largest first (then element pair), each where neither element borders an
    /// open side yet. Adds them and returns them.
    std::vector<ElementPair> open_chosen(const Mesh& mesh, std::vector<Real> choices);
    /// The open sides element e borders.
    [[nodiscard]] int open_sides_of(Index e) const {
        return open_count_[static_cast<std::size_t>(e)];
    }

    /// The sides opened so far, sorted.
    [[nodiscard]] const std::vector<ElementPair>& open() const { return open_; }
    [[nodiscard]] bool is_open(Index e, Index f) const;
    /// Adds sides (any order; repeats allowed).
    void add(const std::vector<ElementPair>& sides);

private:
    /// Whether particle p has a free side: one of its elements' sides at p on the boundary or
    /// open.
    [[nodiscard]] bool on_free_side(const Mesh& mesh, Index p) const;
    /// Whether element e may open one more side: it borders one open side at most (a second
    /// meets the first at a corner: the crack turning through e) and keeps a closed side
    /// shared with another element after it: no element is ever cut out of the sheet.
    [[nodiscard]] bool may_open(const Mesh& mesh, Index e) const;
    /// The sides element e shares with another element that are not open.
    [[nodiscard]] int closed_sides(const Mesh& mesh, Index e) const;

    std::vector<ElementPair> open_;
    std::vector<std::uint8_t> open_count_;  ///< per element, the open sides it borders
};

}  // namespace fpmshell
