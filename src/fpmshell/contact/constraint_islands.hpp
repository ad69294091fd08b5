// Islands of contact constraints (theory.md §8.3): the connected sets of constraints that share
// a particle or a movable rigid body. The projected Gauss-Seidel sweeps over one island never
// read or write what another island's sweeps touch, so each island is solved on its own, in the
// order of its constraints, on any thread, with bitwise the same result for any thread count.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class ConstraintIslands {
public:
    /// The nodes one constraint moves (particles 0..n_particles-1, movable bodies after them);
    /// unused entries are -1, the first is always set.
    using Nodes = std::array<Index, 5>;

    /// Partitions constraints 0..nodes.size()-1. Islands are numbered in the order of their
    /// first constraint and list their constraints in increasing order: the result depends on
    /// the constraints alone.
    void build(const std::vector<Nodes>& nodes, std::size_t n_nodes);

    [[nodiscard]] std::size_t count() const { return start_.empty() ? 0 : start_.size() - 1; }
    [[nodiscard]] std::span<const std::uint32_t> members(std::size_t island) const {
        return {members_.data() + start_[island],
                static_cast<std::size_t>(start_[island + 1] - start_[island])};
    }
    /// The islands from the largest to the smallest (ties by number): the order to hand them to
    /// threads in, so that a large island does not start last.
    [[nodiscard]] const std::vector<std::uint32_t>& largest_first() const { return by_size_; }

private:
    Index find(Index node);

    std::vector<Index> parent_;          ///< union-find forest over the nodes, -1 untouched
    std::vector<std::int64_t> label_;    ///< island of a root node, -1 none yet
    std::vector<Index> touched_;         ///< nodes set in parent_ (reset after each build)
    std::vector<std::uint32_t> island_;  ///< island of each constraint
    std::vector<std::uint32_t> start_;   ///< CSR offsets, count() + 1
    std::vector<std::uint32_t> members_;
    std::vector<std::uint32_t> by_size_;
};

}  // namespace fpmshell
