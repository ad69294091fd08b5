#include "fpmshell/solver/unit_partition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#ifdef FPMSHELL_HAVE_METIS
#include <metis.h>
#endif

namespace fpmshell {

bool partitioning_available() {
#ifdef FPMSHELL_HAVE_METIS
    return true;
#else
    return false;
#endif
}

std::vector<Real> element_costs(const Model& model, const ElementBlocks& units) {
    std::vector<Real> cost(model.triangles.size());
    for (std::size_t e = 0; e < cost.size(); ++e) {
        const Section& sec = model.sections[static_cast<std::size_t>(model.element_section[e])];
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        Real c = static_cast<Real>(sec.thickness_points * sec.inplane_points) / 15.0;
        if (mat.plastic()) c *= 2.0;
        if (units.block_lane[e] < 0) c *= 4.0;
        cost[e] = c;
    }
    return cost;
}

Real UnitPartition::imbalance() const {
    Real total = 0, largest = 0;
    for (const Part& p : parts) {
        total += p.cost;
        largest = std::max(largest, p.cost);
    }
    return total > 0 ? largest * static_cast<Real>(parts.size()) / total : 1.0;
}

namespace {

/// The elements of every unit: the blocks (k_lanes elements each) first, then the elements
/// alone.
std::vector<std::vector<Index>> unit_elements(const ElementBlocks& units) {
    std::vector<std::vector<Index>> out;
    const auto lanes = static_cast<std::ptrdiff_t>(k_lanes);
    for (Index b = 0; b < units.n_blocks(); ++b) {
        const auto first = units.block_elements.begin() + b * lanes;
        out.emplace_back(first, first + lanes);
    }
    for (const Index e : units.alone_elements) out.push_back({e});
    return out;
}

#ifdef FPMSHELL_HAVE_METIS
/// METIS k-way on the unit graph: vertex weights from the costs, edge weights the shared
/// particles.
std::vector<int> metis_parts(const std::vector<std::vector<Index>>& members,
                             const std::vector<std::array<Index, 3>>& triangles, Index n_particles,
                             const std::vector<Real>& element_cost, int n_parts, Index& edge_cut) {
    const std::size_t n_units = members.size();
    std::vector<Index> element_unit(triangles.size(), -1);
    for (std::size_t u = 0; u < n_units; ++u)
        for (const Index e : members[u]) element_unit[static_cast<std::size_t>(e)] = Index(u);
    // particle -> the units touching it, each once, compressed rows
    std::vector<Index> begin(static_cast<std::size_t>(n_particles) + 1, 0);
    for (const auto& tri : triangles)
        for (const Index p : tri) ++begin[static_cast<std::size_t>(p) + 1];
    std::partial_sum(begin.begin(), begin.end(), begin.begin());
    std::vector<Index> at(begin.begin(), begin.end() - 1), touching(begin.back());
    for (std::size_t e = 0; e < triangles.size(); ++e)
        for (const Index p : triangles[e])
            touching[static_cast<std::size_t>(at[static_cast<std::size_t>(p)]++)] = element_unit[e];
    std::vector<Index> unique_end(static_cast<std::size_t>(n_particles));
    for (std::size_t p = 0; p < unique_end.size(); ++p) {
        const auto first = touching.begin() + begin[p], last = touching.begin() + begin[p + 1];
        std::sort(first, last);
        unique_end[p] = static_cast<Index>(std::unique(first, last) - touching.begin());
    }
    // unit graph: a neighbour per shared particle, merged into one weighted edge
    std::vector<idx_t> xadj{0}, adjncy, adjwgt, vwgt;
    std::vector<Index> seen;
    for (std::size_t u = 0; u < n_units; ++u) {
        seen.clear();
        for (const Index e : members[u])
            for (const Index p : triangles[static_cast<std::size_t>(e)]) {
                const auto up = static_cast<std::size_t>(p);
                for (Index k = begin[up]; k < unique_end[up]; ++k) {
                    const Index v = touching[static_cast<std::size_t>(k)];
                    if (v != Index(u)) seen.push_back(v);
                }
            }
        std::sort(seen.begin(), seen.end());
        // a particle met through several of the unit's elements counts once per element
        for (std::size_t i = 0; i < seen.size();) {
            std::size_t j = i;
            while (j < seen.size() && seen[j] == seen[i]) ++j;
            adjncy.push_back(static_cast<idx_t>(seen[i]));
            adjwgt.push_back(static_cast<idx_t>(j - i));
            i = j;
        }
        xadj.push_back(static_cast<idx_t>(adjncy.size()));
        Real w = 0;
        for (const Index e : members[u]) w += element_cost[static_cast<std::size_t>(e)];
        vwgt.push_back(std::max<idx_t>(1, static_cast<idx_t>(std::lround(100.0 * w))));
    }
    idx_t nvtxs = static_cast<idx_t>(n_units), ncon = 1, nparts = n_parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;  // the same parts for the same model, run after run
    options[METIS_OPTION_NUMBERING] = 0;
    std::vector<idx_t> part(n_units, 0);
    const int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), vwgt.data(),
                                           nullptr, adjwgt.data(), &nparts, nullptr, nullptr,
                                           options, &objval, part.data());
    if (status != METIS_OK)
        throw std::runtime_error("METIS could not cut the model into " + std::to_string(n_parts) +
                                 " parts (status " + std::to_string(status) + ")");
    edge_cut = static_cast<Index>(objval);
    return {part.begin(), part.end()};
}
#endif

}  // namespace

UnitPartition partition_units(const ElementBlocks& units,
                              const std::vector<std::array<Index, 3>>& triangles, Index n_particles,
                              const std::vector<Real>& element_cost, int n_parts,
                              Index units_per_atom) {
    if (n_parts < 1) throw std::invalid_argument("partition_units: n_parts must be >= 1");
    if (units_per_atom < 1)
        throw std::invalid_argument("partition_units: units_per_atom must be >= 1");
    const std::vector<std::vector<Index>> members = unit_elements(units);
    UnitPartition out;
    out.n_parts = n_parts;
    out.unit_part.assign(members.size(), 0);
    // more parts than units: METIS leaves some empty, which the statistics show
    if (n_parts > 1) {
#ifdef FPMSHELL_HAVE_METIS
        // the atoms: units_per_atom consecutive units each, cut whole
        const auto per_atom = static_cast<std::size_t>(units_per_atom);
        std::vector<std::vector<Index>> atoms((members.size() + per_atom - 1) / per_atom);
        for (std::size_t u = 0; u < members.size(); ++u)
            atoms[u / per_atom].insert(atoms[u / per_atom].end(), members[u].begin(),
                                       members[u].end());
        const std::vector<int> atom_part =
            metis_parts(atoms, triangles, n_particles, element_cost, n_parts, out.edge_cut);
        for (std::size_t u = 0; u < members.size(); ++u) out.unit_part[u] = atom_part[u / per_atom];
#else
        throw std::runtime_error(
            "this build has no METIS (libmetis-dev): it cannot cut a model into parts");
#endif
    }
    out.element_part.assign(triangles.size(), 0);
    out.parts.assign(static_cast<std::size_t>(n_parts), {});
    for (std::size_t u = 0; u < members.size(); ++u) {
        UnitPartition::Part& part = out.parts[static_cast<std::size_t>(out.unit_part[u])];
        ++part.units;
        for (const Index e : members[u]) {
            out.element_part[static_cast<std::size_t>(e)] = out.unit_part[u];
            ++part.elements;
            part.cost += element_cost[static_cast<std::size_t>(e)];
        }
    }
    // owners, and per particle the corners each part has there
    const auto np = static_cast<std::size_t>(n_particles);
    out.particle_owner.assign(np, -1);
    std::vector<std::vector<std::pair<int, Index>>> corners(np);  // (part, corners)
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const int part = out.element_part[e];
        for (const Index p : triangles[e]) {
            const auto up = static_cast<std::size_t>(p);
            if (out.particle_owner[up] < 0) out.particle_owner[up] = part;  // lowest element
            auto& list = corners[up];
            auto it = std::find_if(list.begin(), list.end(),
                                   [part](const auto& pc) { return pc.first == part; });
            if (it == list.end())
                list.push_back({part, 1});
            else
                ++it->second;
        }
    }
    std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(n_parts));
    for (std::size_t p = 0; p < np; ++p) {
        if (out.particle_owner[p] >= 0)
            ++out.parts[static_cast<std::size_t>(out.particle_owner[p])].owned;
        Index all = 0;
        for (const auto& pc : corners[p]) all += pc.second;
        for (const auto& [part, mine] : corners[p]) {
            UnitPartition::Part& q = out.parts[static_cast<std::size_t>(part)];
            ++q.particles;
            if (corners[p].size() < 2) continue;
            ++q.shared;
            q.remote_slots += all - mine;
            for (const auto& other : corners[p])
                if (other.first != part)
                    neighbours[static_cast<std::size_t>(part)].push_back(other.first);
        }
    }
    for (std::size_t q = 0; q < neighbours.size(); ++q) {
        auto& n = neighbours[q];
        std::sort(n.begin(), n.end());
        out.parts[q].neighbours = static_cast<Index>(std::unique(n.begin(), n.end()) - n.begin());
    }
    return out;
}

}  // namespace fpmshell
