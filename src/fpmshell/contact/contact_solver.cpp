#include "fpmshell/contact/contact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/contact/stopwatch.hpp"
#include "fpmshell/io/restart_archive.hpp"
#include "fpmshell/model/mesh_pieces.hpp"
#include "fpmshell/model/node_thickness.hpp"
#include "fpmshell/model/rigid_body_partition.hpp"
#include "fpmshell/model/rigid_face.hpp"

namespace fpmshell {
namespace {

constexpr Real k_face_tolerance = 0.02;    // theory.md §8.1: barycentric weights >= -0.02
constexpr Real k_open_fraction = 0.5;      // a pair is open at t_n when its distance >= 0.5 offset
constexpr Real k_exclusion_factor = 1.5;   // default exclusion radius: 1.5 x largest thickness (R8)
constexpr Real k_margin_fraction = 0.2;    // search margin: 0.2 x largest offset (§8.1)
constexpr Real k_sweep_tolerance = 1e-3;   // sweeps stop when no gap is below -1e-3 h (§8.3)
constexpr Real k_lambda_tolerance = 1e-6;  // ... and no multiplier changed by 1e-6 of the largest
// Pairs closer than the activation distance at the predictor join the Gauss-Seidel sweeps with
// lambda = 0 (theory.md §8.3): a correction that pushes a particle into a surface it was only
// near is then undone in the same step, not one step later by a force that does positive work.
// A correction moves a particle by about the penetration it removes, itself at most about the
// relative motion of one step: the distance is 4 times the largest motion of the step, at least
// 5 % and at most half of the pair's offset.
constexpr Real k_activation_min = 0.05, k_activation_max = 0.5, k_activation_motions = 4.0;
// An edge point with a corner weight above this is the corner (particle-to-particle pair).
constexpr Real k_corner_weight = 0.99;
// A pass over the constraints (copy, weights, penetrations) costs tens of ns per constraint:
// it runs in parallel from this many times the sweeps' minimum (on the tube's ~1 400 constraints
// a parallel region per pass cost more than it shared out on two threads).
constexpr std::size_t k_pass_factor = 4;
// Clearance of a dropped pair (theory.md eq. 8.1d): the face of weights >= -0.02 reaches
// 0.06 x the largest corner distance beyond the triangle (the frame's radius is 1.1 x that
// distance); the motion of the step of the drop counts twice more (its predictor and its t_n);
// a relative 1e-6 of the offset covers the rounding of the distances.
constexpr Real k_clear_face = 0.06, k_clear_motions = 4.0, k_clear_rounding = 1e-6;

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const Real len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

/// Whether a pair (slave at xs, ys; triangle of frame f, corner a at xa, ya) surely makes no
/// constraint, as collect_self decides it: the slave is on the side of the triangle's plane at y
/// that it was on at x, and farther than `reach` (offset + activation distance) from the
/// triangle's face at y: from its plane, or from a sphere about it. Then the face gap
/// sigma n.(y_s - p) - offset (in the face) or the edge or corner distance - offset (beside it,
/// never less than the plane distance) exceeds the activation distance, and a pair closed at x
/// would need a plane distance below the offset at y. Both signs with a margin of 1e-9 of the
/// reach, far above the rounding of the closest point's plane distance that collect_self takes.
/// Returns, for such a pair, the larger of its plane and sphere distances (both bound the
/// slave's distance to the triangle at y from below: its clearance, eq. 8.1d); none otherwise.
std::optional<Real> far_on_its_side(const ContactSolver::TriangleFrame& f, const Vec3& xs,
                                    const Vec3& ys, const Vec3& xa, const Vec3& ya, Real reach) {
    const Real side_x = f.n_x.dot(xs - xa), side_y = f.n_y.dot(ys - ya);
    const Real margin = 1e-9 * reach;
    if (!((side_x > margin && side_y > margin) || (side_x < -margin && side_y < -margin)))
        return std::nullopt;
    const Real beyond = reach + margin;
    const Real plane = std::abs(side_y);
    const Real centre2 = (ys - f.centre_y).squaredNorm();
    if (!(plane > beyond) && !(centre2 > (beyond + f.radius_y) * (beyond + f.radius_y)))
        return std::nullopt;
    return std::max(plane, std::sqrt(centre2) - f.radius_y);
}

Real activation_distance(Real offset, Real motion) {
    return std::min(k_activation_max * offset,
                    std::max(k_activation_min * offset, k_activation_motions * motion));
}

}  // namespace

ContactSolver::ContactSolver(const Model& model, const MeshTopology& topology,
                             const std::vector<Vec3>& inv_mass,
                             const std::vector<Real>& element_thickness)
    : model_(model), inv_mass_(inv_mass), element_thickness_(element_thickness) {
    // h_s of a particle: the mean thickness of its elements.
    const std::size_t np = model.nodes.size();
    node_thickness_ = mean_node_thickness(model.triangles, element_thickness, np);
    rigid_body_of_ = rigid_body_partition(model).body_of_particle;
    mesh_piece_ = mesh_pieces(np, model.triangles);

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
    d.candidate_triangles.clear();  // remade by collect_self from the new candidates
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

    // The slaves in fixed chunks, in parallel, each chunk into its own list; the lists are
    // joined in chunk order, so the candidates come in slave order for any thread count.
    const std::size_t n_slaves = d.slaves.size();
    const std::size_t n_chunks = (n_slaves + k_collect_chunk - 1) / k_collect_chunk;
    if (search_chunks_.size() < n_chunks) search_chunks_.resize(n_chunks);
    d.candidate_start.assign(n_slaves + 1, 0);
    // the first search (at the initial geometry) counts the particles that start closer to a
    // face than their thickness offsets (initial penetrations, reported as LS-DYNA does)
    const bool first = !d.searched;
    long overlapping = 0;  // a count: the same for any thread count
    [[maybe_unused]] const bool parallel = n_slaves >= parallel_min_slaves_;
#pragma omp parallel for schedule(dynamic) reduction(+ : overlapping) if (parallel)
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        std::vector<Index>& found = search_chunks_[chunk];
        found.clear();
        for (std::size_t i = chunk * k_collect_chunk;
             i < std::min(n_slaves, (chunk + 1) * k_collect_chunk); ++i) {
            bool overlaps = false;
            const Index s = d.slaves[i];
            const Vec3& xs = x[static_cast<std::size_t>(s)];
            const Vec3& xs0 = model_.nodes[static_cast<std::size_t>(s)];
            grid_.for_each_near(xs, [&](Index item) {
                // outside the triangle's box grown by the reach: farther than offset + margin
                // from every point of it (the full test below drops it too, at ten times the cost)
                const auto ui = static_cast<std::size_t>(item);
                if ((xs.array() < box_lo_[ui].array()).any() ||
                    (xs.array() > box_hi_[ui].array()).any())
                    return;
                const Index e = d.def.elements[static_cast<std::size_t>(item)];
                const auto& t = tri[static_cast<std::size_t>(e)];
                if (t[0] == s || t[1] == s || t[2] == s) return;
                if (const Index body = rigid_body_of_[static_cast<std::size_t>(s)];
                    body >= 0 && rigid_body_of_[static_cast<std::size_t>(t[0])] == body &&
                    rigid_body_of_[static_cast<std::size_t>(t[1])] == body &&
                    rigid_body_of_[static_cast<std::size_t>(t[2])] == body)
                    return;  // a rigid body's own face
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
                // Self-contact exclusion (theory.md §8.1, R8): material of one piece of the
                // mesh that starts closer than the exclusion radius is held together by the
                // shell itself, not by contact (separate pieces: by nothing, so never excluded).
                const TriangleClosestPoint cp0 =
                    closest_point_on_triangle(xs0, model_.nodes[static_cast<std::size_t>(t[0])],
                                              model_.nodes[static_cast<std::size_t>(t[1])],
                                              model_.nodes[static_cast<std::size_t>(t[2])], 0.0);
                const Real distance0 = (xs0 - cp0.point).norm();
                if (first && distance0 < offset) overlaps = true;
                // A rigid solid's faces (thickness 0) are no shell: nothing holds them to what
                // they start near, so they are never excluded.
                if (distance0 < d.exclusion_radius &&
                    mesh_piece_[static_cast<std::size_t>(s)] ==
                        mesh_piece_[static_cast<std::size_t>(t[0])] &&
                    element_thickness_[static_cast<std::size_t>(e)] > 0 &&
                    node_thickness_[static_cast<std::size_t>(s)] > 0)
                    return;
                found.push_back(e);
            });
            d.candidate_start[i + 1] = static_cast<std::int64_t>(found.size());  // in the chunk
            if (overlaps) ++overlapping;
        }
    }
    stats_.initial_penetrations += overlapping;
    d.candidates.clear();
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        const auto base = static_cast<std::int64_t>(d.candidates.size());
        for (std::size_t i = chunk * k_collect_chunk;
             i < std::min(n_slaves, (chunk + 1) * k_collect_chunk); ++i)
            d.candidate_start[i + 1] += base;
        const std::vector<Index>& found = search_chunks_[chunk];
        d.candidates.insert(d.candidates.end(), found.begin(), found.end());
    }
    d.candidate_clear.assign(d.candidates.size(), -std::numeric_limits<Real>::infinity());
}

void ContactSolver::collect_self(Definition& d, const std::vector<Vec3>& x,
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
    [[maybe_unused]] const bool parallel = n_slaves >= parallel_min_slaves_;
    // Every triangle's unit normals at x and y, and a sphere about it at y, once per step
    // instead of once per pair: the candidates of one triangle are many slaves.
    if (d.candidate_triangles.empty() && !d.candidates.empty()) {  // after a search or a restart
        d.candidate_triangles = d.candidates;
        std::sort(d.candidate_triangles.begin(), d.candidate_triangles.end());
        d.candidate_triangles.erase(
            std::unique(d.candidate_triangles.begin(), d.candidate_triangles.end()),
            d.candidate_triangles.end());
    }
    // (after a restart the clearances are not known: every pair is computed once)
    if (d.candidate_clear.size() != d.candidates.size())
        d.candidate_clear.assign(d.candidates.size(), -std::numeric_limits<Real>::infinity());
    // eq. 8.1d: a pair is skipped while travelled + d_a < its clearance; d_a grows with the
    // offset, so that of the definition's largest offset bounds every pair's.
    const Real clear_activation = activation_distance(d.max_offset, motion_);
    frames_.resize(tri.size());
    const std::size_t n_tri = d.candidate_triangles.size();
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t k = 0; k < n_tri; ++k) {
        const auto e = static_cast<std::size_t>(d.candidate_triangles[k]);
        const auto& t = tri[e];
        const Vec3& ya = y[static_cast<std::size_t>(t[0])];
        const Vec3& yb = y[static_cast<std::size_t>(t[1])];
        const Vec3& yc = y[static_cast<std::size_t>(t[2])];
        TriangleFrame& f = frames_[e];
        f.n_x = unit_normal(x[static_cast<std::size_t>(t[0])], x[static_cast<std::size_t>(t[1])],
                            x[static_cast<std::size_t>(t[2])]);
        f.n_y = lagrange ? unit_normal(ya, yb, yc) : f.n_x;
        f.centre_y = (ya + yb + yc) / 3.0;
        // the face of §8.1 reaches barycentric weights of -k_face_tolerance: the triangle
        // scaled about its centroid by 1 + 3 k_face_tolerance; 1.1 covers it
        f.radius_y = 1.1 * std::sqrt(std::max({(ya - f.centre_y).squaredNorm(),
                                               (yb - f.centre_y).squaredNorm(),
                                               (yc - f.centre_y).squaredNorm()}));
    }
    const bool clearances = lagrange && pair_clearances_;
    long skipped = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : skipped) if (parallel)
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
                Real& clear = d.candidate_clear[static_cast<std::size_t>(k)];
                if (d.travelled + clear_activation < clear) {
                    ++skipped;
                    continue;
                }
                const Index e = d.candidates[static_cast<std::size_t>(k)];
                const auto& t = tri[static_cast<std::size_t>(e)];
                const Real offset =
                    d.slave_offset[i] + 0.5 * element_thickness_[static_cast<std::size_t>(e)];
                const TriangleFrame& f = frames_[static_cast<std::size_t>(e)];
                // eq. 8.1d: the clearance of a pair dropped at a distance >= `distance` from the
                // triangle at y
                auto keep_clear = [&](Real distance) {
                    // a point beside the triangle but over the extended face (eq. 8.1d)
                    const Real face = k_clear_face * (f.radius_y + 3 * d.margin);
                    clear = d.travelled - k_clear_motions * motion_ + distance -
                            offset * (1 + k_clear_rounding) - face * face / (2 * offset);
                };
                if (const std::optional<Real> distance = far_on_its_side(
                        f, x[us], y[us], x[static_cast<std::size_t>(t[0])],
                        y[static_cast<std::size_t>(t[0])],
                        offset + (lagrange ? activation_distance(offset, motion_) : 0.0))) {
                    if (clearances) keep_clear(*distance);
                    continue;
                }
                Constraint c;
                c.slave = s;
                c.element = e;
                c.master = t;
                c.offset = offset;
                // the slave's thickness; a face of a rigid solid has none: the pair's distance
                c.thickness = d.slave_offset[i] > 0 ? 2 * d.slave_offset[i] : 2 * offset;
                if (lagrange) c.friction = d.def.friction;
                // Positions the gap is measured at: the predictor (Lagrange multipliers, normal and
                // weights frozen there, §8.2) or t_n (penalty).
                const Vec3& ya = y[static_cast<std::size_t>(t[0])];
                const Vec3& yb = y[static_cast<std::size_t>(t[1])];
                const Vec3& yc = y[static_cast<std::size_t>(t[2])];
                const Vec3& n_y = f.n_y;
                TriangleClosestPoint cp_y;
                if (lagrange) {
                    cp_y = closest_point_on_triangle(y[us], ya, yb, yc, k_face_tolerance);
                    // Beside the triangle at y and farther than the offset plus the activation
                    // distance from it: no constraint whatever the side at t_n (below, such a
                    // pair is either closed at t_n, kept only in the face, or measured by its
                    // edge or corner distance, never less than this one), so its closest point
                    // at t_n is not needed. A margin of 1e-9 of the reach covers the rounding
                    // of the corner distance. (Two thirds of the tube's candidates near a wall
                    // are beside the triangle: this saves their second closest point.)
                    if (!cp_y.in_face) {
                        const Real reach = offset + activation_distance(offset, motion_);
                        const Real distance = (y[us] - cp_y.point).norm();
                        if (distance > reach * (1.0 + 1e-9)) {
                            if (clearances) keep_clear(distance);
                            continue;
                        }
                    }
                }
                // Side of the pair from t_n (§8.2): the surfaces are apart there.
                const Vec3& xa = x[static_cast<std::size_t>(t[0])];
                const Vec3& xb = x[static_cast<std::size_t>(t[1])];
                const Vec3& xc = x[static_cast<std::size_t>(t[2])];
                const Vec3& n_x = f.n_x;
                const TriangleClosestPoint cp_x =
                    closest_point_on_triangle(x[us], xa, xb, xc, k_face_tolerance);
                const Vec3 rel_x = x[us] - cp_x.point;
                const Real d_x = rel_x.dot(n_x);
                const Real sigma = d_x >= 0 ? 1.0 : -1.0;  // side of the slave at t_n
                if (!lagrange) cp_y = cp_x;
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
                if (!(c.gap < (lagrange ? activation_distance(offset, motion_) : 0.0))) continue;
                if (key[0] < 0) {
                    buf.out.push_back(c);
                } else {
                    buf.keys.push_back(key);
                    buf.keyed.push_back(c);
                }
            }
        }
        // The chunk's keys in order, the first found of equal ones kept. Sorted as two integers
        // (particles >= 0; the third entry -1 of a corner key becomes 0), in the order of the
        // keys themselves.
        buf.sorted.resize(buf.keys.size());
        for (std::size_t k = 0; k < buf.keys.size(); ++k) {
            const std::array<Index, 3>& key = buf.keys[k];
            buf.sorted[k] = {
                (static_cast<std::uint64_t>(static_cast<std::uint32_t>(key[0])) << 32) |
                    static_cast<std::uint32_t>(key[1]),
                static_cast<std::uint32_t>(key[2] + 1), static_cast<std::uint32_t>(k)};
        }
        std::sort(buf.sorted.begin(), buf.sorted.end(), [](const SortKey& p, const SortKey& q) {
            return p.high != q.high ? p.high < q.high
                   : p.low != q.low ? p.low < q.low
                                    : p.index < q.index;
        });
        buf.unique.clear();
        for (std::size_t k = 0; k < buf.sorted.size(); ++k)
            if (k == 0 || buf.sorted[k].high != buf.sorted[k - 1].high ||
                buf.sorted[k].low != buf.sorted[k - 1].low)
                buf.unique.push_back(buf.sorted[k].index);
    }
    stats_.pairs_skipped += skipped;
    // One constraint per key: the first found (slave order, then candidate order), so the
    // result does not depend on anything but the mesh and the state. Each chunk has sorted its
    // keys and kept the first of equal ones; merging the chunks' lists, the earliest chunk
    // first among equal keys, gives the keys in order, each with its first-found constraint.
    // The unkeyed constraints come first, in chunk order, then the keyed ones in key order.
    std::size_t n_out = out.size(), n_closed = closed.size();
    merge_heads_.clear();
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        CollectBuffers& buf = collect_chunks_[chunk];
        buf.out_at = n_out;
        buf.closed_at = n_closed;
        n_out += buf.out.size();
        n_closed += buf.closed.size();
        if (!buf.unique.empty()) merge_heads_.push_back({chunk, 0});
    }
    merged_.clear();
    auto later = [&](const MergeHead& a, const MergeHead& b) {  // a comes after b
        const auto& ka = collect_chunks_[a.chunk].keys[collect_chunks_[a.chunk].unique[a.next]];
        const auto& kb = collect_chunks_[b.chunk].keys[collect_chunks_[b.chunk].unique[b.next]];
        return kb < ka || (kb == ka && b.chunk < a.chunk);
    };
    std::make_heap(merge_heads_.begin(), merge_heads_.end(), later);
    while (!merge_heads_.empty()) {
        std::pop_heap(merge_heads_.begin(), merge_heads_.end(), later);
        MergeHead& h = merge_heads_.back();
        const CollectBuffers& buf = collect_chunks_[h.chunk];
        const std::array<Index, 3>& key = buf.keys[buf.unique[h.next]];
        if (merged_.empty() || merged_.back().key != key)
            merged_.push_back({key, h.chunk, buf.unique[h.next]});
        if (++h.next < buf.unique.size())
            std::push_heap(merge_heads_.begin(), merge_heads_.end(), later);
        else
            merge_heads_.pop_back();
    }
    const std::size_t keyed_at = n_out;
    out.resize(n_out + merged_.size());
    closed.resize(n_closed);
    const std::size_t n_merged = merged_.size();
#pragma omp parallel if (parallel && n_out + n_merged >= k_pass_factor * parallel_min_constraints_)
    {
#pragma omp for schedule(static) nowait
        for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
            const CollectBuffers& buf = collect_chunks_[chunk];
            std::copy(buf.out.begin(), buf.out.end(), out.begin() + buf.out_at);
            std::copy(buf.closed.begin(), buf.closed.end(), closed.begin() + buf.closed_at);
        }
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n_merged; ++k)
            out[keyed_at + k] = collect_chunks_[merged_[k].chunk].keyed[merged_[k].index];
    }
}

void ContactSolver::collect_rigid(const Definition& d, const std::vector<Vec3>& y,
                                  const std::vector<Vec3>& body_u, bool lagrange,
                                  std::vector<Constraint>& out) {
    const auto b = static_cast<std::size_t>(d.def.body);
    const RigidBody& body = model_.rigid_bodies[b];
    // The slaves in fixed chunks, in parallel, each into its own buffer, joined in chunk order:
    // the constraints come in slave order for any thread count (as in collect_self).
    const std::size_t n_slaves = d.slaves.size();
    const std::size_t n_chunks = (n_slaves + k_collect_chunk - 1) / k_collect_chunk;
    if (collect_chunks_.size() < n_chunks) collect_chunks_.resize(n_chunks);
    [[maybe_unused]] const bool parallel = n_slaves >= parallel_min_slaves_;
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk) {
        std::vector<Constraint>& found = collect_chunks_[chunk].out;
        found.clear();
        for (std::size_t i = chunk * k_collect_chunk;
             i < std::min(n_slaves, (chunk + 1) * k_collect_chunk); ++i) {
            const Index s = d.slaves[i];
            const auto us = static_cast<std::size_t>(s);
            // Thickness offset h_s / 2 in every direction (theory.md §8.3): a particle touches
            // the face with a ball of its half thickness, so the contact point does not jump
            // when the shell turns (an offset that follows the orientation does work and
            // creates energy).
            // A definition's own offset (LS-DYNA's rigid walls: 0, the node itself) replaces it;
            // the activation distance keeps the half thickness's scale.
            const Real half_thickness = 0.5 * node_thickness_[us];
            const Real offset = d.def.offset >= 0 ? d.def.offset : half_thickness;
            // a curved face is linearised at the point below the particle for this step
            const RigidFacePoint face = rigid_face_point(body, y[us], body_u[b]);
            if (!face.faces) continue;
            const Real gap = face.normal.dot(y[us] - (face.anchor + body_u[b])) - offset;
            if (!(gap < (lagrange ? activation_distance(half_thickness, motion_) : 0.0))) continue;
            Constraint c;
            c.slave = s;
            c.body = d.def.body;
            c.normal = face.normal;
            c.anchor = face.anchor;
            c.offset = offset;
            c.gap = gap;
            c.thickness = node_thickness_[us];
            if (lagrange) c.friction = d.def.friction;
            found.push_back(c);
        }
    }
    for (std::size_t chunk = 0; chunk < n_chunks; ++chunk)
        out.insert(out.end(), collect_chunks_[chunk].out.begin(), collect_chunks_[chunk].out.end());
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
