// The traffic of a distributed run between its ranks (docs/architecture.md "On several ranks"):
// this rank's share of the model (DomainDecomposition), the positions of the particles held
// around its own, the particles shared whole on every rank before the parts of the step that run
// whole there (the contact, the nodal rigid bodies and the ties), the joins of per-rank
// lists, and the records of its particles' state for a restart file's pieces. On one rank every
// call is a no-op (or the identity), so the solver calls them unconditionally where that reads
// better.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
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

    /// The parts of the step that run whole on every rank, each reading its own particles.
    enum class Whole : std::size_t {
        contact,      ///< the contact's particles
        constraints,  ///< those of the nodal rigid bodies and of the ties (§6.11, §6.12)
    };
    /// The particles that `part` reads (sorted or not); then share brings the given particle
    /// arrays of each of them from its owner to every rank, so that every rank runs `part` on
    /// the single process's values.
    void set_whole_particles(Whole part, const std::vector<Index>& particles);
    void share(Whole part, std::initializer_list<std::vector<Vec3>*> arrays);

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
    Communicator::Pending positions_in_flight_;  ///< start_positions' messages
    struct WholeParticles {
        std::vector<std::vector<Index>> owned;  ///< per rank: the part's particles it owns
        std::vector<Real> send, all;            ///< share's buffers
    };
    std::array<WholeParticles, 2> whole_;  ///< per Whole
};

}  // namespace fpmshell
