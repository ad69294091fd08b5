#include "fpmshell/model/mesh_topology.hpp"

#include <algorithm>
#include <cmath>

#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/model/rigid_inertia_shares.hpp"

namespace fpmshell {
namespace {

/// CSR begin array from per-row counts (counts[p + 1] holds row p's count on entry).
void prefix_sum(std::vector<Index>& begin) {
    for (std::size_t p = 0; p + 1 < begin.size(); ++p) begin[p + 1] += begin[p];
}

}  // namespace

MeshTopology::MeshTopology(const Model& model) {
    const auto& tri = model.triangles;
    const std::size_t np = model.nodes.size(), ne = tri.size();

    // Particle -> elements, ascending (filled in element order).
    element_begin.assign(np + 1, 0);
    for (const auto& t : tri)
        for (const Index p : t) ++element_begin[static_cast<std::size_t>(p) + 1];
    prefix_sum(element_begin);
    element.assign(static_cast<std::size_t>(element_begin[np]), 0);
    {
        std::vector<Index> fill(element_begin.begin(), element_begin.end() - 1);
        for (std::size_t e = 0; e < ne; ++e)
            for (const Index p : tri[e])
                element[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] =
                    static_cast<Index>(e);
    }

    // Particle -> particles of its elements, ascending, unique.
    neighbour_begin.assign(np + 1, 0);
    std::vector<Index> around;
    for (std::size_t p = 0; p < np; ++p) {
        around.clear();
        for (const Index e : elements_of(static_cast<Index>(p))) {
            const auto& t = tri[static_cast<std::size_t>(e)];
            for (std::size_t k = 0; k < 3; ++k)
                if (t[k] == static_cast<Index>(p))
                    for (std::size_t j = 0; j < 3; ++j)
                        if (j != k) around.push_back(t[j]);
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        neighbour.insert(neighbour.end(), around.begin(), around.end());
        neighbour_begin[p + 1] = static_cast<Index>(neighbour.size());
    }

    // Side neighbours: side i of e joins (i + 1) and (i + 2); the elements on it are those of
    // the first end that also hold the second.
    side_neighbour.assign(3 * ne, -1);
    side_neighbour_side.assign(3 * ne, -1);
    side_neighbour_corner.assign(6 * ne, -1);
    for (std::size_t e = 0; e < ne; ++e)
        for (std::size_t i = 0; i < 3; ++i) {
            const Index a = tri[e][(i + 1) % 3], b = tri[e][(i + 2) % 3];
            int on_side = 0;
            Index other = -1;
            for (const Index n : elements_of(a)) {
                const auto& tn = tri[static_cast<std::size_t>(n)];
                if (std::find(tn.begin(), tn.end(), b) == tn.end()) continue;
                ++on_side;
                if (n != static_cast<Index>(e)) other = n;
            }
            if (on_side != 2 || other < 0) continue;
            const std::size_t side = 3 * e + i;
            const auto& tn = tri[static_cast<std::size_t>(other)];
            side_neighbour[side] = other;
            for (int c = 0; c < 3; ++c) {
                const Index q = tn[static_cast<std::size_t>(c)];
                if (q == a)
                    side_neighbour_corner[2 * side] = c;
                else if (q == b)
                    side_neighbour_corner[2 * side + 1] = c;
                else
                    side_neighbour_side[side] = c;  // the side opposite the corner off it
            }
        }

    // §6.1-6.2 lumped masses and rotary inertias, summed in element order.
    particle_mass.assign(np, 0.0);
    particle_inertia.assign(np, 0.0);
    element_node_mass.resize(ne);
    element_node_inertia.resize(ne);
    element_gyration2.resize(ne);
    corner_particle.resize(3 * ne);
    for (std::size_t e = 0; e < ne; ++e) {
        const auto& t = tri[e];
        for (std::size_t k = 0; k < 3; ++k) corner_particle[3 * e + k] = t[k];
        const Section& sec = model.sections[static_cast<std::size_t>(model.element_section[e])];
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        const Vec3& p0 = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = model.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = model.nodes[static_cast<std::size_t>(t[2])];
        const Vec3 cr = (p1 - p0).cross(p2 - p0);
        const Real area = 0.5 * cr.norm();
        const Real shortest_edge = std::sqrt(
            std::min({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm()}));
        const NodeInertiaShare share = node_inertia_share(model.control.rotary_inertia, mat.density,
                                                          sec.thickness, area, shortest_edge);
        // a rigid section with a given inertia shares its mass by eq. 6.11-9 instead
        element_node_mass[e] = sec.has_inertia ? 0.0 : share.mass;
        element_node_inertia[e] = sec.has_inertia ? 0.0 : share.inertia;
        element_gyration2[e] = sec.has_inertia ? 0.0 : share.gyration2;
    }
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        if (!model.sections[s].has_inertia) continue;
        const RigidInertiaShares shares = rigid_inertia_shares(model, static_cast<Index>(s));
        for (std::size_t k = 0; k < shares.particles.size(); ++k) {
            const auto p = static_cast<std::size_t>(shares.particles[k]);
            if (inertia_share_mass.empty()) {
                inertia_share_mass.assign(np, 0.0);
                inertia_share_inertia.assign(np, 0.0);
            }
            inertia_share_mass[p] += shares.mass[k];
            inertia_share_inertia[p] += shares.inertia[k];
        }
    }
    for (const PointMass& m : model.point_masses) {  // §6.1: a point mass adds no inertia
        if (point_mass.empty()) point_mass.assign(np, 0.0);
        for (std::size_t k = 0; k < m.nodes.size(); ++k)
            point_mass[static_cast<std::size_t>(m.nodes[k])] += m.masses[k];
    }
    sum_particle_shares();
}

void MeshTopology::sum_particle_shares() {
    particle_mass.assign(particle_mass.size(), 0.0);
    particle_inertia.assign(particle_inertia.size(), 0.0);
    for (std::size_t e = 0; e < element_node_mass.size(); ++e) {
        const std::size_t first = static_cast<std::size_t>(3 * e);
        for (std::size_t k = first; k < first + 3; ++k) {
            const Index p = corner_particle[k];
            particle_mass[static_cast<std::size_t>(p)] += element_node_mass[e];
            // The inertia is summed by a fused multiply-add (mass * gyration2 + sum, rounded
            // once): the compiler contracts `sum += share.inertia` so wherever the share is
            // computed beside the sum (-ffp-contract=fast, GCC's default for C++), and the
            // particle inertias must be the same bits wherever they are made.
            auto& inertia = particle_inertia[static_cast<std::size_t>(p)];
            inertia = std::fma(element_node_mass[e], element_gyration2[e], inertia);
        }
    }
    for (std::size_t p = 0; p < inertia_share_mass.size(); ++p) {
        particle_mass[p] += inertia_share_mass[p];
        particle_inertia[p] += inertia_share_inertia[p];
    }
    for (std::size_t p = 0; p < point_mass.size(); ++p) particle_mass[p] += point_mass[p];
}

void MeshTopology::scale_element_masses(const std::vector<Real>& factor) {
    for (std::size_t e = 0; e < element_node_mass.size(); ++e) {
        element_node_mass[e] *= factor[e];
        element_node_inertia[e] = element_node_mass[e] * element_gyration2[e];
    }
    sum_particle_shares();
}

}  // namespace fpmshell
