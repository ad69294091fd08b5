#include "fpmshell/model/separated_model.hpp"

#include <algorithm>

namespace fpmshell {
namespace {

/// `nodes` (sorted or not) with the new particles of each listed parent added, sorted where it
/// was.
void add_children(std::vector<Index>& nodes, const std::vector<std::vector<Index>>& children_of) {
    const bool sorted = std::is_sorted(nodes.begin(), nodes.end());
    const std::size_t n = nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto p = static_cast<std::size_t>(nodes[i]);
        if (p < children_of.size())
            nodes.insert(nodes.end(), children_of[p].begin(), children_of[p].end());
    }
    if (sorted) std::sort(nodes.begin(), nodes.end());
}

}  // namespace

Model separated_model(const Model& model, const Separation& separation) {
    Model m = model;
    m.triangles = separation.triangles;
    std::vector<std::vector<Index>> children_of(model.nodes.size());
    for (const ParticleSplit& s : separation.splits)
        children_of[static_cast<std::size_t>(s.parent)] = s.children;
    if (m.separated_from.empty())
        for (Index p = 0; p < model.n_particles(); ++p) m.separated_from.push_back(p);
    for (const Index parent : separation.parent_of_new) {
        m.nodes.push_back(model.nodes[static_cast<std::size_t>(parent)]);
        m.separated_from.push_back(m.separated_from[static_cast<std::size_t>(parent)]);
    }
    for (auto& [name, nodes] : m.node_sets) add_children(nodes, children_of);
    for (BoundaryCondition& bc : m.boundary) add_children(bc.nodes, children_of);
    for (Load& load : m.loads)
        if (load.type == LoadType::Gravity) add_children(load.nodes, children_of);
    for (ContactDefinition& c : m.contacts) add_children(c.nodes, children_of);
    return m;
}

Model replay_separations(const Model& model, const SeparationHistory& history) {
    Model m = model;
    for (const std::uint64_t opened : history.splits) {
        const std::span<const ElementPair> sides(history.opened.data(),
                                                 static_cast<std::size_t>(opened));
        m = separated_model(m, separate_along_edges(m.triangles, m.nodes.size(),
                                                    unsplit_edges(m.triangles, sides)));
    }
    return m;
}

}  // namespace fpmshell
