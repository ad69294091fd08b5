// The traffic of a distributed run between its ranks (docs/architecture.md "On several ranks"):
// this rank's share of the model (DomainDecomposition), the positions of the particles held
// around its own, the contact's particles shared before the contact, the joins of per-rank
// lists, and the records of its particles' state for a restart file's pieces. On one rank every
// call is a no-op (or the identity), so the solver calls them unconditionally where that reads
// better.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/particle_state.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

class RankExchange {
public:
    /// This rank's share of the model, cut over Communicator::world()'s ranks by the costs of
    /// the elements' units.
    RankExchange(const Model& model, const MeshTopology& topology, const ShellElements& elements);
    ~RankExchange();
    RankExchange(const RankExchange&) = delete;
    RankExchange& operator=(const RankExchange&) = delete;

    [[nodiscard]] const DomainDecomposition& decomposition() const { return d_; }
    [[nodiscard]] bool distributed() const { return d_.distributed(); }
    /// Whether this rank owns particle p (every particle on one rank).
    [[nodiscard]] bool owns(std::size_t p) const {
        return !d_.distributed() || d_.particle_owner[p] == d_.rank;
    }

    /// The positions x^{n+1} of the particles around the held ones that other ranks hold:
    /// sent at the end of a step, received into x after the next step's element loop (which
    /// does not read them).
    void start_positions(const std::vector<Vec3>& x);
    void finish_positions(std::vector<Vec3>& x);

    /// The particles the contact reads (the contact runs whole on every rank); then
    /// share_contact_particles brings a and b (two particle arrays) of each of them from its
    /// owner to every rank.
    void set_contact_particles(const std::vector<Index>& particles);
    void share_contact_particles(std::vector<Vec3>& a, std::vector<Vec3>& b);

    /// Every rank's list of element indices joined and sorted (this rank's alone on one rank).
    [[nodiscard]] std::vector<Index> join_sorted(std::vector<Index> mine) const;
    /// Every rank's records of `width` numbers joined, ordered by their first number (each
    /// rank's already in that order; on one rank: `mine`).
    [[nodiscard]] std::vector<Real> join_records(const std::vector<Real>& mine,
                                                 std::size_t width) const;
    /// Every rank's exact sums added, exactly (the same bits for any number of ranks).
    void sum(std::span<ExactSum> sums) const {
        if (d_.distributed()) Communicator::world().sum(sums);
    }
    /// The largest of every rank's `value`.
    [[nodiscard]] Real max(Real value) const;
    /// The index of the rank whose `value` is smallest (the lowest rank among equals; on one
    /// rank: `index`).
    [[nodiscard]] Index index_at_min(Real value, Index index) const {
        return d_.distributed() ? Communicator::world().min_loc(value, index).second : index;
    }

    /// The records of the particles this rank owns (all on one rank), in the order of its
    /// atoms: each particle's index, then every array of its state. What a distributed restart
    /// file's pieces hold.
    [[nodiscard]] std::vector<char> owned_particle_records(ParticleState& s) const;
    /// Writes such records into s, counting each particle in `seen` (one entry per particle).
    /// Throws std::invalid_argument for a record cut short or of a particle s does not have
    /// (records read from a file).
    static void read_particle_records(const std::vector<char>& bytes, ParticleState& s,
                                      std::vector<std::uint8_t>& seen);

private:
    DomainDecomposition d_;
    std::vector<std::vector<Real>> position_send_, position_recv_;
    Communicator::Pending positions_in_flight_;      ///< start_positions' messages
    std::vector<std::vector<Index>> contact_owned_;  ///< per rank: the contact's particles it owns
    std::vector<Real> contact_send_, contact_all_;   ///< share_contact_particles' buffers
};

}  // namespace fpmshell
