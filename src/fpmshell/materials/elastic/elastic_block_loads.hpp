// The block path of the linear elastic law (solver/block_point_loads.hpp): its elements
// k_lanes at a time.
#pragma once

#include <array>

#include "fpmshell/materials/elastic/linear_elastic.hpp"
#include "fpmshell/solver/block_point_loads.hpp"

namespace fpmshell {

/// A linear elastic section: the state is the stress (§3.2).
[[nodiscard]] inline ElasticTriangleLoads<RealPack> block_point_loads(
    const LinearElastic& /*material*/, const BlockStep& step) {
    using namespace block_points_detail;
    prefetch_fields(step, 0, 3);
    std::array<RealPack, 3 * k_max_block_points> stress;
    for (std::size_t p = 0; p < step.n_points; ++p)
        for (std::size_t r = 0; r < 3; ++r) stress[3 * p + r] = step.state[r * step.n_points + p];
    const ElasticTriangleLoads<RealPack> loads = elastic_triangle_loads(
        *step.motion, *step.constants, step.thickness, stress.data(), step.viscous_rate);
    store_stress(step, loads.valid, stress.data(), 0);
    return loads;
}

}  // namespace fpmshell
