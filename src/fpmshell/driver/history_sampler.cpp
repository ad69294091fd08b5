#include "fpmshell/driver/history_sampler.hpp"

#include <algorithm>
#include <limits>

#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/exact_sum.hpp"
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
    // A history over particles: its sums and extremes over the particles this rank owns (all
    // on one rank), then over the ranks. The sums are exact (core/exact_sum.hpp), so that a
    // row is the same bits on any number of ranks without bringing the particles to one rank.
    const DomainDecomposition& d = solver.decomposition();
    const std::vector<HistoryRequest>& requests = model.output.histories;
    std::vector<ExactSum> sums;     // per history over particles: values, mass x values, masses
    std::vector<Real> lowest;       // per history over particles: its least value, then minus
    std::vector<Real> neg_highest;  // its largest (one reduction to the least takes both)
    for (const HistoryRequest& h : requests) {
        if (h.body >= 0 || h.model_wide || h.contact >= 0) continue;
        ExactSum acc, weighted, mass;
        Real lo = std::numeric_limits<Real>::infinity(), hi = -lo;
        for (const Index p : h.nodes) {
            if (d.distributed() && d.particle_owner[static_cast<std::size_t>(p)] != d.rank)
                continue;
            const Real v = particle_quantity(solver, h.quantity, p);
            const Real m = solver.state().mass[static_cast<std::size_t>(p)];
            acc.add(v);
            weighted.add(m * v);
            mass.add(m);
            lo = std::min(lo, v);  // NaN is passed over (std::min keeps lo)
            hi = std::max(hi, v);
        }
        sums.insert(sums.end(), {acc, weighted, mass});
        lowest.push_back(lo);
        neg_highest.push_back(-hi);
    }
    const Communicator& comm = Communicator::world();
    comm.sum(sums);
    lowest.insert(lowest.end(), neg_highest.begin(), neg_highest.end());
    comm.min(lowest);  // never NaN: the least of numbers and infinities

    std::vector<Real> out;
    out.reserve(requests.size());
    const std::size_t n_particle_histories = neg_highest.size();
    std::size_t k = 0;  // the particle history
    for (const HistoryRequest& h : requests) {
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
        const Real acc = sums[3 * k].value(), weighted = sums[3 * k + 1].value(),
                   mass = sums[3 * k + 2].value();
        const Real lo = lowest[k], hi = -lowest[n_particle_histories + k];
        ++k;
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

void HistoryShare::sample(const ExplicitSolver& solver, Real /*time*/,
                          std::optional<bool> /*converged*/) {
    (void)sample_histories(model_, solver);
}

}  // namespace fpmshell
