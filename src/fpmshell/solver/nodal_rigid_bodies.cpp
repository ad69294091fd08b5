// Nodal rigid bodies: the merge of groups that share particles, and the rigid projection of the
// velocities (theory.md §6.11).
#include "fpmshell/solver/nodal_rigid_bodies.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"
#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

NodalRigidBodies::NodalRigidBodies(const Model& model) {
    RigidBodyPartition partition = rigid_body_partition(model);
    if (partition.problem)  // the model reader reports it at its line; a model built in code here
        throw InputError("boundary entry " + std::to_string(partition.problem->first + 1) + ": " +
                         partition.problem->second);
    bodies_ = std::move(partition.bodies);
    fixed_ = std::move(partition.held);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (const RigidPrescription& pr : partition.prescribed[b])
            if (pr.kind != PrescribedKind::None) {
                if (prescribed_.empty()) {
                    prescribed_ = partition.prescribed;
                    driven_.assign(bodies_.size(), 0);
                }
                driven_[b] = 1;
            }
}

std::vector<Index> NodalRigidBodies::driven_particles() const {
    std::vector<Index> out;
    for (std::size_t b = 0; b < driven_.size(); ++b)
        if (driven_[b]) out.insert(out.end(), bodies_[b].begin(), bodies_[b].end());
    std::sort(out.begin(), out.end());
    return out;
}

Real NodalRigidBodies::prescribed_value(std::size_t b, std::size_t k, const Vec3& centre,
                                        const Vec3& centre0, const PrescribedMotionTimes& at,
                                        const std::vector<Curve>& curves) const {
    if (prescribed_.empty()) return 0;
    const RigidPrescription& pr = prescribed_[b][k];
    const auto d = static_cast<Eigen::Index>(k % 3);
    switch (pr.kind) {
        case PrescribedKind::None:
            return 0;  // held at zero
        case PrescribedKind::AngularVelocity:
            return pr.value * curve_factor(curves, pr.curve, at.t_half);
        case PrescribedKind::Velocity:
            if (!at.relaxation) return pr.value * curve_factor(curves, pr.curve, at.t_half);
            // in relaxation, the centre reaches the integral of the velocity (as a particle's)
            return (centre0[d] + pr.value * curve_factor_integral(curves, pr.curve, at.load_time) -
                    centre[d]) /
                   at.dt_new;
        case PrescribedKind::Displacement:
            return (centre0[d] + pr.value * curve_factor(curves, pr.curve, at.t_next) - centre[d]) /
                   at.dt_new;
    }
    return 0;
}

std::vector<Real> NodalRigidBodies::contact_masses(const std::vector<Real>& mass) const {
    std::vector<Real> out = mass;
    for (const std::vector<Index>& body : bodies_) {
        Real total = 0;
        for (const Index p : body) total += mass[static_cast<std::size_t>(p)];
        for (const Index p : body) out[static_cast<std::size_t>(p)] = total;
    }
    return out;
}

void NodalRigidBodies::make_rigid(ParticleState& s, const PrescribedMotionTimes& at,
                                  const std::vector<Curve>& curves) const {
    const Real dt_new = at.dt_new;
    const auto n_bodies = static_cast<std::ptrdiff_t>(bodies_.size());
#pragma omp parallel for schedule(static) if (n_bodies >= 64)
    for (std::ptrdiff_t ib = 0; ib < n_bodies; ++ib) {
        const auto b = static_cast<std::size_t>(ib);
        const std::vector<Index>& body = bodies_[b];
        const bool driven = !driven_.empty() && driven_[b] != 0;
        // mass, centre of mass at x^n, linear momentum (eq. 6.11-1)
        Real mass = 0;
        Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero(), centre0 = Vec3::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            mass += s.mass[p];
            centre += s.mass[p] * s.x[p];
            momentum += s.mass[p] * s.v[p];
            if (driven) centre0 += s.mass[p] * s.x0[p];
        }
        centre /= mass;
        centre0 /= mass;
        const std::array<bool, 6>& fixed = fixed_[b];
        Vec3 velocity = momentum / mass;
        for (std::size_t k = 0; k < 3; ++k)  // eqs. 6.11-6, 6.11-7
            if (fixed[k])
                velocity[static_cast<Eigen::Index>(k)] =
                    prescribed_value(b, k, centre, centre0, at, curves);
        // angular momentum and inertia tensor about the centre (eq. 6.11-2); a shell particle
        // turns in its tangent plane only, so its own inertia has no part about its normal
        Vec3 spin = Vec3::Zero();
        Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            spin += s.mass[p] * r.cross(s.v[p] - velocity) + s.inertia[p] * s.omega[p];
            inertia +=
                s.mass[p] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
            const Vec3& n = s.normal[p];
            inertia += s.full_rotation[p]
                           ? Eigen::Matrix3d(s.inertia[p] * Eigen::Matrix3d::Identity())
                           : Eigen::Matrix3d(s.inertia[p] *
                                             (Eigen::Matrix3d::Identity() - n * n.transpose()));
        }
        // omega = I^+ L (eq. 6.11-3): the pseudo-inverse leaves out a rotation no particle's
        // mass or inertia resists (two welded particles on the line of their normals cannot
        // turn each other about it), which carries no angular momentum either. Held rotation
        // axes (eqs. 6.11-6, 6.11-7): their angular velocity omega_h is known, so the free
        // axes' block of I takes their part of L less I_fh omega_h; the held rows and columns
        // become the largest inertia times the identity.
        Vec3 held_omega = Vec3::Zero();
        if (fixed[3] || fixed[4] || fixed[5]) {
            for (std::size_t k = 0; k < 3; ++k)
                if (fixed[3 + k])
                    held_omega[static_cast<Eigen::Index>(k)] =
                        prescribed_value(b, 3 + k, centre, centre0, at, curves);
            if (driven) spin -= inertia * held_omega;
            const Real scale = std::max(inertia.trace(), Real(0));
            for (int k = 0; k < 3; ++k) {
                if (!fixed[static_cast<std::size_t>(3 + k)]) continue;
                inertia.row(k).setZero();
                inertia.col(k).setZero();
                inertia(k, k) = scale;
                spin[k] = 0;
            }
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
        const Vec3 values = eigen.eigenvalues();
        const Real floor = 1e-12 * std::max(values.maxCoeff(), Real(0));
        Vec3 projected = eigen.eigenvectors().transpose() * spin;
        for (int k = 0; k < 3; ++k) projected[k] = values[k] > floor ? projected[k] / values[k] : 0;
        Vec3 omega = eigen.eigenvectors() * projected;
        for (int k = 0; k < 3; ++k)
            if (fixed[static_cast<std::size_t>(3 + k)]) omega[k] = held_omega[k];  // exactly
        // each particle moves with the body, the rotation over the step exact (eq. 6.11-4)
        const Real angle = dt_new * omega.norm();
        const Eigen::Matrix3d turn =
            angle > 0 ? Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix()
                      : Eigen::Matrix3d::Identity();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            const Vec3 v_before = s.v[p], omega_before = s.omega[p];
            s.v[p] = velocity + (turn * r - r) / dt_new;
            const Vec3& n = s.normal[p];
            s.omega[p] = s.full_rotation[p] ? omega : Vec3(omega - n.dot(omega) * n);
            if (driven) {  // the drive's reaction, booked as a support's (eq. 6.11-7)
                s.reaction[p] += (s.mass[p] / (at.c1 * at.dt_n)) * (s.v[p] - v_before);
                s.reaction_moment[p] +=
                    (s.inertia[p] / (at.c1 * at.dt_n)) * (s.omega[p] - omega_before);
            }
        }
    }
}

}  // namespace fpmshell
