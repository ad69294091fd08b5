// The block path of the J2 laws (solver/block_point_loads.hpp): their elements k_lanes at a
// time.
#pragma once

#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/solver/block_point_loads.hpp"

namespace fpmshell {

/// A J2 section (§7.3): the trial check on every point of the block at once, and the return
/// mapping on the yielding (point, lane) pairs, k_lanes pairs at a time.
[[nodiscard]] ElasticTriangleLoads<RealPack> block_point_loads(const J2Plastic& material,
                                                               const BlockStep& step);

}  // namespace fpmshell
