#include "fpmshell/solver/explicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fpmshell/core/byte_buffer.hpp"
#include "fpmshell/core/chunked_loop.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/rotation.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/solver/unit_partition.hpp"

namespace fpmshell {
namespace {

constexpr Real k_kink_cosine = 0.9397;  // cos 20 deg: beyond it a particle gets 3 rotations (§1.3)
// Particle loops of smaller models stay serial: a parallel region costs more than it saves there.
constexpr Index k_parallel_min_particles = 2000;

}  // namespace

ExplicitSolver::ExplicitSolver(const Model& model)
    : model_(model),
      topology_(model),
      elements_(model, topology_, make_element_group, false),  // each rank's state alone
      ranks_(model, topology_, elements_),
      nodal_rigid_bodies_(model),
      weld_sheet_strain_(model, topology_) {
    const std::size_t np = model.nodes.size();
    elements_.set_decomposition(&ranks_.decomposition());
    s_.resize(np);
    s_.x0 = model.nodes;
    s_.x = model.nodes;
    s_.x_prev = model.nodes;
    // §6.10 mass scaling of the elements below the target step, then the §6.1 lumped mass
    // and §6.2 rotary inertia (summed by the topology).
    added_mass_ = apply_mass_scaling(model, topology_, elements_.time_steps());
    if (model.control.mass_scaling.time_step > 0 &&
        model.control.mass_scaling.during_run)  // and during the run
        elements_.time_steps().enable_run_scaling(model.control.mass_scaling.time_step /
                                                  model.control.time_step_scale);
    s_.mass = topology_.particle_mass;
    s_.inertia = topology_.particle_inertia;
    // §1.3 the area-weighted normal; the mean edge length.
    std::vector<Vec3> normal_sum(np, Vec3::Zero());
    Real edge_sum = 0;
    for (const auto& t : model.triangles) {
        const Vec3& p0 = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = model.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = model.nodes[static_cast<std::size_t>(t[2])];
        const Vec3 cr = (p1 - p0).cross(p2 - p0);
        for (Index p : t) normal_sum[static_cast<std::size_t>(p)] += cr;
        edge_sum += (p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm();
    }
    if (!model.triangles.empty())
        length_scale_ = edge_sum / (3.0 * static_cast<Real>(model.triangles.size()));
    // §1.3 kink particles: an attached element normal deviates by more than 20 degrees.
    for (std::size_t p = 0; p < np; ++p) s_.normal[p] = normal_sum[p].normalized();
    for (const auto& t : model.triangles) {
        const Vec3 n = (model.nodes[static_cast<std::size_t>(t[1])] -
                        model.nodes[static_cast<std::size_t>(t[0])])
                           .cross(model.nodes[static_cast<std::size_t>(t[2])] -
                                  model.nodes[static_cast<std::size_t>(t[0])])
                           .normalized();
        for (Index p : t)
            if (n.dot(s_.normal[static_cast<std::size_t>(p)]) < k_kink_cosine)
                s_.full_rotation[static_cast<std::size_t>(p)] = 1;
    }
    // the particles of rigid sections with a given inertia turn about all three axes (§6.11)
    for (const Index p : nodal_rigid_bodies_.full_rotation_particles())
        s_.full_rotation[static_cast<std::size_t>(p)] = 1;
    // Boundary conditions (§6.7) and the drill axes they leave (§2.6, eq. 2.6c).
    bc_ = std::make_unique<BoundaryConditions>(model, s_.full_rotation);
    // the particles of driven rigid bodies have reactions (eq. 6.11-7)
    bc_->add_reactions(nodal_rigid_bodies_.driven_particles());
    for (std::size_t p = 0; p < np; ++p) s_.drill_axis[p] = bc_->drill_axis(p, s_.normal[p]);
    // Initial conditions: v^0, w^0 (the first cycle uses v^{-1/2} := v^0).
    for (const InitialVelocity& ic : model.initial_conditions) {
        Vec3 spin_centre = ic.spin_centre;
        if (ic.spin_about_mass_centre) {  // the centre of mass of the set's particles
            Real mass = 0;
            Vec3 first = Vec3::Zero();
            for (const Index p : ic.nodes) {
                mass += s_.mass[static_cast<std::size_t>(p)];
                first +=
                    s_.mass[static_cast<std::size_t>(p)] * model.nodes[static_cast<std::size_t>(p)];
            }
            if (mass > 0) spin_centre = first / mass;
        }
        for (Index p : ic.nodes) {
            // normal_velocity: along the initial surface normal of the particle (§1.3); spin: a
            // rigid rotation of the set
            const auto up = static_cast<std::size_t>(p);
            s_.v[up] = ic.velocity + ic.normal_velocity * s_.normal[up] +
                       ic.spin.cross(model.nodes[up] - spin_centre);
            s_.omega[up] = ic.angular_velocity + ic.spin;
        }
    }
    nodal_rigid_bodies_.make_initial_motion_rigid(s_);  // §6.11
    for (std::size_t p = 0; p < np; ++p) {
        s_.v[p] = bc_->without_fixed_translation(p, s_.v[p]);
        s_.v_prev[p] = s_.v[p];
        s_.omega_prev[p] = s_.omega[p];
        energy_.external_work += 0.5 * s_.mass[p] * s_.v[p].squaredNorm() +
                                 0.5 * s_.inertia[p] * s_.omega[p].squaredNorm();
    }
    energy_.external_work += nodal_rigid_bodies_.extra_kinetic_energy(s_);  // eq. 6.11-10
    loads_ = std::make_unique<ExternalLoads>(model, topology_);
    if (ranks_.distributed())
        loads_->set_subset(&ranks_.decomposition().near_elements,
                           &ranks_.decomposition().held_particles);
    parallel_particles_ = static_cast<Index>(np) >= k_parallel_min_particles;
    // Rigid bodies and contact (theory.md §8).
    bodies_ = RigidBodyState::from_model(model);
    for (const RigidBodyState& b : bodies_)
        energy_.external_work += 0.5 * b.mass * b.v.squaredNorm();
    if (!model.contacts.empty() || !model.tied_surfaces.empty()) {
        std::vector<Real> thickness(model.triangles.size());
        for (std::size_t e = 0; e < thickness.size(); ++e)
            thickness[e] = elements_.thickness(static_cast<Index>(e));
        if (!model.contacts.empty())
            contact_ = std::make_unique<ContactSolver>(model, topology_,
                                                       bc_->free_inverse_mass(s_.mass), thickness);
        if (!model.tied_surfaces.empty()) tied_ = std::make_unique<TiedSurfaces>(model, thickness);
    }
    refresh_contact_masses();
    // distributed: the contact and the constraints run whole on every rank
    if (contact_) ranks_.set_whole_particles(RankExchange::Whole::contact, contact_->particles());
    if (ranks_.distributed() && (!nodal_rigid_bodies_.empty() || tied_)) {
        std::vector<Index> constrained = tied_ ? tied_->particles() : std::vector<Index>{};
        for (const std::vector<Index>& body : nodal_rigid_bodies_.bodies())
            constrained.insert(constrained.end(), body.begin(), body.end());
        std::sort(constrained.begin(), constrained.end());  // a tied body particle once
        constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
        ranks_.set_whole_particles(RankExchange::Whole::constraints, constrained);
    }
    energy_.kinetic = energy_.external_work;
    // Without prescribed motions and Lagrange contact, which change v^{n+1/2} between the two,
    // the velocity update and the energy pass are one sweep over the particle arrays instead
    // of two (the same sums in the same order).
    if (elements_.separates()) {  // §7.7: the particles whose constraints hold one particle
        opening_ = EdgeOpening(model.n_elements());
        pinned_.assign(np, 0);
        for (const std::vector<Index>& body : nodal_rigid_bodies_.bodies())
            for (const Index p : body) pinned_[static_cast<std::size_t>(p)] = 1;
        for (const NodalRigidBody& weld : model.nodal_rigid_bodies)  // failed welds too
            for (const Index p : weld.nodes) pinned_[static_cast<std::size_t>(p)] = 1;
        for (const TiedSurface& tie : model.tied_surfaces)
            for (const Index p : tie.nodes) pinned_[static_cast<std::size_t>(p)] = 1;
    }
    // control.minimum_time_step: the floor, from the first step (LS-DYNA's TSMIN = DTMIN x the
    // initial step); with erode, the elements below it erode (their unscaled critical step)
    if (const MinimumTimeStep& floor = model.control.minimum_time_step; floor.active()) {
        min_step_ = floor.time_step > 0 ? floor.time_step : floor.factor * stable_dt();
        if (floor.erode) elements_.set_erosion_step(min_step_ / model.control.time_step_scale);
    }
    fused_particle_pass_ = !bc_->has_prescribed_motions() &&
                           !(contact_ && contact_->has_lagrange()) && nodal_rigid_bodies_.empty() &&
                           !tied_;
}

Vec3 ExplicitSolver::body_acceleration(Index b) const {
    const RigidBodyState& body = bodies_[static_cast<std::size_t>(b)];
    if (dt_center_ <= 0) return Vec3::Zero();
    return (body.v - body.v_prev) / dt_center_;
}

Real ExplicitSolver::stable_dt() const {
    return model_.control.time_step_scale * elements_.min_critical_dt(s_.x);
}

Vec3 ExplicitSolver::acceleration(Index p) const {
    const std::size_t up = static_cast<std::size_t>(p);
    if (dt_center_ <= 0) return Vec3::Zero();
    return (s_.v[up] - s_.v_prev[up]) / dt_center_;
}

void ExplicitSolver::step(Real max_dt) {
    separation_due_.reset();
    cycle(CyclePolicy::dynamic(model_), time_, max_dt);
    time_ += dt_half_;
    check_energy_balance();
}

// The cycle t_n -> t_{n+1} (§6.8).
void ExplicitSolver::cycle(const CyclePolicy& policy, Real load_time, Real dt_cap) {
    const ShellElements::StepTotals elements = compute_internal_loads(policy);  // 1 §2-§5
    ranks_.finish_positions(s_.x);  // distributed: the positions step 2 reads around the held ones
    if (elements_.separates() && !policy.relaxation) open_failed_sides();        // §7.7
    loads_->update_normals_and_loads(s_, *bc_, load_time, parallel_particles_);  // 2 §1.3, §6.7
    const StepLengths dt = next_step_lengths(policy, elements, dt_cap);          // 3 §6.4
    penalty_contact(dt);                                                         // 4 §8.2
    ParticleSums particles;
    if (fused_particle_pass_) {
        particles = update_velocities_and_advance_particles(policy, dt);  // 5, 8-9 §6.6
        update_body_velocities(dt);
    } else {
        particles = update_velocities(policy, dt);         // 5 §6.6
        impose_prescribed_motions(policy, load_time, dt);  // 6 §6.7
        update_body_velocities(dt);
        const PrescribedMotionTimes at = prescribed_motion_times(policy, load_time, dt);
        if (!nodal_rigid_bodies_.empty() || tied_)  // what 6b and 6c read, from the owners
            ranks_.share(RankExchange::Whole::constraints,
                         {&s_.x, &s_.v, &s_.omega, &s_.v_prev, &s_.omega_prev, &s_.normal});
        nodal_rigid_bodies_.make_rigid(s_, at, model_.curves);      // 6b §6.11
        if (tied_) tied_->impose(s_, *bc_, dt.c1 * dt.dt_n, true);  // 6c §6.12
        lagrange_contact(dt);                                       // 7 §8.3
        if (contact_ && contact_->has_lagrange()) {                 // what the contact moved
            nodal_rigid_bodies_.make_rigid(s_, at, model_.curves, true);
            if (tied_) tied_->impose(s_, *bc_, dt.c1 * dt.dt_n, false);
        }
        if (nodal_rigid_bodies_.has_failing_welds()) {  // eqs. 6.11-13 to 6.11-15
            if (!weld_sheet_strain_.empty()) weld_sheet_strain_.update(elements_, ranks_);
            if (nodal_rigid_bodies_.judge_welds(s_, dt.c1 * dt.dt_n, at.t_next,
                                                weld_sheet_strain_) > 0)
                release_failed_welds();
        }
        advance_particles(dt, particles);  // 8-9
    }
    book_energies(dt, particles);  // 8 §6.8
    finish_step(dt, particles);    // 9
    ranks_.start_positions(s_.x);
}

ExplicitSolver::~ExplicitSolver() = default;

template <class F>
Real ExplicitSolver::max_over_particles(F&& value) const {
    Real largest = 0;
    for (std::size_t p = 0; p < s_.size(); ++p)
        if (ranks_.owns(p)) largest = std::max(largest, value(p));
    return ranks_.max(largest);
}

ShellElements::StepTotals ExplicitSolver::compute_internal_loads(const CyclePolicy& policy) {
    const Real a_s = model_.damping.stiffness;
    const Real viscous_rate = (a_s > 0 && dt_half_ > 0) ? a_s / dt_half_ : 0.0;
    elements_.set_time(time_);  // t_n, for the failure criteria of a time (§7.6)
    const ShellElements::StepTotals tot =
        elements_.compute(s_, viscous_rate, policy.rate_effects ? dt_half_ : 0.0);
    element_steps_ += elements_.size();
    min_dt_element_ = tot.min_dt_element;
    if (tot.failed_element >= 0) report_failed_element(tot.failed_element);
    if (tot.mass_scaled > 0) add_scaled_mass();
    // the strain work of the elements eroded this step leaves the internal energy for the
    // eroded one, as LS-DYNA's glstat books it (theory.md §7.6)
    energy_.internal += tot.strain_work - tot.eroded_work;  // includes the plastic dissipation,
    energy_.plastic += tot.plastic_work;  // like LS-DYNA's internal energy; also on its own
    energy_.eroded_internal += tot.eroded_work;
    if (tot.eroded_elements > 0) {
        if (eroded_elements_ == 0) first_erosion_time_ = time_;
        eroded_elements_ += tot.eroded_elements;
        drop_eroded_faces();
    }
    energy_.damping += tot.damping_work;
    return tot;
}

// §7.6: the faces of the elements eroded this step leave the self-contacts before this step's
// contact, the ties to them let go (ties run on one rank only) and the pressures and blasts on
// them stop; a distributed run's contact is whole on every rank, so the ranks' lists are joined.
// Neighbours they leave in a piece of one or two take their exact membrane step (eq. 6.4-3).
void ExplicitSolver::drop_eroded_faces() {
    const std::vector<Index> eroded = ranks_.join_sorted(elements_.eroded_in_last_step());
    elements_.steady_small_pieces(eroded, s_.x);  // eq. 6.4-3
    if (contact_) contact_->drop_faces(eroded, true);
    if (tied_) tied_->release_eroded(eroded);
    loads_->unload(eroded);
}

// §6.10 during the run: the corners of the elements the loop scaled gain their mass and inertia
// (in element order: the same sums for any thread count) before the velocity update uses them.
// The velocity v^{n-1/2} stays; the kinetic energy 1/2 v^{n-1/2} M v^{n+1/2} of t_n then holds
// 1/2 dm |v^{n-1/2}|^2 more than the work of the forces gives (eq. 6.10b): external work.
void ExplicitSolver::add_scaled_mass() {
    // Per scaled element: its index, the mass and inertia each corner gains and the work of
    // each corner (the owner's: it holds the corners' velocities); a distributed run gathers
    // every rank's and adds them in element order, as one process does.
    std::vector<Real> records;
    for (const ElementTimeSteps::CornerAddition& a :
         elements_.time_steps().take_pending_scaling()) {
        records.insert(records.end(), {static_cast<Real>(a.element), a.mass, a.inertia});
        for (const Index p : model_.triangles[static_cast<std::size_t>(a.element)]) {
            const auto up = static_cast<std::size_t>(p);
            records.push_back(
                0.5 * (a.mass * s_.v[up].squaredNorm() + a.inertia * s_.omega[up].squaredNorm()));
        }
    }
    constexpr std::size_t k_record = 6;
    records = ranks_.join_records(records, k_record);  // in element order, as one process
    for (std::size_t i = 0; i + k_record <= records.size(); i += k_record) {
        const auto ue = static_cast<std::size_t>(records[i]);
        const Real mass = records[i + 1], inertia = records[i + 2];
        added_mass_.added[static_cast<std::size_t>(model_.element_section[ue])] += 3.0 * mass;
        for (std::size_t k = 0; k < 3; ++k) {
            const Index p = model_.triangles[ue][k];
            const auto up = static_cast<std::size_t>(p);
            const Real work = records[i + 3 + k];
            added_mass_.kinetic_energy += work;
            energy_.external_work += work;
            s_.mass[up] += mass;
            s_.inertia[up] += inertia;
            if (contact_) contact_->set_inverse_mass(p, bc_->free_inverse_mass(up, s_.mass[up]));
        }
    }
    if (!records.empty()) refresh_contact_masses();  // the bodies' masses changed too
}

void ExplicitSolver::release_failed_welds() {
    if (!contact_) return;
    // the particles that left a body take their own mass in the contact again
    const std::vector<Index>& body_of = nodal_rigid_bodies_.body_of_particle();
    for (const NodalRigidBody& g : model_.nodal_rigid_bodies)
        for (const Index p : g.nodes)
            if (body_of[static_cast<std::size_t>(p)] < 0)
                contact_->set_inverse_mass(
                    p, bc_->free_inverse_mass(static_cast<std::size_t>(p),
                                              s_.mass[static_cast<std::size_t>(p)]));
    refresh_contact_masses();
    contact_->set_rigid_body_of(body_of);
}

void ExplicitSolver::refresh_contact_masses() {
    if (!contact_ || nodal_rigid_bodies_.empty()) return;
    contact_mass_ = nodal_rigid_bodies_.contact_masses(s_.mass);
    const auto& bodies = nodal_rigid_bodies_.bodies();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        // a body held in all six components gives way to no contact (eq. 6.11-6)
        const auto& fixed = nodal_rigid_bodies_.fixed()[b];
        const bool held = std::all_of(fixed.begin(), fixed.end(), [](bool f) { return f; });
        for (const Index p : bodies[b])
            contact_->set_inverse_mass(
                p, held ? Vec3(Vec3::Zero())
                        : bc_->free_inverse_mass(static_cast<std::size_t>(p),
                                                 contact_mass_[static_cast<std::size_t>(p)]));
    }
}

ExplicitSolver::StepLengths ExplicitSolver::next_step_lengths(
    const CyclePolicy& policy, const ShellElements::StepTotals& elements, Real dt_cap) {
    StepLengths dt;
    dt.dt_new = policy.step_scale * elements.min_dt;
    if (dt.dt_new < min_step_) {  // control.minimum_time_step without erode (with it, the
        std::ostringstream msg;   // elements below it have eroded in the loop)
        msg << "the stable time step " << dt.dt_new << " fell below control.minimum_time_step ("
            << min_step_ << ") at step " << steps_ << " (t = " << time_ << "), set by element "
            << elements.min_dt_element + 1;
        throw RunFailure(msg.str());
    }
    if (dt_half_ > 0 && policy.cap_step_growth) dt.dt_new = std::min(dt.dt_new, 1.2 * dt_half_);
    dt.dt_new = std::min(dt.dt_new, dt_cap);
    if (!(dt.dt_new > 0) || !std::isfinite(dt.dt_new)) {
        std::ostringstream msg;
        msg << "the stable time step became " << dt.dt_new << " at step " << steps_ << " (element "
            << elements.min_dt_element + 1 << ")";
        throw RunFailure(msg.str());
    }
    // Start (and restart after a kinetic-damping reset, when v^{n-1/2} = 0 stands for v^n = 0):
    // v^{1/2} = v^0 + dt/2 a^0. A full dt_n there would make the relaxation a gradient descent
    // with step dt^2/m, unstable for dt omega_max > sqrt(2).
    dt.dt_n = (dt_half_ > 0 && !restart_) ? 0.5 * (dt_half_ + dt.dt_new) : 0.5 * dt.dt_new;
    dt.first = !(dt_half_ > 0) && !restart_;
    if (dt_half_ > 0 && !(dt_half_prev_ > 0) && !restart_) dt.prev_weight = 0.5;
    restart_ = false;
    dt.a_m = policy.mass_damping;
    dt.c1 = 1.0 / (1.0 + 0.5 * dt.a_m * dt.dt_n);
    dt.c2 = 1.0 - 0.5 * dt.a_m * dt.dt_n;
    return dt;
}

void ExplicitSolver::penalty_contact(const StepLengths& dt) {
    for (RigidBodyState& b : bodies_) {
        b.force_prev = b.force;
        b.force.setZero();
    }
    if (!contact_) return;
    std::swap(s_.f_contact, s_.f_contact_prev);
    for (Vec3& f : s_.f_contact) f.setZero();
    if (!contact_->has_penalty()) return;
    const Real motion2 =
        max_over_particles([&](std::size_t p) { return (s_.x[p] - s_.x_prev[p]).squaredNorm(); });
    ranks_.share(RankExchange::Whole::contact, {&s_.x, &s_.x_prev});
    body_u_pred_.resize(bodies_.size());  // here: the bodies at t_n
    for (std::size_t b = 0; b < bodies_.size(); ++b) body_u_pred_[b] = bodies_[b].u;
    contact_->penalty_forces(s_.x, s_.v, body_u_pred_, bodies_, dt.c1 * dt.dt_n * dt.dt_new,
                             dt.dt_n * dt.dt_new, dt.dt_new, std::sqrt(motion2), steps_,
                             s_.f_contact);
}

PrescribedMotionTimes ExplicitSolver::prescribed_motion_times(const CyclePolicy& policy,
                                                              Real load_time,
                                                              const StepLengths& dt) const {
    PrescribedMotionTimes at;
    at.load_time = load_time;
    at.t_half = load_time + (policy.advance_time ? 0.5 * dt.dt_new : 0.0);
    at.t_next = load_time + (policy.advance_time ? dt.dt_new : 0.0);
    at.dt_n = dt.dt_n;
    at.dt_new = dt.dt_new;
    at.c1 = dt.c1;
    at.relaxation = policy.relaxation;
    return at;
}

void ExplicitSolver::impose_prescribed_motions(const CyclePolicy& policy, Real load_time,
                                               const StepLengths& dt) {
    bc_->impose_prescribed_motions(s_, model_.curves,
                                   prescribed_motion_times(policy, load_time, dt));
}

void ExplicitSolver::update_body_velocities(const StepLengths& dt) {
    // v^{n+1/2} from the (penalty) contact force; a fixed body keeps its velocity.
    for (RigidBodyState& b : bodies_) {
        b.v_prev = b.v;
        b.v += (dt.dt_n * b.inv_mass) * b.force;
    }
}

void ExplicitSolver::lagrange_contact(const StepLengths& dt) {
    if (!contact_ || !contact_->has_lagrange()) return;
    // Predictor x* = x^n + dt v^{n+1/2}; the multipliers move it onto the admissible set and
    // the velocities follow: v^{n+1/2} = (x^{n+1} - x^n) / dt (§8.3).
    const std::size_t np = s_.size();
    const Real dt_new = dt.dt_new;
    ranks_.share(RankExchange::Whole::contact, {&s_.x, &s_.v});
    x_pred_.resize(np);
    for (std::size_t p = 0; p < np; ++p) x_pred_[p] = s_.x[p] + dt_new * s_.v[p];
    const Real motion2 =
        max_over_particles([&](std::size_t p) { return (dt_new * s_.v[p]).squaredNorm(); });
    body_u_pred_.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        body_u_pred_[b] = bodies_[b].u + dt_new * bodies_[b].v;
    x_pred_before_ = x_pred_;  // scratch members: no allocation in the time loop
    body_u_before_ = body_u_pred_;
    contact_->enforce(s_.x, x_pred_, body_u_pred_, bodies_, dt.c1 * dt.dt_n * dt_new,
                      dt.dt_n * dt_new, dt_new, std::sqrt(motion2), steps_, s_.f_contact);
    // A particle of a nodal rigid body moved as if it had its body's mass (eq. 6.11-5): its
    // velocity changes by the contact's impulse over its own mass, which make_rigid then
    // shares with its body.
    for (std::size_t p = 0; p < np; ++p) {
        if (x_pred_[p] == x_pred_before_[p]) continue;
        const Vec3 dv = (x_pred_[p] - x_pred_before_[p]) / dt_new;
        s_.v[p] += contact_mass_.empty() ? dv : Vec3((contact_mass_[p] / s_.mass[p]) * dv);
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (body_u_pred_[b] != body_u_before_[b])
            bodies_[b].v += (body_u_pred_[b] - body_u_before_[b]) / dt_new;
}

void ExplicitSolver::book_energies(const StepLengths& dt, const ParticleSums& particles) {
    Real kinetic = 0, external_work = 0, contact_work = 0;
    for (const RigidBodyState& b : bodies_) {
        // the step's displacement; in the first cycle that of v^{-1/2} over dt_n (eq. 6.8-3)
        const Vec3 du = dt.first ? Vec3(dt.dt_n * b.v_prev) : Vec3(b.u - b.u_prev);
        const Real body_work = 0.5 * (dt.prev_weight * b.force_prev + b.force).dot(du);
        contact_work += body_work;
        kinetic += 0.5 * b.mass * b.v_prev.dot(b.v);
        if (b.inv_mass == 0) external_work -= body_work;  // what drives a fixed body on
    }
    kinetic += nodal_rigid_bodies_.extra_kinetic_energy(s_);  // eq. 6.11-10
    energy_.kinetic = kinetic + particles.kinetic;
    energy_.contact -=
        contact_work + particles.contact_work;  // dissipated (multipliers) or stored (penalty)
    energy_.external_work += external_work + particles.external_work;
    energy_.damping += particles.damping;
    energy_.damping_ahead = particles.damping_ahead;
    // eq. 6.8-2: this step's rounding, as if every step so far had had it
    energy_.rounding = static_cast<Real>(steps_ + 1) * particles.rounding;
}

void ExplicitSolver::finish_step(const StepLengths& dt, const ParticleSums& particles) {
    std::swap(s_.x, s_.x_prev);  // x^{n+1} was written over x^{n-1}
    for (RigidBodyState& b : bodies_) {
        b.u_prev = b.u;
        b.u += dt.dt_new * b.v;
    }
    residual2_ = particles.residual2;
    reference2_ = particles.reference2;
    dt_center_ = dt.dt_n;
    dt_half_prev_ = dt_half_;
    dt_half_ = dt.dt_new;
    ++steps_;
    if (particles.non_finite > 0) report_non_finite_state();
}

void ExplicitSolver::report_failed_element(Index e) const {
    std::ostringstream msg;
    msg << "element " << e + 1 << " (particles";
    for (Index p : model_.triangles[static_cast<std::size_t>(e)]) msg << " " << p + 1;
    msg << ") was crushed, stretched or turned over within one step at step " << steps_
        << " (t = " << time_
        << "): the solution has diverged (load beyond what the model can carry, "
        << "or a time step too large)";
    throw RunFailure(msg.str());
}

void ExplicitSolver::report_non_finite_state() const {
    const std::size_t np = s_.size();
    if (ranks_.distributed()) {  // the first owned one over the ranks
        Index first = -1;
        for (std::size_t p = 0; p < np && first < 0; ++p)
            if (ranks_.owns(p) && !finite_state(p, s_.x[p])) first = static_cast<Index>(p);
        first = ranks_.index_at_min(first >= 0 ? 0.0 : 1.0, first);
        std::ostringstream msg;
        msg << "the solution became NaN or infinite at step " << steps_ << " (t = " << time_
            << ") at particle " << first + 1;
        throw RunFailure(msg.str());
    }
    for (std::size_t p = 0; p < np; ++p) {
        if (!finite_state(p, s_.x[p])) {
            std::ostringstream msg;
            msg << "the solution became NaN or infinite at step " << steps_ << " (t = " << time_
                << ") at particle " << p + 1 << " (internal force " << s_.f_int[p].transpose()
                << ")";
            throw RunFailure(msg.str());
        }
    }
}

void ExplicitSolver::check_energy_balance() const {
    const Real err = energy_.error();
    if (steps_ <= 10 || std::abs(err) <= model_.control.energy_error_limit) return;
    // Where: the particle with the largest kinetic energy (an instability grows fastest there)
    // and the element that sets the stable step.
    const bool distributed = ranks_.distributed();
    std::size_t hot = 0;
    Real hot_ke = -1;
    for (std::size_t p = 0; p < s_.size(); ++p) {
        if (!ranks_.owns(p)) continue;
        const Real ke =
            s_.mass[p] * s_.v[p].squaredNorm() + s_.inertia[p] * s_.omega[p].squaredNorm();
        if (ke > hot_ke) {
            hot_ke = ke;
            hot = p;
        }
    }
    Index critical = -1;
    if (distributed) {  // over the ranks: the largest kinetic energy, the last step's element
        hot = static_cast<std::size_t>(ranks_.index_at_min(-hot_ke, static_cast<Index>(hot)));
        critical = min_dt_element_;
    } else {
        (void)elements_.min_critical_dt(s_.x, &critical);
    }
    std::ostringstream msg;
    msg << "the energy balance error reached " << err * 100 << " % at step " << steps_
        << " (t = " << time_ << "), beyond the limit of " << model_.control.energy_error_limit * 100
        << " % (control.energy_error_limit): the run is unstable; the largest kinetic energy is at "
           "particle "
        << hot + 1 << ", the smallest stable step at element " << critical + 1;
    throw RunFailure(msg.str());
}

void ExplicitSolver::move_to_kinetic_energy_peak(Real ke_before, Real ke_peak, Real ke_after) {
    // Barnes (1988) kinetic damping: the kinetic energies of the last three half steps
    // (tau = -1, 0, +1 around t_{n-1/2}) bracket a peak; the parabola through them puts it at
    // tau*, where the dominant mode passes its equilibrium. Stopping the particles there, not at
    // x_{n+1}, removes that mode's energy entirely; stopping at x_{n+1} leaves a part of it,
    // and a mode with a period of a few steps can then be re-excited at every restart (the
    // relaxation stalls with a reset every 4 steps). Motion over [t_{n-1}, t_n] is v_{n-1/2}:
    // x(t_{n-1/2} + tau dt) = x_n + (tau - 1/2) dt_{n-1/2} v_{n-1/2}.
    const Real curvature = 2.0 * ke_peak - ke_before - ke_after;
    const Real tau =
        curvature > 0 ? std::clamp(0.5 * (ke_after - ke_before) / curvature, -0.5, 0.5) : 0.5;
    const Real back = (tau - 0.5) * dt_half_prev_;
    for (std::size_t p = 0; p < s_.size(); ++p) {
        s_.x[p] = bc_->where_not_prescribed(p, s_.x_prev[p] + back * s_.v_prev[p], s_.x[p]);
        if (!bc_->prescribed_rotation(p)) {
            // undo the last increment, apply the one to the peak; the next path element goes
            // from x_n to the peak state
            const Vec3 dtheta_peak = back * s_.omega_prev[p];
            s_.rotation[p] = rotation_quaternion(dtheta_peak) *
                             rotation_quaternion(s_.dtheta[p]).conjugate() * s_.rotation[p];
            s_.dtheta[p] = dtheta_peak;
        }
    }
}

ExplicitSolver::RelaxResult ExplicitSolver::relax(Real load_time) {
    RelaxResult res;
    time_ = load_time;
    const Real tol = model_.control.tolerance;
    Real ke_prev = 0, ke_prev2 = 0;
    for (long it = 1; it <= model_.control.max_relaxation_iterations; ++it) {
        cycle(CyclePolicy::relaxing(model_), load_time, std::numeric_limits<Real>::infinity());
        res.iterations = it;
        res.residual_ratio = reference2_ > 0 ? std::sqrt(residual2_ / reference2_) : 0.0;
        // Kinetic damping: at a peak of the kinetic energy, stop every particle.
        Real ke = kinetic_measure();
        if (ke < ke_prev) {
            move_to_kinetic_energy_peak(ke_prev2, ke_prev, ke);
            // distributed: the positions sent at the end of the cycle were those before the
            // move; the held particles' moved positions go instead
            ranks_.finish_positions(s_.x);
            ranks_.start_positions(s_.x);
            // The kinetic energy taken out is dissipated, like damping: the balance stays closed.
            energy_.damping += energy_.kinetic;
            energy_.kinetic = 0;
            for (std::size_t p = 0; p < s_.size(); ++p) {
                s_.v[p] = bc_->where_not_prescribed(p, Vec3::Zero(), s_.v[p]);
                if (!bc_->prescribed_rotation(p)) s_.omega[p].setZero();
            }
            ke = 0;
            restart_ = true;
        }
        ke_prev2 = ke_prev;
        ke_prev = ke;
        if (it > 2 && (res.residual_ratio <= tol || reference2_ == 0)) {
            res.converged = true;
            break;
        }
    }
    return res;
}

}  // namespace fpmshell
