// Thickness of a particle: the mean thickness of the triangles around it (contact offsets,
// theory.md §8.2). Shared by the model reader (initial-penetration check) and the contact.
#pragma once

#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// element_thickness: one value per triangle. Particles on no triangle get 0.
[[nodiscard]] inline std::vector<Real> mean_node_thickness(
    const std::vector<std::array<Index, 3>>& triangles, const std::vector<Real>& element_thickness,
    std::size_t n_nodes) {
    std::vector<Real> h(n_nodes, 0.0);
    std::vector<int> count(n_nodes, 0);
    for (std::size_t e = 0; e < triangles.size(); ++e)
        for (const Index p : triangles[e]) {
            h[static_cast<std::size_t>(p)] += element_thickness[e];
            ++count[static_cast<std::size_t>(p)];
        }
    for (std::size_t p = 0; p < n_nodes; ++p)
        if (count[p] > 0) h[p] /= count[p];
    return h;
}

}  // namespace fpmshell
