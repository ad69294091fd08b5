// The element loop's units of work (SIMD blocks and elements computed alone,
// solver/corner_assembly.hpp) cut into parts, one per process of a distributed run: METIS
// (k-way) on the graph of the units that share a particle, each unit weighted by an estimate of
// its cost, each edge by the particles the two units share. Whole units, not elements, are cut:
// a block's lanes then stay together, so that a part computes every element, and every block
// total, as the single-process run does.
//
// A particle is owned by the part of the lowest-numbered element touching it. A part holds the
// particles of its elements ("local"); a local particle that elements of other parts touch too
// is shared, and the corner loads of those elements are what a part receives every step
// (UnitPartition::Part::remote_slots): the halo traffic of the scaling model in
// docs/performance.md.
#pragma once

#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/corner_assembly.hpp"

namespace fpmshell {

/// Whether this build can cut a model into more than one part (METIS was found).
[[nodiscard]] bool partitioning_available();

/// Relative cost of each element per step: its section's points / 15 (a 5 x 3 section is 1),
/// times 2 for an elastic-plastic material (the crash kernels: a plastic block costs 1.5 to 4
/// times an elastic one, by the share of its points that yield), times 4 for an element
/// computed alone (outside the SIMD blocks: 3 to 5 times a lane of a block).
[[nodiscard]] std::vector<Real> element_costs(const Model& model, const ElementBlocks& units);

struct UnitPartition {
    struct Part {
        Index units = 0, elements = 0;
        Real cost = 0;           ///< sum of element_costs
        Index particles = 0;     ///< local: touched by its elements
        Index owned = 0;         ///< owned particles
        Index shared = 0;        ///< local particles touched by other parts' elements too
        Index remote_slots = 0;  ///< corners of other parts' elements at its shared particles
        Index neighbours = 0;    ///< parts it shares particles with
    };
    int n_parts = 1;
    std::vector<int> unit_part;       ///< per unit (blocks, then the elements alone)
    std::vector<int> element_part;    ///< per element
    std::vector<int> particle_owner;  ///< per particle (-1: touched by no element)
    std::vector<Part> parts;
    Index edge_cut = 0;  ///< the METIS objective: shared particles summed over cut unit pairs

    /// Largest part cost over the mean (1: perfect balance).
    [[nodiscard]] Real imbalance() const;
};

/// Cuts `units` of a mesh of n_particles particles into n_parts parts (1 <= n_parts; the same
/// input gives the same parts: METIS with a fixed seed). element_cost: per element.
/// units_per_atom: the units are cut in atoms of that many consecutive units, kept whole (a
/// distributed run sums its energies atom by atom, solver/domain_decomposition.hpp).
[[nodiscard]] UnitPartition partition_units(const ElementBlocks& units,
                                            const std::vector<std::array<Index, 3>>& triangles,
                                            Index n_particles,
                                            const std::vector<Real>& element_cost, int n_parts,
                                            Index units_per_atom = 1);

}  // namespace fpmshell
