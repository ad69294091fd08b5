#include "fpmshell/solver/explicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fpmshell/core/chunked_loop.hpp"
#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/rotation.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/io/restart_archive.hpp"

namespace fpmshell {
namespace {

constexpr Real k_kink_cosine = 0.9397;  // cos 20 deg: beyond it a particle gets 3 rotations (§1.3)
constexpr Real k_relaxation_step_scale = 0.75;
// Particle loops of smaller models stay serial: a parallel region costs more than it saves there.
constexpr Index k_parallel_min_particles = 2000;

/// Removes from w its components along the constraint directions (Gram-Schmidt on the fly).
Vec3 remove_components(Vec3 w, const std::array<Vec3, 4>& dirs, int n_dirs) {
    std::array<Vec3, 3> basis;
    int nb = 0;
    for (int i = 0; i < n_dirs && nb < 3; ++i) {
        Vec3 d = dirs[static_cast<std::size_t>(i)];
        for (int j = 0; j < nb; ++j) d -= d.dot(basis[static_cast<std::size_t>(j)]) * basis[static_cast<std::size_t>(j)];
        const Real len = d.norm();
        if (len > 1e-8) basis[static_cast<std::size_t>(nb++)] = d / len;
    }
    for (int j = 0; j < nb; ++j) w -= w.dot(basis[static_cast<std::size_t>(j)]) * basis[static_cast<std::size_t>(j)];
    return w;
}

}  // namespace

ExplicitSolver::ExplicitSolver(const Model& model) : model_(model), topology_(model), elements_(model, topology_) {
    const std::size_t np = model.nodes.size();
    s_.resize(np);
    s_.x0 = model.nodes;
    s_.x = model.nodes;
    s_.x_prev = model.nodes;
    // §6.1 lumped mass, §6.2 option B rotary inertia: (rho h A / 3)(A/8 + h^2/12).
    std::vector<Vec3> normal_sum(np, Vec3::Zero());
    Real edge_sum = 0;
    for (std::size_t e = 0; e < model.triangles.size(); ++e) {
        const auto& t = model.triangles[e];
        const Section& sec = model.sections[static_cast<std::size_t>(model.element_section[e])];
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        const Vec3& p0 = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = model.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = model.nodes[static_cast<std::size_t>(t[2])];
        const Vec3 cr = (p1 - p0).cross(p2 - p0);
        const Real area = 0.5 * cr.norm();
        const NodeInertiaShare share = lumped_node_share(mat.density, sec.thickness, area);
        for (Index p : t) {
            s_.mass[static_cast<std::size_t>(p)] += share.mass;
            s_.inertia[static_cast<std::size_t>(p)] += share.inertia;
            normal_sum[static_cast<std::size_t>(p)] += cr;
        }
        edge_sum += (p1 - p0).norm() + (p2 - p1).norm() + (p0 - p2).norm();
    }
    if (!model.triangles.empty()) length_scale_ = edge_sum / (3.0 * static_cast<Real>(model.triangles.size()));
    // §1.3 kink particles: an attached element normal deviates by more than 20 degrees.
    for (std::size_t p = 0; p < np; ++p) s_.normal[p] = normal_sum[p].normalized();
    for (const auto& t : model.triangles) {
        const Vec3 n = (model.nodes[static_cast<std::size_t>(t[1])] - model.nodes[static_cast<std::size_t>(t[0])])
                           .cross(model.nodes[static_cast<std::size_t>(t[2])] - model.nodes[static_cast<std::size_t>(t[0])])
                           .normalized();
        for (Index p : t)
            if (n.dot(s_.normal[static_cast<std::size_t>(p)]) < k_kink_cosine) s_.full_rotation[static_cast<std::size_t>(p)] = 1;
    }
    // Boundary conditions -> per-particle masks and prescribed motions.
    fixed_.assign(np, {});
    prescribed_translation_.assign(np, 0);
    prescribed_rotation_.assign(np, 0);
    prescribed_rotation_applied_.assign(np, Vec3::Zero());
    for (const BoundaryCondition& bc : model.boundary) {
        for (Index p : bc.nodes) {
            const std::size_t up = static_cast<std::size_t>(p);
            for (std::size_t d = 0; d < 6; ++d) fixed_[up][d] = fixed_[up][d] || bc.fixed[d];
            if (bc.prescribed != PrescribedKind::None) {
                prescribed_.push_back({p, bc.prescribed, bc.value, bc.curve});
                if (bc.prescribed == PrescribedKind::AngularVelocity)
                    prescribed_rotation_[up] = 1;
                else
                    prescribed_translation_[up] = 1;
            }
        }
    }
    constrained_.assign(np, 0);
    for (std::size_t p = 0; p < np; ++p)
        constrained_[p] = prescribed_translation_[p] || prescribed_rotation_[p] ||
                          std::any_of(fixed_[p].begin(), fixed_[p].end(), [](bool f) { return f; });
    // §2.6 eq. 2.6c: the rotation the update leaves out (as the particle update below decides
    // whether to project onto the tangent plane).
    drill_kind_.assign(np, DrillKind::None);
    drill_free_axis_.assign(np, 0);
    for (std::size_t p = 0; p < np; ++p) {
        const int n_fixed_rot = fixed_[p][3] + fixed_[p][4] + fixed_[p][5];
        if (prescribed_rotation_[p] || s_.full_rotation[p] || n_fixed_rot == 3) continue;
        if (n_fixed_rot < 2) {
            drill_kind_[p] = DrillKind::Normal;
        } else {
            drill_kind_[p] = DrillKind::InSymmetryPlane;
            for (Eigen::Index d = 0; d < 3; ++d)
                if (!fixed_[p][3 + static_cast<std::size_t>(d)]) drill_free_axis_[p] = d;
        }
        s_.drill_axis[p] = drill_axis(p, s_.normal[p]);
    }
    for (const Load& load : model.loads) has_moment_loads_ = has_moment_loads_ || load.type == LoadType::Moment;
    // Initial conditions: v^0, w^0 (the first cycle uses v^{-1/2} := v^0).
    for (const InitialVelocity& ic : model.initial_conditions)
        for (Index p : ic.nodes) {
            // normal_velocity: along the initial surface normal of the particle (§1.3)
            s_.v[static_cast<std::size_t>(p)] = ic.velocity + ic.normal_velocity * s_.normal[static_cast<std::size_t>(p)];
            s_.omega[static_cast<std::size_t>(p)] = ic.angular_velocity;
        }
    for (std::size_t p = 0; p < np; ++p) {
        for (std::size_t d = 0; d < 3; ++d)
            if (fixed_[p][d]) s_.v[p][static_cast<Eigen::Index>(d)] = 0;
        s_.v_prev[p] = s_.v[p];
        s_.omega_prev[p] = s_.omega[p];
        energy_.external_work += 0.5 * s_.mass[p] * s_.v[p].squaredNorm() +
                                 0.5 * s_.inertia[p] * s_.omega[p].squaredNorm();
    }
    // Particle -> its triangles, in element order (update_normals).
    node_element_begin_.assign(np + 1, 0);
    for (const auto& t : model.triangles)
        for (Index p : t) ++node_element_begin_[static_cast<std::size_t>(p) + 1];
    for (std::size_t p = 0; p < np; ++p) node_element_begin_[p + 1] += node_element_begin_[p];
    node_element_.assign(static_cast<std::size_t>(node_element_begin_[np]), 0);
    {
        std::vector<Index> fill(node_element_begin_.begin(), node_element_begin_.end() - 1);
        for (std::size_t e = 0; e < model.triangles.size(); ++e)
            for (Index p : model.triangles[e])
                node_element_[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] = static_cast<Index>(e);
    }
    element_cross_.assign(model.triangles.size(), Vec3::Zero());
    // Pressure loads: loaded particle -> its loaded triangles, in the load's element order.
    pressure_gather_.resize(model.loads.size());
    for (std::size_t l = 0; l < model.loads.size(); ++l) {
        const Load& load = model.loads[l];
        if (load.type != LoadType::Pressure) continue;
        std::vector<std::vector<Index>> of_particle(np);
        for (Index e : load.elements)
            for (Index p : model.triangles[static_cast<std::size_t>(e)]) of_particle[static_cast<std::size_t>(p)].push_back(e);
        PressureGather& g = pressure_gather_[l];
        g.begin.push_back(0);
        for (std::size_t p = 0; p < np; ++p) {
            if (of_particle[p].empty()) continue;
            g.particle.push_back(static_cast<Index>(p));
            g.element.insert(g.element.end(), of_particle[p].begin(), of_particle[p].end());
            g.begin.push_back(static_cast<Index>(g.element.size()));
        }
    }
    // A first load that is a pressure on every triangle (in element order) is summed in the
    // pass of the normals, over the same triangles in the same order (the same bits).
    if (!model.loads.empty() && model.loads[0].type == LoadType::Pressure) {
        const PressureGather& g = pressure_gather_[0];
        fused_pressure_ = g.particle.size() == np && g.begin == node_element_begin_ && g.element == node_element_;
    }
    parallel_particles_ = static_cast<Index>(np) >= k_parallel_min_particles;
    // Rigid bodies and contact (theory.md §8).
    bodies_ = RigidBodyState::from_model(model);
    for (const RigidBodyState& b : bodies_) energy_.external_work += 0.5 * b.mass * b.v.squaredNorm();
    if (!model.contacts.empty()) {
        inv_mass_.assign(np, Vec3::Zero());
        for (std::size_t p = 0; p < np; ++p) {
            if (prescribed_translation_[p] || !(s_.mass[p] > 0)) continue;
            for (std::size_t d = 0; d < 3; ++d)
                if (!fixed_[p][d]) inv_mass_[p][static_cast<Eigen::Index>(d)] = 1.0 / s_.mass[p];
        }
        std::vector<Real> thickness(model.triangles.size());
        for (std::size_t e = 0; e < thickness.size(); ++e) thickness[e] = elements_.thickness(static_cast<Index>(e));
        contact_ = std::make_unique<ContactSolver>(model, inv_mass_, thickness);
    }
    energy_.kinetic = energy_.external_work;
}

Vec3 ExplicitSolver::body_acceleration(Index b) const {
    const RigidBodyState& body = bodies_[static_cast<std::size_t>(b)];
    if (dt_center_ <= 0) return Vec3::Zero();
    return (body.v - body.v_prev) / dt_center_;
}

void ExplicitSolver::penalty_contact(Real dt_n, Real dt_new, Real c1) {
    Real motion2 = 0;
    for (std::size_t p = 0; p < s_.size(); ++p) motion2 = std::max(motion2, (s_.x[p] - s_.x_prev[p]).squaredNorm());
    body_u_pred_.resize(bodies_.size());  // here: the bodies at t_n
    for (std::size_t b = 0; b < bodies_.size(); ++b) body_u_pred_[b] = bodies_[b].u;
    contact_->penalty_forces(s_.x, body_u_pred_, bodies_, c1 * dt_n * dt_new, dt_n * dt_new,
                             std::sqrt(motion2), steps_, s_.f_contact);
}

void ExplicitSolver::lagrange_contact(Real dt_n, Real dt_new, Real c1) {
    // Predictor x* = x^n + dt v^{n+1/2}; the multipliers move it onto the admissible set and
    // the velocities follow: v^{n+1/2} = (x^{n+1} - x^n) / dt (§8.3).
    const std::size_t np = s_.size();
    x_pred_.resize(np);
    Real motion2 = 0;
    for (std::size_t p = 0; p < np; ++p) {
        const Vec3 dx = dt_new * s_.v[p];
        x_pred_[p] = s_.x[p] + dx;
        motion2 = std::max(motion2, dx.squaredNorm());
    }
    body_u_pred_.resize(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) body_u_pred_[b] = bodies_[b].u + dt_new * bodies_[b].v;
    x_pred_before_ = x_pred_;  // scratch members: no allocation in the time loop
    body_u_before_ = body_u_pred_;
    contact_->enforce(s_.x, x_pred_, body_u_pred_, bodies_, c1 * dt_n * dt_new, dt_n * dt_new,
                      std::sqrt(motion2), steps_, s_.f_contact);
    for (std::size_t p = 0; p < np; ++p)
        if (x_pred_[p] != x_pred_before_[p]) s_.v[p] += (x_pred_[p] - x_pred_before_[p]) / dt_new;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (body_u_pred_[b] != body_u_before_[b]) bodies_[b].v += (body_u_pred_[b] - body_u_before_[b]) / dt_new;
}

Real ExplicitSolver::curve_value(Index curve, Real t) const {
    return curve < 0 ? 1.0 : model_.curves[static_cast<std::size_t>(curve)].value(t);
}

Real ExplicitSolver::curve_integral(Index curve, Real t) const {
    if (curve < 0) return t;
    // Exact integral of the piecewise-linear curve from 0 to t (flat outside its points).
    const auto& pts = model_.curves[static_cast<std::size_t>(curve)].points;
    const Curve& c = model_.curves[static_cast<std::size_t>(curve)];
    std::vector<Real> knots{0.0};
    for (const auto& pt : pts)
        if (pt.first > 0 && pt.first < t) knots.push_back(pt.first);
    knots.push_back(t);
    Real sum = 0;
    for (std::size_t i = 1; i < knots.size(); ++i)
        sum += 0.5 * (c.value(knots[i - 1]) + c.value(knots[i])) * (knots[i] - knots[i - 1]);
    return sum;
}

Real ExplicitSolver::stable_dt() const {
    return model_.control.time_step_scale * elements_.min_critical_dt(s_.x);
}

Vec3 ExplicitSolver::acceleration(Index p) const {
    const std::size_t up = static_cast<std::size_t>(p);
    if (dt_center_ <= 0) return Vec3::Zero();
    return (s_.v[up] - s_.v_prev[up]) / dt_center_;
}

void ExplicitSolver::update_normals_and_loads(Real t) {
    // §1.3 area-weighted normal, recomputed from the current positions: the cross product of
    // every triangle, then each particle sums those of its triangles in element order (the
    // order of a serial scatter, without its write conflicts).
    const Index ne = static_cast<Index>(model_.triangles.size());
    parallel_for_each(ne, parallel_particles_, [&](Index e) {
        const auto& tri = model_.triangles[static_cast<std::size_t>(e)];
        element_cross_[static_cast<std::size_t>(e)] =
            (s_.x[static_cast<std::size_t>(tri[1])] - s_.x[static_cast<std::size_t>(tri[0])])
                .cross(s_.x[static_cast<std::size_t>(tri[2])] - s_.x[static_cast<std::size_t>(tri[0])]);
    });
    // §6.7 follower pressure: f_i = -p A_t n_t / 3 (positive pushes against n), A n = cr / 2.
    auto pressure_scale = [&](const Load& load) { return -load.pressure * curve_value(load.curve, t) / 6.0; };
    // The external loads start from zero (the fused pressure: from its first triangle); those of
    // t_{n-1} stay for the work of the step by exchanging the arrays (every entry of the new
    // ones is written below).
    std::swap(s_.f_ext, s_.f_ext_prev);
    if (has_moment_loads_) std::swap(s_.m_ext, s_.m_ext_prev);
    const Real fused_scale = fused_pressure_ ? pressure_scale(model_.loads[0]) : 0.0;
    parallel_for_each(static_cast<Index>(s_.size()), parallel_particles_, [&](Index ip) {
        const std::size_t p = static_cast<std::size_t>(ip);
        Vec3 sum = Vec3::Zero(), f = Vec3::Zero();
        for (Index k = node_element_begin_[p]; k < node_element_begin_[p + 1]; ++k) {
            const Vec3& cross = element_cross_[static_cast<std::size_t>(node_element_[static_cast<std::size_t>(k)])];
            sum += cross;
            if (fused_pressure_) f += fused_scale * cross;
        }
        const Real len = sum.norm();
        s_.normal[p] = len > 0 ? Vec3(sum / len) : Vec3::UnitZ();
        s_.drill_axis[p] = drill_axis(p, s_.normal[p]);
        s_.f_ext[p] = f;
        if (has_moment_loads_) s_.m_ext[p] = Vec3::Zero();
    });
    for (std::size_t l = fused_pressure_ ? 1 : 0; l < model_.loads.size(); ++l) {
        const Load& load = model_.loads[l];
        const Real factor = curve_value(load.curve, t);
        switch (load.type) {
            case LoadType::Pressure: {
                // Each particle adds its loaded triangles in the load's order (that of a serial
                // scatter).
                const Real scale = pressure_scale(load);
                const PressureGather& g = pressure_gather_[l];
                parallel_for_each(static_cast<Index>(g.particle.size()), parallel_particles_, [&](Index i) {
                    const std::size_t ui = static_cast<std::size_t>(i);
                    Vec3& f = s_.f_ext[static_cast<std::size_t>(g.particle[ui])];
                    for (Index k = g.begin[ui]; k < g.begin[ui + 1]; ++k)
                        f += scale * element_cross_[static_cast<std::size_t>(g.element[static_cast<std::size_t>(k)])];
                });
                break;
            }
            case LoadType::Force:
                for (Index p : load.nodes) s_.f_ext[static_cast<std::size_t>(p)] += factor * load.vector;
                break;
            case LoadType::Moment:
                for (Index p : load.nodes) s_.m_ext[static_cast<std::size_t>(p)] += factor * load.vector;
                break;
        }
    }
}

void ExplicitSolver::cycle(Real load_time, Real dt_new_cap, bool relaxation) {
    // 1 element loop on the path element (x^{n-1}, x^n, dtheta^{n-1/2}) -> f_int^n, m_int^n.
    const Real a_s = model_.damping.stiffness;
    const Real viscous_rate = (a_s > 0 && dt_half_ > 0) ? a_s / dt_half_ : 0.0;
    // The path element lasts dt_{n-1/2}; relaxation steps are fictitious time: no rate effects.
    const ShellElements::StepTotals tot = elements_.compute(s_, viscous_rate, relaxation ? 0.0 : dt_half_);
    element_steps_ += elements_.size();
    if (tot.failed_element >= 0) {
        std::ostringstream msg;
        msg << "element " << tot.failed_element + 1 << " (particles";
        for (Index p : model_.triangles[static_cast<std::size_t>(tot.failed_element)]) msg << " " << p + 1;
        msg << ") was crushed, stretched or turned over within one step at step " << steps_
            << " (t = " << time_ << "): the solution has diverged (load beyond what the model can carry, "
            << "or a time step too large)";
        throw RunFailure(msg.str());
    }
    energy_.internal += tot.strain_work;  // includes the plastic dissipation, like LS-DYNA's
    energy_.plastic += tot.plastic_work;  // internal energy; reported on its own as well
    energy_.damping += tot.damping_work;

    // 2 tangent planes and external loads at t_n.
    update_normals_and_loads(load_time);

    // 3 dt_{n+1/2} = s min dt_e, growth capped at 1.2 dt_{n-1/2} (§6.4).
    // Relaxation caps the factor at 0.75, inside the provably stable 0.8 of §6.4: with a mode
    // close to its stability limit, kinetic damping never removes it and the residual stalls.
    const Real scale = relaxation ? std::min(model_.control.time_step_scale, k_relaxation_step_scale)
                                  : model_.control.time_step_scale;
    Real dt_new = scale * tot.min_dt;
    if (dt_half_ > 0 && !relaxation) dt_new = std::min(dt_new, 1.2 * dt_half_);
    dt_new = std::min(dt_new, dt_new_cap);
    if (!(dt_new > 0) || !std::isfinite(dt_new)) {
        std::ostringstream msg;
        msg << "the stable time step became " << dt_new << " at step " << steps_ << " (element "
            << tot.min_dt_element + 1 << ")";
        throw RunFailure(msg.str());
    }
    // Start (and restart after a kinetic-damping reset, when v^{n-1/2} = 0 stands for v^n = 0):
    // v^{1/2} = v^0 + dt/2 a^0. A full dt_n there would make the relaxation a gradient descent
    // with step dt^2/m, unstable for dt omega_max > sqrt(2).
    const Real dt_n = (dt_half_ > 0 && !restart_) ? 0.5 * (dt_half_ + dt_new) : 0.5 * dt_new;
    restart_ = false;
    const Real a_m = relaxation ? 0.0 : model_.damping.mass;
    const Real c1 = 1.0 / (1.0 + 0.5 * a_m * dt_n), c2 = 1.0 - 0.5 * a_m * dt_n;

    // Penalty contact forces at t_n (the Lagrange multipliers come after the update).
    const std::size_t np = s_.size();
    for (RigidBodyState& b : bodies_) {
        b.force_prev = b.force;
        b.force.setZero();
    }
    if (contact_) {
        std::swap(s_.f_contact, s_.f_contact_prev);
        for (std::size_t p = 0; p < np; ++p) s_.f_contact[p].setZero();
        if (contact_->has_penalty()) penalty_contact(dt_n, dt_new, c1);
    }

    // 4 central difference (§6.6) with boundary conditions (§6.7); constraint reactions.
    const Real t_half = load_time + (relaxation ? 0.0 : 0.5 * dt_new);
    const Real t_next = load_time + (relaxation ? 0.0 : dt_new);
    Real kinetic = 0, damping_work = 0, ext_work = 0;
    // Every particle on its own; the residual sums in fixed chunks (core/chunked_loop.hpp), only
    // in relaxation (its convergence test is their only reader). v^{n-1/2} and w^{n-1/2} become
    // the previous half-step values by exchanging the arrays, not by a copy (every particle's
    // new value is written below).
    std::swap(s_.v, s_.v_prev);
    std::swap(s_.omega, s_.omega_prev);
    const bool has_contact = static_cast<bool>(contact_);
    // v^{n+1/2}, w^{n+1/2} and the reactions of particle p; in relaxation, its out-of-balance
    // and applied loads squared into residual[0], residual[1].
    auto update_particle = [&](std::size_t p, Real* residual) {
        Vec3 force = s_.f_ext[p] - s_.f_int[p];
        if (has_contact) force += s_.f_contact[p];
        const Real m = s_.mass[p];
        const bool constrained = constrained_[p];
        const std::array<bool, 6>& fixed = fixed_[p];
        auto without_fixed = [&fixed](Vec3 u) {  // the fixed translation components set to 0
            for (Eigen::Index d = 0; d < 3; ++d)
                if (fixed[static_cast<std::size_t>(d)]) u[d] = 0;
            return u;
        };
        const Vec3 v_free = c1 * (c2 * s_.v_prev[p] + (dt_n / m) * force);  // v^{n+1/2}
        const Vec3 v_new = without_fixed(v_free);
        s_.v[p] = v_new;  // prescribed values are written below
        if (constrained) s_.reaction[p] = (m / (c1 * dt_n)) * (v_new - v_free);

        // Rotations in the tangent plane: w^{n+1/2} = c1 [c2 P w^{n-1/2} + dt_n P M / J].
        // With at most one free rotation axis (symmetry planes, §6.7) the rotation is about that
        // axis alone; the tangent-plane projection is skipped because the one-sided normal of a
        // particle on a symmetry plane is tilted out of the plane and would also block it.
        const Vec3 moment = has_moment_loads_ ? Vec3(s_.m_ext[p] - s_.m_int[p]) : Vec3(-s_.m_int[p]);
        std::array<Vec3, 4> dirs;
        int nd = 0;
        const int n_fixed_rot = fixed[3] + fixed[4] + fixed[5];
        const bool project = !s_.full_rotation[p] && n_fixed_rot < 2;
        const Vec3& normal = s_.normal[p];
        if (project) dirs[static_cast<std::size_t>(nd++)] = normal;
        for (std::size_t d = 0; d < 3; ++d)
            if (fixed[3 + d]) dirs[static_cast<std::size_t>(nd++)] = Vec3::Unit(static_cast<Eigen::Index>(d));
        const Vec3 moment_tangent = project ? Vec3(moment - moment.dot(normal) * normal) : moment;
        const Vec3& omega = s_.omega_prev[p];  // w^{n-1/2}
        const Vec3 omega_tangent = project ? Vec3(omega - omega.dot(normal) * normal) : omega;
        const Real j = s_.inertia[p];
        const Vec3 w_free = c1 * (c2 * omega_tangent + (dt_n / j) * moment_tangent);
        // A particle whose only constraint is its tangent plane: w_free is tangent already (both
        // of its terms are), and projecting it again would change it by rounding only.
        const bool tangent_only = project && nd == 1;
        const Vec3 w_new = tangent_only ? w_free : remove_components(w_free, dirs, nd);
        s_.omega[p] = w_new;
        if (constrained) s_.reaction_moment[p] = (j / (c1 * dt_n)) * (w_new - w_free);
        if (!relaxation) return;

        // Out-of-balance force and moment on the free directions, against the applied ones.
        const Vec3 force_free = prescribed_translation_[p] ? Vec3::Zero() : without_fixed(force);
        residual[0] += force_free.squaredNorm();
        residual[1] += s_.f_ext[p].squaredNorm() + (force - force_free).squaredNorm();
        const Vec3 moment_free = prescribed_rotation_[p] ? Vec3::Zero() : remove_components(moment_tangent, dirs, nd);
        const Real ls2 = length_scale_ * length_scale_;
        residual[0] += moment_free.squaredNorm() / ls2;
        residual[1] += (s_.m_ext[p].squaredNorm() + (moment_tangent - moment_free).squaredNorm()) / ls2;
    };
    // The energies of particle p at t_n into energy[0..3] (kinetic, work of loads and reactions,
    // contact work, damping), energy[4]: 1 if its new state is not finite (a diverged run); then
    // its x^{n+1} and rotation increment.
    auto advance_particle = [&](std::size_t p, Real* energy) {
        // Energies at t_n: leapfrog kinetic energy, work of loads and reactions over
        // [t_{n-1}, t_n] (trapezoidal), mass-damping dissipation over dt_n.
        energy[0] += 0.5 * s_.mass[p] * s_.v_prev[p].dot(s_.v[p]) +
                     0.5 * s_.inertia[p] * s_.omega_prev[p].dot(s_.omega[p]);
        // (a free particle has no reactions; without moment loads m_ext stays zero)
        const bool constrained = constrained_[p];
        Vec3 force_sum = s_.f_ext_prev[p] + s_.f_ext[p];
        Vec3 moment_sum = has_moment_loads_ ? Vec3(s_.m_ext_prev[p] + s_.m_ext[p]) : Vec3::Zero();
        if (constrained) {
            force_sum = force_sum + s_.reaction_prev[p] + s_.reaction[p];
            moment_sum = moment_sum + s_.reaction_moment_prev[p] + s_.reaction_moment[p];
        }
        energy[1] += 0.5 * force_sum.dot(s_.x[p] - s_.x_prev[p]) + 0.5 * moment_sum.dot(s_.dtheta[p]);
        if (has_contact) energy[2] += 0.5 * (s_.f_contact_prev[p] + s_.f_contact[p]).dot(s_.x[p] - s_.x_prev[p]);
        if (a_m > 0) {
            const Vec3 vbar = 0.5 * (s_.v_prev[p] + s_.v[p]);
            const Vec3 wbar = 0.5 * (s_.omega_prev[p] + s_.omega[p]);
            energy[3] += a_m * dt_n * (s_.mass[p] * vbar.squaredNorm() + s_.inertia[p] * wbar.squaredNorm());
        }
        if (constrained) {
            s_.reaction_prev[p] = s_.reaction[p];
            s_.reaction_moment_prev[p] = s_.reaction_moment[p];
        }

        // 5 x^{n+1} = x^n + dt v^{n+1/2}, written over x^{n-1} (the arrays are exchanged after
        // the pass); rotation increment for the next path element. In the same pass as the
        // energies (which read x^n, x^{n-1} and dtheta first): one sweep over the particle
        // arrays instead of two.
        s_.x_prev[p] = s_.x[p] + dt_new * s_.v[p];
        s_.dtheta[p] = dt_new * s_.omega[p];
        s_.rotation[p] = rotation_quaternion(s_.dtheta[p]) * s_.rotation[p];
        if (!finite_state(p, s_.x_prev[p])) energy[4] += 1;
    };
    // Without prescribed motions and Lagrange contact, which change v^{n+1/2} between the two,
    // the update and the energy pass are one sweep over the particle arrays instead of two (the
    // same sums in the same order).
    const bool one_pass = prescribed_.empty() && !(contact_ && contact_->has_lagrange());
    std::array<Real, 2> residual{};
    std::array<Real, 5> particle_energy{};
    if (one_pass) {
        const std::array<Real, 7> sums = chunked_sum<7>(static_cast<Index>(np), parallel_particles_, sums7_,
                                                        [&](Index ip, std::array<Real, 7>& acc) {
            const std::size_t p = static_cast<std::size_t>(ip);
            update_particle(p, acc.data() + 5);
            advance_particle(p, acc.data());
        });
        std::copy_n(sums.begin(), 5, particle_energy.begin());
        std::copy_n(sums.begin() + 5, 2, residual.begin());
    } else {
        residual = chunked_sum<2>(static_cast<Index>(np), parallel_particles_, sums2_,
                                  [&](Index ip, std::array<Real, 2>& acc) { update_particle(static_cast<std::size_t>(ip), acc.data()); });
    }
    residual2_ = residual[0];
    reference2_ = residual[1];
    for (const Prescribed& pr : prescribed_) {
        const std::size_t p = static_cast<std::size_t>(pr.particle);
        const Real m = s_.mass[p];
        const Vec3 v_before = s_.v[p];
        if (pr.kind == PrescribedKind::Velocity) {
            if (relaxation) {
                const Vec3 target = s_.x0[p] + curve_integral(pr.curve, load_time) * pr.value;
                s_.v[p] = (target - s_.x[p]) / dt_new;
            } else {
                s_.v[p] = curve_value(pr.curve, t_half) * pr.value;
            }
        } else if (pr.kind == PrescribedKind::Displacement) {
            const Vec3 target = s_.x0[p] + curve_value(pr.curve, t_next) * pr.value;
            s_.v[p] = (target - s_.x[p]) / dt_new;
        } else {  // angular velocity: imposed about a fixed axis, no tangent-plane projection
            const Vec3 omega_before = s_.omega[p];
            if (relaxation) {
                const Vec3 target = curve_integral(pr.curve, load_time) * pr.value;
                s_.omega[p] = (target - prescribed_rotation_applied_[p]) / dt_new;
            } else {
                s_.omega[p] = curve_value(pr.curve, t_half) * pr.value;
            }
            prescribed_rotation_applied_[p] += dt_new * s_.omega[p];
            // the moment that imposes it: J / dt_n times the change it makes (like the force above)
            s_.reaction_moment[p] += (s_.inertia[p] / (c1 * dt_n)) * (s_.omega[p] - omega_before);
            continue;
        }
        s_.reaction[p] += (m / (c1 * dt_n)) * (s_.v[p] - v_before);
    }
    // Rigid bodies: v^{n+1/2} from the (penalty) contact force; a fixed body keeps its velocity.
    for (RigidBodyState& b : bodies_) {
        b.v_prev = b.v;
        b.v += (dt_n * b.inv_mass) * b.force;
    }
    if (contact_ && contact_->has_lagrange()) lagrange_contact(dt_n, dt_new, c1);

    Real contact_work = 0;  // particles: in the energy loop below
    for (const RigidBodyState& b : bodies_) {
        const Real body_work = 0.5 * (b.force_prev + b.force).dot(b.u - b.u_prev);
        contact_work += body_work;
        kinetic += 0.5 * b.mass * b.v_prev.dot(b.v);
        if (b.inv_mass == 0) ext_work -= body_work;  // what drives a fixed body on
    }
    if (!one_pass)
        particle_energy = chunked_sum<5>(static_cast<Index>(np), parallel_particles_, sums5_,
                                         [&](Index ip, std::array<Real, 5>& acc) { advance_particle(static_cast<std::size_t>(ip), acc.data()); });
    std::swap(s_.x, s_.x_prev);
    kinetic += particle_energy[0];
    ext_work += particle_energy[1];
    contact_work += particle_energy[2];
    damping_work += particle_energy[3];
    energy_.kinetic = kinetic;
    energy_.contact -= contact_work;  // dissipated (Lagrange multipliers) or stored (penalty)
    energy_.external_work += ext_work;
    energy_.damping += damping_work;

    // 5 positions of the rigid bodies (those of the particles: in the energy pass above).
    for (RigidBodyState& b : bodies_) {
        b.u_prev = b.u;
        b.u += dt_new * b.v;
    }
    dt_center_ = dt_n;
    dt_half_prev_ = dt_half_;
    dt_half_ = dt_new;
    ++steps_;
    if (particle_energy[4] > 0) report_non_finite_state();
}

void ExplicitSolver::report_non_finite_state() const {
    const std::size_t np = s_.size();
    for (std::size_t p = 0; p < np; ++p) {
        if (!finite_state(p, s_.x[p])) {
            std::ostringstream msg;
            msg << "the solution became NaN or infinite at step " << steps_ << " (t = " << time_
                << ") at particle " << p + 1 << " (internal force " << s_.f_int[p].transpose() << ")";
            throw RunFailure(msg.str());
        }
    }
}

void ExplicitSolver::step(Real max_dt) {
    cycle(time_, max_dt, false);
    time_ += dt_half_;
    const Real err = energy_.error();
    if (steps_ > 10 && std::abs(err) > model_.control.energy_error_limit) {
        // Where: the particle with the largest kinetic energy (an instability grows fastest
        // there) and the element that sets the stable step.
        std::size_t hot = 0;
        Real hot_ke = -1;
        for (std::size_t p = 0; p < s_.size(); ++p) {
            const Real ke = s_.mass[p] * s_.v[p].squaredNorm() + s_.inertia[p] * s_.omega[p].squaredNorm();
            if (ke > hot_ke) {
                hot_ke = ke;
                hot = p;
            }
        }
        Index critical = -1;
        (void)elements_.min_critical_dt(s_.x, &critical);
        std::ostringstream msg;
        msg << "the energy balance error reached " << err * 100 << " % at step " << steps_
            << " (t = " << time_ << "), beyond the limit of " << model_.control.energy_error_limit * 100
            << " % (control.energy_error_limit): the run is unstable; the largest kinetic energy is at particle "
            << hot + 1 << ", the smallest stable step at element " << critical + 1;
        throw RunFailure(msg.str());
    }
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
    const Real tau = curvature > 0 ? std::clamp(0.5 * (ke_after - ke_before) / curvature, -0.5, 0.5) : 0.5;
    const Real back = (tau - 0.5) * dt_half_prev_;
    for (std::size_t p = 0; p < s_.size(); ++p) {
        if (!prescribed_translation_[p]) s_.x[p] = s_.x_prev[p] + back * s_.v_prev[p];
        if (!prescribed_rotation_[p]) {
            // undo the last increment, apply the one to the peak; the next path element goes
            // from x_n to the peak state
            const Vec3 dtheta_peak = back * s_.omega_prev[p];
            s_.rotation[p] = rotation_quaternion(dtheta_peak) * rotation_quaternion(s_.dtheta[p]).conjugate() * s_.rotation[p];
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
        cycle(load_time, std::numeric_limits<Real>::infinity(), true);
        res.iterations = it;
        res.residual_ratio = reference2_ > 0 ? std::sqrt(residual2_ / reference2_) : 0.0;
        // Kinetic damping: at a peak of the kinetic energy, stop every particle.
        Real ke = 0;
        for (std::size_t p = 0; p < s_.size(); ++p)
            ke += s_.mass[p] * s_.v[p].squaredNorm() + s_.inertia[p] * s_.omega[p].squaredNorm();
        if (ke < ke_prev) {
            move_to_kinetic_energy_peak(ke_prev2, ke_prev, ke);
            // The kinetic energy taken out is dissipated, like damping: the balance stays closed.
            energy_.damping += energy_.kinetic;
            energy_.kinetic = 0;
            for (std::size_t p = 0; p < s_.size(); ++p) {
                if (!prescribed_translation_[p]) s_.v[p].setZero();
                if (!prescribed_rotation_[p]) s_.omega[p].setZero();
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

template <class Archive>
void ExplicitSolver::transfer_state(Archive& ar) {
    ar(time_, dt_half_, dt_half_prev_, dt_center_, steps_, restart_, element_steps_);
    ar(s_, energy_, bodies_, prescribed_rotation_applied_);
}

void ExplicitSolver::save(RestartWriter& out) const {
    out.section("solver");
    const_cast<ExplicitSolver*>(this)->transfer_state(out);
    out.section("elements");
    elements_.save(out);
    out.section("contact");
    out(static_cast<bool>(contact_));
    if (contact_) contact_->save(out);
}

void ExplicitSolver::load(RestartReader& in) {
    in.section("solver");
    const std::size_t n_bodies = bodies_.size();
    transfer_state(in);
    // The model's initial positions must be those the run started from, bit for bit.
    if (s_.x0 != model_.nodes) in.fail("restart file of another model: its particles are not those of this mesh");
    if (bodies_.size() != n_bodies) in.fail("restart file of a model with other rigid bodies");
    for (std::size_t p = 0; p < s_.size(); ++p) s_.drill_axis[p] = drill_axis(p, s_.normal[p]);
    // a free particle's reactions are zero (earlier versions stored rounding noise there)
    for (std::size_t p = 0; p < s_.size(); ++p)
        if (!constrained_[p])
            s_.reaction[p] = s_.reaction_prev[p] = s_.reaction_moment[p] = s_.reaction_moment_prev[p] = Vec3::Zero();
    in.section("elements");
    elements_.load(in);
    in.section("contact");
    bool has_contact = false;
    in(has_contact);
    if (has_contact != static_cast<bool>(contact_)) in.fail("restart file of a model with other contact definitions");
    if (contact_) contact_->load(in);
}

}  // namespace fpmshell
