#include "fpmshell/solver/slot_gather_plan.hpp"

#include <algorithm>
#include <limits>

namespace fpmshell {

std::vector<Index> equal_block_ranges(Index n_blocks, int ranges) {
    const auto n_ranges = static_cast<std::size_t>(std::max(1, ranges));
    std::vector<Index> begin(n_ranges + 1);
    for (std::size_t t = 0; t <= n_ranges; ++t)
        begin[t] = static_cast<Index>(static_cast<std::size_t>(n_blocks) * t / n_ranges);
    return begin;
}

SlotGatherPlan make_slot_gather_plan(Index n_blocks, int ranges,
                                     const std::vector<Index>& slot_begin,
                                     const std::vector<std::size_t>& slot_offset,
                                     const std::vector<GatherMode>& mode) {
    return make_slot_gather_plan(equal_block_ranges(n_blocks, ranges), slot_begin, slot_offset,
                                 mode);
}

SlotGatherPlan make_slot_gather_plan(const std::vector<Index>& range_begin,
                                     const std::vector<Index>& slot_begin,
                                     const std::vector<std::size_t>& slot_offset,
                                     const std::vector<GatherMode>& mode) {
    auto mode_of = [&](std::size_t p) { return mode.empty() ? GatherMode::Any : mode[p]; };
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    constexpr std::size_t group_reals = SlotGatherPlan::k_components * w;
    constexpr Index tile = SlotGatherPlan::k_tile_blocks, ring = SlotGatherPlan::k_ring_blocks;
    SlotGatherPlan plan;
    const Index n_blocks = range_begin.back();
    const std::size_t n_ranges = range_begin.size() - 1;
    plan.range_begin = range_begin;
    plan.range_first_tile.assign(n_ranges + 1, 0);
    for (std::size_t t = 1; t <= n_ranges; ++t) {
        const Index blocks = plan.range_begin[t] - plan.range_begin[t - 1];
        plan.range_first_tile[t] = plan.range_first_tile[t - 1] + (blocks + tile - 1) / tile;
    }
    const Index n_tiles = plan.range_first_tile[n_ranges];
    // The range of block b, its tile, and the block after the end of that tile.
    auto range_of = [&](Index b) {
        return static_cast<std::size_t>(
            std::upper_bound(plan.range_begin.begin(), plan.range_begin.end(), b) -
            plan.range_begin.begin() - 1);
    };
    auto tile_of = [&](Index b, std::size_t t) {
        return plan.range_first_tile[t] + (b - plan.range_begin[t]) / tile;
    };
    auto tile_end = [&](Index b, std::size_t t) {
        return std::min(plan.range_begin[t + 1],
                        plan.range_begin[t] + ((b - plan.range_begin[t]) / tile + 1) * tile);
    };
    // Slot group 3 b + c holds corner c of block b; groups past the blocks': elements alone.
    const std::size_t n_particles = slot_begin.size() - 1;
    std::vector<Index> ready_tile(n_particles, -1);  // -1: summed after the loop
    std::size_t n_summed = 0;  // the particles this plan sums (all but the skipped)
    for (std::size_t p = 0; p < n_particles; ++p) {
        if (mode_of(p) == GatherMode::Skip) continue;
        ++n_summed;
        if (mode_of(p) == GatherMode::After) continue;
        Index first = std::numeric_limits<Index>::max(), last = -1;
        bool alone = false;
        for (Index k = slot_begin[p]; k < slot_begin[p + 1]; ++k) {
            const auto group =
                static_cast<Index>(slot_offset[static_cast<std::size_t>(k)] / group_reals);
            if (group >= 3 * n_blocks) alone = true;
            first = std::min(first, group / 3);
            last = std::max(last, group / 3);
        }
        if (alone || last < 0) continue;
        const std::size_t t = range_of(first);
        // its last block in the same range, and its first block's slots not yet overwritten
        // in the ring when the tile of its last block ends
        if (last < plan.range_begin[t + 1] && tile_end(last, t) <= first + ring)
            ready_tile[p] = tile_of(last, t);
    }
    const auto n_ready = static_cast<std::size_t>(
        std::count_if(ready_tile.begin(), ready_tile.end(), [](Index t) { return t >= 0; }));
    const bool use_ring = n_summed > 0 && 2 * n_ready >= n_summed;
    if (!use_ring) std::fill(ready_tile.begin(), ready_tile.end(), -1);
    // The ready particles by tile (in particle order within a tile), the others in order.
    plan.ready_begin.assign(static_cast<std::size_t>(n_tiles) + 1, 0);
    for (Index t : ready_tile)
        if (t >= 0) ++plan.ready_begin[static_cast<std::size_t>(t) + 1];
    for (std::size_t t = 0; t < static_cast<std::size_t>(n_tiles); ++t)
        plan.ready_begin[t + 1] += plan.ready_begin[t];
    plan.ready.resize(static_cast<std::size_t>(plan.ready_begin.back()));
    std::vector<Index> fill(plan.ready_begin.begin(), plan.ready_begin.end() - 1);
    plan.keep.assign(static_cast<std::size_t>(n_blocks), use_ring ? 0 : 1);
    plan.offset = slot_offset;
    for (std::size_t p = 0; p < n_particles; ++p) {
        const Index t = ready_tile[p];
        if (mode_of(p) == GatherMode::Skip) continue;
        if (t < 0) {
            plan.after.push_back(static_cast<Index>(p));
            for (Index k = slot_begin[p]; k < slot_begin[p + 1]; ++k) {
                const auto group =
                    static_cast<Index>(slot_offset[static_cast<std::size_t>(k)] / group_reals);
                if (group < 3 * n_blocks) plan.keep[static_cast<std::size_t>(group / 3)] = 1;
            }
            continue;
        }
        plan.ready[static_cast<std::size_t>(fill[static_cast<std::size_t>(t)]++)] =
            static_cast<Index>(p);
        // in the ring: block b of range r at position (b - first block of r) mod k_ring_blocks
        for (Index k = slot_begin[p]; k < slot_begin[p + 1]; ++k) {
            std::size_t& at = plan.offset[static_cast<std::size_t>(k)];
            const std::size_t group = at / group_reals, in_group = at % group_reals;
            const auto b = static_cast<Index>(group / 3);
            const auto position =
                static_cast<std::size_t>((b - plan.range_begin[range_of(b)]) % ring);
            at = (3 * position + group % 3) * group_reals + in_group;
        }
    }
    if (use_ring)
        plan.rings.assign(n_ranges,
                          std::vector<Real, Eigen::aligned_allocator<Real>>(
                              static_cast<std::size_t>(ring) * SlotGatherPlan::k_block_reals, 0.0));
    return plan;
}

}  // namespace fpmshell
