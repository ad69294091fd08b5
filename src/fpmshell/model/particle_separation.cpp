// The split of particles along open edges (theory.md §7.7).
#include "fpmshell/model/particle_separation.hpp"

#include <algorithm>
#include <numeric>

namespace fpmshell {

namespace {

/// The groups of the fan `fan` (the elements around particle p, ascending) joined through
/// their edges at p that are not open: each group ascending, in the order of its lowest element.
std::vector<std::vector<Index>> fan_groups(const std::vector<std::array<Index, 3>>& triangles,
                                           Index p, const std::vector<Index>& fan,
                                           const std::vector<MeshEdge>& open) {
    std::vector<std::size_t> root(fan.size());
    std::iota(root.begin(), root.end(), std::size_t{0});
    const auto find = [&](std::size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    // two elements of the fan that share another corner q share the edge p-q
    for (std::size_t i = 0; i < fan.size(); ++i)
        for (std::size_t j = i + 1; j < fan.size(); ++j)
            for (const Index q : triangles[static_cast<std::size_t>(fan[i])]) {
                if (q == p) continue;
                const auto& other = triangles[static_cast<std::size_t>(fan[j])];
                if (std::find(other.begin(), other.end(), q) == other.end()) continue;
                if (std::binary_search(open.begin(), open.end(), mesh_edge(p, q))) continue;
                const std::size_t a = find(i), b = find(j);
                root[std::max(a, b)] = std::min(a, b);  // the lower root: groups in fan order
            }
    std::vector<std::vector<Index>> groups;
    std::vector<std::size_t> group_of_root(fan.size(), fan.size());
    for (std::size_t i = 0; i < fan.size(); ++i) {
        const std::size_t r = find(i);
        if (group_of_root[r] == fan.size()) {
            group_of_root[r] = groups.size();
            groups.emplace_back();
        }
        groups[group_of_root[r]].push_back(fan[i]);
    }
    return groups;
}

}  // namespace

Separation separate_along_edges(const std::vector<std::array<Index, 3>>& triangles,
                                std::size_t n_particles, std::span<const MeshEdge> open) {
    Separation s;
    s.triangles = triangles;
    std::vector<MeshEdge> edges(open.begin(), open.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    if (edges.empty()) return s;
    // the particles at an open edge, and their fans (elements ascending)
    std::vector<Index> touched;
    for (const MeshEdge& e : edges) touched.insert(touched.end(), {e.a, e.b});
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    std::vector<std::vector<Index>> fans(touched.size());
    for (std::size_t e = 0; e < triangles.size(); ++e)
        for (const Index p : triangles[e]) {
            const auto it = std::lower_bound(touched.begin(), touched.end(), p);
            if (it != touched.end() && *it == p)
                fans[static_cast<std::size_t>(it - touched.begin())].push_back(
                    static_cast<Index>(e));
        }
    auto next = static_cast<Index>(n_particles);
    for (std::size_t t = 0; t < touched.size(); ++t) {
        const Index p = touched[t];
        std::vector<std::vector<Index>> groups = fan_groups(triangles, p, fans[t], edges);
        if (groups.size() < 2) continue;
        ParticleSplit split;
        split.parent = p;
        for (std::size_t g = 1; g < groups.size(); ++g) {
            split.children.push_back(next);
            s.parent_of_new.push_back(p);
            for (const Index e : groups[g])
                for (Index& corner : s.triangles[static_cast<std::size_t>(e)])
                    if (corner == p) corner = next;
            ++next;
        }
        split.groups = std::move(groups);
        s.splits.push_back(std::move(split));
    }
    return s;
}

std::vector<Real> split_exactly(Real whole, std::span<const Real> shares) {
    std::vector<Real> parts(shares.size() + 1, 0.0);
    Real rest = whole;
    for (std::size_t k = 0; k < shares.size(); ++k) {
        const Real share = std::clamp(shares[k], Real(0), rest);
        // Sterbenz: y - x is exact for x in [y/2, 2y]; the larger of the part and the rest is
        // rounded, the other is the exact difference
        Real part;
        if (share >= 0.5 * rest) {
            part = share;
        } else {
            const Real kept = rest - share;  // >= rest / 2
            part = rest - kept;
        }
        parts[k + 1] = part;
        rest -= part;  // exact
    }
    parts[0] = rest;
    return parts;
}

std::vector<MeshEdge> unsplit_edges(const std::vector<std::array<Index, 3>>& triangles,
                                    std::span<const ElementPair> sides) {
    std::vector<MeshEdge> edges;
    for (const auto& [e, f] : sides) {
        const auto& te = triangles[static_cast<std::size_t>(e)];
        const auto& tf = triangles[static_cast<std::size_t>(f)];
        std::array<Index, 2> shared{};
        std::size_t n = 0;
        for (const Index p : te)
            if (n < 2 && std::find(tf.begin(), tf.end(), p) != tf.end()) shared[n++] = p;
        if (n == 2) edges.push_back(mesh_edge(shared[0], shared[1]));
    }
    return edges;
}

}  // namespace fpmshell
