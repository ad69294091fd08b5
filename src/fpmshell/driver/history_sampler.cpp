#include "fpmshell/driver/history_sampler.hpp"

#include <algorithm>
#include <limits>

#include "fpmshell/core/rotation.hpp"

namespace fpmshell {

Real particle_quantity(const ExplicitSolver& solver, Quantity q, Index p) {
    const ParticleState& s = solver.state();
    const std::size_t up = static_cast<std::size_t>(p);
    const Vec3 u = s.x[up] - s.x0[up];
    switch (q) {
        case Quantity::Ux:
            return u.x();
        case Quantity::Uy:
            return u.y();
        case Quantity::Uz:
            return u.z();
        case Quantity::Umag:
            return u.norm();
        case Quantity::Vx:
            return s.v[up].x();
        case Quantity::Vy:
            return s.v[up].y();
        case Quantity::Vz:
            return s.v[up].z();
        case Quantity::Ax:
            return solver.acceleration(p).x();
        case Quantity::Ay:
            return solver.acceleration(p).y();
        case Quantity::Az:
            return solver.acceleration(p).z();
        case Quantity::Rx:
            return rotation_vector(s.rotation[up]).x();
        case Quantity::Ry:
            return rotation_vector(s.rotation[up]).y();
        case Quantity::Rz:
            return rotation_vector(s.rotation[up]).z();
        case Quantity::ReactionX:
            return s.reaction[up].x();
        case Quantity::ReactionY:
            return s.reaction[up].y();
        case Quantity::ReactionZ:
            return s.reaction[up].z();
        case Quantity::ReactionMx:
            return s.reaction_moment[up].x();
        case Quantity::ReactionMy:
            return s.reaction_moment[up].y();
        case Quantity::ReactionMz:
            return s.reaction_moment[up].z();
        case Quantity::ForceX:
            return s.f_ext[up].x();
        case Quantity::ForceY:
            return s.f_ext[up].y();
        case Quantity::ForceZ:
            return s.f_ext[up].z();
        case Quantity::Pressure: {
            // a pressure p on every triangle of the particle gives f = -p sum(cross) / 6
            // (theory.md §6.7): p = -6 f.c / |c|^2, c = sum(cross), at any curvature; on the
            // positions the loads were computed on (x^n, those of the step before s.x)
            Vec3 c = Vec3::Zero();
            for (const Index e : solver.topology().elements_of(p)) {
                const auto& t = solver.model().triangles[static_cast<std::size_t>(e)];
                const Vec3& a = s.x_prev[static_cast<std::size_t>(t[0])];
                c += (s.x_prev[static_cast<std::size_t>(t[1])] - a)
                         .cross(s.x_prev[static_cast<std::size_t>(t[2])] - a);
            }
            const Real c2 = c.squaredNorm();
            return c2 > 0 ? -6.0 * s.f_ext[up].dot(c) / c2 : 0.0;
        }
        default:
            break;  // rigid-body quantities: body_quantity
    }
    return 0;
}

Real body_quantity(const ExplicitSolver& solver, Quantity q, Index b) {
    const RigidBodyState& body = solver.bodies()[static_cast<std::size_t>(b)];
    switch (q) {
        case Quantity::RigidUx:
            return body.u.x();
        case Quantity::RigidUy:
            return body.u.y();
        case Quantity::RigidUz:
            return body.u.z();
        case Quantity::RigidVx:
            return body.v.x();
        case Quantity::RigidVy:
            return body.v.y();
        case Quantity::RigidVz:
            return body.v.z();
        case Quantity::RigidAx:
            return solver.body_acceleration(b).x();
        case Quantity::RigidAy:
            return solver.body_acceleration(b).y();
        case Quantity::RigidAz:
            return solver.body_acceleration(b).z();
        case Quantity::RigidForceX:
            return body.force.x();
        case Quantity::RigidForceY:
            return body.force.y();
        case Quantity::RigidForceZ:
            return body.force.z();
        default:
            break;
    }
    return 0;
}

std::vector<Real> sample_histories(const Model& model, const ExplicitSolver& solver) {
    std::vector<Real> out;
    out.reserve(model.output.histories.size());
    for (const HistoryRequest& h : model.output.histories) {
        if (h.body >= 0) {
            out.push_back(body_quantity(solver, h.quantity, h.body));
            continue;
        }
        if (h.model_wide) {  // eroded_elements
            out.push_back(static_cast<Real>(solver.eroded_elements()));
            continue;
        }
        if (h.contact >= 0) {  // the force on the definition's slaves (contact_<n>_force_<c>)
            const Vec3 f = solver.contact_force(h.contact);
            out.push_back(h.quantity == Quantity::ContactForceX   ? f.x()
                          : h.quantity == Quantity::ContactForceY ? f.y()
                                                                  : f.z());
            continue;
        }
        Real acc = 0, weighted = 0, mass = 0;
        Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
        for (Index p : h.nodes) {
            const Real v = particle_quantity(solver, h.quantity, p);
            const Real m = solver.state().mass[static_cast<std::size_t>(p)];
            acc += v;
            weighted += m * v;
            mass += m;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        switch (h.reduce) {
            case Reduce::Single:
            case Reduce::Sum:
                out.push_back(acc);
                break;
            case Reduce::Mean:
                out.push_back(h.nodes.empty() ? 0 : acc / static_cast<Real>(h.nodes.size()));
                break;
            case Reduce::MassMean:
                out.push_back(mass > 0 ? weighted / mass : 0);
                break;
            case Reduce::Max:
                out.push_back(hi);
                break;
            case Reduce::Min:
                out.push_back(lo);
                break;
        }
    }
    return out;
}

}  // namespace fpmshell
