#include "fpmshell/contact/constraint_islands.hpp"

#include <algorithm>

namespace fpmshell {

Index ConstraintIslands::find(Index node) {
    auto u = static_cast<std::size_t>(node);
    while (parent_[u] != static_cast<Index>(u)) {
        const auto up = static_cast<std::size_t>(parent_[u]);
        parent_[u] = parent_[up];  // path halving
        u = static_cast<std::size_t>(parent_[u]);
    }
    return static_cast<Index>(u);
}

void ConstraintIslands::build(const std::vector<Nodes>& nodes, std::size_t n_nodes) {
    if (parent_.size() < n_nodes) {
        parent_.resize(n_nodes, -1);
        label_.resize(n_nodes, -1);
    }
    const std::size_t n = nodes.size();
    for (const Nodes& c : nodes) {
        Index root = -1;
        for (Index v : c) {
            if (v < 0) continue;
            const auto uv = static_cast<std::size_t>(v);
            if (parent_[uv] < 0) {
                parent_[uv] = v;
                touched_.push_back(v);
            }
            const Index r = find(v);
            if (root < 0) {
                root = r;
            } else if (r != root) {
                // the smaller index is the root: the forest depends on the constraints alone
                const Index lo = std::min(r, root), hi = std::max(r, root);
                parent_[static_cast<std::size_t>(hi)] = lo;
                root = lo;
            }
        }
    }
    island_.resize(n);
    std::uint32_t n_islands = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const auto root = static_cast<std::size_t>(find(nodes[k][0]));
        if (label_[root] < 0) label_[root] = n_islands++;
        island_[k] = static_cast<std::uint32_t>(label_[root]);
    }
    // Counting sort of the constraints by island, stable: each island keeps their order.
    start_.assign(n_islands + 1, 0);
    for (std::uint32_t i : island_) ++start_[i + 1];
    for (std::uint32_t i = 0; i < n_islands; ++i) start_[i + 1] += start_[i];
    members_.resize(n);
    by_size_.assign(start_.begin(), start_.end() - 1);  // fill positions, reused below
    for (std::size_t k = 0; k < n; ++k)
        members_[by_size_[island_[k]]++] = static_cast<std::uint32_t>(k);
    by_size_.resize(n_islands);
    for (std::uint32_t i = 0; i < n_islands; ++i) by_size_[i] = i;
    std::stable_sort(by_size_.begin(), by_size_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return start_[a + 1] - start_[a] > start_[b + 1] - start_[b];
    });
    for (Index v : touched_) {
        parent_[static_cast<std::size_t>(v)] = -1;
        label_[static_cast<std::size_t>(v)] = -1;
    }
    touched_.clear();
}

}  // namespace fpmshell
