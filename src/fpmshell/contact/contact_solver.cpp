#include "fpmshell/contact/contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/model/node_thickness.hpp"

namespace fpmshell {
namespace {

constexpr Real k_face_tolerance = 0.02;    // theory.md §8.1: barycentric weights >= -0.02
constexpr Real k_open_fraction = 0.5;      // a pair is open at t_n when its distance >= 0.5 offset
constexpr Real k_exclusion_factor = 1.5;   // default exclusion radius: 1.5 x largest thickness (R8)
constexpr Real k_margin_fraction = 0.5;    // search margin: 0.5 x largest offset
constexpr Real k_sweep_tolerance = 1e-3;   // sweeps stop when no gap is below -1e-3 h (§8.3)
constexpr Real k_lambda_tolerance = 1e-6;  // ... and no multiplier changed by 1e-6 of the largest
// Pairs closer than this fraction of their offset at the predictor join the Gauss-Seidel
// sweeps with lambda = 0: a correction that pushes a particle into a surface it was only near
// is then undone in the same step, not one step later by a force that does positive work.
constexpr Real k_activation_fraction = 0.5;
// An edge point with a corner weight above this is the corner (particle-to-particle pair).
constexpr Real k_corner_weight = 0.99;

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const Real len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

class Stopwatch {
public:
    explicit Stopwatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
    ~Stopwatch() {
        total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    Stopwatch(const Stopwatch&) = delete;
    Stopwatch& operator=(const Stopwatch&) = delete;

private:
    double& total_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

ContactSolver::ContactSolver(const Model& model, const MeshTopology& topology,
                             const std::vector<Vec3>& inv_mass,
                             const std::vector<Real>& element_thickness)
    : model_(model), inv_mass_(inv_mass), element_thickness_(element_thickness) {
    // h_s of a particle: the mean thickness of its elements.
    const std::size_t np = model.nodes.size();
    node_thickness_ = mean_node_thickness(model.triangles, element_thickness, np);

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
                for (Index p : model.triangles[static_cast<std::size_t>(e)]) d.slaves.push_back(p);
                h_max = std::max(h_max, element_thickness[static_cast<std::size_t>(e)]);
            }
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
}

void ContactSolver::prepare_search(Definition& d, const std::vector<Vec3>& x, Real motion) {
    // Candidates found at x within offset + margin stay complete while no two points have
    // closed in by more than the margin: relative motion <= twice the fastest particle's.
    if (!d.searched || d.travelled + 2 * motion > d.margin) {
        search(d, x);
        d.travelled = 0;
        d.searched = true;
    }
    d.travelled += 2 * motion;
}

void ContactSolver::search(Definition& d, const std::vector<Vec3>& x) {
    ++stats_.searches;
    const auto& tri = model_.triangles;
    const std::size_t ne = d.def.elements.size();
    const Real reach = d.max_offset + d.margin;
    box_lo_.resize(ne);
    box_hi_.resize(ne);
    Real mean_extent = 0;
    for (std::size_t i = 0; i < ne; ++i) {
        const auto& t = tri[static_cast<std::size_t>(d.def.elements[i])];
        const Vec3& a = x[static_cast<std::size_t>(t[0])];
        const Vec3& b = x[static_cast<std::size_t>(t[1])];
        const Vec3& c = x[static_cast<std::size_t>(t[2])];
        box_lo_[i] = a.cwiseMin(b).cwiseMin(c) - Vec3::Constant(reach);
        box_hi_[i] = a.cwiseMax(b).cwiseMax(c) + Vec3::Constant(reach);
        mean_extent += (box_hi_[i] - box_lo_[i]).maxCoeff();
    }
    if (ne > 0) mean_extent /= static_cast<Real>(ne);
    grid_.build(box_lo_, box_hi_, mean_extent);

    d.candidate_start.assign(d.slaves.size() + 1, 0);
    d.candidates.clear();
    for (std::size_t i = 0; i < d.slaves.size(); ++i) {
        const Index s = d.slaves[i];
        const Vec3& xs = x[static_cast<std::size_t>(s)];
        const Vec3& xs0 = model_.nodes[static_cast<std::size_t>(s)];
        grid_.for_each_near(xs, [&](Index item) {
            const Index e = d.def.elements[static_cast<std::size_t>(item)];
            const auto& t = tri[static_cast<std::size_t>(e)];
            if (t[0] == s || t[1] == s || t[2] == s) return;
            for (std::int64_t k = d.neighbour_start[i]; k < d.neighbour_start[i + 1]; ++k) {
                const Index nb = d.neighbours[static_cast<std::size_t>(k)];
                if (t[0] == nb || t[1] == nb || t[2] == nb) return;
            }
            const Vec3& a = x[static_cast<std::size_t>(t[0])];
            const Vec3& b = x[static_cast<std::size_t>(t[1])];
            const Vec3& c = x[static_cast<std::size_t>(t[2])];
            const Real offset =
                d.slave_offset[i] + 0.5 * element_thickness_[static_cast<std::size_t>(e)];
            const TriangleClosestPoint cp = closest_point_on_triangle(xs, a, b, c, 0.0);
            if ((xs - cp.point).norm() > offset + d.margin) return;
            // Self-contact exclusion (theory.md §8.1, R8): material that starts closer than the
            // exclusion radius is held together by the shell itself, not by contact.
            const TriangleClosestPoint cp0 =
                closest_point_on_triangle(xs0, model_.nodes[static_cast<std::size_t>(t[0])],
                                          model_.nodes[static_cast<std::size_t>(t[1])],
                                          model_.nodes[static_cast<std::size_t>(t[2])], 0.0);
            if ((xs0 - cp0.point).norm() < d.exclusion_radius) return;
            d.candidates.push_back(e);
        });
        d.candidate_start[i + 1] = static_cast<std::int64_t>(d.candidates.size());
    }
}

void ContactSolver::collect_self(const Definition& d, const std::vector<Vec3>& x,
                                 const std::vector<Vec3>& y, bool lagrange,
                                 std::vector<Constraint>& out, std::vector<Constraint>& closed) {
    const auto& tri = model_.triangles;
    // Contacts beside a triangle (at an edge or a corner) are found once per triangle sharing
    // that edge or corner, and a particle-to-corner pair once from each particle: such copies
    // are merged by a key (slave, edge) or (particle, particle), or the sweeps would split the
    // force between identical constraints and settle slowly.
    // The slaves in fixed chunks, in parallel, each into its own buffers; the buffers are then
    // joined in chunk order, so the constraints come in slave order for any thread count.
    const std::size_t n_slaves = d.slaves.size();
    const std::size_t n_chunks = (n_slaves + k_collect_chunk - 1) / k_collect_chunk;
    if (collect_chunks_.size() < n_chunks) collect_chunks_.resize(n_chunks);
#pragma omp parallel for schedule(dynamic) if (n_chunks > 1)
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        CollectBuffers& buf = collect_chunks_[chunk];
        buf.out.clear();
        buf.closed.clear();
        buf.keys.clear();
        buf.keyed.clear();
        for (std::size_t i = chunk * k_collect_chunk;
             i < std::min(n_slaves, (chunk + 1) * k_collect_chunk); ++i) {
            const std::int64_t begin = d.candidate_start[i], end = d.candidate_start[i + 1];
            const Index s = d.slaves[i];
            const std::size_t us = static_cast<std::size_t>(s);
            for (std::int64_t k = begin; k < end; ++k) {
                const Index e = d.candidates[static_cast<std::size_t>(k)];
                const auto& t = tri[static_cast<std::size_t>(e)];
                const Real offset =
                    d.slave_offset[i] + 0.5 * element_thickness_[static_cast<std::size_t>(e)];
                Constraint c;
                c.slave = s;
                c.element = e;
                c.master = t;
                c.offset = offset;
                c.thickness = 2 * d.slave_offset[i];
                // Side of the pair from t_n (§8.2): the surfaces are apart there.
                const Vec3& xa = x[static_cast<std::size_t>(t[0])];
                const Vec3& xb = x[static_cast<std::size_t>(t[1])];
                const Vec3& xc = x[static_cast<std::size_t>(t[2])];
                const Vec3 n_x = unit_normal(xa, xb, xc);
                const TriangleClosestPoint cp_x =
                    closest_point_on_triangle(x[us], xa, xb, xc, k_face_tolerance);
                const Vec3 rel_x = x[us] - cp_x.point;
                const Real d_x = rel_x.dot(n_x);
                const Real sigma = d_x >= 0 ? 1.0 : -1.0;  // side of the slave at t_n
                // Positions the gap is measured at: the predictor (Lagrange multipliers, normal and
                // weights frozen there, §8.2) or t_n (penalty).
                const Vec3& ya = y[static_cast<std::size_t>(t[0])];
                const Vec3& yb = y[static_cast<std::size_t>(t[1])];
                const Vec3& yc = y[static_cast<std::size_t>(t[2])];
                const Vec3 n_y = lagrange ? unit_normal(ya, yb, yc) : n_x;
                const TriangleClosestPoint cp_y =
                    lagrange ? closest_point_on_triangle(y[us], ya, yb, yc, k_face_tolerance)
                             : cp_x;
                const Vec3 rel_y = y[us] - cp_y.point;
                if (lagrange &&
                    (cp_x.in_face ? std::abs(d_x) : rel_x.norm()) < k_open_fraction * offset) {
                    // Already through at t_n (entered sideways, or a pair closed from the start):
                    // no side to restore; only its penetration is recorded.
                    if (cp_y.in_face && std::abs(rel_y.dot(n_y)) < offset) {
                        c.normal = n_y;
                        c.xi = cp_y.xi;
                        c.gap = std::abs(rel_y.dot(n_y)) - offset;
                        buf.closed.push_back(c);
                    }
                    continue;
                }
                c.xi = cp_y.xi;
                std::array<Index, 3> key{-1, -1, -1};
                if (cp_y.in_face) {
                    c.normal = sigma * n_y;
                    c.gap = c.normal.dot(rel_y) - offset;
                } else {
                    // Beside the triangle: the distance to its nearest edge or corner (a particle
                    // may pass round an edge from one side to the other).
                    const auto top = std::max_element(c.xi.begin(), c.xi.end()) - c.xi.begin();
                    Vec3 rel = rel_y;
                    if (c.xi[static_cast<std::size_t>(top)] >
                        k_corner_weight) {  // particle to particle
                        const Index v = t[static_cast<std::size_t>(top)];
                        c.xi = {0, 0, 0};
                        c.xi[static_cast<std::size_t>(top)] = 1;
                        rel = y[us] - y[static_cast<std::size_t>(v)];
                        key = {std::min(s, v), std::max(s, v), -1};
                    } else {
                        const std::size_t off = c.xi[0] == 0   ? 0
                                                : c.xi[1] == 0 ? 1
                                                               : 2;  // the corner not on the edge
                        const Index a = t[(off + 1) % 3], b = t[(off + 2) % 3];
                        key = {s, std::min(a, b), std::max(a, b)};
                    }
                    const Real dist = rel.norm();
                    if (!(dist > 1e-12 * offset)) continue;
                    c.normal = rel / dist;
                    c.gap = dist - offset;
                }
                if (!(c.gap < (lagrange ? k_activation_fraction * offset : 0.0))) continue;
                if (key[0] < 0) {
                    buf.out.push_back(c);
                } else {
                    buf.keys.push_back(key);
                    buf.keyed.push_back(c);
                }
            }
        }
    }
    keyed_.clear();
    keyed_constraints_.clear();
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        const CollectBuffers& buf = collect_chunks_[chunk];
        out.insert(out.end(), buf.out.begin(), buf.out.end());
        closed.insert(closed.end(), buf.closed.begin(), buf.closed.end());
        for (std::size_t k = 0; k < buf.keys.size(); ++k) {
            keyed_.push_back({buf.keys[k], keyed_constraints_.size()});
            keyed_constraints_.push_back(buf.keyed[k]);
        }
    }
    // One constraint per key: the first found (slave order, then candidate order), so the
    // result does not depend on anything but the mesh and the state. Sorting (key, order
    // found) pairs, not the constraints themselves, moves 32 bytes per pair instead of ~190.
    std::sort(keyed_.begin(), keyed_.end());
    for (std::size_t k = 0; k < keyed_.size(); ++k)
        if (k == 0 || keyed_[k].first != keyed_[k - 1].first)
            out.push_back(keyed_constraints_[keyed_[k].second]);
}

void ContactSolver::collect_rigid(const Definition& d, const std::vector<Vec3>& y,
                                  const std::vector<Vec3>& body_u, bool lagrange,
                                  std::vector<Constraint>& out) const {
    const auto b = static_cast<std::size_t>(d.def.body);
    const RigidBody& body = model_.rigid_bodies[b];
    const Vec3 point = body.point + body_u[b];
    for (Index s : d.slaves) {
        const auto us = static_cast<std::size_t>(s);
        // Thickness offset h_s / 2 in every direction (theory.md §8.3): a particle touches the
        // face with a ball of its half thickness, so the contact point does not jump when the
        // shell turns (an offset that follows the orientation does work and creates energy).
        const Real offset = 0.5 * node_thickness_[us];
        const Real gap = body.normal.dot(y[us] - point) - offset;
        if (!(gap < (lagrange ? k_activation_fraction * offset : 0.0))) continue;
        Constraint c;
        c.slave = s;
        c.body = d.def.body;
        c.normal = body.normal;
        c.offset = offset;
        c.gap = gap;
        c.thickness = node_thickness_[us];
        out.push_back(c);
    }
}

Real ContactSolver::weight(const Constraint& c, Real beta_particle, Real beta_body,
                           const std::vector<RigidBodyState>& bodies) const {
    const Vec3 n2 = c.normal.cwiseProduct(c.normal);
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
    stats_.max_penetration_ratio = penetration / c.thickness;
    stats_.max_penetration_step = step;
    stats_.max_penetration_particle = c.slave;
    stats_.max_penetration_element = c.element;
}

void ContactSolver::penalty_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& body_u,
                                   std::vector<RigidBodyState>& bodies, Real beta_particle,
                                   Real beta_body, Real motion, long step,
                                   std::vector<Vec3>& f_contact) {
    Stopwatch watch(stats_.seconds);
    constraints_.clear();
    for (Definition& d : definitions_) {
        if (d.def.method != ContactMethod::Penalty) continue;
        const std::size_t first = constraints_.size();
        if (d.def.type == ContactType::Self) {
            prepare_search(d, x, motion);
            collect_self(d, x, x, false, constraints_, closed_);
        } else {
            collect_rigid(d, x, body_u, false, constraints_);
        }
        for (std::size_t i = first; i < constraints_.size(); ++i) {
            Constraint& c = constraints_[i];
            const Real w = weight(c, beta_particle, beta_body, bodies);
            if (!(w > 0) || !(c.gap < 0)) continue;
            // scale x the force that would remove the whole penetration in one step
            c.lambda = d.def.penalty_scale * (-c.gap) / w;
            note_penetration(-c.gap, c, step);
        }
    }
    for (const Constraint& c : constraints_) {
        f_contact[static_cast<std::size_t>(c.slave)] += c.lambda * c.normal;
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                f_contact[static_cast<std::size_t>(c.master[k])] -= c.lambda * c.xi[k] * c.normal;
        if (c.body >= 0) bodies[static_cast<std::size_t>(c.body)].force -= c.lambda * c.normal;
    }
    stats_.active =
        static_cast<long>(std::count_if(constraints_.begin(), constraints_.end(),
                                        [](const Constraint& c) { return c.lambda > 0; }));
    stats_.max_active = std::max(stats_.max_active, stats_.active);
}

void ContactSolver::enforce(const std::vector<Vec3>& x, std::vector<Vec3>& x_pred,
                            std::vector<Vec3>& body_u_pred, std::vector<RigidBodyState>& bodies,
                            Real beta_particle, Real beta_body, Real motion, long step,
                            std::vector<Vec3>& f_contact) {
    Stopwatch watch(stats_.seconds);
    constraints_.clear();
    closed_.clear();
    int max_iterations = 1;
    Real h_min = 0;
    for (Definition& d : definitions_) {
        if (d.def.method != ContactMethod::LagrangeMultiplier) continue;
        max_iterations = std::max(max_iterations, d.def.max_iterations);
        if (d.def.type == ContactType::Self) {
            prepare_search(d, x, motion);
            collect_self(d, x, x_pred, true, constraints_, closed_);
        } else {
            collect_rigid(d, x_pred, body_u_pred, true, constraints_);
        }
    }
    // Drop constraints that nothing can satisfy (every particle fixed); set the weights. A
    // pair that is already inside at t_n (it escaped detection, or the linearised gap of the
    // last step left it slightly in) is held where it is, not pushed out: pushing it out
    // against its force would do positive work and create energy.
    std::size_t kept = 0;
    for (Constraint& c : constraints_) {
        Vec3 r = x[static_cast<std::size_t>(c.slave)];
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                r -= c.xi[k] * x[static_cast<std::size_t>(c.master[k])];
        if (c.body >= 0)
            r -= model_.rigid_bodies[static_cast<std::size_t>(c.body)].point +
                 bodies[static_cast<std::size_t>(c.body)].u;
        const Real inside = c.offset - c.normal.dot(r);
        if (inside > k_sweep_tolerance * c.offset) {
            c.allowance = inside;
            ++stats_.held_penetrations;
        }
        c.weight = weight(c, beta_particle, beta_body, bodies);
        if (c.weight > 0) {
            h_min = kept == 0 ? c.thickness : std::min(h_min, c.thickness);
            constraints_[kept++] = c;
        }
    }
    constraints_.resize(kept);

    auto gap = [&](const Constraint& c) {
        Vec3 r = x_pred[static_cast<std::size_t>(c.slave)];
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                r -= c.xi[k] * x_pred[static_cast<std::size_t>(c.master[k])];
        if (c.body >= 0) {
            const auto b = static_cast<std::size_t>(c.body);
            r -= model_.rigid_bodies[b].point + body_u_pred[b];
        }
        return c.normal.dot(r) - c.offset + c.allowance;
    };
    // Projected Gauss-Seidel on lambda >= 0, g + W dlambda >= 0, complementarity (§8.3).
    // An open constraint (lambda = 0, gap >= 0 when last evaluated) none of whose particles or
    // body has moved since gives the same gap again, hence no update and no change to the
    // sweep's measures: it is skipped, which leaves the result bitwise the same (most pairs
    // near contact are open; the few closed ones need the sweeps).
    particle_moved_at_.resize(x_pred.size(), -1);
    body_moved_at_.resize(body_u_pred.size(), -1);
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
    int sweeps = 0;
    bool converged = constraints_.empty();
    while (!converged && sweeps < max_iterations) {
        ++sweeps;
        Real deepest = 0, largest_change = 0, largest_lambda = 0, largest_move = 0;
        for (Constraint& c : constraints_) {
            if (c.lambda == 0 && c.last_gap >= 0 && unchanged_since_evaluated(c)) continue;
            const Real g = gap(c);
            c.last_gap = g;
            c.evaluated_at = updates_;
            deepest = std::max(deepest, -g);
            const Real lambda_new = std::max(Real(0), c.lambda - g / c.weight);
            const Real dl = lambda_new - c.lambda;
            largest_lambda = std::max(largest_lambda, lambda_new);
            if (dl == 0) continue;
            c.lambda = lambda_new;
            largest_change = std::max(largest_change, std::abs(dl));
            largest_move = std::max(largest_move, std::abs(dl) * c.weight);
            ++updates_;
            const auto us = static_cast<std::size_t>(c.slave);
            x_pred[us] += (beta_particle * dl) * inv_mass_[us].cwiseProduct(c.normal);
            particle_moved_at_[us] = updates_;
            if (c.element >= 0)
                for (std::size_t k = 0; k < 3; ++k) {
                    const auto um = static_cast<std::size_t>(c.master[k]);
                    x_pred[um] -=
                        (beta_particle * dl * c.xi[k]) * inv_mass_[um].cwiseProduct(c.normal);
                    particle_moved_at_[um] = updates_;
                }
            if (c.body >= 0) {
                const auto b = static_cast<std::size_t>(c.body);
                body_u_pred[b] -= (beta_body * dl * bodies[b].inv_mass) * c.normal;
                body_moved_at_[b] = updates_;
            }
        }
        // §8.3: every gap closed to 1e-3 h and the multipliers settled to 1e-6 (relative), or,
        // where two nearly parallel constraints share the force and the multipliers drift
        // slowly between them, no gap moved by more than 1e-6 h in the sweep.
        converged = deepest <= k_sweep_tolerance * h_min &&
                    (largest_change <= k_lambda_tolerance * largest_lambda ||
                     largest_move <= k_lambda_tolerance * h_min);
    }
    if (!converged) ++stats_.unconverged_steps;
    stats_.sweeps = sweeps;
    stats_.max_sweeps = std::max(stats_.max_sweeps, sweeps);
    stats_.active =
        static_cast<long>(std::count_if(constraints_.begin(), constraints_.end(),
                                        [](const Constraint& c) { return c.lambda > 0; }));
    stats_.max_active = std::max(stats_.max_active, stats_.active);

    for (const Constraint& c : constraints_) {
        note_penetration(c.allowance - gap(c), c, step);  // <= 0 (not noted) for the pairs apart
        if (c.lambda == 0) continue;
        f_contact[static_cast<std::size_t>(c.slave)] += c.lambda * c.normal;
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                f_contact[static_cast<std::size_t>(c.master[k])] -= c.lambda * c.xi[k] * c.normal;
        if (c.body >= 0) bodies[static_cast<std::size_t>(c.body)].force -= c.lambda * c.normal;
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

template <class Archive>
void ContactSolver::transfer_state(Archive& ar) {
    for (Definition& d : definitions_) ar(d.travelled, d.searched, d.candidate_start, d.candidates);
    ContactStatistics& st = stats_;
    ar(st.active, st.max_active, st.sweeps, st.max_sweeps, st.unconverged_steps, st.searches);
    ar(st.held_penetrations, st.max_penetration, st.max_penetration_ratio, st.max_penetration_step);
    ar(st.max_penetration_particle, st.max_penetration_element, st.seconds);
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
}

}  // namespace fpmshell
