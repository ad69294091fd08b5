// The assembly of element corner loads into particles (style.md §4): which elements the
// element loop computes k_lanes at a time and which one by one, the slot every element corner
// writes its force and moment into, and the particle -> slot map each particle sums in element
// order (bitwise the same for any thread count), with the plan of when it sums them
// (slot_gather_plan.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/slot_gather_plan.hpp"

namespace fpmshell {

/// Which elements are computed k_lanes at a time (blocks) and which one by one (alone): group
/// by group, k_lanes elements of one group per block, the rest of the group alone.
struct ElementBlocks {
    std::vector<Index> block_elements;  ///< k_lanes per block, blocks in group order
    std::vector<Index> alone_elements;  ///< in group order, each group's in element order
    std::vector<Index> block_lane;      ///< per element: its index in block_elements, -1: alone
    std::vector<Index>
        alone_position;  ///< per element: its index in alone_elements, -1: in a block
    /// per group (and one past the last): its first block, and its first element alone
    std::vector<Index> group_first_block, group_first_alone;
    std::vector<Index> block_group;  ///< per block: its group

    [[nodiscard]] Index n_blocks() const { return static_cast<Index>(block_group.size()); }
    [[nodiscard]] Index n_alone() const { return static_cast<Index>(alone_elements.size()); }
};

/// element_group: the group of every element; blockable: per group, whether its elements may
/// be computed in blocks.
[[nodiscard]] ElementBlocks assign_blocks(const std::vector<Index>& element_group,
                                          const std::vector<bool>& blockable);

class CornerAssembly {
public:
    static constexpr std::size_t k_components =
        SlotGatherPlan::k_components;  // force x y z, moment x y z

    /// across_sides: the elements alone also load the particles across their sides (the
    /// smoothed membrane), 6 slots each instead of 3. slots_now: the slot array made now for
    /// every element (else by allocate_slots or keep_blocks).
    CornerAssembly(ElementBlocks blocks, const std::vector<std::array<Index, 3>>& triangles,
                   const MeshTopology& topology, bool across_sides, bool slots_now = true);

    [[nodiscard]] const ElementBlocks& blocks() const { return blocks_; }
    /// Slots per element computed alone (3, or 6 with the particles across the sides).
    [[nodiscard]] std::size_t slots_per_alone() const { return slots_per_alone_; }
    /// Offset in slots() of component 0 of slot k of element e (component c: + c k_lanes).
    [[nodiscard]] std::size_t slot_offset(std::size_t e, std::size_t k) const {
        return stored(full_offset(e, k));
    }
    /// The same in the layout of every element's slots (particle_slots, a distributed run's
    /// exchange lists), which keep_blocks does not change.
    [[nodiscard]] std::size_t full_offset(std::size_t e, std::size_t k) const;
    /// The slot array (slot k >= 3 of an element alone: the particle across side k - 3), and
    /// its length in numbers.
    [[nodiscard]] Real* slots() { return slot_loads_.data(); }
    [[nodiscard]] std::size_t slot_numbers() const { return slot_loads_.size(); }
    /// The 3 corner slots of block b: 6 whole packs per corner.
    [[nodiscard]] Real* block_slots(Index b) {
        return slot_loads_.data() + 3 * stored_block(static_cast<std::size_t>(b)) * k_components *
                                        static_cast<std::size_t>(k_lanes);
    }
    /// The slot array of every element (where not made yet).
    void allocate_slots();
    /// A rank of a distributed run keeps the slots of the blocks with `kept` (per block) and
    /// those of the elements alone: the others' are never written nor read there.
    void keep_blocks(const std::vector<std::uint8_t>& kept);
    /// Where the slot at `full` (full_offset) lies in slots().
    [[nodiscard]] std::size_t stored(std::size_t full) const {
        if (block_page_.empty()) return full;
        constexpr std::size_t group_reals = k_components * static_cast<std::size_t>(k_lanes);
        const std::size_t group = full / group_reals;
        const std::size_t block_groups = 3 * block_page_.size();
        if (group >= block_groups) return full - (block_groups - 3 * kept_blocks_) * group_reals;
        return (3 * block_page_[group / 3] + group % 3) * group_reals + full % group_reals;
    }

    /// The gather plan for `ranges` ranges of blocks (remade, in equal ranges, when the count
    /// changes).
    const SlotGatherPlan& plan(int ranges);
    /// The plan remade for the ranges of blocks that start at range_begin (slot_gather_plan.hpp).
    void set_ranges(const std::vector<Index>& range_begin);
    /// How each particle is summed from now on (a distributed run; slot_gather_plan.hpp).
    void set_gather_modes(std::vector<GatherMode> mode);
    /// The plan as last made.
    [[nodiscard]] const SlotGatherPlan& plan() const { return plan_; }
    /// Ring storage of range r of the plan.
    [[nodiscard]] Real* ring(std::size_t r) { return plan_.rings[r].data(); }
    /// Sums the slots of particle p (in element order) into s.f_int, s.m_int; base: the ring
    /// or slots(), which the plan's offsets point into. (Inline: once per particle and step.)
    void gather_particle(std::size_t p, const Real* base, ParticleState& s) const {
        constexpr auto w = static_cast<std::size_t>(k_lanes);
        Vec3 f = Vec3::Zero(), m = Vec3::Zero();
        for (Index k = csr_begin_[p]; k < csr_begin_[p + 1]; ++k) {
            const Real* slot = base + plan_.offset[static_cast<std::size_t>(k)];
            f += Vec3(slot[0], slot[w], slot[2 * w]);
            m += Vec3(slot[3 * w], slot[4 * w], slot[5 * w]);
        }
        s.f_int[p] = f;
        s.m_int[p] = m;
    }

    /// The full-array offsets (full_offset, component 0) of particle p's slots, in element
    /// order (an element alone with slots across its sides: after its corners).
    [[nodiscard]] std::span<const std::size_t> particle_slots(std::size_t p) const {
        return {csr_slot_.data() + csr_begin_[p], csr_slot_.data() + csr_begin_[p + 1]};
    }

private:
    ElementBlocks blocks_;
    std::size_t slots_per_alone_ = 3;
    // The force and moment on each corner of every element (and, across the sides, on the
    // particles there), in groups of k_lanes slots, component by component (fx fy fz mx my mz,
    // k_lanes values each), so that a block stores its corner loads as 6 whole packs per
    // corner. Slot sigma lies in group sigma / k_lanes at lane sigma % k_lanes; corner i of
    // block b is slot (3 b + i) k_lanes + lane, and the elements alone follow the blocks,
    // slots_per_alone_ slots each.
    std::vector<Real, Eigen::aligned_allocator<Real>> slot_loads_;
    /// per block: its place among the kept blocks' slots (empty: every block kept, in order;
    /// keep_blocks, KeptPlaces), and how many are kept
    std::vector<std::size_t> block_page_;
    std::size_t kept_blocks_ = 0;
    std::size_t full_numbers_ = 0;  ///< the slot array's length with every element's slots
    [[nodiscard]] std::size_t stored_block(std::size_t b) const {
        return block_page_.empty() ? b : block_page_[b];
    }
    /// The plan's offsets of the particles summed from slots() (not from a ring) where they lie.
    void store_plan_offsets();
    std::vector<Index> csr_begin_;  ///< particle -> its slots (csr_slot_[csr_begin_[p]...])
    std::vector<std::size_t>
        csr_slot_;  ///< full_offset of each slot, by particle, in element order
    SlotGatherPlan plan_;
    std::vector<GatherMode> gather_mode_;  ///< per particle (empty: every one Any)
};

}  // namespace fpmshell
