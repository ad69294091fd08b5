// When and from where every particle sums the loads of its element corners (the assembly of
// style.md §4 without its round trip through memory).
//
// The element loop writes each element corner's force and moment into a slot; each particle
// then sums its slots in element order, which makes the result bitwise the same for any thread
// count. Summed a whole pass later, the slots of a large model leave the caches in between:
// written, read for ownership and read again, about 430 bytes per element-step at 10^6
// elements, more than the rest of the step's traffic. This plan sums a particle as soon as the
// last block of elements touching it is done, from a small ring of block slots that stays in
// the cache:
// - the blocks are cut into `ranges` contiguous ranges (one per thread) and each range into
//   tiles of k_tile_blocks blocks; after each tile, its range sums the particles whose slots
//   are all in its range and whose last one is in that tile ("ready" particles);
// - the range keeps its blocks' slots in a ring of k_ring_blocks blocks (block b of the range
//   at position (b - first block) mod k_ring_blocks); a particle is ready only if its first
//   slot is still in the ring when its tile ends;
// - every other particle (its slots in two ranges, or too far apart, or of an element computed
//   alone) is summed after the element loop from the full slot array, which the blocks holding
//   one of its slots fill too ("kept" blocks).
// The values and the order of every particle's sum are those of the full array's, so the
// result is the same bits whichever way a particle is summed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct SlotGatherPlan {
    static constexpr Index k_tile_blocks = 16;
    static constexpr Index k_ring_blocks =
        256;  ///< a multiple of k_tile_blocks; 295 kB per ring with 8 lanes
    static constexpr std::size_t k_components = 6;  ///< force x y z, moment x y z
    /// Reals of the slots of one block: 3 corners x 6 components x k_lanes.
    static constexpr std::size_t k_block_reals =
        3 * k_components * static_cast<std::size_t>(k_lanes);

    std::vector<Index> range_begin;       ///< per range: its first block (ranges + 1 entries)
    std::vector<Index> range_first_tile;  ///< per range: its first tile (ranges + 1 entries)
    std::vector<Index> ready_begin;  ///< per tile: its first entry in ready (tiles + 1 entries)
    std::vector<Index> ready;        ///< the particles summed from the ring, by tile
    std::vector<Index> after;        ///< the particles summed after the element loop
    std::vector<std::uint8_t> keep;  ///< per block: 1 if it also fills the full slot array
    /// per entry of the particle -> slot map: the slot's offset in its particle's ring (ready
    /// particles) or in the full slot array (the others)
    std::vector<std::size_t> offset;
    std::vector<std::vector<Real, Eigen::aligned_allocator<Real>>>
        rings;  ///< per range; none without the ring

    /// The thread count it was made for (0: none yet).
    [[nodiscard]] int ranges() const {
        return range_begin.empty() ? 0 : static_cast<int>(range_begin.size()) - 1;
    }
    /// false: every particle is summed after the loop.
    [[nodiscard]] bool use_ring() const { return !rings.empty(); }
};

/// The first blocks of `ranges` contiguous ranges of n_blocks blocks as equal as can be, and
/// n_blocks (ranges + 1 entries).
[[nodiscard]] std::vector<Index> equal_block_ranges(Index n_blocks, int ranges);

/// How a particle is summed in a distributed run (DomainDecomposition): like any other, after
/// the element loop from the full slot array (a particle shared with other ranks, whose slots
/// arrive there), or not at all (a particle this rank does not hold).
enum class GatherMode : std::uint8_t { Any = 0, After = 1, Skip = 2 };

/// The plan for the contiguous ranges of blocks that start at range_begin (one more entry: the
/// number of blocks), one range per thread; any ranges give the same sums. slot_begin /
/// slot_offset: the particle -> slot map as below. mode: per particle (empty: Any for all).
[[nodiscard]] SlotGatherPlan make_slot_gather_plan(const std::vector<Index>& range_begin,
                                                   const std::vector<Index>& slot_begin,
                                                   const std::vector<std::size_t>& slot_offset,
                                                   const std::vector<GatherMode>& mode = {});

/// The plan for n_blocks blocks on `ranges` threads. slot_begin / slot_offset: the particle ->
/// slot map into the full array, whose slot groups (k_lanes slots, 6 components each) hold
/// corner c of block b as group 3 b + c, and slots of elements computed alone after them.
/// The ring is left out (use_ring() false) when fewer than half of the particles would be
/// summed from it: a mesh numbered without locality would pay for both arrays.
[[nodiscard]] SlotGatherPlan make_slot_gather_plan(Index n_blocks, int ranges,
                                                   const std::vector<Index>& slot_begin,
                                                   const std::vector<std::size_t>& slot_offset,
                                                   const std::vector<GatherMode>& mode = {});

}  // namespace fpmshell
