// The contact's set-up, its Lagrange-multiplier sweeps (theory.md §8.3) with their warm start
// and multiplier memory, and its restart state; the pair search is contact_pair_search.cpp.
#include "fpmshell/contact/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/contact/contact_tolerances.hpp"
#include "fpmshell/contact/stopwatch.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/model/mesh_pieces.hpp"
#include "fpmshell/model/node_thickness.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"

namespace fpmshell {
namespace {

using contact_tolerances::k_face_tolerance;
using contact_tolerances::k_pass_factor;
using contact_tolerances::unit_normal;

constexpr Real k_exclusion_factor = 1.5;   // default exclusion radius: 1.5 x largest thickness (R8)
constexpr Real k_margin_fraction = 0.2;    // search margin: 0.2 x largest offset (§8.1)
constexpr Real k_sweep_tolerance = 1e-3;   // sweeps stop when no gap is below -1e-3 h (§8.3)
constexpr Real k_lambda_tolerance = 1e-6;  // ... and no multiplier changed by 1e-6 of the largest

}  // namespace

ContactSolver::ContactSolver(const Model& model, const MeshTopology& topology,
                             const std::vector<Vec3>& inv_mass,
                             const std::vector<Real>& element_thickness)
    : model_(model), inv_mass_(inv_mass), element_thickness_(element_thickness) {
    // h_s of a particle: the mean thickness of its elements.
    const std::size_t np = model.nodes.size();
    node_thickness_ = mean_node_thickness(model.triangles, element_thickness, np);
    rigid_body_of_ = rigid_body_partition(model).body_of_particle;
    mesh_piece_ = mesh_pieces(np, model.triangles, model.separated_from);

    for (const ContactDefinition& def : model.contacts) {
        Definition d;
        d.def = def;
        if (def.method == ContactMethod::Penalty)
            has_penalty_ = true;
        else
            has_lagrange_ = true;
        if (def.type == ContactType::Self) {
            Real h_max = 0;
            for (Index e : def.elements) {
                if (def.nodes.empty())
                    for (Index p : model.triangles[static_cast<std::size_t>(e)])
                        d.slaves.push_back(p);
                h_max = std::max(h_max, element_thickness[static_cast<std::size_t>(e)]);
            }
            if (!def.nodes.empty()) d.slaves = def.nodes;  // given: they alone touch the faces
            std::sort(d.slaves.begin(), d.slaves.end());
            d.slaves.erase(std::unique(d.slaves.begin(), d.slaves.end()), d.slaves.end());
            // Edge neighbours of every slave (over all the model's triangles): a triangle that
            // touches one of them is in the slave's 2-ring and never its contact partner (§8.1).
            d.neighbour_start.push_back(0);
            for (Index s : d.slaves) {
                const std::span<const Index> a = topology.neighbours_of(s);
                d.neighbours.insert(d.neighbours.end(), a.begin(), a.end());
                d.neighbour_start.push_back(static_cast<std::int64_t>(d.neighbours.size()));
            }
            for (Index s : d.slaves) {
                d.slave_offset.push_back(0.5 * node_thickness_[static_cast<std::size_t>(s)]);
                h_max = std::max(h_max, node_thickness_[static_cast<std::size_t>(s)]);
            }
            d.max_offset = h_max;  // (h_s + h_e) / 2 <= max h
            d.exclusion_radius =
                def.exclusion_radius > 0 ? def.exclusion_radius : k_exclusion_factor * h_max;
            d.margin = k_margin_fraction * d.max_offset;
        } else {
            d.slaves = def.nodes;
        }
        definitions_.push_back(std::move(d));
    }
    slave_force_.assign(definitions_.size(), Vec3::Zero());
}

std::vector<Index> ContactSolver::particles() const {
    std::vector<Index> out;
    for (const Definition& d : definitions_) {
        out.insert(out.end(), d.slaves.begin(), d.slaves.end());
        for (const Index e : d.def.elements)
            for (const Index p : model_.triangles[static_cast<std::size_t>(e)]) out.push_back(p);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Real ContactSolver::weight_along(const Constraint& c, const Vec3& along, Real beta_particle,
                                 Real beta_body, const std::vector<RigidBodyState>& bodies) const {
    const Vec3 n2 = along.cwiseProduct(along);
    Real w = beta_particle * n2.dot(inv_mass_[static_cast<std::size_t>(c.slave)]);
    if (c.element >= 0)
        for (std::size_t k = 0; k < 3; ++k)
            w += beta_particle * c.xi[k] * c.xi[k] *
                 n2.dot(inv_mass_[static_cast<std::size_t>(c.master[k])]);
    if (c.body >= 0) w += beta_body * bodies[static_cast<std::size_t>(c.body)].inv_mass;
    return w;
}

void ContactSolver::note_penetration(Real penetration, const Constraint& c, long step) {
    if (!(penetration > stats_.max_penetration)) return;
    stats_.max_penetration = penetration;
    stats_.max_penetration_ratio = c.thickness > 0 ? penetration / c.thickness : 0.0;
    stats_.max_penetration_step = step;
    stats_.max_penetration_particle = c.slave;
    stats_.max_penetration_element = c.element;
}

void ContactSolver::enforce(const std::vector<Vec3>& x, std::vector<Vec3>& x_pred,
                            std::vector<Vec3>& body_u_pred, std::vector<RigidBodyState>& bodies,
                            Real beta_particle, Real beta_body, Real dt_new, Real motion, long step,
                            std::vector<Vec3>& f_contact) {
    Stopwatch watch(stats_.seconds);
    constraints_.clear();
    closed_.clear();
    motion_ = motion;
    int max_iterations = 1;
    for (Definition& d : definitions_) {
        if (d.def.method != ContactMethod::LagrangeMultiplier) continue;
        max_iterations = std::max(max_iterations, d.def.max_iterations);
        const std::size_t first = constraints_.size();
        slave_force_[definition_index(d)].setZero();
        if (d.def.type == ContactType::Self) {
            prepare_search(d, x, motion);
            collect_self(d, x, x_pred, true, constraints_, closed_);
        } else {
            collect_rigid(d, x_pred, body_u_pred, true, constraints_);
        }
        for (std::size_t i = first; i < constraints_.size(); ++i)
            constraints_[i].definition = definition_index(d);
    }
    // Drop constraints that nothing can satisfy (every particle fixed); set the weights. A
    // pair that is already inside at t_n (it escaped detection, or the linearised gap of the
    // last step left it slightly in) is held where it is, not pushed out: pushing it out
    // against its force would do positive work and create energy.
    const std::size_t n_found = constraints_.size();
    [[maybe_unused]] const bool parallel_all = n_found >= k_pass_factor * parallel_min_constraints_;
    long held = 0, kept = 0;  // counts and a smallest value: the same for any thread count
    Real h_min = std::numeric_limits<Real>::infinity();
#pragma omp parallel for schedule(static) reduction(+ : held, kept) reduction(min : h_min) \
    if (parallel_all)
    for (std::size_t k = 0; k < n_found; ++k) {
        Constraint& c = constraints_[k];
        Vec3 r = x[static_cast<std::size_t>(c.slave)];
        if (c.element >= 0)
            for (std::size_t j = 0; j < 3; ++j)
                r -= c.xi[j] * x[static_cast<std::size_t>(c.master[j])];
        if (c.body >= 0) r -= c.anchor + bodies[static_cast<std::size_t>(c.body)].u;
        const Real inside = c.offset - c.normal.dot(r);
        // (the tolerance's scale: the offset, or half the thickness for a rigid contact whose
        // offset is smaller, as LS-DYNA's walls' 0)
        if (inside > k_sweep_tolerance * std::max(c.offset, 0.5 * c.thickness)) {
            c.allowance = inside;
            ++held;
        }
        c.weight = weight(c, beta_particle, beta_body, bodies);
        // eq. 8.4-5: the coefficient at the sliding speed of the predictor (before contact)
        const ContactDefinition& def = definitions_[c.definition].def;
        if (c.friction > 0 && def.friction_decay > 0 && dt_new > 0) {
            const Real speed = tangential_slip(c, x, x_pred, body_u_pred, bodies).norm() / dt_new;
            c.friction = def.friction_dynamic + (def.friction - def.friction_dynamic) *
                                                    std::exp(-def.friction_decay * speed);
        }
        if (c.weight > 0) {
            ++kept;
            h_min = std::min(h_min, c.thickness);
        }
    }
    stats_.held_penetrations += held;
    if (kept == 0) h_min = 0;
    if (static_cast<std::size_t>(kept) < n_found)
        constraints_.erase(std::remove_if(constraints_.begin(), constraints_.end(),
                                          [](const Constraint& c) { return !(c.weight > 0); }),
                           constraints_.end());

    auto gap = [&](const Constraint& c) {
        Vec3 r = x_pred[static_cast<std::size_t>(c.slave)];
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                r -= c.xi[k] * x_pred[static_cast<std::size_t>(c.master[k])];
        if (c.body >= 0) r -= c.anchor + body_u_pred[static_cast<std::size_t>(c.body)];
        return c.normal.dot(r) - c.offset + c.allowance;
    };
    // Projected Gauss-Seidel on lambda >= 0, g + W dlambda >= 0, complementarity (§8.3), per
    // island of constraints (contact/constraint_islands.hpp): constraints that share no
    // particle and no movable body never see each other's updates, so each island is a problem
    // of its own, swept in its constraints' order, and the islands run in parallel with results
    // that do not depend on the thread count. A fixed body (infinite mass) does not move: it
    // joins no island.
    const std::size_t np = x_pred.size();
    // (by the definitions, not a pass over the constraints: most models have no friction)
    const bool friction =
        std::any_of(definitions_.begin(), definitions_.end(), [](const Definition& d) {
            return d.def.method == ContactMethod::LagrangeMultiplier && d.def.friction > 0;
        });
    if (friction) friction_lambda_.assign(constraints_.size(), Vec3::Zero());
    warm_start(x_pred, body_u_pred, bodies, beta_particle, beta_body);
    island_nodes_.resize(constraints_.size());
    particle_moved_at_.resize(np, -1);
    body_moved_at_.resize(body_u_pred.size(), -1);
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
        const Constraint& c = constraints_[k];
        ConstraintIslands::Nodes& nodes = island_nodes_[k];
        nodes = {c.slave, -1, -1, -1, -1};
        if (c.element >= 0)
            for (std::size_t j = 0; j < 3; ++j) nodes[j + 1] = c.master[j];
        if (c.body >= 0 && bodies[static_cast<std::size_t>(c.body)].inv_mass > 0)
            nodes[4] = static_cast<Index>(np) + c.body;
        for (Index v : nodes)  // no update of this step yet (the sweep bookkeeping below)
            if (v >= 0) {
                if (static_cast<std::size_t>(v) < np)
                    particle_moved_at_[static_cast<std::size_t>(v)] = -1;
                else
                    body_moved_at_[static_cast<std::size_t>(v) - np] = -1;
            }
    }
    islands_.build(island_nodes_, np + body_u_pred.size());
    const std::size_t n_islands = islands_.count();
    island_sweeps_.assign(n_islands, 0);
    island_updates_.assign(n_islands, 0);

    // An open constraint (lambda = 0, gap >= 0 when last evaluated) none of whose particles or
    // body has moved since gives the same gap again, hence no update and no change to the
    // sweep's measures: it is skipped, which leaves the result bitwise the same (most pairs
    // near contact are open; the few closed ones need the sweeps). The stamps count the
    // updates of the island in this step.
    auto unchanged_since_evaluated = [&](const Constraint& c) {
        if (c.evaluated_at < 0 ||
            particle_moved_at_[static_cast<std::size_t>(c.slave)] > c.evaluated_at)
            return false;
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                if (particle_moved_at_[static_cast<std::size_t>(c.master[k])] > c.evaluated_at)
                    return false;
        return c.body < 0 || body_moved_at_[static_cast<std::size_t>(c.body)] <= c.evaluated_at;
    };
    auto sweep_island = [&](std::size_t island) {
        SweepMeasures m;
        std::int64_t& updates = island_updates_[island];
        for (std::uint32_t member : islands_.members(island)) {
            Constraint& c = constraints_[member];
            if (c.lambda == 0 && c.last_gap >= 0 && unchanged_since_evaluated(c)) continue;
            const Real g = gap(c);
            c.last_gap = g;
            c.evaluated_at = updates;
            m.deepest = std::max(m.deepest, -g);
            const Real lambda_new = std::max(Real(0), c.lambda - g / c.weight);
            const Real dl = lambda_new - c.lambda;
            m.largest_lambda = std::max(m.largest_lambda, lambda_new);
            if (dl != 0) {
                c.lambda = lambda_new;
                m.largest_change = std::max(m.largest_change, std::abs(dl));
                m.largest_move = std::max(m.largest_move, std::abs(dl) * c.weight);
                ++updates;
                move_by(c, dl, x_pred, body_u_pred, bodies, beta_particle, beta_body, updates);
            }
            if (c.friction > 0) {  // §8.4, after the normal multiplier that bounds it
                const Vec3 dt = slide(c, friction_lambda_[member], x, x_pred, body_u_pred, bodies,
                                      beta_particle, beta_body, updates + 1);
                if (dt.squaredNorm() > 0) {
                    ++updates;
                    m.largest_change = std::max(m.largest_change, dt.norm());
                    m.largest_move = std::max(m.largest_move, dt.norm() * c.weight);
                }
            }
        }
        return m;
    };
    // Each island is swept until it has converged by itself (§8.3): every gap closed to 1e-3 h
    // and the multipliers settled to 1e-6 (relative), or, where two nearly parallel constraints
    // share the force and the multipliers drift slowly between them, no gap moved by more than
    // 1e-6 h in the sweep. An island's sweeps depend on that island alone, so the islands run
    // without a barrier between sweeps.
    // In parallel only when the largest island leaves the others at least half of the work:
    // one island that holds most constraints (the tube's folds and striker) gains nothing from
    // a second thread and would pay the region.
    [[maybe_unused]] const bool parallel =
        n_islands > 1 && constraints_.size() >= parallel_min_constraints_ &&
        (parallel_min_constraints_ == 0 ||
         2 * islands_.members(islands_.largest_first()[0]).size() <= constraints_.size());
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
    for (std::size_t j = 0; j < n_islands; ++j) {
        const std::uint32_t island = islands_.largest_first()[j];
        int sweeps = 0;
        bool converged = false;
        while (!converged && sweeps < max_iterations) {
            ++sweeps;
            const SweepMeasures m = sweep_island(island);
            converged = m.deepest <= k_sweep_tolerance * h_min &&
                        (m.largest_change <= k_lambda_tolerance * m.largest_lambda ||
                         m.largest_move <= k_lambda_tolerance * h_min);
        }
        island_sweeps_[island] = converged ? sweeps : -sweeps;
    }
    int sweeps = 0;
    bool converged = true;
    for (int s : island_sweeps_) {
        sweeps = std::max(sweeps, std::abs(s));
        converged = converged && s > 0;
    }
    if (!converged) ++stats_.unconverged_steps;
    keep_multipliers();
    stats_.sweeps = sweeps;
    stats_.max_sweeps = std::max(stats_.max_sweeps, sweeps);
    stats_.active =
        static_cast<long>(std::count_if(constraints_.begin(), constraints_.end(),
                                        [](const Constraint& c) { return c.lambda > 0; }));
    stats_.max_active = std::max(stats_.max_active, stats_.active);

    // The penetrations left at t_{n+1} (<= 0 for the pairs apart), in parallel; the largest
    // is picked in constraint order, the first of equal ones, like the forces' sums below.
    penetration_.resize(constraints_.size());
#pragma omp parallel for schedule(static) if (parallel_all)
    for (std::size_t k = 0; k < constraints_.size(); ++k)
        penetration_[k] = constraints_[k].allowance - gap(constraints_[k]);
    for (std::size_t i = 0; i < constraints_.size(); ++i) {
        const Constraint& c = constraints_[i];
        note_penetration(penetration_[i], c, step);
        if (c.lambda == 0) continue;
        // the force on the slave: the normal push and the friction against its slip (§8.4)
        const Vec3 force = c.friction > 0 ? Vec3(c.lambda * c.normal - friction_lambda_[i])
                                          : Vec3(c.lambda * c.normal);
        f_contact[static_cast<std::size_t>(c.slave)] += force;
        slave_force_[c.definition] += force;
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                f_contact[static_cast<std::size_t>(c.master[k])] -=
                    c.friction > 0 ? Vec3(c.xi[k] * force) : Vec3(c.lambda * c.xi[k] * c.normal);
        if (c.body >= 0) bodies[static_cast<std::size_t>(c.body)].force -= force;
    }
    // Pairs that were through already at t_n: their penetration at t_{n+1}.
    for (const Constraint& c : closed_) {
        const auto& t = c.master;
        const Vec3& ya = x_pred[static_cast<std::size_t>(t[0])];
        const Vec3& yb = x_pred[static_cast<std::size_t>(t[1])];
        const Vec3& yc = x_pred[static_cast<std::size_t>(t[2])];
        const TriangleClosestPoint cp = closest_point_on_triangle(
            x_pred[static_cast<std::size_t>(c.slave)], ya, yb, yc, k_face_tolerance);
        if (!cp.in_face) continue;
        const Real dist = std::abs(
            (x_pred[static_cast<std::size_t>(c.slave)] - cp.point).dot(unit_normal(ya, yb, yc)));
        note_penetration(c.offset - dist, c, step);
    }
}

void ContactSolver::move_by(const Constraint& c, Real dl, std::vector<Vec3>& x_pred,
                            std::vector<Vec3>& body_u_pred,
                            const std::vector<RigidBodyState>& bodies, Real beta_particle,
                            Real beta_body, std::int64_t stamp) {
    const auto us = static_cast<std::size_t>(c.slave);
    x_pred[us] += (beta_particle * dl) * inv_mass_[us].cwiseProduct(c.normal);
    if (stamp >= 0) particle_moved_at_[us] = stamp;
    if (c.element >= 0)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto um = static_cast<std::size_t>(c.master[k]);
            x_pred[um] -= (beta_particle * dl * c.xi[k]) * inv_mass_[um].cwiseProduct(c.normal);
            if (stamp >= 0) particle_moved_at_[um] = stamp;
        }
    if (c.body >= 0 && bodies[static_cast<std::size_t>(c.body)].inv_mass > 0) {
        const auto b = static_cast<std::size_t>(c.body);
        body_u_pred[b] -= (beta_body * dl * bodies[b].inv_mass) * c.normal;
        if (stamp >= 0) body_moved_at_[b] = stamp;
    }
}

MultiplierMemory::Key ContactSolver::key_of(const Constraint& c) {
    return {c.slave, c.master[0], c.master[1], c.master[2], c.body};
}

// §8.3a: every constraint starts from the multiplier its key had at the end of the last step,
// applied as the sweeps apply an update (in constraint order: the same for any thread count).
void ContactSolver::warm_start(std::vector<Vec3>& x_pred, std::vector<Vec3>& body_u_pred,
                               const std::vector<RigidBodyState>& bodies, Real beta_particle,
                               Real beta_body) {
    if (memory_.size() == 0) return;
    for (Constraint& c : constraints_) {
        if (!memory_.has_slave(c.slave)) continue;
        const Real lambda = memory_.recall(key_of(c));
        if (lambda == 0) continue;
        c.lambda = lambda;
        move_by(c, lambda, x_pred, body_u_pred, bodies, beta_particle, beta_body, -1);
    }
}

void ContactSolver::keep_multipliers() {
    for (const Constraint& c : constraints_)
        if (c.lambda > 0) memory_entries_.emplace_back(key_of(c), c.lambda);
    memory_.keep(memory_entries_);
}

std::vector<std::pair<Index, Index>> ContactSolver::candidate_pairs(std::size_t definition) const {
    const Definition& d = definitions_[definition];
    std::vector<std::pair<Index, Index>> pairs;
    if (!d.searched) return pairs;
    for (std::size_t i = 0; i < d.slaves.size(); ++i)
        for (std::int64_t k = d.candidate_start[i]; k < d.candidate_start[i + 1]; ++k)
            pairs.emplace_back(d.slaves[i], d.candidates[static_cast<std::size_t>(k)]);
    return pairs;
}

template <class Archive>
void ContactSolver::transfer_state(Archive& ar) {
    for (Definition& d : definitions_) ar(d.travelled, d.searched, d.candidate_start, d.candidates);
    ContactStatistics& st = stats_;
    ar(st.active, st.max_active, st.sweeps, st.max_sweeps, st.unconverged_steps, st.searches);
    ar(st.held_penetrations, st.max_penetration, st.max_penetration_ratio, st.max_penetration_step);
    ar(st.initial_penetrations);
    ar(st.max_penetration_particle, st.max_penetration_element, st.seconds);
    memory_.transfer(ar);
    ar(slave_force_);
}

void ContactSolver::save(RestartWriter& out) const {
    out(static_cast<std::uint64_t>(definitions_.size()));
    const_cast<ContactSolver*>(this)->transfer_state(out);
}

void ContactSolver::load(RestartReader& in) {
    std::uint64_t n = 0;
    in(n);
    if (n != definitions_.size()) in.fail("restart file of a model with other contact definitions");
    transfer_state(in);
    // the loaded lists index this model's particles, triangles and bodies (section "contact")
    const auto n_particles = static_cast<Index>(model_.nodes.size());
    const auto n_triangles = static_cast<Index>(model_.triangles.size());
    const auto n_bodies = static_cast<Index>(model_.rigid_bodies.size());
    auto fail = [&in](const char* what) {
        in.fail(std::string("restart file of another model or damaged: its contact ") + what +
                " do not fit this model");
    };
    for (Definition& d : definitions_) {
        d.candidate_triangles.clear();  // of the loaded candidates
        if (!(std::isfinite(d.travelled) && d.travelled >= 0)) fail("search distances");
        if (!d.searched) {
            d.candidate_start.clear();
            d.candidates.clear();
            continue;
        }
        const std::vector<std::int64_t>& start = d.candidate_start;
        bool valid = start.size() == d.slaves.size() + 1 && start.front() == 0 &&
                     start.back() == static_cast<std::int64_t>(d.candidates.size());
        for (std::size_t i = 1; i < start.size() && valid; ++i) valid = start[i - 1] <= start[i];
        for (const Index e : d.candidates) valid = valid && e >= 0 && e < n_triangles;
        if (!valid) fail("candidate lists");
    }
    const ContactStatistics& st = stats_;
    if (st.max_penetration_particle < -1 || st.max_penetration_particle >= n_particles ||
        st.max_penetration_element < -1 || st.max_penetration_element >= n_triangles)
        fail("statistics");
    if (!memory_.restored(n_particles, n_bodies)) fail("multipliers");
    bool forces_valid = slave_force_.size() == definitions_.size();
    for (const Vec3& f : slave_force_) forces_valid = forces_valid && f.allFinite();
    if (!forces_valid) fail("forces");
}

}  // namespace fpmshell
