// The SIMD block kernel (elements/elastic_triangle_block.hpp) run on one block of k_lanes
// elements of a section, with the point state of the section's material: one overload of
// block_point_loads per material that has a block path, in the material's folder
// (materials/elastic/elastic_block_loads.hpp, materials/j2/j2_block_loads.hpp). A material
// without one has its elements computed one by one (solver/element_group.hpp).
//
// The state of a block is kept [field][point] as whole packs (one lane per element), in the
// layout the material declares (k_point_fields, materials/*.hpp), so that a step streams only
// the fields it reads.
#pragma once

#include <array>
#include <cstddef>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"

namespace fpmshell {

/// One block's step: its path elements, its section, its state.
struct BlockStep {
    const TriangleMotion<RealPack>* motion = nullptr;
    const ElasticSectionConstants* constants = nullptr;
    RealPack thickness{0.0};    ///< h of every lane at the start of the step
    RealPack* state = nullptr;  ///< this block's point state, [field][point]
    std::size_t n_points = 0;   ///< points per element
    /// The next block's state (of the same section), fetched into the cache while an elastic
    /// block computes: without it the loads of the stresses stalled on memory (perf: a fifth of
    /// the block's time on the elastic 10^5 plate). A J2 block does not use it (see there).
    /// nullptr: none.
    const RealPack* next_state = nullptr;
    Real viscous_rate = 0;  ///< a_s / dt_{n-1/2} (§6.5)
    Real dt = 0;            ///< dt_{n-1/2} for rate-dependent materials
    /// the fading of the points' stress by their damage (a plastic law's points; eq. 7.6-6),
    /// nullptr where none fades
    const StressFading<RealPack>* fading = nullptr;
};

namespace block_points_detail {

/// Prefetches n_fields fields from first_field on of the next block's state.
inline void prefetch_fields(const BlockStep& step, std::size_t first_field, std::size_t n_fields) {
    if (step.next_state)
        prefetch_packs(step.next_state + first_field * step.n_points, n_fields * step.n_points);
}

/// Stores the new stresses of the valid lanes (an invalid lane's old state stays for the
/// general code).
inline void store_stress(const BlockStep& step, const MaskOf<RealPack>& valid,
                         const RealPack* stress, std::size_t stress_field) {
    for (std::size_t p = 0; p < step.n_points; ++p)
        for (std::size_t r = 0; r < 3; ++r)
            stdx::where(valid, step.state[(stress_field + r) * step.n_points + p]) =
                stress[3 * p + r];
}

}  // namespace block_points_detail

}  // namespace fpmshell
