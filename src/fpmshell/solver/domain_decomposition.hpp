// What one process of a run computes (core/communicator.hpp): its share of the element loop's
// units, the particles it updates, and the two exchanges of every step that keep its particles
// bitwise those of a single-process run.
//
// - Atoms: the units of the element loop (SIMD blocks, then the elements computed alone,
//   solver/corner_assembly.hpp) in groups of k_atom_units consecutive units; METIS cuts the
//   atoms into one part per rank (solver/unit_partition.hpp). Every sum of the cycle is made
//   atom by atom (a plain sum over the atom's units, or over the particles it owns, in their
//   order) and the atoms' sums are added exactly (core/exact_sum.hpp): the totals are the same
//   bits for any number of ranks and threads.
// - A particle belongs to the atom of its lowest-numbered element (its energies are summed
//   there) and is owned by that atom's rank (which writes it to the results). A rank holds the
//   particles of its elements: it updates them, those shared with other ranks redundantly.
// - Each step, after the element loop, a held particle receives the corner loads of its
//   elements on other ranks and sums all its slots in element order, as one process does
//   (exchange of slots); after the step, a rank receives the positions of the particles of the
//   triangles around its held particles that it does not hold (exchange of positions: their
//   normals and pressure loads at t_n read those triangles).
#pragma once

#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/corner_assembly.hpp"

namespace fpmshell {

/// Units per atom: 8 units are 64 elements in blocks of 8 lanes, enough for a partial sum to
/// outweigh its exact addition (a few ns per term), few enough for METIS to balance parts of a
/// small model.
inline constexpr Index k_atom_units = 8;

struct DomainDecomposition {
    int rank = 0, ranks = 1;
    Index n_units = 0, n_atoms = 0;
    std::vector<int> unit_rank;  ///< per unit
    std::vector<int> atom_rank;  ///< per atom
    /// The units this rank computes: blocks (ascending) and positions in alone_elements.
    std::vector<Index> own_blocks, own_alone;
    std::vector<std::uint8_t> own_unit;  ///< per unit: computed here
    /// The own blocks with an element at a shared particle (ascending): computed first, their
    /// slots sent while the others compute.
    std::vector<Index> boundary_blocks;
    /// Particles by atom, compressed rows (atom n_atoms: the particles of no element, on rank
    /// 0), each atom's in ascending order.
    std::vector<Index> atom_particle_begin, atom_particles;
    std::vector<Index> own_atoms;       ///< the atoms whose sums this rank makes
    std::vector<Index> held_not_owned;  ///< held particles another rank owns (ascending)
    std::vector<std::uint8_t> held;     ///< per particle: updated here
    std::vector<std::uint8_t> shared;   ///< per particle: held by several ranks
    std::vector<Index> held_particles;  ///< the particles updated here (ascending)
    std::vector<Index> near_elements;   ///< the triangles with a held particle (ascending)
    std::vector<int> particle_owner;    ///< per particle: its owner rank
    /// The exchange of slots: per peer rank, the full-array offsets (full_offset, component
    /// 0) of the slots this rank sends and of those it receives, by particle then element.
    std::vector<int> slot_peers;
    std::vector<std::vector<std::size_t>> slot_send, slot_recv;
    /// The exchange of positions: per peer rank, the particles whose positions go and come.
    std::vector<int> position_peers;
    std::vector<std::vector<Index>> position_send, position_recv;

    [[nodiscard]] bool distributed() const { return ranks > 1; }
    /// The atom of unit u.
    [[nodiscard]] static Index atom_of_unit(Index u) { return u / k_atom_units; }
};

/// The decomposition of `model` for `rank` of `ranks` (every rank computes all of it, the
/// same: METIS with a fixed seed). units: the element loop's (CornerAssembly::blocks());
/// slots: the assembly, for the slot offsets. element_cost: per element (element_costs).
[[nodiscard]] DomainDecomposition decompose(const Model& model, const MeshTopology& topology,
                                            const CornerAssembly& assembly,
                                            const std::vector<Real>& element_cost, int rank,
                                            int ranks);

}  // namespace fpmshell
