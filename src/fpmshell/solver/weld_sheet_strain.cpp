// The sheets' plastic strain at the ductile welds' particles (theory.md eq. 6.11-15).
#include "fpmshell/solver/weld_sheet_strain.hpp"

#include <algorithm>
#include <span>

#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/rank_exchange.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

WeldSheetStrain::WeldSheetStrain(const Model& model, const MeshTopology& topology) {
    for (const NodalRigidBody& g : model.nodal_rigid_bodies)
        if (g.fails_by_plastic_strain())
            particles_.insert(particles_.end(), g.nodes.begin(), g.nodes.end());
    std::sort(particles_.begin(), particles_.end());
    particles_.erase(std::unique(particles_.begin(), particles_.end()), particles_.end());
    if (particles_.empty()) return;
    // per particle followed, its elements (the topology's, ascending)
    std::vector<std::span<const Index>> around;
    for (const Index p : particles_) around.push_back(topology.elements_of(p));
    for (const std::span<const Index> list : around)
        elements_.insert(elements_.end(), list.begin(), list.end());
    std::sort(elements_.begin(), elements_.end());
    elements_.erase(std::unique(elements_.begin(), elements_.end()), elements_.end());
    first_.push_back(0);
    for (const std::span<const Index> list : around) {
        for (const Index e : list)
            element_place_.push_back(static_cast<std::size_t>(
                std::lower_bound(elements_.begin(), elements_.end(), e) - elements_.begin()));
        first_.push_back(element_place_.size());
    }
    for (const Index e : elements_) {
        const auto& t = model.triangles[static_cast<std::size_t>(e)];
        const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& b = model.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& c = model.nodes[static_cast<std::size_t>(t[2])];
        area_.push_back(0.5 * (b - a).cross(c - a).norm());
    }
    value_.assign(particles_.size(), 0.0);
}

void WeldSheetStrain::update(const ShellElements& elements, const RankExchange& ranks) {
    // the records (element, its plastic strain) of the elements this rank computes, in order
    std::vector<Real> mine;
    for (const Index e : elements_)
        if (elements.computes(e))
            mine.insert(mine.end(), {static_cast<Real>(e), elements.mean_plastic_strain(e)});
    const std::vector<Real> all = ranks.join_records(mine, 2);
    std::vector<Real> strain(elements_.size(), 0.0);
    for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
        const auto e = static_cast<Index>(all[i]);
        strain[static_cast<std::size_t>(std::lower_bound(elements_.begin(), elements_.end(), e) -
                                        elements_.begin())] = all[i + 1];
    }
    // eq. 6.11-15: the lumped least-squares projection, each particle's elements in order
    for (std::size_t k = 0; k < particles_.size(); ++k) {
        Real weighted = 0, area = 0;
        for (std::size_t j = first_[k]; j < first_[k + 1]; ++j) {
            weighted += area_[element_place_[j]] * strain[element_place_[j]];
            area += area_[element_place_[j]];
        }
        value_[k] = area > 0 ? weighted / area : 0.0;
    }
}

Real WeldSheetStrain::at(Index p) const {
    const auto it = std::lower_bound(particles_.begin(), particles_.end(), p);
    if (it == particles_.end() || *it != p) return 0.0;
    return value_[static_cast<std::size_t>(it - particles_.begin())];
}

}  // namespace fpmshell
