#include "fpmshell/solver/external_loads.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fpmshell/core/chunked_loop.hpp"

namespace fpmshell {

ExternalLoads::ExternalLoads(const Model& model, const MeshTopology& topology)
    : model_(model), topology_(topology) {
    const std::size_t np = model.nodes.size();
    for (const Load& load : model.loads)
        has_moment_loads_ = has_moment_loads_ || load.type == LoadType::Moment;
    element_cross_.assign(model.triangles.size(), Vec3::Zero());
    pressure_gather_.resize(model.loads.size());
    for (std::size_t l = 0; l < model.loads.size(); ++l) {
        const Load& load = model.loads[l];
        if (load.type != LoadType::Pressure) continue;
        std::vector<std::vector<Index>> of_particle(np);
        for (Index e : load.elements)
            for (Index p : model.triangles[static_cast<std::size_t>(e)])
                of_particle[static_cast<std::size_t>(p)].push_back(e);
        PressureGather& g = pressure_gather_[l];
        g.begin.push_back(0);
        for (std::size_t p = 0; p < np; ++p) {
            if (of_particle[p].empty()) continue;
            g.particle.push_back(static_cast<Index>(p));
            g.element.insert(g.element.end(), of_particle[p].begin(), of_particle[p].end());
            g.begin.push_back(static_cast<Index>(g.element.size()));
        }
    }
    // §6.13 the blasts: each triangle's face, summed in the pass of the normals
    for (const BlastLoad& blast : model.blast_loads) {
        Blast b{BlastFaces(blast, model.nodes, model.triangles),
                std::vector<Index>(model.triangles.size(), -1),
                0,
                0,
                {},
                {},
                false,
                false,
                false,
                {}};
        for (std::size_t k = 0; k < blast.elements.size(); ++k)
            b.face_of_element[static_cast<std::size_t>(blast.elements[k])] = static_cast<Index>(k);
        b.first_arrival = std::numeric_limits<Real>::infinity();
        b.last_end = -b.first_arrival;
        for (std::size_t k = 0; k < b.faces.size(); ++k) {
            b.first_arrival = std::min(b.first_arrival, b.faces.arrival(k));
            b.last_end = std::max(b.last_end, b.faces.arrival(k) + b.faces.duration(k));
        }
        if (blast.negative_phase) b.last_end = std::numeric_limits<Real>::infinity();  // eq. 6.13-5
        const auto w = static_cast<std::size_t>(k_lanes);
        b.dot.assign((b.faces.size() + w - 1) / w * w, 1.0);  // padding: cos = 1, no pulse
        b.norms.assign(b.dot.size(), 1.0);
        b.in_order = blast.elements.size() == model.triangles.size();
        for (std::size_t k = 0; b.in_order && k < blast.elements.size(); ++k)
            b.in_order = blast.elements[k] == static_cast<Index>(k);
        blasts_.push_back(std::move(b));
    }
    if (!blasts_.empty()) element_blast_scale_.assign(model.triangles.size(), 0.0);
    // A first load that is a pressure on every triangle (in element order) is summed in the
    // pass of the normals, over the same triangles in the same order (the same bits).
    if (!model.loads.empty() && model.loads[0].type == LoadType::Pressure) {
        const PressureGather& g = pressure_gather_[0];
        fused_pressure_ = g.particle.size() == np && g.begin == topology_.element_begin &&
                          g.element == topology_.element;
    }
}

void ExternalLoads::set_subset(const std::vector<Index>* near, const std::vector<Index>* held) {
    near_ = near;
    held_ = held;
    // a blast's pulses only where this rank's triangles are: the packs that hold one
    const auto w = static_cast<std::size_t>(k_lanes);
    for (Blast& b : blasts_) {
        b.near_packs.clear();
        if (near_ == nullptr) continue;
        for (const Index e : *near_)
            if (const Index k = b.face_of_element[static_cast<std::size_t>(e)]; k >= 0)
                b.near_packs.push_back(static_cast<Index>(static_cast<std::size_t>(k) / w));
        std::sort(b.near_packs.begin(), b.near_packs.end());
        b.near_packs.erase(std::unique(b.near_packs.begin(), b.near_packs.end()),
                           b.near_packs.end());
    }
}

void ExternalLoads::update_normals_and_loads(ParticleState& s, const BoundaryConditions& bc, Real t,
                                             bool parallel) {
    // §1.3 area-weighted normal, recomputed from the current positions: the cross product of
    // every triangle (cross_products), then each particle sums those of its triangles in
    // element order (the order of a serial scatter, without its write conflicts).
    // §6.13: a blast acts in the span of time in which some face is in its positive phase
    // (with its negative phase, from the first arrival to its death time)
    for (std::size_t l = 0; l < blasts_.size(); ++l) {
        const BlastLoad& load = model_.blast_loads[l];
        const Real since = t - load.detonation_time;
        blasts_[l].active = since >= blasts_[l].first_arrival && since <= blasts_[l].last_end &&
                            t < load.death_time;
    }
    const bool fused_blast = cross_products(s, t, parallel);
    if (!blasts_.empty() && !fused_blast) blast_scales(t, parallel);
    // §6.7 follower pressure: f_i = -p A_t n_t / 3 (positive pushes against n), A n = cr / 2.
    auto pressure_scale = [&](const Load& load) {
        return -load.pressure * curve_factor(model_.curves, load.curve, t) / 6.0;
    };
    // The external loads start from zero (the fused pressure: from its first triangle); those of
    // t_{n-1} stay for the work of the step by exchanging the arrays (every entry of the new
    // ones is written below).
    std::swap(s.f_ext, s.f_ext_prev);
    if (has_moment_loads_) std::swap(s.m_ext, s.m_ext_prev);
    const Real fused_scale = fused_pressure_ ? pressure_scale(model_.loads[0]) : 0.0;
    const Index n_particles =
        held_ ? static_cast<Index>(held_->size()) : static_cast<Index>(s.size());
    parallel_for_each(n_particles, parallel, [&](Index i) {
        const Index ip = held_ ? (*held_)[static_cast<std::size_t>(i)] : i;
        const std::size_t p = static_cast<std::size_t>(ip);
        Vec3 sum = Vec3::Zero(), f = Vec3::Zero();
        for (const Index e : topology_.elements_of(ip)) {
            const Vec3& cross = element_cross_[static_cast<std::size_t>(e)];
            sum += cross;
            if (fused_pressure_ && loaded(e)) f += fused_scale * cross;
            if (!blasts_.empty()) f += element_blast_scale_[static_cast<std::size_t>(e)] * cross;
        }
        const Real len = sum.norm();
        s.normal[p] = len > 0 ? Vec3(sum / len) : Vec3::UnitZ();
        s.drill_axis[p] = bc.drill_axis(p, s.normal[p]);
        s.f_ext[p] = f;
        if (has_moment_loads_) s.m_ext[p] = Vec3::Zero();
    });
    for (std::size_t l = fused_pressure_ ? 1 : 0; l < model_.loads.size(); ++l) {
        const Load& load = model_.loads[l];
        const Real factor = curve_factor(model_.curves, load.curve, t);
        switch (load.type) {
            case LoadType::Pressure: {
                // Each particle adds its loaded triangles in the load's order (that of a serial
                // scatter).
                const Real scale = pressure_scale(load);
                const PressureGather& g = pressure_gather_[l];
                parallel_for_each(static_cast<Index>(g.particle.size()), parallel, [&](Index i) {
                    const std::size_t ui = static_cast<std::size_t>(i);
                    Vec3& f = s.f_ext[static_cast<std::size_t>(g.particle[ui])];
                    for (Index k = g.begin[ui]; k < g.begin[ui + 1]; ++k) {
                        const Index e = g.element[static_cast<std::size_t>(k)];
                        if (loaded(e)) f += scale * element_cross_[static_cast<std::size_t>(e)];
                    }
                });
                break;
            }
            case LoadType::Force:
                for (Index p : load.nodes)
                    s.f_ext[static_cast<std::size_t>(p)] += factor * load.vector;
                break;
            case LoadType::Moment:
                for (Index p : load.nodes)
                    s.m_ext[static_cast<std::size_t>(p)] += factor * load.vector;
                break;
            case LoadType::Gravity: {  // eq. 6.7-4: the particle's mass (mass scaling's too)
                const Vec3 g = factor * load.vector;
                for (Index p : load.nodes) {
                    const auto up = static_cast<std::size_t>(p);
                    s.f_ext[up] += s.mass[up] * g;
                }
                break;
            }
        }
    }
}

bool ExternalLoads::cross_products(const ParticleState& s, Real t, bool parallel) {
    auto cross_of = [&](std::size_t e) {
        const auto& tri = model_.triangles[e];
        element_cross_[e] =
            (s.x[static_cast<std::size_t>(tri[1])] - s.x[static_cast<std::size_t>(tri[0])])
                .cross(s.x[static_cast<std::size_t>(tri[2])] -
                       s.x[static_cast<std::size_t>(tri[0])]);
    };
    // §6.13, eq. 6.13-4's angle of triangle e's face of blast l: side n.(c - x), |n|^2 |c - x|^2
    auto angle_of = [&](std::size_t l, std::size_t e, Real& dot, Real& norms) {
        const BlastLoad& load = model_.blast_loads[l];
        const auto& tri = model_.triangles[e];
        const Vec3 to_charge = load.centre - (s.x[static_cast<std::size_t>(tri[0])] +
                                              s.x[static_cast<std::size_t>(tri[1])] +
                                              s.x[static_cast<std::size_t>(tri[2])]) /
                                                 3.0;
        const Vec3& cross = element_cross_[e];
        dot = (load.reversed ? -1.0 : 1.0) * cross.dot(to_charge);
        norms = cross.squaredNorm() * to_charge.squaredNorm();
    };
    const std::size_t nt = model_.triangles.size();
    if (!near_ && blasts_.size() == 1 && blasts_[0].in_order && blasts_[0].active) {
        // the blast's faces k_lanes triangles at a time, in the pass (its dot and norms stay
        // in the pack: one pass over the triangles)
        blasts_[0].zeroed = false;
        const auto w = static_cast<std::size_t>(k_lanes);
        parallel_for_each(static_cast<Index>((nt + w - 1) / w), parallel, [&](Index i) {
            const std::size_t first = static_cast<std::size_t>(i) * w;
            const std::size_t n = std::min(w, nt - first);
            alignas(64) std::array<Real, k_lanes> dot, norms;
            dot.fill(1.0);  // past the faces: cos = 1, no pulse (as Blast::dot's padding)
            norms.fill(1.0);
            for (std::size_t j = 0; j < n; ++j) {
                cross_of(first + j);
                angle_of(0, first + j, dot[j], norms[j]);
            }
            const RealPack scale = face_scales(0, first, dot.data(), norms.data(), t);
            for (std::size_t j = 0; j < n; ++j)
                element_blast_scale_[first + j] =
                    loaded(static_cast<Index>(first + j)) ? lane(scale, static_cast<int>(j)) : 0.0;
        });
        return true;
    }
    const Index ne = near_ ? static_cast<Index>(near_->size()) : static_cast<Index>(nt);
    parallel_for_each(ne, parallel, [&](Index i) {
        const auto e = static_cast<std::size_t>(near_ ? (*near_)[static_cast<std::size_t>(i)] : i);
        cross_of(e);
        for (std::size_t l = 0; l < blasts_.size(); ++l) {
            Blast& b = blasts_[l];
            const Index k = b.active ? b.face_of_element[e] : -1;
            if (k >= 0)
                angle_of(l, e, b.dot[static_cast<std::size_t>(k)],
                         b.norms[static_cast<std::size_t>(k)]);
        }
    });
    return false;
}

RealPack ExternalLoads::face_scales(std::size_t l, std::size_t first, const Real* dot,
                                    const Real* norms, Real t) const {
    // eq. 6.13-4: cos theta of each face (a zero normal or distance: head on)
    const RealPack product(norms, stdx::element_aligned);
    const RealPack d(dot, stdx::element_aligned);
    const auto seen = product > 0.0;
    const RealPack cos_theta =
        select(seen, d / stdx::sqrt(select(seen, product, RealPack(1.0))), RealPack(1.0));
    const Real scale_factor = (model_.blast_loads[l].reversed ? 1.0 : -1.0) / 6.0;  // -side / 6
    return scale_factor * blasts_[l].faces.pressures(first, t, cos_theta);
}

void ExternalLoads::unload(const std::vector<Index>& eroded) {
    if (eroded.empty()) return;
    if (unloaded_.empty()) unloaded_.assign(model_.triangles.size(), 0);
    for (const Index e : eroded) unloaded_[static_cast<std::size_t>(e)] = 1;
}

void ExternalLoads::blast_scales(Real t, bool parallel) {
    // several blasts add on the triangles they share: each adds to zeros
    const bool several = blasts_.size() > 1;
    if (several) std::fill(element_blast_scale_.begin(), element_blast_scale_.end(), 0.0);
    const auto w = static_cast<std::size_t>(k_lanes);
    for (std::size_t l = 0; l < blasts_.size(); ++l) {
        const BlastLoad& load = model_.blast_loads[l];
        Blast& b = blasts_[l];
        // outside the span in which some face is in its phase: zeros, written once
        if (!b.active) {
            if (!b.zeroed && !several)
                for (const Index e : load.elements)
                    element_blast_scale_[static_cast<std::size_t>(e)] = 0.0;
            b.zeroed = true;
            continue;
        }
        b.zeroed = false;
        const BlastFaces& faces = b.faces;
        // every pack, or with a subset the packs of its triangles (the same lanes: the same
        // bits for the faces computed)
        const auto n_packs = static_cast<Index>(near_ ? b.near_packs.size() : b.dot.size() / w);
        parallel_for_each(n_packs, parallel, [&](Index i) {
            const Index pack = near_ ? b.near_packs[static_cast<std::size_t>(i)] : i;
            const std::size_t first = static_cast<std::size_t>(pack) * w;
            const RealPack scale =
                face_scales(l, first, b.dot.data() + first, b.norms.data() + first, t);
            const std::size_t n = std::min(w, faces.size() - first);
            for (std::size_t j = 0; j < n; ++j) {
                const Index e = load.elements[first + j];
                Real& out = element_blast_scale_[static_cast<std::size_t>(e)];
                out = (several ? out : 0.0) + (loaded(e) ? lane(scale, static_cast<int>(j)) : 0.0);
            }
        });
    }
}

}  // namespace fpmshell
