// Tied surfaces: the pairing of each slave with its closest face at t = 0 (a bucket grid over the
// faces), and the velocity projection of eq. 6.12-1 (theory.md §6.12).
#include "fpmshell/solver/tied_surfaces.hpp"

#include <algorithm>
#include <cmath>

#include "fpmshell/contact/bucket_grid.hpp"
#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/model/node_thickness.hpp"
#include "fpmshell/solver/boundary_conditions.hpp"
#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

TiedSurfaces::TiedSurfaces(const Model& model, const std::vector<Real>& element_thickness)
    : model_(&model) {
    if (model.tied_surfaces.empty()) return;
    const std::vector<Real> node_h =
        mean_node_thickness(model.triangles, element_thickness, model.nodes.size());
    for (std::size_t entry = 0; entry < model.tied_surfaces.size(); ++entry) {
        const TiedSurface& surface = model.tied_surfaces[entry];
        // the faces' boxes grown by the largest reach a pair may have
        Real h_max = 0;
        for (const Index e : surface.elements)
            h_max = std::max(h_max, element_thickness[static_cast<std::size_t>(e)]);
        for (const Index p : surface.nodes)
            h_max = std::max(h_max, node_h[static_cast<std::size_t>(p)]);
        const Real reach = surface.tolerance > 0 ? surface.tolerance : h_max;
        std::vector<Vec3> lo(surface.elements.size()), hi(surface.elements.size());
        Real mean_extent = 0;
        for (std::size_t i = 0; i < surface.elements.size(); ++i) {
            const auto& t = model.triangles[static_cast<std::size_t>(surface.elements[i])];
            const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
            const Vec3& b = model.nodes[static_cast<std::size_t>(t[1])];
            const Vec3& c = model.nodes[static_cast<std::size_t>(t[2])];
            lo[i] = a.cwiseMin(b).cwiseMin(c) - Vec3::Constant(reach);
            hi[i] = a.cwiseMax(b).cwiseMax(c) + Vec3::Constant(reach);
            mean_extent += (hi[i] - lo[i]).maxCoeff();
        }
        mean_extent /= static_cast<Real>(surface.elements.size());
        BucketGrid grid;
        grid.build(lo, hi, mean_extent);
        for (const Index s : surface.nodes) {
            const Vec3& x = model.nodes[static_cast<std::size_t>(s)];
            Tie best;
            Real best_distance = 0;
            grid.for_each_near(x, [&](Index item) {
                const auto ui = static_cast<std::size_t>(item);
                if ((x.array() < lo[ui].array()).any() || (x.array() > hi[ui].array()).any())
                    return;
                const Index e = surface.elements[ui];
                const auto& t = model.triangles[static_cast<std::size_t>(e)];
                if (t[0] == s || t[1] == s || t[2] == s) return;  // its own face
                const TriangleClosestPoint cp =
                    closest_point_on_triangle(x, model.nodes[static_cast<std::size_t>(t[0])],
                                              model.nodes[static_cast<std::size_t>(t[1])],
                                              model.nodes[static_cast<std::size_t>(t[2])], 0.0);
                const Real distance = (x - cp.point).norm();
                const Real tolerance =
                    surface.tolerance > 0
                        ? surface.tolerance
                        : std::max(node_h[static_cast<std::size_t>(s)],
                                   element_thickness[static_cast<std::size_t>(e)]);
                if (distance > tolerance) return;
                // the closest face; of equally close ones the first in the element order (the
                // buckets' order is that of the items, the same on every run)
                if (best.slave >= 0 && !(distance < best_distance)) return;
                // the side of the face the slave starts on (a tiebreak's tension, eq. 6.12-2)
                const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
                const Vec3 n = (model.nodes[static_cast<std::size_t>(t[1])] - a)
                                   .cross(model.nodes[static_cast<std::size_t>(t[2])] - a)
                                   .normalized();
                const Real off = n.dot(x - cp.point);
                const int side = std::abs(off) > 1e-9 * (1 + x.norm()) ? (off > 0 ? 1 : -1) : 0;
                best = {s, t, cp.xi, static_cast<Index>(entry), side};
                best.face = e;
                best_distance = distance;
            });
            if (best.slave >= 0)
                ties_.push_back(best);
            else
                ++untied_;
        }
    }
    // eq. 6.12-3: each slave's area, for the limits given as stresses
    std::vector<Real> node_area(model.nodes.size(), 0.0);
    for (const auto& t : model.triangles) {
        const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
        const Real third = (model.nodes[static_cast<std::size_t>(t[1])] - a)
                               .cross(model.nodes[static_cast<std::size_t>(t[2])] - a)
                               .norm() /
                           6.0;
        for (const Index p : t) node_area[static_cast<std::size_t>(p)] += third;
    }
    for (Tie& t : ties_) t.area = node_area[static_cast<std::size_t>(t.slave)];
    broken_.assign(ties_.size(), 0);
    impulse_.assign(ties_.size(), Vec3::Zero());
    tension_.assign(ties_.size(), 0.0);
    shear_.assign(ties_.size(), 0.0);
}

std::size_t TiedSurfaces::broken() const {
    return static_cast<std::size_t>(std::count(broken_.begin(), broken_.end(), 1));
}

void TiedSurfaces::release_eroded(const std::vector<Index>& eroded) {
    for (std::size_t i = 0; i < ties_.size(); ++i)
        if (std::binary_search(eroded.begin(), eroded.end(), ties_[i].face)) {
            broken_[i] = 1;
            tension_[i] = shear_[i] = 0;
        }
}

std::vector<Index> TiedSurfaces::slaves() const {
    std::vector<Index> out;
    for (const Tie& t : ties_) out.push_back(t.slave);
    return out;
}

std::vector<Index> TiedSurfaces::particles() const {
    std::vector<Index> out;
    for (const Tie& t : ties_) {
        out.push_back(t.slave);
        out.insert(out.end(), t.corner.begin(), t.corner.end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

void TiedSurfaces::impose(ParticleState& s, const BoundaryConditions& bc, Real impulse_time,
                          bool new_step) {
    if (ties_.empty()) return;
    Real scale = 0;  // the largest velocity of the tied particles
    for (std::size_t i = 0; i < ties_.size(); ++i) {
        if (new_step) impulse_[i].setZero();
        if (broken_[i]) continue;
        const Tie& t = ties_[i];
        scale = std::max(scale, s.v[static_cast<std::size_t>(t.slave)].cwiseAbs().maxCoeff());
        for (const Index k : t.corner)
            scale = std::max(scale, s.v[static_cast<std::size_t>(k)].cwiseAbs().maxCoeff());
    }
    const Real tolerance = 1e-13 * scale;
    for (int sweep = 0; sweep < k_max_sweeps; ++sweep) {
        Real largest = 0;
        for (std::size_t i = 0; i < ties_.size(); ++i) {
            if (broken_[i]) continue;
            const Tie& t = ties_[i];
            const auto us = static_cast<std::size_t>(t.slave);
            Vec3 mismatch = -s.v[us];
            for (std::size_t k = 0; k < 3; ++k)
                mismatch += t.xi[k] * s.v[static_cast<std::size_t>(t.corner[k])];
            largest = std::max(largest, mismatch.cwiseAbs().maxCoeff());
            // the impulse J per direction: v_s + J / m_s = sum xi_k (v_k - xi_k J / m_k)
            const Vec3 inv_s = bc.free_inverse_mass(us, s.mass[us]);
            Vec3 weight = inv_s;
            std::array<Vec3, 3> inv_k;
            for (std::size_t k = 0; k < 3; ++k) {
                const auto uk = static_cast<std::size_t>(t.corner[k]);
                inv_k[k] = bc.free_inverse_mass(uk, s.mass[uk]);
                weight += (t.xi[k] * t.xi[k]) * inv_k[k];
            }
            Vec3 impulse = Vec3::Zero();
            for (Eigen::Index d = 0; d < 3; ++d)
                if (weight[d] > 0) impulse[d] = mismatch[d] / weight[d];
            impulse_[i] += impulse;
            s.v[us] += inv_s.cwiseProduct(impulse);
            for (std::size_t k = 0; k < 3; ++k)
                s.v[static_cast<std::size_t>(t.corner[k])] -=
                    t.xi[k] * inv_k[k].cwiseProduct(impulse);
        }
        if (largest <= tolerance) break;
    }
    // eq. 6.12-2: each tie's force on its slave, f = J / (c1 dt_n), in tension (pulling the slave
    // back to its side of the face; either way for a slave on the face) and in shear
    for (std::size_t i = 0; i < ties_.size(); ++i) {
        tension_[i] = shear_[i] = 0;
        if (broken_[i]) continue;
        const Tie& t = ties_[i];
        const TiedSurface& surface = model_->tied_surfaces[static_cast<std::size_t>(t.surface)];
        const Vec3& a = s.x[static_cast<std::size_t>(t.corner[0])];
        const Vec3 n = (s.x[static_cast<std::size_t>(t.corner[1])] - a)
                           .cross(s.x[static_cast<std::size_t>(t.corner[2])] - a)
                           .normalized();
        const Vec3 force = impulse_[i] / impulse_time;
        const Real along = force.dot(n);
        tension_[i] = t.side > 0   ? std::max(Real(0), -along)
                      : t.side < 0 ? std::max(Real(0), along)
                                   : std::abs(along);
        shear_[i] = (force - along * n).norm();
        // the limits: forces, or stresses times the slave's area (eq. 6.12-3)
        const Real normal_limit =
            surface.normal_force > 0 ? surface.normal_force : surface.normal_stress * t.area;
        const Real shear_limit =
            surface.shear_force > 0 ? surface.shear_force : surface.shear_stress * t.area;
        if (normal_limit == 0 && shear_limit == 0) continue;
        Real criterion = 0;
        if (normal_limit > 0)
            criterion += std::pow(tension_[i] / normal_limit, surface.normal_exponent);
        if (shear_limit > 0) criterion += std::pow(shear_[i] / shear_limit, surface.shear_exponent);
        if (criterion >= 1) broken_[i] = 1;
    }
}

}  // namespace fpmshell
