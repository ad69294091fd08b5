// ShellElements on one rank of a distributed run (solver/domain_decomposition.hpp): which units
// it computes, the order its particles sum their slots in, the slots it keeps, and the exchange
// of the slots of the shared particles with the other ranks.
#include "fpmshell/core/communicator.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

void ShellElements::set_decomposition(const DomainDecomposition* d) {
    decomposition_ = d;
    if (!state_made_) allocate_state();
    if (!d || !d->distributed()) return;
    // The ring loop computes the interior blocks: not another rank's, nor those computed first
    // (at the shared particles). A particle of those sums after the loop from the full array
    // (a shared one also receives its other ranks' slots there), one this rank does not hold
    // not at all.
    const ElementBlocks& blocks = assembly_.blocks();
    not_in_ring_loop_.assign(static_cast<std::size_t>(blocks.n_blocks()), 0);
    for (Index b = 0; b < blocks.n_blocks(); ++b)
        not_in_ring_loop_[static_cast<std::size_t>(b)] = !d->own_unit[static_cast<std::size_t>(b)];
    std::vector<GatherMode> mode(d->held.size(), GatherMode::Any);
    for (const Index b : d->boundary_blocks) {
        not_in_ring_loop_[static_cast<std::size_t>(b)] = 1;
        for (Index l = 0; l < k_lanes; ++l)
            for (const Index p : tri_[static_cast<std::size_t>(
                     blocks.block_elements[static_cast<std::size_t>(b * k_lanes + l)])])
                mode[static_cast<std::size_t>(p)] = GatherMode::After;
    }
    // (a particle shared by other ranks alone is not summed here: its slots are not here)
    for (std::size_t p = 0; p < mode.size(); ++p)
        if (!d->held[p])
            mode[p] = GatherMode::Skip;
        else if (d->shared[p])
            mode[p] = GatherMode::After;
    assembly_.set_gather_modes(std::move(mode));
    // The slot array keeps this rank's blocks and those whose slots it receives: the blocks
    // of the other ranks at its shared particles.
    constexpr std::size_t group_reals = CornerAssembly::k_components * k_lanes;
    std::vector<std::uint8_t> kept(static_cast<std::size_t>(blocks.n_blocks()), 0);
    for (Index b = 0; b < blocks.n_blocks(); ++b)
        kept[static_cast<std::size_t>(b)] = d->own_unit[static_cast<std::size_t>(b)];
    for (const std::vector<std::size_t>& offsets : d->slot_recv)
        for (const std::size_t at : offsets)
            if (const std::size_t block = at / group_reals / 3; block < kept.size())
                kept[block] = 1;
    assembly_.keep_blocks(kept);
}

Communicator::Pending ShellElements::start_slot_exchange() {
    const DomainDecomposition& d = *decomposition_;
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    constexpr std::size_t nc = CornerAssembly::k_components;
    const std::size_t n_peers = d.slot_peers.size();
    slot_send_.resize(n_peers);
    slot_recv_.resize(n_peers);
    const Real* slots = assembly_.slots();
    for (std::size_t k = 0; k < n_peers; ++k) {
        std::vector<Real>& out = slot_send_[k];
        out.resize(nc * d.slot_send[k].size());
        for (std::size_t i = 0; i < d.slot_send[k].size(); ++i)
            for (std::size_t c = 0, at = assembly_.stored(d.slot_send[k][i]); c < nc; ++c)
                out[nc * i + c] = slots[at + c * w];
        slot_recv_[k].resize(nc * d.slot_recv[k].size());
    }
    return Communicator::world().start_exchange(d.slot_peers, slot_send_, slot_recv_);
}

void ShellElements::finish_slot_exchange(Communicator::Pending& pending) {
    const DomainDecomposition& d = *decomposition_;
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    constexpr std::size_t nc = CornerAssembly::k_components;
    Real* slots = assembly_.slots();
    Communicator::world().wait(pending);
    for (std::size_t k = 0; k < d.slot_peers.size(); ++k)
        for (std::size_t i = 0; i < d.slot_recv[k].size(); ++i)
            for (std::size_t c = 0, at = assembly_.stored(d.slot_recv[k][i]); c < nc; ++c)
                slots[at + c * w] = slot_recv_[k][nc * i + c];
}

}  // namespace fpmshell
