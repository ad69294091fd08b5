#include "fpmshell/solver/corner_assembly.hpp"

#include <utility>

#include "fpmshell/core/kept_places.hpp"

namespace fpmshell {

ElementBlocks assign_blocks(const std::vector<Index>& element_group,
                            const std::vector<bool>& blockable) {
    const std::size_t ne = element_group.size(), n_groups = blockable.size();
    const auto w = static_cast<std::size_t>(k_lanes);
    ElementBlocks b;
    b.group_first_block.push_back(0);
    b.group_first_alone.push_back(0);
    std::vector<std::vector<Index>> members(n_groups);
    for (std::size_t e = 0; e < ne; ++e)
        members[static_cast<std::size_t>(element_group[e])].push_back(static_cast<Index>(e));
    for (std::size_t g = 0; g < n_groups; ++g) {
        const auto& m = members[g];
        const std::size_t n_blocked = blockable[g] ? m.size() / w * w : 0;
        b.block_elements.insert(b.block_elements.end(), m.begin(),
                                m.begin() + static_cast<std::ptrdiff_t>(n_blocked));
        b.alone_elements.insert(b.alone_elements.end(),
                                m.begin() + static_cast<std::ptrdiff_t>(n_blocked), m.end());
        b.block_group.insert(b.block_group.end(), n_blocked / w, static_cast<Index>(g));
        b.group_first_block.push_back(static_cast<Index>(b.block_group.size()));
        b.group_first_alone.push_back(static_cast<Index>(b.alone_elements.size()));
    }
    b.block_lane.assign(ne, -1);
    b.alone_position.assign(ne, -1);
    for (std::size_t i = 0; i < b.block_elements.size(); ++i)
        b.block_lane[static_cast<std::size_t>(b.block_elements[i])] = static_cast<Index>(i);
    for (std::size_t i = 0; i < b.alone_elements.size(); ++i)
        b.alone_position[static_cast<std::size_t>(b.alone_elements[i])] = static_cast<Index>(i);
    return b;
}

CornerAssembly::CornerAssembly(ElementBlocks blocks,
                               const std::vector<std::array<Index, 3>>& triangles,
                               const MeshTopology& topology, bool across_sides, bool slots_now)
    : blocks_(std::move(blocks)), slots_per_alone_(across_sides ? 6 : 3) {
    const auto w = static_cast<std::size_t>(k_lanes);
    const std::size_t n_slots =
        3 * blocks_.block_elements.size() + slots_per_alone_ * blocks_.alone_elements.size();
    full_numbers_ = (n_slots + w - 1) / w * k_components * w;
    if (slots_now) allocate_slots();
    // CSR particle -> slots, slots in increasing element order (fixed summation order).
    const std::size_t np = static_cast<std::size_t>(topology.n_particles()), ne = triangles.size();
    // slot k of element e -> its particle (-1: none); the 3 across the sides exist (and are
    // gathered) only with across_sides
    auto slot_particle = [&](std::size_t e, std::size_t k) -> Index {
        if (k < 3) return triangles[e][k];
        const std::size_t side = 3 * e + (k - 3);
        const Index n = topology.side_neighbour[side];
        return n < 0 ? -1
                     : triangles[static_cast<std::size_t>(n)]
                                [static_cast<std::size_t>(topology.side_neighbour_side[side])];
    };
    csr_begin_.assign(np + 1, 0);
    for (std::size_t e = 0; e < ne; ++e)
        for (std::size_t k = 0; k < slots_per_alone_; ++k)
            if (const Index p = slot_particle(e, k); p >= 0)
                ++csr_begin_[static_cast<std::size_t>(p) + 1];
    for (std::size_t p = 0; p < np; ++p) csr_begin_[p + 1] += csr_begin_[p];
    csr_slot_.assign(static_cast<std::size_t>(csr_begin_[np]), 0);
    std::vector<Index> fill(csr_begin_.begin(), csr_begin_.end() - 1);
    for (std::size_t e = 0; e < ne; ++e)
        for (std::size_t k = 0; k < slots_per_alone_; ++k)
            if (const Index p = slot_particle(e, k); p >= 0)
                csr_slot_[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] =
                    full_offset(e, k);
}

std::size_t CornerAssembly::full_offset(std::size_t e, std::size_t k) const {
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    const Index at = blocks_.block_lane[e];
    const std::size_t slot =
        at >= 0
            ? (3 * (static_cast<std::size_t>(at) / w) + k) * w + static_cast<std::size_t>(at) % w
            : 3 * blocks_.block_elements.size() +
                  slots_per_alone_ * static_cast<std::size_t>(blocks_.alone_position[e]) + k;
    return slot / w * (k_components * w) + slot % w;
}

const SlotGatherPlan& CornerAssembly::plan(int ranges) {
    if (plan_.ranges() != ranges) {
        plan_ =
            make_slot_gather_plan(blocks_.n_blocks(), ranges, csr_begin_, csr_slot_, gather_mode_);
        store_plan_offsets();
    }
    return plan_;
}

void CornerAssembly::set_ranges(const std::vector<Index>& range_begin) {
    plan_ = make_slot_gather_plan(range_begin, csr_begin_, csr_slot_, gather_mode_);
    store_plan_offsets();
}

void CornerAssembly::set_gather_modes(std::vector<GatherMode> mode) {
    gather_mode_ = std::move(mode);
    plan_ = make_slot_gather_plan(
        plan_.range_begin.empty() ? equal_block_ranges(blocks_.n_blocks(), 1) : plan_.range_begin,
        csr_begin_, csr_slot_, gather_mode_);
    store_plan_offsets();
}

void CornerAssembly::allocate_slots() {
    if (slot_loads_.empty()) slot_loads_.assign(full_numbers_, 0.0);
}

void CornerAssembly::keep_blocks(const std::vector<std::uint8_t>& kept) {
    constexpr std::size_t group_reals = k_components * static_cast<std::size_t>(k_lanes);
    const std::size_t n_blocks = kept.size();
    const std::size_t alone_reals = full_numbers_ - 3 * n_blocks * group_reals;
    KeptPlaces places = kept_places(n_blocks, [&](std::size_t b) { return kept[b] != 0; });
    block_page_ = std::move(places.place);
    kept_blocks_ = places.count;
    slot_loads_.assign(3 * kept_blocks_ * group_reals + alone_reals, 0.0);
    slot_loads_.shrink_to_fit();  // (where every element's were made before)
    store_plan_offsets();
}

void CornerAssembly::store_plan_offsets() {
    if (block_page_.empty()) return;
    for (const Index p : plan_.after)
        for (Index k = csr_begin_[static_cast<std::size_t>(p)];
             k < csr_begin_[static_cast<std::size_t>(p) + 1]; ++k)
            plan_.offset[static_cast<std::size_t>(k)] =
                stored(csr_slot_[static_cast<std::size_t>(k)]);
}

}  // namespace fpmshell
