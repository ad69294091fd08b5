// Nodal rigid bodies: the merge of groups that share particles, and the rigid projection of the
// velocities (theory.md §6.11).
#include "fpmshell/solver/nodal_rigid_bodies.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/symmetric_solve.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"
#include "fpmshell/model/rigid_inertia_shares.hpp"
#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

NodalRigidBodies::NodalRigidBodies(const Model& model) : model_(&model) {
    for (const NodalRigidBody& g : model.nodal_rigid_bodies)
        if (g.can_fail()) {
            let_go_.assign(model.nodal_rigid_bodies.size(), 0);
            weld_force_.assign(let_go_.size(), Vec3::Zero());
            weld_tension_.assign(let_go_.size(), 0);
            weld_shear_.assign(let_go_.size(), 0);
            node_force_.assign(let_go_.size(), {});
        }
    rebuild();
}

void NodalRigidBodies::rebuild() {
    const Model& model = *model_;
    RigidBodyPartition partition = rigid_body_partition(model, let_go_);
    if (partition.problem)  // the model reader reports it at its line; a model built in code here
        throw InputError("boundary entry " + std::to_string(partition.problem->first + 1) + ": " +
                         partition.problem->second);
    bodies_ = std::move(partition.bodies);
    body_of_particle_ = std::move(partition.body_of_particle);
    fixed_ = std::move(partition.held);
    corrections_.clear();
    full_rotation_.clear();
    set_inertia_corrections(model, body_of_particle_);
    prescribed_.clear();
    driven_.clear();
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (const RigidPrescription& pr : partition.prescribed[b])
            if (pr.kind != PrescribedKind::None) {
                if (prescribed_.empty()) {
                    prescribed_ = partition.prescribed;
                    driven_.assign(bodies_.size(), 0);
                }
                driven_[b] = 1;
            }
    set_weld_sides();
}

void NodalRigidBodies::set_weld_sides() {
    welds_.clear();
    weld_slot_.clear();
    weld_impulse_.clear();
    if (let_go_.empty()) return;
    SpotWeldSides sides = spot_weld_sides(*model_, let_go_);
    if (sides.problem)  // the model reader reports it at its line
        throw InputError("constraints entry " + std::to_string(sides.problem->first + 1) + ": " +
                         sides.problem->second);
    welds_ = std::move(sides.welds);
    weld_slot_.assign(model_->nodes.size(), -1);
    Index slots = 0;
    const auto add_slots = [&](const std::vector<Index>& side) {
        for (const Index p : side)
            if (weld_slot_[static_cast<std::size_t>(p)] < 0)
                weld_slot_[static_cast<std::size_t>(p)] = slots++;
    };
    for (const SpotWeldSide& w : welds_) {
        add_slots(w.side);
        for (const std::vector<Index>& side : w.node_sides) add_slots(side);
    }
    weld_impulse_.assign(static_cast<std::size_t>(slots), Vec3::Zero());
}

std::size_t NodalRigidBodies::failed_welds() const {
    return static_cast<std::size_t>(std::count(let_go_.begin(), let_go_.end(), 1));
}

Vec3 NodalRigidBodies::side_force(const std::vector<Index>& side, Real impulse_time) const {
    Vec3 force = Vec3::Zero();
    for (const Index p : side)
        force += weld_impulse_[static_cast<std::size_t>(weld_slot_[static_cast<std::size_t>(p)])];
    return force / impulse_time;
}

NodalRigidBodies::WeldLoad NodalRigidBodies::load_along(const NodalRigidBody& group,
                                                        const Vec3& force, const Vec3& axis,
                                                        bool coincident) {
    WeldLoad load;
    load.force = force;
    const Real along = force.dot(axis);
    load.tension = coincident ? std::abs(along) : std::max(Real(0), along);
    load.shear = (force - along * axis).norm();
    const NodalRigidBody::Failure& limit = group.failure;  // eq. 6.11-13
    if (limit.normal_force > 0)
        load.criterion += std::pow(load.tension / limit.normal_force, limit.normal_exponent);
    if (limit.shear_force > 0)
        load.criterion += std::pow(load.shear / limit.shear_force, limit.shear_exponent);
    return load;
}

NodalRigidBodies::WeldLoad NodalRigidBodies::weld_load(const SpotWeldSide& w,
                                                       const ParticleState& s,
                                                       Real impulse_time) const {
    const NodalRigidBody& group = model_->nodal_rigid_bodies[w.entry];
    // the force on the first particle's side through the weld
    const Vec3 force = w.sign * side_force(w.side, impulse_time);
    const auto a = static_cast<std::size_t>(group.nodes[0]);
    const auto b = static_cast<std::size_t>(group.nodes[1]);
    // the weld's axis, from the first particle to the second; for coincident particles
    // their mean normal, either way in tension
    const Vec3 chord = s.x[b] - s.x[a];
    const Real reach = std::max(s.x[a].cwiseAbs().maxCoeff(), s.x[b].cwiseAbs().maxCoeff());
    const bool coincident = !(chord.norm() > 1e-9 * reach);
    const Vec3 axis =
        coincident ? Vec3((s.normal[a] + s.normal[b]).normalized()) : Vec3(chord / chord.norm());
    return load_along(group, force, axis, coincident);
}

// A generalized weld (eq. 6.11-14): each particle's side takes the force through the group, its
// normal from the particle to the group's geometric centre (OpenRadioss's reading of LS-DYNA's
// *CONSTRAINED_GENERALIZED_WELD_SPOT); the particle whose criterion is largest judges the weld.
NodalRigidBodies::WeldLoad NodalRigidBodies::generalized_weld_load(const SpotWeldSide& w,
                                                                   const ParticleState& s,
                                                                   Real impulse_time) {
    const NodalRigidBody& group = model_->nodal_rigid_bodies[w.entry];
    const std::size_t n = group.nodes.size();
    std::vector<Vec3>& node_force = node_force_[w.entry];
    node_force.assign(n, Vec3::Zero());
    Vec3 others = Vec3::Zero(), centre = Vec3::Zero();
    Real reach = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3& x = s.x[static_cast<std::size_t>(group.nodes[k])];
        centre += x;
        reach = std::max(reach, x.cwiseAbs().maxCoeff());
        if (static_cast<std::ptrdiff_t>(k) == w.derived) continue;
        node_force[k] = side_force(w.node_sides[k], impulse_time);
        others += node_force[k];
    }
    centre /= static_cast<Real>(n);
    if (w.derived >= 0) node_force[static_cast<std::size_t>(w.derived)] = -others;
    WeldLoad worst;
    for (std::size_t k = 0; k < n; ++k) {
        const auto p = static_cast<std::size_t>(group.nodes[k]);
        const Vec3 inward = centre - s.x[p];
        // a particle at the centre: its normal, either way in tension
        const bool coincident = !(inward.norm() > 1e-9 * reach);
        const Vec3 axis = coincident ? s.normal[p] : Vec3(inward / inward.norm());
        const WeldLoad load = load_along(group, node_force[k], axis, coincident);
        if (k == 0 || load.criterion > worst.criterion) worst = load;
    }
    return worst;
}

std::size_t NodalRigidBodies::judge_welds(const ParticleState& s, Real impulse_time, Real time,
                                          const WeldSheetStrain& sheets) {
    std::size_t failed = 0;
    std::fill(weld_force_.begin(), weld_force_.end(), Vec3::Zero());
    std::fill(weld_tension_.begin(), weld_tension_.end(), Real(0));
    std::fill(weld_shear_.begin(), weld_shear_.end(), Real(0));
    for (std::vector<Vec3>& forces : node_force_)
        std::fill(forces.begin(), forces.end(), Vec3::Zero());
    for (const SpotWeldSide& w : welds_) {
        const NodalRigidBody& group = model_->nodal_rigid_bodies[w.entry];
        const WeldLoad load = w.node_sides.empty() ? weld_load(w, s, impulse_time)
                                                   : generalized_weld_load(w, s, impulse_time);
        weld_force_[w.entry] = load.force;
        weld_tension_[w.entry] = load.tension;
        weld_shear_[w.entry] = load.shear;
        const bool torn_out =  // eq. 6.11-15
            group.fails_by_plastic_strain() &&
            std::any_of(group.nodes.begin(), group.nodes.end(),
                        [&](Index p) { return sheets.at(p) >= group.failure.plastic_strain; });
        if (load.criterion >= 1 || time >= group.failure.time || torn_out) {
            let_go_[w.entry] = 1;
            ++failed;
        }
    }
    if (failed > 0) {
        if (first_weld_failure_time_ < 0) first_weld_failure_time_ = time;
        rebuild();
    }
    return failed;
}

namespace {

/// [a - o, b - o, (a - o) x (b - o)]: a rigid motion turns it by its rotation.
Mat3 frame(const Vec3& o, const Vec3& a, const Vec3& b) {
    Mat3 f;
    f.col(0) = a - o;
    f.col(1) = b - o;
    f.col(2) = (a - o).cross(b - o);
    return f;
}

}  // namespace

void NodalRigidBodies::set_inertia_corrections(const Model& model,
                                               const std::vector<Index>& body_of_particle) {
    std::map<std::size_t, InertiaCorrection> by_body;
    for (std::size_t sec = 0; sec < model.sections.size(); ++sec) {
        const Section& section = model.sections[sec];
        if (!section.has_inertia) continue;
        const RigidInertiaShares shares = rigid_inertia_shares(model, static_cast<Index>(sec));
        if (shares.particles.empty()) continue;
        const auto body = static_cast<std::size_t>(
            body_of_particle[static_cast<std::size_t>(shares.particles.front())]);
        InertiaCorrection& c = by_body[body];
        c.body = body;
        // eq. 6.11-10: the section's tensor less what its shares carry about its centre
        c.delta0 += section.inertia.tensor;
        for (std::size_t k = 0; k < shares.particles.size(); ++k) {
            const Vec3 r =
                model.nodes[static_cast<std::size_t>(shares.particles[k])] - section.inertia.centre;
            c.delta0 -= shares.mass[k] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose()) +
                        shares.inertia[k] * Mat3::Identity();
            full_rotation_.push_back(shares.particles[k]);
        }
        if (c.o >= 0) continue;
        // eq. 6.11-11: o, the particle farthest from o, the one farthest off their line
        const auto at = [&](Index p) { return model.nodes[static_cast<std::size_t>(p)]; };
        c.o = shares.particles.front();
        Real best = -1;
        for (const Index p : shares.particles)
            if (const Real d = (at(p) - at(c.o)).squaredNorm(); d > best) {
                best = d;
                c.a = p;
            }
        best = -1;
        for (const Index p : shares.particles)
            if (const Real d = (at(p) - at(c.o)).cross(at(c.a) - at(c.o)).squaredNorm(); d > best) {
                best = d;
                c.b = p;
            }
        c.frame0_inverse = frame(at(c.o), at(c.a), at(c.b)).inverse();
    }
    for (auto& [body, c] : by_body) corrections_.push_back(c);
    std::sort(full_rotation_.begin(), full_rotation_.end());
    full_rotation_.erase(std::unique(full_rotation_.begin(), full_rotation_.end()),
                         full_rotation_.end());
}

Mat3 NodalRigidBodies::rotation_of(const InertiaCorrection& c, const std::vector<Vec3>& x) {
    return frame(x[static_cast<std::size_t>(c.o)], x[static_cast<std::size_t>(c.a)],
                 x[static_cast<std::size_t>(c.b)]) *
           c.frame0_inverse;
}

std::vector<Index> NodalRigidBodies::full_rotation_particles() const { return full_rotation_; }

Real NodalRigidBodies::extra_kinetic_energy(const ParticleState& s) const {
    Real energy = 0;
    for (const InertiaCorrection& c : corrections_) {
        const Mat3 turn = rotation_of(c, s.x);
        const auto o = static_cast<std::size_t>(c.o);
        energy += 0.5 * s.omega_prev[o].dot(turn * c.delta0 * turn.transpose() * s.omega[o]);
    }
    return energy;
}

void NodalRigidBodies::make_initial_motion_rigid(ParticleState& s) const {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const std::vector<Index>& body = bodies_[b];
        Real mass = 0;
        Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            mass += s.mass[p];
            centre += s.mass[p] * s.x[p];
            momentum += s.mass[p] * s.v[p];
        }
        centre /= mass;
        const Vec3 velocity = momentum / mass;
        Vec3 spin = Vec3::Zero();
        Mat3 inertia = Mat3::Zero();
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            spin += s.mass[p] * r.cross(s.v[p] - velocity) + s.inertia[p] * s.omega[p];
            inertia += s.mass[p] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
            const Vec3& n = s.normal[p];
            inertia += s.full_rotation[p]
                           ? Mat3(s.inertia[p] * Mat3::Identity())
                           : Mat3(s.inertia[p] * (Mat3::Identity() - n * n.transpose()));
        }
        for (const InertiaCorrection& c : corrections_)
            if (c.body == b) {  // eq. 6.11-10 at t = 0
                inertia += c.delta0;
                spin += c.delta0 * s.omega[static_cast<std::size_t>(c.o)];
            }
        const Vec3 omega = symmetric_pseudo_solve(inertia, spin);
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            s.v[p] = velocity + omega.cross(s.x[p] - centre);
            const Vec3& n = s.normal[p];
            s.omega[p] = s.full_rotation[p] ? omega : Vec3(omega - n.dot(omega) * n);
        }
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
                                        const Vec3& centre0, const Vec3& velocity_prev,
                                        const PrescribedMotionTimes& at,
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
        case PrescribedKind::Acceleration:  // V^{n+1/2} = V^{n-1/2} + dt_n a(t_n)
            return velocity_prev[d] +
                   at.dt_n * pr.value * curve_factor(curves, pr.curve, at.load_time);
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
                                  const std::vector<Curve>& curves, bool again) {
    const Real dt_new = at.dt_new;
    if (!again) std::fill(weld_impulse_.begin(), weld_impulse_.end(), Vec3::Zero());
    const bool welds = !weld_impulse_.empty();
    const auto n_bodies = static_cast<std::ptrdiff_t>(bodies_.size());
#pragma omp parallel for schedule(static) if (n_bodies >= 64)
    for (std::ptrdiff_t ib = 0; ib < n_bodies; ++ib) {
        const auto b = static_cast<std::size_t>(ib);
        const std::vector<Index>& body = bodies_[b];
        const bool driven = !driven_.empty() && driven_[b] != 0;
        // mass, centre of mass at x^n, linear momentum (eq. 6.11-1)
        Real mass = 0;
        Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero(), centre0 = Vec3::Zero();
        Vec3 velocity_prev = Vec3::Zero();  // V^{n-1/2}, for a prescribed acceleration
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            mass += s.mass[p];
            centre += s.mass[p] * s.x[p];
            momentum += s.mass[p] * s.v[p];
            if (driven) {
                centre0 += s.mass[p] * s.x0[p];
                velocity_prev += s.mass[p] * s.v_prev[p];
            }
        }
        centre /= mass;
        centre0 /= mass;
        velocity_prev /= mass;
        const std::array<bool, 6>& fixed = fixed_[b];
        Vec3 velocity = momentum / mass;
        for (std::size_t k = 0; k < 3; ++k)  // eqs. 6.11-6, 6.11-7
            if (fixed[k])
                velocity[static_cast<Eigen::Index>(k)] =
                    prescribed_value(b, k, centre, centre0, velocity_prev, at, curves);
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
        const bool held_rotation = fixed[3] || fixed[4] || fixed[5];
        if (held_rotation)
            for (std::size_t k = 0; k < 3; ++k)
                if (fixed[3 + k])
                    held_omega[static_cast<Eigen::Index>(k)] =
                        prescribed_value(b, 3 + k, centre, centre0, velocity_prev, at, curves);
        const auto solve = [&](Mat3 tensor, Vec3 l) {
            if (held_rotation) {
                if (driven) l -= tensor * held_omega;
                const Real scale = std::max(tensor.trace(), Real(0));
                for (int k = 0; k < 3; ++k) {
                    if (!fixed[static_cast<std::size_t>(3 + k)]) continue;
                    tensor.row(k).setZero();
                    tensor.col(k).setZero();
                    tensor(k, k) = scale;
                    l[k] = 0;
                }
            }
            Vec3 w = symmetric_pseudo_solve(tensor, l);
            for (int k = 0; k < 3; ++k)
                if (fixed[static_cast<std::size_t>(3 + k)]) w[k] = held_omega[k];  // exactly
            return w;
        };
        // A body with a given inertia (eq. 6.11-10): dJ(t) = R dJ0 R^T is what its particles
        // leave out. Its angular momentum is stepped as a rigid body's (eq. 6.11-12):
        // L^{n+1/2} = I^{n-1/2} w^{n-1/2} plus the step's impulses, and w^{n+1/2} =
        // (I^{n+1/2})^-1 L^{n+1/2}, I at a half step being I(t_n) turned by half the step's
        // rotation (a few fixed-point passes); w^{n-1/2} is on particle o (it turns about all
        // three axes). The particles' chord velocities carry w only to O(w dt): summed step
        // after step, that would turn the axis of a free spin away.
        const InertiaCorrection* correction = nullptr;
        Mat3 delta = Mat3::Zero();
        Vec3 omega_before_step = Vec3::Zero();
        if (!corrections_.empty()) {
            const auto it = std::lower_bound(
                corrections_.begin(), corrections_.end(), b,
                [](const InertiaCorrection& c, std::size_t key) { return c.body < key; });
            if (it != corrections_.end() && it->body == b) correction = &*it;
        }
        Vec3 omega;
        if (correction == nullptr) {
            omega = solve(inertia, spin);
        } else {
            const Mat3 turn_n = rotation_of(*correction, s.x);
            delta = turn_n * correction->delta0 * turn_n.transpose();
            inertia += delta;
            omega_before_step = s.omega_prev[static_cast<std::size_t>(correction->o)];
            const auto half_turn = [](const Vec3& w, Real dt) {
                const Real angle = 0.5 * dt * w.norm();  // negative: back
                return angle != 0
                           ? Mat3(Eigen::AngleAxisd(angle, w.normalized()).toRotationMatrix())
                           : Mat3(Mat3::Identity());
            };
            if (!again) {  // from w^{n-1/2}: the impulses are the changes of the step
                const Real dt_prev = std::max(2 * at.dt_n - dt_new, Real(0));
                const Mat3 back = half_turn(omega_before_step, -dt_prev);
                spin = back * inertia * back.transpose() * omega_before_step;
                for (const Index ip : body) {
                    const auto p = static_cast<std::size_t>(ip);
                    spin += s.mass[p] * (s.x[p] - centre).cross(s.v[p] - s.v_prev[p]) +
                            s.inertia[p] * (s.omega[p] - s.omega_prev[p]);
                }
            } else {  // from the first pass's w: the impulses are what the contact changed
                const Vec3 w1 = s.omega[static_cast<std::size_t>(correction->o)];
                const Mat3 ahead = half_turn(w1, dt_new);
                spin = ahead * inertia * ahead.transpose() * w1;
                const Real angle1 = dt_new * w1.norm();
                const Mat3 turn1 =
                    angle1 > 0 ? Mat3(Eigen::AngleAxisd(angle1, w1.normalized()).toRotationMatrix())
                               : Mat3(Mat3::Identity());
                for (const Index ip : body) {
                    const auto p = static_cast<std::size_t>(ip);
                    const Vec3 r = s.x[p] - centre;
                    const Vec3& n = s.normal[p];
                    const Vec3 w1_p = s.full_rotation[p] ? w1 : Vec3(w1 - n.dot(w1) * n);
                    spin += s.mass[p] * r.cross(s.v[p] - (turn1 * r - r) / dt_new) +
                            s.inertia[p] * (s.omega[p] - w1_p);
                }
                omega_before_step = w1;
            }
            omega = omega_before_step;
            for (int pass = 0; pass < 4; ++pass) {
                const Mat3 ahead = half_turn(omega, dt_new);
                omega = solve(ahead * inertia * ahead.transpose(), spin);
            }
        }
        // each particle moves with the body, the rotation over the step exact (eq. 6.11-4)
        const Real angle = dt_new * omega.norm();
        const Eigen::Matrix3d turn =
            angle > 0 ? Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix()
                      : Eigen::Matrix3d::Identity();
        if (driven && correction != nullptr)  // the drive's reaction on the inertia dJ
            s.reaction_moment[static_cast<std::size_t>(correction->o)] +=
                (delta * (omega - omega_before_step)) / (at.c1 * at.dt_n);
        for (const Index ip : body) {
            const auto p = static_cast<std::size_t>(ip);
            const Vec3 r = s.x[p] - centre;
            const Vec3 v_before = s.v[p], omega_before = s.omega[p];
            s.v[p] = velocity + (turn * r - r) / dt_new;
            const Vec3& n = s.normal[p];
            s.omega[p] = s.full_rotation[p] ? omega : Vec3(omega - n.dot(omega) * n);
            if (welds)  // the constraint's impulse, for the weld it sides with (eq. 6.11-13)
                if (const Index slot = weld_slot_[p]; slot >= 0)
                    weld_impulse_[static_cast<std::size_t>(slot)] +=
                        s.mass[p] * (s.v[p] - v_before);
            if (driven) {  // the drive's reaction, booked as a support's (eq. 6.11-7)
                s.reaction[p] += (s.mass[p] / (at.c1 * at.dt_n)) * (s.v[p] - v_before);
                s.reaction_moment[p] +=
                    (s.inertia[p] / (at.c1 * at.dt_n)) * (s.omega[p] - omega_before);
            }
        }
    }
}

}  // namespace fpmshell
