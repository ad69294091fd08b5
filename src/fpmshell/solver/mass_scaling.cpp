#include "fpmshell/solver/mass_scaling.hpp"

#include <numeric>

namespace fpmshell {

Real AddedMass::total_added() const { return std::accumulate(added.begin(), added.end(), 0.0); }

Real AddedMass::total_physical() const {
    return std::accumulate(physical.begin(), physical.end(), 0.0);
}

std::vector<Index> AddedMass::over_limit(const Model& model) const {
    std::vector<Index> over;
    for (std::size_t s = 0; s < added.size(); ++s)
        if (added[s] > model.control.mass_scaling.added_mass_limit * physical[s])
            over.push_back(static_cast<Index>(s));
    return over;
}

AddedMass apply_mass_scaling(const Model& model, MeshTopology& topology, ElementTimeSteps& steps) {
    AddedMass out;
    out.added.assign(model.sections.size(), 0.0);
    out.physical.assign(model.sections.size(), 0.0);
    const std::size_t ne = model.triangles.size();
    // each element carries 3 node shares (§6.1)
    for (std::size_t e = 0; e < ne; ++e)
        out.physical[static_cast<std::size_t>(model.element_section[e])] +=
            3.0 * topology.element_node_mass[e];
    const Real target = model.control.mass_scaling.time_step;
    if (!(target > 0)) return out;
    const std::vector<Real> factor = steps.mass_scaling_factors(
        target / model.control.time_step_scale, model.triangles, model.nodes);
    for (std::size_t e = 0; e < ne; ++e)
        out.added[static_cast<std::size_t>(model.element_section[e])] +=
            3.0 * topology.element_node_mass[e] * (factor[e] - 1.0);
    topology.scale_element_masses(factor);
    steps.scale_masses(factor);
    return out;
}

}  // namespace fpmshell
