#include "fpmshell/solver/external_loads.hpp"

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
    // §6.13 the blasts: each particle's loaded faces, as a pressure's
    for (const BlastLoad& blast : model.blast_loads) {
        BlastGather b{BlastFaces(blast, model.nodes, model.triangles), {}, {}};
        std::vector<std::vector<Index>> of_particle(np);
        for (std::size_t k = 0; k < blast.elements.size(); ++k)
            for (Index p : model.triangles[static_cast<std::size_t>(blast.elements[k])])
                of_particle[static_cast<std::size_t>(p)].push_back(static_cast<Index>(k));
        b.gather.begin.push_back(0);
        for (std::size_t p = 0; p < np; ++p) {
            if (of_particle[p].empty()) continue;
            b.gather.particle.push_back(static_cast<Index>(p));
            b.gather.element.insert(b.gather.element.end(), of_particle[p].begin(),
                                    of_particle[p].end());
            b.gather.begin.push_back(static_cast<Index>(b.gather.element.size()));
        }
        b.face_scale.assign(blast.elements.size(), 0.0);
        blasts_.push_back(std::move(b));
    }
    // A first load that is a pressure on every triangle (in element order) is summed in the
    // pass of the normals, over the same triangles in the same order (the same bits).
    if (!model.loads.empty() && model.loads[0].type == LoadType::Pressure) {
        const PressureGather& g = pressure_gather_[0];
        fused_pressure_ = g.particle.size() == np && g.begin == topology_.element_begin &&
                          g.element == topology_.element;
    }
}

void ExternalLoads::update_normals_and_loads(ParticleState& s, const BoundaryConditions& bc, Real t,
                                             bool parallel) {
    // §1.3 area-weighted normal, recomputed from the current positions: the cross product of
    // every triangle, then each particle sums those of its triangles in element order (the
    // order of a serial scatter, without its write conflicts).
    const Index ne =
        near_ ? static_cast<Index>(near_->size()) : static_cast<Index>(model_.triangles.size());
    parallel_for_each(ne, parallel, [&](Index i) {
        const Index e = near_ ? (*near_)[static_cast<std::size_t>(i)] : i;
        const auto& tri = model_.triangles[static_cast<std::size_t>(e)];
        element_cross_[static_cast<std::size_t>(e)] =
            (s.x[static_cast<std::size_t>(tri[1])] - s.x[static_cast<std::size_t>(tri[0])])
                .cross(s.x[static_cast<std::size_t>(tri[2])] -
                       s.x[static_cast<std::size_t>(tri[0])]);
    });
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
            if (fused_pressure_) f += fused_scale * cross;
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
                    for (Index k = g.begin[ui]; k < g.begin[ui + 1]; ++k)
                        f += scale * element_cross_[static_cast<std::size_t>(
                                         g.element[static_cast<std::size_t>(k)])];
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
        }
    }
    if (!blasts_.empty()) add_blast_loads(s, t, parallel);
}

void ExternalLoads::add_blast_loads(ParticleState& s, Real t, bool parallel) {
    for (std::size_t l = 0; l < blasts_.size(); ++l) {
        const BlastLoad& load = model_.blast_loads[l];
        BlastGather& b = blasts_[l];
        // eq. 6.13-4 on each face: its current normal against the line from its current
        // centroid to the charge; f_i = -p A n / 3 = -p cross / 6 (as a pressure, §6.7)
        parallel_for_each(static_cast<Index>(b.face_scale.size()), parallel, [&](Index i) {
            const auto k = static_cast<std::size_t>(i);
            const auto e = static_cast<std::size_t>(load.elements[k]);
            const auto& tri = model_.triangles[e];
            const Vec3 centroid =
                (s.x[static_cast<std::size_t>(tri[0])] + s.x[static_cast<std::size_t>(tri[1])] +
                 s.x[static_cast<std::size_t>(tri[2])]) /
                3.0;
            const Real side = load.reversed ? -1.0 : 1.0;  // the faces' normal: side n_e
            const Vec3& cross = element_cross_[e];
            const Vec3 to_charge = load.centre - centroid;
            const Real norms = cross.norm() * to_charge.norm();
            const Real cos_theta = norms > 0 ? side * cross.dot(to_charge) / norms : 1.0;
            b.face_scale[k] = -side * b.faces.pressure(k, t, cos_theta) / 6.0;
        });
        const PressureGather& g = b.gather;
        parallel_for_each(static_cast<Index>(g.particle.size()), parallel, [&](Index i) {
            const auto ui = static_cast<std::size_t>(i);
            Vec3& f = s.f_ext[static_cast<std::size_t>(g.particle[ui])];
            for (Index j = g.begin[ui]; j < g.begin[ui + 1]; ++j) {
                const auto k = static_cast<std::size_t>(g.element[static_cast<std::size_t>(j)]);
                f += b.face_scale[k] * element_cross_[static_cast<std::size_t>(load.elements[k])];
            }
        });
    }
}

}  // namespace fpmshell
