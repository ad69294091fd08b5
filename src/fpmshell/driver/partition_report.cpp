#include "fpmshell/driver/partition_report.hpp"

#include <fmt/format.h>

#include "fpmshell/solver/corner_assembly.hpp"
#include "fpmshell/solver/domain_decomposition.hpp"
#include "fpmshell/solver/shell_elements.hpp"
#include "fpmshell/solver/unit_partition.hpp"

namespace fpmshell {

std::string partition_report(const Model& model, int n_parts) {
    const ElementBlocks units = element_units(model);
    // the parts a distributed run makes: atoms of k_atom_units units (domain_decomposition.hpp)
    const UnitPartition cut =
        partition_units(units, model.triangles, static_cast<Index>(model.nodes.size()),
                        element_costs(model, units), n_parts, k_atom_units);
    // a received corner slot: force and moment, 6 doubles
    constexpr double k_slot_bytes = 6 * sizeof(Real);
    std::string out = fmt::format(
        "{} elements in {} units ({} blocks of {}, {} elements alone), {} particles\n"
        "cut into {} part(s) by METIS k-way on the graph of atoms of {} units, weighted by "
        "element cost: "
        "imbalance {:.3f}, edge cut {}\n",
        model.triangles.size(), units.n_blocks() + units.n_alone(), units.n_blocks(), k_lanes,
        units.n_alone(), model.nodes.size(), n_parts, k_atom_units, cut.imbalance(), cut.edge_cut);
    out +=
        "| part | units | elements | cost | particles | owned | shared | received slots / "
        "step | received kB / step | neighbours |\n";
    out += "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    Index slots = 0;
    for (std::size_t p = 0; p < cut.parts.size(); ++p) {
        const UnitPartition::Part& q = cut.parts[p];
        slots += q.remote_slots;
        out +=
            fmt::format("| {} | {} | {} | {:.0f} | {} | {} | {} | {} | {:.1f} | {} |\n", p, q.units,
                        q.elements, q.cost, q.particles, q.owned, q.shared, q.remote_slots,
                        static_cast<double>(q.remote_slots) * k_slot_bytes / 1e3, q.neighbours);
    }
    out += fmt::format("all parts: {} received slots per step, {:.1f} kB\n", slots,
                       static_cast<double>(slots) * k_slot_bytes / 1e3);
    return out;
}

}  // namespace fpmshell
