// The state ShellElements carries from step to step: made for the units this rank computes, and
// in a restart file, whole or as the bytes of a distributed run's pieces.
#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "fpmshell/core/byte_buffer.hpp"
#include "fpmshell/core/kept_places.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

namespace {
template <class T>
T take(const std::vector<char>& bytes, std::size_t& at) {
    if (bytes.size() - at < sizeof(T))  // at <= size always
        throw std::invalid_argument("the element states are cut short");
    T v;
    read_bytes(bytes, at, v);
    return v;
}
}  // namespace

// Per element: its index, thickness, N, M, bending step ratio and length, its mass scaling
// state (§6.10), where elements can fail its erosion state and its criteria's (§7.6), then its
// points.
std::vector<Index> ShellElements::computed_elements() const {
    std::vector<Index> elements;
    const ElementBlocks& blocks = assembly_.blocks();
    if (decomposition_) {
        for (const Index b : decomposition_->own_blocks)
            for (Index l = 0; l < k_lanes; ++l)
                elements.push_back(
                    blocks.block_elements[static_cast<std::size_t>(b * k_lanes + l)]);
        for (const Index i : decomposition_->own_alone)
            elements.push_back(blocks.alone_elements[static_cast<std::size_t>(i)]);
    } else {
        for (Index e = 0; e < size(); ++e) elements.push_back(e);
    }
    return elements;
}

std::vector<char> ShellElements::pack_state() const {
    const std::vector<Index> elements = computed_elements();
    std::vector<char> bytes;
    auto& self = const_cast<ShellElements&>(*this);  // the step ratios have no const access
    for (const Index e : elements) {
        const auto ue = static_cast<std::size_t>(e);
        append_bytes(bytes, e);
        append_bytes(bytes, thickness_[ue]);
        const Voigt3 n = resultant(ue, 0), m = resultant(ue, 3);
        for (int c = 0; c < 3; ++c) append_bytes(bytes, n[c]);
        for (int c = 0; c < 3; ++c) append_bytes(bytes, m[c]);
        append_bytes(bytes, self.time_steps_.ratio()[ue]);
        append_bytes(bytes, self.time_steps_.ratio_length()[ue]);
        append_bytes(bytes, time_steps_.mass_state(ue));
        if (can_erode()) {  // §7.6
            append_bytes(bytes, eroded_[ue]);
            if (separates()) append_bytes(bytes, cracked_[ue]);
            append_bytes(bytes, element_work_[ue]);
            append_bytes(bytes, last_loads_[ue]);
            for (std::size_t i = 0; i < failure_numbers(ue); ++i)
                append_bytes(bytes, self.failure_number(ue, i));
        }
        const ElementGroup& group = group_of(ue);
        const GroupPlace place = place_of(ue);
        std::vector<Real> fields(group.point_fields());
        for (std::size_t p = 0; p < group.n_points(); ++p) {
            group.read_fields(place, p, fields.data());
            for (const Real f : fields) append_bytes(bytes, f);
        }
    }
    return bytes;
}

void ShellElements::unpack_state(const std::vector<char>& bytes, std::vector<std::uint8_t>& seen) {
    std::size_t at = 0;
    while (at < bytes.size()) {
        const Index e = take<Index>(bytes, at);
        if (e < 0 || static_cast<std::size_t>(e) >= tri_.size())
            throw std::invalid_argument(fmt::format("a state of element {} of {}", e, tri_.size()));
        const auto ue = static_cast<std::size_t>(e);
        ++seen[ue];
        // the state of the points, the criteria and the resultants is kept only where this
        // rank computes e
        const bool here = computes(e);
        thickness_[ue] = take<Real>(bytes, at);
        Voigt3 n, m;
        for (int c = 0; c < 3; ++c) n[c] = take<Real>(bytes, at);
        for (int c = 0; c < 3; ++c) m[c] = take<Real>(bytes, at);
        if (here) set_resultants(ue, n, m);
        time_steps_.ratio()[ue] = take<Real>(bytes, at);
        time_steps_.ratio_length()[ue] = take<Real>(bytes, at);
        time_steps_.set_mass_state(ue, take<std::array<Real, 3>>(bytes, at));
        if (can_erode()) {
            eroded_[ue] = take<std::uint8_t>(bytes, at);
            if (separates()) cracked_[ue] = take<std::uint8_t>(bytes, at);
            element_work_[ue] = take<Real>(bytes, at);
            last_loads_[ue] = take<std::array<Real, 18>>(bytes, at);
            for (std::size_t i = 0; i < failure_numbers(ue); ++i) {
                const Real v = take<Real>(bytes, at);
                if (here) failure_number(ue, i) = v;
            }
        }
        ElementGroup& group = *groups_[static_cast<std::size_t>(section_[ue])];
        const GroupPlace place = place_of(ue);
        std::vector<Real> fields(group.point_fields());
        for (std::size_t p = 0; p < group.n_points(); ++p) {
            for (Real& f : fields) f = take<Real>(bytes, at);
            if (here) group.write_fields(place, p, fields.data());
        }
    }
}

// The restart file holds every point's state as its law's numbers (ElementGroup::point_fields),
// in element order (format 10), whatever the layout in memory.
void ShellElements::save(RestartWriter& out) const {
    if (decomposition_ && decomposition_->distributed())  // a rank keeps its elements' alone
        throw std::logic_error("a distributed run saves its elements in pieces (pack_state)");
    std::vector<Real> fields;
    for (std::size_t e = 0; e < tri_.size(); ++e) {
        const ElementGroup& group = group_of(e);
        const GroupPlace place = place_of(e);
        for (std::size_t p = 0; p < group.n_points(); ++p) {
            fields.resize(fields.size() + group.point_fields());
            group.read_fields(place, p, fields.data() + fields.size() - group.point_fields());
        }
    }
    std::vector<Voigt3> n(tri_.size()), m(tri_.size());
    for (std::size_t e = 0; e < tri_.size(); ++e) {
        n[e] = resultant(e, 0);
        m[e] = resultant(e, 3);
    }
    auto& self = const_cast<ShellElements&>(*this);  // the archive's interface is shared with load
    out.put_block(std::move(fields));  // the largest list: written from its own memory
    out(self.thickness_, self.time_steps_.ratio(), self.time_steps_.ratio_length(), n, m);
    // §7.6 (empty: none can fail), the criteria's state element by element
    std::vector<Real> failure;
    for (std::size_t e = 0; e < tri_.size(); ++e)
        for (std::size_t i = 0; i < failure_numbers(e); ++i)
            failure.push_back(self.failure_number(e, i));
    out(self.eroded_, self.element_work_, self.last_loads_, failure, self.cracked_);
}

void ShellElements::load(RestartReader& in) {
    const std::size_t n_elements = tri_.size();
    std::size_t n_fields = 0;
    for (std::size_t e = 0; e < n_elements; ++e)
        n_fields += group_of(e).n_points() * group_of(e).point_fields();
    std::vector<Real> fields;
    std::vector<Voigt3> n, m;  // the resultants N, M of every element
    const std::vector<std::size_t> ratio_lengths =
        stored_lengths(time_steps_.ratio(), time_steps_.ratio_length());
    in(fields, thickness_, time_steps_.ratio(), time_steps_.ratio_length(), n, m);
    if (fields.size() != n_fields || thickness_.size() != n_elements || n.size() != n_elements ||
        m.size() != n_elements ||
        stored_lengths(time_steps_.ratio(), time_steps_.ratio_length()) != ratio_lengths)
        in.fail("restart file of a model with other elements, materials or integration rules");
    std::vector<Real> failure;
    for (std::size_t e = 0; e < n_elements; ++e)
        failure.resize(failure.size() + failure_numbers(e));
    const std::vector<std::size_t> erosion_lengths =
        stored_lengths(eroded_, element_work_, last_loads_, failure, cracked_);
    in(eroded_, element_work_, last_loads_, failure, cracked_);
    if (stored_lengths(eroded_, element_work_, last_loads_, failure, cracked_) != erosion_lengths)
        in.fail("restart file of a model with other failure criteria");
    // the state of the points, the criteria and the resultants is kept only where this rank
    // computes e
    for (std::size_t e = 0, k = 0; e < n_elements; ++e) {
        const bool here = computes(static_cast<Index>(e));
        for (std::size_t i = 0; i < failure_numbers(e); ++i, ++k)
            if (here) failure_number(e, i) = failure[k];
    }
    for (std::size_t e = 0; e < n_elements; ++e)
        if (computes(static_cast<Index>(e))) set_resultants(e, n[e], m[e]);
    std::size_t i = 0;
    for (std::size_t e = 0; e < n_elements; ++e) {
        ElementGroup& group = *groups_[static_cast<std::size_t>(section_[e])];
        const GroupPlace place = place_of(e);
        const bool here = computes(static_cast<Index>(e));
        for (std::size_t p = 0; p < group.n_points(); ++p) {
            if (here) group.write_fields(place, p, fields.data() + i);
            i += group.point_fields();
        }
    }
}

// The state of the points and the failure criteria (§7.6) and the arrays per block: of the
// units this rank computes alone (every unit on one rank), made once the decomposition is known.
void ShellElements::allocate_state() {
    const bool distributed = decomposition_ && decomposition_->distributed();
    // the slots: every element's on one rank; on several, set_decomposition keeps the rank's
    if (!distributed) assembly_.allocate_slots();
    const ElementBlocks& blocks = assembly_.blocks();
    const auto n_blocks = static_cast<std::size_t>(blocks.n_blocks());
    const auto computed = [&](std::size_t first) {
        return [this, first](std::size_t u) { return computes_unit(first + u); };
    };
    // the blocks' own arrays: of those this rank computes, in block order
    const KeptPlaces kept = kept_places(n_blocks, computed(0));
    block_store_ = distributed ? kept.place : std::vector<std::size_t>{};
    block_totals_.assign(kept.count, ElementTotals{});
    block_resultants_.assign(6 * kept.count, RealPack(0.0));
    // eq. 6.4-2 the blocks' initial volumes as whole packs (a pack filled lane by lane through
    // memory every step stalled the block: 6 % of the elastic kernel); §7.6 the element sizes
    block_initial_volume_.assign(kept.count, RealPack(0.0));
    if (can_erode()) block_element_size_.assign(kept.count, RealPack(0.0));
    for (std::size_t b = 0; b < n_blocks; ++b) {
        const std::size_t k = kept.place[b];
        if (k == k_not_kept) continue;
        for (int l = 0; l < k_lanes; ++l) {
            const auto e = static_cast<std::size_t>(
                blocks.block_elements[b * static_cast<std::size_t>(k_lanes) +
                                      static_cast<std::size_t>(l)]);
            set_lane(block_initial_volume_[k], l, time_steps_.initial_volume(e));
            if (can_erode()) set_lane(block_element_size_[k], l, element_size_[e]);
        }
    }
    // the points' state, group by group
    for (std::size_t g = 0; g < groups_.size(); ++g) {
        const auto first_block = static_cast<std::size_t>(blocks.group_first_block[g]);
        const auto first_alone = static_cast<std::size_t>(blocks.group_first_alone[g]);
        const auto group_blocks =
            static_cast<std::size_t>(blocks.group_first_block[g + 1]) - first_block;
        const auto group_alone =
            static_cast<std::size_t>(blocks.group_first_alone[g + 1]) - first_alone;
        const KeptPlaces kept_blocks = kept_places(group_blocks, computed(first_block));
        const KeptPlaces kept_alone = kept_places(group_alone, computed(n_blocks + first_alone));
        groups_[g]->allocate(group_blocks, group_alone, distributed ? &kept_blocks : nullptr,
                             distributed ? &kept_alone : nullptr);
    }
    allocate_failure_state();
    state_made_ = true;
}

bool ShellElements::computes(Index e) const {
    const ElementBlocks& blocks = assembly_.blocks();
    const auto ue = static_cast<std::size_t>(e);
    if (const Index at = blocks.block_lane[ue]; at >= 0)
        return computes_unit(static_cast<std::size_t>(at / k_lanes));
    return computes_unit(static_cast<std::size_t>(blocks.n_blocks() + blocks.alone_position[ue]));
}

std::size_t ShellElements::kept_state_numbers() const {
    std::size_t n = failure_state_.size() * static_cast<std::size_t>(k_lanes);
    for (const auto& g : groups_) n += g->kept_numbers();
    return n;
}

}  // namespace fpmshell
