// The connectivity of a model's triangles and the lumped inertia of its particles, built once
// from the Model and shared by everything that needs them (the particle update, the element
// loop, the contact, the output).
//
// Numbering: corner i (0, 1, 2) of element e is particle triangles[e][i]. Side i of element e is
// the side opposite its corner i: it runs from corner (i + 1) % 3 to corner (i + 2) % 3, and
// has the index 3 e + i in the per-side arrays. Two elements are side neighbours when exactly
// two elements share the side's two particles; a side on the boundary, or shared by three or
// more elements (a T-junction), has no neighbour.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct MeshTopology {
    /// Builds the maps, the side neighbours and the lumped masses of the model's triangles.
    explicit MeshTopology(const Model& model);

    [[nodiscard]] Index n_particles() const { return static_cast<Index>(particle_mass.size()); }
    [[nodiscard]] Index n_elements() const { return static_cast<Index>(element_node_mass.size()); }

    /// Particle -> the elements it is a corner of, in ascending element order (CSR: those of
    /// particle p are element[element_begin[p] ... element_begin[p + 1] - 1]).
    std::vector<Index> element_begin, element;
    [[nodiscard]] std::span<const Index> elements_of(Index p) const {
        const auto up = static_cast<std::size_t>(p);
        return {element.data() + element_begin[up], element.data() + element_begin[up + 1]};
    }

    /// Particle -> the other particles of its elements, ascending, each once (CSR as above).
    std::vector<Index> neighbour_begin, neighbour;
    [[nodiscard]] std::span<const Index> neighbours_of(Index p) const {
        const auto up = static_cast<std::size_t>(p);
        return {neighbour.data() + neighbour_begin[up], neighbour.data() + neighbour_begin[up + 1]};
    }

    /// Per side 3 e + i: the element across it (-1: none), and that element's side there.
    std::vector<Index> side_neighbour;
    std::vector<int> side_neighbour_side;
    /// Per side 3 e + i, two entries (2 (3 e + i) and + 1): the neighbour's corners at this
    /// side's ends, corner (i + 1) % 3 and corner (i + 2) % 3 of e (-1: no neighbour).
    std::vector<int> side_neighbour_corner;

    /// Multiplies each element's mass and inertia shares by factor[e] (>= 1, §6.10 mass
    /// scaling) and sums the particles' masses and inertias again.
    void scale_element_masses(const std::vector<Real>& factor);

    /// §6.1 lumped mass and §6.2 rotary inertia (control.rotary_inertia) of every particle:
    /// the shares of its elements (node_inertia_share) summed in element order.
    std::vector<Real> particle_mass, particle_inertia;
    /// Per element, its share at each of its corners (the same for the three), and the
    /// share's inertia / mass.
    std::vector<Real> element_node_mass, element_node_inertia, element_gyration2;
    /// per particle, its shares of the rigid sections with a given inertia (eq. 6.11-9);
    /// empty without such sections
    std::vector<Real> inertia_share_mass, inertia_share_inertia;
    /// per particle, the point masses of `masses` it carries (§6.1), in their order; empty
    /// without them
    std::vector<Real> point_mass;

private:
    /// particle_mass and particle_inertia from the element shares, in element order, then the
    /// rigid sections' shares and the point masses.
    void sum_particle_shares();
    std::vector<Index> corner_particle;  ///< 3 e + i: corner i of element e
};

}  // namespace fpmshell
