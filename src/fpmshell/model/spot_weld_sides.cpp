// The sides of each spot weld in its rigid body: a breadth-first search of the body's graph with
// the weld's link cut (theory.md eq. 6.11-13).
#include "fpmshell/model/spot_weld_sides.hpp"

#include <algorithm>
#include <iterator>

#include "fpmshell/model/rigid_body_partition.hpp"

namespace fpmshell {

namespace {

/// The graph of the groups as links between particles (each group a star about its first
/// particle), in compressed rows; the link's group is kept so that one can be cut.
struct GroupGraph {
    std::vector<std::size_t> start;  ///< per particle, its first link; one past the last
    std::vector<Index> other;        ///< per link, the particle it reaches
    std::vector<std::size_t> group;  ///< per link, its group
};

GroupGraph group_graph(std::size_t n_particles, const std::vector<RigidGroup>& groups) {
    GroupGraph g;
    g.start.assign(n_particles + 1, 0);
    for (const RigidGroup& group : groups)
        for (std::size_t k = 1; k < group.nodes.size(); ++k) {
            ++g.start[static_cast<std::size_t>(group.nodes[0]) + 1];
            ++g.start[static_cast<std::size_t>(group.nodes[k]) + 1];
        }
    for (std::size_t p = 0; p < n_particles; ++p) g.start[p + 1] += g.start[p];
    g.other.resize(g.start.back());
    g.group.resize(g.start.back());
    std::vector<std::size_t> next(g.start.begin(), g.start.end() - 1);
    for (std::size_t i = 0; i < groups.size(); ++i) {
        const std::vector<Index>& nodes = groups[i].nodes;
        for (std::size_t k = 1; k < nodes.size(); ++k) {
            const auto a = static_cast<std::size_t>(nodes[0]),
                       b = static_cast<std::size_t>(nodes[k]);
            g.other[next[a]] = nodes[k];
            g.group[next[a]++] = i;
            g.other[next[b]] = nodes[0];
            g.group[next[b]++] = i;
        }
    }
    return g;
}

/// The particles reached from `from` without the links of group `cut`, ascending.
std::vector<Index> reached(const GroupGraph& g, Index from, std::size_t cut,
                           std::vector<std::uint8_t>& seen) {
    std::vector<Index> out{from};
    seen[static_cast<std::size_t>(from)] = 1;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const auto p = static_cast<std::size_t>(out[i]);
        for (std::size_t l = g.start[p]; l < g.start[p + 1]; ++l) {
            const auto q = static_cast<std::size_t>(g.other[l]);
            if (g.group[l] == cut || seen[q]) continue;
            seen[q] = 1;
            out.push_back(g.other[l]);
        }
    }
    for (const Index p : out) seen[static_cast<std::size_t>(p)] = 0;
    std::sort(out.begin(), out.end());
    return out;
}

/// The sides of group `cut`, a generalized weld of `nodes` (entry `entry`): each particle's side
/// with the group cut, which must hold none of the group's other particles, and at most one of
/// which may hold a rigid material's particle (its force is then the others' negative sum).
template <class HoldsRigid>
SpotWeldSide generalized_weld(const GroupGraph& graph, std::size_t cut, std::size_t entry,
                              const std::vector<Index>& nodes, std::vector<std::uint8_t>& seen,
                              const HoldsRigid& holds_rigid_material,
                              std::optional<std::pair<std::size_t, std::string>>& problem) {
    SpotWeldSide w;
    w.entry = entry;
    std::vector<Index> sorted_nodes = nodes;
    std::sort(sorted_nodes.begin(), sorted_nodes.end());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        std::vector<Index> side = reached(graph, nodes[k], cut, seen);
        std::vector<Index> shared;
        std::set_intersection(side.begin(), side.end(), sorted_nodes.begin(), sorted_nodes.end(),
                              std::back_inserter(shared));
        if (shared.size() > 1) {
            problem = {entry,
                       "the generalized weld's particles are joined also through other "
                       "constraints or rigid parts, so the forces it carries are not "
                       "determined: a weld that can fail must be their only link"};
            return w;
        }
        if (holds_rigid_material(side)) {
            if (w.derived >= 0) {
                problem = {entry,
                           "two of the generalized weld's particles are joined to rigid parts, "
                           "whose reactions leave the forces it carries undetermined"};
                return w;
            }
            w.derived = static_cast<std::ptrdiff_t>(k);
        }
        w.node_sides.push_back(std::move(side));
    }
    return w;
}

}  // namespace

SpotWeldSides spot_weld_sides(const Model& model, const std::vector<std::uint8_t>& let_go) {
    SpotWeldSides out;
    bool any = false;
    for (std::size_t e = 0; e < model.nodal_rigid_bodies.size(); ++e)
        any = any || (model.nodal_rigid_bodies[e].can_fail() && (let_go.empty() || !let_go[e]));
    if (!any) return out;
    const std::vector<RigidGroup> groups = rigid_groups(model, let_go);
    const GroupGraph graph = group_graph(model.nodes.size(), groups);
    std::vector<std::uint8_t> rigid_material(model.nodes.size(), 0), seen(model.nodes.size(), 0);
    for (const RigidGroup& group : groups)
        if (group.entry < 0)
            for (const Index p : group.nodes) rigid_material[static_cast<std::size_t>(p)] = 1;
    const auto holds_rigid_material = [&](const std::vector<Index>& side) {
        return std::any_of(side.begin(), side.end(),
                           [&](Index p) { return rigid_material[static_cast<std::size_t>(p)]; });
    };
    for (std::size_t i = 0; i < groups.size(); ++i) {
        if (groups[i].entry < 0) continue;
        const auto entry = static_cast<std::size_t>(groups[i].entry);
        if (!model.nodal_rigid_bodies[entry].can_fail()) continue;
        const std::vector<Index>& nodes = groups[i].nodes;
        if (nodes.size() > 2) {
            out.welds.push_back(
                generalized_weld(graph, i, entry, nodes, seen, holds_rigid_material, out.problem));
            if (out.problem) return out;
            continue;
        }
        const Index a = nodes[0], b = nodes[1];
        std::vector<Index> side_a = reached(graph, a, i, seen);
        if (std::binary_search(side_a.begin(), side_a.end(), b)) {
            out.problem = {entry,
                           "the spot weld's two particles are joined also through other "
                           "constraints or rigid parts, so the force it carries is not "
                           "determined: a weld that can fail must be their only link"};
            return out;
        }
        std::vector<Index> side_b = reached(graph, b, i, seen);
        const bool rigid_a = holds_rigid_material(side_a), rigid_b = holds_rigid_material(side_b);
        const bool use_b =
            (rigid_a && !rigid_b) || (rigid_a == rigid_b && side_b.size() < side_a.size());
        out.welds.push_back(
            {entry, use_b ? std::move(side_b) : std::move(side_a), use_b ? Real(-1) : Real(1)});
    }
    return out;
}

}  // namespace fpmshell
