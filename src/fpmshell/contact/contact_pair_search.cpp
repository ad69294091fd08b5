// The contact's pair search (theory.md §8.1): the bucket-grid search of a self-contact's
// candidates, and the closest-point pairs of the candidates (self-contact) or of the slave
// particles and a rigid body's faces (rigid contact) that the sweeps or the penalty forces take.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "fpmshell/contact/closest_point.hpp"
#include "fpmshell/contact/contact_solver.hpp"
#include "fpmshell/contact/contact_tolerances.hpp"
#include "fpmshell/model/rigid_face.hpp"

namespace fpmshell {
namespace {

using contact_tolerances::k_face_tolerance;
using contact_tolerances::k_pass_factor;
using contact_tolerances::unit_normal;

constexpr Real k_open_fraction = 0.5;  // a pair is open at t_n when its distance >= 0.5 offset
// Pairs closer than the activation distance at the predictor join the Gauss-Seidel sweeps with
// lambda = 0 (theory.md §8.3): a correction that pushes a particle into a surface it was only
// near is then undone in the same step, not one step later by a force that does positive work.
// A correction moves a particle by about the penetration it removes, itself at most about the
// relative motion of one step: the distance is 4 times the largest motion of the step, at least
// 5 % and at most half of the pair's offset.
constexpr Real k_activation_min = 0.05, k_activation_max = 0.5, k_activation_motions = 4.0;
// An edge point with a corner weight above this is the corner (particle-to-particle pair).
constexpr Real k_corner_weight = 0.99;
// Clearance of a dropped pair (theory.md eq. 8.1d): the face of weights >= -0.02 reaches
// 0.06 x the largest corner distance beyond the triangle (the frame's radius is 1.1 x that
// distance); the motion of the step of the drop counts twice more (its predictor and its t_n);
// a relative 1e-6 of the offset covers the rounding of the distances.
constexpr Real k_clear_face = 0.06, k_clear_motions = 4.0, k_clear_rounding = 1e-6;

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
    const bool first = !d.searched && !initial_counted_;
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

}  // namespace fpmshell
