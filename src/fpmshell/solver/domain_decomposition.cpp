#include "fpmshell/solver/domain_decomposition.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "fpmshell/solver/unit_partition.hpp"

namespace fpmshell {

namespace {

/// The unit of every element: its block, or n_blocks + its position among the elements alone.
std::vector<Index> element_units_of(const ElementBlocks& units, std::size_t n_elements) {
    std::vector<Index> unit(n_elements);
    for (std::size_t e = 0; e < n_elements; ++e)
        unit[e] = units.block_lane[e] >= 0 ? units.block_lane[e] / k_lanes
                                           : units.n_blocks() + units.alone_position[e];
    return unit;
}

/// The sorted, unique ranks in `ranks`.
void sort_unique(std::vector<int>& ranks) {
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
}

}  // namespace

DomainDecomposition decompose(const Model& model, const MeshTopology& topology,
                              const CornerAssembly& assembly, const std::vector<Real>& element_cost,
                              int rank, int ranks) {
    const ElementBlocks& units = assembly.blocks();
    const std::size_t ne = model.triangles.size(), np = model.nodes.size();
    DomainDecomposition d;
    d.rank = rank;
    d.ranks = ranks;
    d.n_units = units.n_blocks() + units.n_alone();
    d.n_atoms = (d.n_units + k_atom_units - 1) / k_atom_units;
    const UnitPartition parts = partition_units(units, model.triangles, static_cast<Index>(np),
                                                element_cost, ranks, k_atom_units);
    d.unit_rank = parts.unit_part;
    d.atom_rank.assign(static_cast<std::size_t>(d.n_atoms), 0);
    for (Index u = 0; u < d.n_units; ++u)
        d.atom_rank[static_cast<std::size_t>(DomainDecomposition::atom_of_unit(u))] =
            d.unit_rank[static_cast<std::size_t>(u)];
    d.own_unit.assign(static_cast<std::size_t>(d.n_units), 0);
    for (Index u = 0; u < d.n_units; ++u)
        d.own_unit[static_cast<std::size_t>(u)] = d.unit_rank[static_cast<std::size_t>(u)] == rank;
    for (Index b = 0; b < units.n_blocks(); ++b)
        if (d.unit_rank[static_cast<std::size_t>(b)] == rank) d.own_blocks.push_back(b);
    for (Index i = 0; i < units.n_alone(); ++i)
        if (d.unit_rank[static_cast<std::size_t>(units.n_blocks() + i)] == rank)
            d.own_alone.push_back(i);

    // Atoms of the particles (that of the lowest element), their owners, and the ranks that
    // hold each particle.
    const std::vector<Index> element_unit = element_units_of(units, ne);
    std::vector<Index> particle_atom(np, d.n_atoms);            // n_atoms: no element
    std::vector<std::vector<int>> holders(ranks > 1 ? np : 0);  // one rank: itself
    for (std::size_t e = 0; e < ne; ++e) {
        const Index u = element_unit[e];
        const int r = d.unit_rank[static_cast<std::size_t>(u)];
        for (const Index p : model.triangles[e]) {
            const auto up = static_cast<std::size_t>(p);
            if (particle_atom[up] == d.n_atoms)
                particle_atom[up] = DomainDecomposition::atom_of_unit(u);
            if (ranks > 1) holders[up].push_back(r);
        }
    }
    d.atom_particle_begin.assign(static_cast<std::size_t>(d.n_atoms) + 2, 0);
    for (std::size_t p = 0; p < np; ++p)
        ++d.atom_particle_begin[static_cast<std::size_t>(particle_atom[p]) + 1];
    for (std::size_t a = 0; a + 1 < d.atom_particle_begin.size(); ++a)
        d.atom_particle_begin[a + 1] += d.atom_particle_begin[a];
    d.atom_particles.assign(np, 0);
    {
        std::vector<Index> fill(d.atom_particle_begin.begin(), d.atom_particle_begin.end() - 1);
        for (std::size_t p = 0; p < np; ++p)
            d.atom_particles[static_cast<std::size_t>(
                fill[static_cast<std::size_t>(particle_atom[p])]++)] = static_cast<Index>(p);
    }
    for (Index a = 0; a < d.n_atoms; ++a)
        if (d.atom_rank[static_cast<std::size_t>(a)] == rank) d.own_atoms.push_back(a);
    if (rank == 0) d.own_atoms.push_back(d.n_atoms);  // the particles of no element
    d.held.assign(np, 0);
    d.shared.assign(np, 0);
    d.particle_owner.assign(np, 0);
    if (ranks == 1) {  // everything here
        d.held.assign(np, 1);
        d.shared.assign(np, 0);
        d.particle_owner.assign(np, 0);
        d.held_particles.resize(np);
        for (std::size_t p = 0; p < np; ++p) d.held_particles[p] = static_cast<Index>(p);
        return d;
    }
    for (std::size_t p = 0; p < np; ++p) {
        sort_unique(holders[p]);
        const Index a = particle_atom[p];
        d.particle_owner[p] = a < d.n_atoms ? d.atom_rank[static_cast<std::size_t>(a)] : 0;
        // a particle of no element is updated everywhere (its loads are external only)
        const bool held =
            holders[p].empty() || std::binary_search(holders[p].begin(), holders[p].end(), rank);
        d.held[p] = held ? 1 : 0;
        d.shared[p] = holders[p].size() > 1 ? 1 : 0;
        if (held) d.held_particles.push_back(static_cast<Index>(p));
        if (held && d.particle_owner[p] != rank && !holders[p].empty())
            d.held_not_owned.push_back(static_cast<Index>(p));
    }
    for (const Index b : d.own_blocks) {
        bool boundary = false;
        for (Index l = 0; l < k_lanes && !boundary; ++l)
            for (const Index p : model.triangles[static_cast<std::size_t>(
                     units.block_elements[static_cast<std::size_t>(b * k_lanes + l)])])
                boundary = boundary || d.shared[static_cast<std::size_t>(p)];
        if (boundary) d.boundary_blocks.push_back(b);
    }
    for (std::size_t e = 0; e < ne; ++e) {
        const auto& t = model.triangles[e];
        if (d.held[static_cast<std::size_t>(t[0])] || d.held[static_cast<std::size_t>(t[1])] ||
            d.held[static_cast<std::size_t>(t[2])])
            d.near_elements.push_back(static_cast<Index>(e));
    }

    // The exchange of slots: slot j of particle p (its j-th element, in element order) is
    // computed by the rank of that element's unit and sent to every other rank holding p.
    std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> slots;
    {
        for (std::size_t p = 0; p < np; ++p) {
            if (holders[p].size() < 2) continue;
            // the particle's elements in element order, as its slots
            const std::span<const Index> elements = topology.elements_of(static_cast<Index>(p));
            const std::span<const std::size_t> offsets = assembly.particle_slots(p);
            for (std::size_t j = 0; j < elements.size() && j < offsets.size(); ++j) {
                const int from = d.unit_rank[static_cast<std::size_t>(
                    element_unit[static_cast<std::size_t>(elements[j])])];
                for (const int to : holders[p]) {
                    if (to == from) continue;
                    if (from == rank) slots[to].first.push_back(offsets[j]);
                    if (to == rank) slots[from].second.push_back(offsets[j]);
                }
            }
        }
    }
    for (auto& [peer, lists] : slots) {
        d.slot_peers.push_back(peer);
        d.slot_send.push_back(std::move(lists.first));
        d.slot_recv.push_back(std::move(lists.second));
    }

    // The exchange of positions: every rank holding a node of a triangle needs the positions
    // of all three (the triangle's normal and pressure at t_n); the owner sends those it does
    // not hold.
    std::map<int, std::pair<std::vector<Index>, std::vector<Index>>> positions;
    {
        std::vector<std::pair<Index, int>> needs;  // (particle, rank that needs it)
        for (std::size_t e = 0; e < ne; ++e) {
            std::vector<int> near;
            for (const Index p : model.triangles[e]) {
                const auto& h = holders[static_cast<std::size_t>(p)];
                near.insert(near.end(), h.begin(), h.end());
            }
            sort_unique(near);
            for (const Index p : model.triangles[e]) {
                const auto& h = holders[static_cast<std::size_t>(p)];
                for (const int r : near)
                    if (!std::binary_search(h.begin(), h.end(), r)) needs.push_back({p, r});
            }
        }
        std::sort(needs.begin(), needs.end());
        needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
        for (const auto& [p, r] : needs) {
            const int from = d.particle_owner[static_cast<std::size_t>(p)];
            if (from == rank) positions[r].first.push_back(p);
            if (r == rank) positions[from].second.push_back(p);
        }
    }
    for (auto& [peer, lists] : positions) {
        d.position_peers.push_back(peer);
        d.position_send.push_back(std::move(lists.first));
        d.position_recv.push_back(std::move(lists.second));
    }
    return d;
}

}  // namespace fpmshell
