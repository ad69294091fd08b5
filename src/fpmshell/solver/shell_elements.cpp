#include "fpmshell/solver/shell_elements.hpp"

#include "fpmshell/io/restart_archive.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "fpmshell/core/chunked_loop.hpp"
#include "fpmshell/elements/bending_time_step.hpp"
#include "fpmshell/elements/elastic_triangle_block.hpp"
#include "fpmshell/elements/lumped_inertia.hpp"
#include "fpmshell/elements/membrane_smoothing.hpp"

#include <map>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace fpmshell {
namespace {

constexpr Index k_parallel_min_elements = 2000;
constexpr std::size_t k_slot_components = SlotGatherPlan::k_components;  // force x y z, moment x y z
// Smoothed membrane: neighbours whose normals differ by more than this (a fold, such as a tube
// corner) are not averaged with (cos 20 deg, like the kink limit of §1.3).
constexpr Real k_smooth_cosine = 0.9397;
// The bending step ratio depends on the element shape and h / L_c only; it is re-evaluated (a
// 9x9 eigenproblem) when L_c has changed by more than this fraction since the last evaluation,
// which bounds the ratio's staleness to a few per cent of the step.
constexpr Real k_bending_ratio_drift = 0.05;

/// Local flat shape of the triangle (p0, p1, p2): node 1 at the origin, edge 1-2 along x.
TriangleShape local_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 e1 = p1 - p0;
    const Real x2 = e1.norm();
    const Vec3 ex = e1 / x2;
    const Vec3 d = p2 - p0;
    return TriangleShape(x2, d.dot(ex), ex.cross(d).norm());
}

/// The class of a local coordinate for sharing the bending step ratio between elements of one
/// shape: its bits with the mantissa rounded to 32 bits (2^-32 relative).
std::int64_t shape_class(Real v) {
    return static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(v) + (std::uint64_t{1} << 19)) >> 20);
}

Real characteristic_length(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Real two_area = (p1 - p0).cross(p2 - p0).norm();
    const Real lmax = std::sqrt(std::max({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(),
                                          (p0 - p2).squaredNorm()}));
    return two_area / lmax;  // §6.4, L_c = 2A / l_max
}

}  // namespace

ShellElements::ShellElements(const Model& model)
    : tri_(model.triangles), section_(model.element_section),
      stiffness_damping_(model.damping.stiffness) {
    bending_kernel_ = model.control.bending;
    for (const Section& sec : model.sections) {
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        ShellRule rule;
        rule.thickness = sec.thickness;
        rule.inplane = triangle_rule(sec.inplane_points);
        rule.through = thickness_rule(sec.thickness_points);
        rule.bending = model.control.bending;
        rules_.push_back(rule);
        materials_.push_back(make_section_material(mat));
        wave_speed_.push_back(std::sqrt(mat.youngs_modulus /
                                        (mat.density * (1.0 - mat.poisson_ratio * mat.poisson_ratio))));
        bending_rigidity_.push_back(elastic_stiffness(materials_.back()) * (sec.thickness * sec.thickness * sec.thickness / 12.0));
    }
    const std::size_t ne = tri_.size();
    thickness_update_ = model.control.thickness_update;
    thickness_.resize(ne);
    for (std::size_t e = 0; e < ne; ++e)
        thickness_[e] = model.sections[static_cast<std::size_t>(section_[e])].thickness;
    node_mass_.resize(ne);
    node_inertia_.resize(ne);
    bend_ratio_.assign(ne, 1.0);
    bend_lc_.assign(ne, 0.0);
    // The bending step ratio needs a 9 x 9 eigenproblem per element where h / L_c is near 1
    // (nearly all the set-up's time on a fine mesh). It depends on the section and the local
    // shape only, and the elements of a structured mesh come in a few shapes: it is computed
    // once per section and shape class (local coordinates equal to 2^-32 relative, far below
    // the 5 % drift the ratio is allowed before it is re-evaluated), for the lowest-numbered
    // element of the class, and shared by the others.
    std::vector<std::array<std::int64_t, 4>> shape_key(ne);
    std::vector<Real> initial_lc(ne);
#pragma omp parallel for schedule(static) if (static_cast<Index>(ne) >= k_parallel_min_elements)
    for (std::size_t e = 0; e < ne; ++e) {
        const auto& t = tri_[e];
        const Vec3& p0 = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3& p1 = model.nodes[static_cast<std::size_t>(t[1])];
        const Vec3& p2 = model.nodes[static_cast<std::size_t>(t[2])];
        const Section& sec = model.sections[static_cast<std::size_t>(section_[e])];
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        const NodeInertiaShare share =
            lumped_node_share(mat.density, sec.thickness, 0.5 * (p1 - p0).cross(p2 - p0).norm());
        node_mass_[e] = share.mass;
        node_inertia_[e] = share.inertia;
        initial_lc[e] = current_length(static_cast<Index>(e), model.nodes);
        const TriangleShape shape = local_shape(p0, p1, p2);
        shape_key[e] = {section_[e], shape_class(shape.x[1]), shape_class(shape.x[2]), shape_class(shape.y[2])};
    }
    std::vector<Index> by_shape;  // the elements with a length, by key, each class in element order
    for (std::size_t e = 0; e < ne; ++e)
        if (initial_lc[e] > 0) by_shape.push_back(static_cast<Index>(e));
    std::sort(by_shape.begin(), by_shape.end(), [&](Index a, Index b) {
        const auto& ka = shape_key[static_cast<std::size_t>(a)];
        const auto& kb = shape_key[static_cast<std::size_t>(b)];
        return ka != kb ? ka < kb : a < b;
    });
    std::vector<std::size_t> class_begin;  // first entry of each class in by_shape
    for (std::size_t i = 0; i < by_shape.size(); ++i)
        if (i == 0 || shape_key[static_cast<std::size_t>(by_shape[i])] != shape_key[static_cast<std::size_t>(by_shape[i - 1])])
            class_begin.push_back(i);
    class_begin.push_back(by_shape.size());
    const auto n_classes = static_cast<Index>(class_begin.size()) - 1;
#pragma omp parallel for schedule(dynamic, 64) if (n_classes >= k_parallel_min_elements)
    for (Index c = 0; c < n_classes; ++c) {
        const auto first = class_begin[static_cast<std::size_t>(c)], end = class_begin[static_cast<std::size_t>(c) + 1];
        const Real ratio = bending_ratio(by_shape[first], model.nodes);
        for (std::size_t i = first; i < end; ++i) {
            const auto e = static_cast<std::size_t>(by_shape[i]);
            bend_ratio_[e] = ratio;
            bend_lc_[e] = initial_lc[e];
        }
    }
    // Side neighbours: side i of element e is opposite its corner i; an edge shared by exactly
    // two elements joins them.
    smoothed_membrane_ = model.control.membrane == MembraneKernel::Smoothed;
    side_neighbour_.assign(3 * ne, -1);
    side_neighbour_side_.assign(3 * ne, -1);
    side_neighbour_corner_.assign(6 * ne, -1);
    if (smoothed_membrane_) {
        std::map<std::pair<Index, Index>, std::vector<std::pair<Index, int>>> edges;
        for (std::size_t e = 0; e < ne; ++e)
            for (int i = 0; i < 3; ++i) {
                const Index a = tri_[e][static_cast<std::size_t>((i + 1) % 3)];
                const Index b = tri_[e][static_cast<std::size_t>((i + 2) % 3)];
                edges[{std::min(a, b), std::max(a, b)}].push_back({static_cast<Index>(e), i});
            }
        for (const auto& [key, sides] : edges) {
            if (sides.size() != 2) continue;
            for (int k = 0; k < 2; ++k) {
                const auto& [e, i] = sides[static_cast<std::size_t>(k)];
                const auto& [n, m] = sides[static_cast<std::size_t>(1 - k)];
                const std::size_t side = static_cast<std::size_t>(3 * e + i);
                side_neighbour_[side] = n;
                side_neighbour_side_[side] = m;
                const auto& te = tri_[static_cast<std::size_t>(e)];
                const auto& tn = tri_[static_cast<std::size_t>(n)];
                for (int c = 0; c < 3; ++c) {
                    if (tn[static_cast<std::size_t>(c)] == te[static_cast<std::size_t>((i + 1) % 3)]) side_neighbour_corner_[2 * side] = c;
                    if (tn[static_cast<std::size_t>(c)] == te[static_cast<std::size_t>((i + 2) % 3)]) side_neighbour_corner_[2 * side + 1] = c;
                }
            }
        }
        reversed_.resize(ne);
        cst_strain_.assign(ne, Voigt3::Zero());
    }
    membrane_force_.assign(ne, Voigt3::Zero());
    bending_moment_.assign(ne, Voigt3::Zero());
    // SIMD blocks: the elements of DKT and BCIZ sections, linear elastic or J2 (whose elastic steps the
    // block kernel does), without the smoothed membrane (which couples
    // neighbours); k_lanes elements of one section per block, the rest one by one.
    for (std::size_t sec = 0; sec < rules_.size(); ++sec) {
        ElasticSectionConstants c;
        const Mat3& stiffness = elastic_stiffness(materials_[sec]);
        c.c11 = stiffness(0, 0);
        c.c12 = stiffness(0, 1);
        c.c33 = stiffness(2, 2);
        std::visit([&](const auto& m) {
            c.thickness_factor = (1.0 - 2.0 * m.poisson_ratio()) / m.youngs_modulus();
        }, materials_[sec]);
        c.inplane = rules_[sec].inplane;
        c.through = rules_[sec].through;
        c.bending = rules_[sec].bending;
        elastic_constants_.push_back(c);
    }
    auto blockable = [&](std::size_t sec) {
        return !smoothed_membrane_ && static_cast<std::size_t>(rules_[sec].n_points()) <= k_max_block_points;
    };
    for (std::size_t sec = 0; sec < rules_.size(); ++sec) {
        std::vector<Index> members;
        for (std::size_t e = 0; e < ne; ++e)
            if (static_cast<std::size_t>(section_[e]) == sec) members.push_back(static_cast<Index>(e));
        const std::size_t n_blocked = blockable(sec) ? members.size() / k_lanes * k_lanes : 0;
        block_elements_.insert(block_elements_.end(), members.begin(), members.begin() + static_cast<std::ptrdiff_t>(n_blocked));
        scalar_elements_.insert(scalar_elements_.end(), members.begin() + static_cast<std::ptrdiff_t>(n_blocked), members.end());
    }
    // The slots: the blocks' (3 per element), then those of the elements computed alone.
    slots_per_alone_ = smoothed_membrane_ ? 6 : 3;
    alone_position_.assign(ne, -1);
    for (std::size_t i = 0; i < scalar_elements_.size(); ++i) alone_position_[static_cast<std::size_t>(scalar_elements_[i])] = static_cast<Index>(i);
    const std::size_t n_slots = 3 * block_elements_.size() + slots_per_alone_ * scalar_elements_.size();
    const std::size_t n_groups = (n_slots + static_cast<std::size_t>(k_lanes) - 1) / static_cast<std::size_t>(k_lanes);
    slot_loads_.assign(n_groups * k_slot_components * static_cast<std::size_t>(k_lanes), 0.0);
    block_totals_.assign(block_elements_.size() / static_cast<std::size_t>(k_lanes), ElementTotals{});
    alone_totals_.assign(scalar_elements_.size(), ElementTotals{});
    block_resultants_.assign(6 * block_totals_.size(), RealPack(0.0));
    // Material points. A plastic section's points hold their whole history; an elastic
    // section's points hold a stress only, a third of the memory traffic. The elements of the
    // SIMD blocks keep theirs block by block, field by field, point by point, one lane per
    // element (block_state_): a block reads and writes them as whole packs (gathered element
    // by element they cost as much as the element itself). The elements computed alone keep
    // theirs in points_ (plastic) or elastic_stress_ (elastic).
    block_lane_.assign(ne, -1);
    for (std::size_t i = 0; i < block_elements_.size(); ++i) block_lane_[static_cast<std::size_t>(block_elements_[i])] = static_cast<Index>(i);
    const std::size_t n_blocks = block_elements_.size() / static_cast<std::size_t>(k_lanes);
    block_state_offset_.assign(n_blocks + 1, 0);
    for (std::size_t b = 0; b < n_blocks; ++b) {
        const std::size_t first = static_cast<std::size_t>(block_elements_[b * static_cast<std::size_t>(k_lanes)]);
        block_state_offset_[b + 1] = block_state_offset_[b] + point_fields(first) * n_points_of(first);
    }
    block_state_.assign(block_state_offset_[n_blocks], RealPack(0.0));
    // The flow radius of a J2 point in a block is kept valid from the start: sigma_f(0) until
    // the point first yields (the material point's own convention is 0 with alpha = 0), so
    // that the trial check reads the radius alone, not the plastic strain too.
    for (std::size_t b = 0; b < n_blocks; ++b) {
        const std::size_t first = static_cast<std::size_t>(block_elements_[b * static_cast<std::size_t>(k_lanes)]);
        const auto* j2 = std::get_if<J2Plastic>(&materials_[static_cast<std::size_t>(section_[first])]);
        if (!j2) continue;
        const std::size_t n = n_points_of(first);
        for (std::size_t p = 0; p < n; ++p)
            block_state_[block_state_offset_[b] + k_flow_radius * n + p] = RealPack(j2->initial_flow_radius());
    }
    point_offset_.resize(ne + 1);
    stress_offset_.resize(ne + 1);
    point_offset_[0] = stress_offset_[0] = 0;
    for (std::size_t e = 0; e < ne; ++e) {
        const bool alone = block_lane_[e] < 0, elastic = point_fields(e) == k_stress_fields;
        point_offset_[e + 1] = point_offset_[e] + (alone && !elastic ? n_points_of(e) : 0);
        stress_offset_[e + 1] = stress_offset_[e] + (alone && elastic ? n_points_of(e) : 0);
        (elastic ? n_elastic_points_ : n_plastic_points_) += n_points_of(e);
    }
    points_.assign(point_offset_[ne], MaterialPoint{});
    elastic_stress_.assign(stress_offset_[ne], Voigt3::Zero());
    // CSR particle -> slots, slots in increasing element order (fixed summation order).
    const std::size_t np = model.nodes.size();
    csr_begin_.assign(np + 1, 0);
    // slot k of element e -> its particle (-1: unused)
    auto slot_particle = [&](std::size_t e, int k) -> Index {
        if (k < 3) return tri_[e][static_cast<std::size_t>(k)];
        const Index n = side_neighbour_[3 * e + static_cast<std::size_t>(k - 3)];
        return n < 0 ? -1 : tri_[static_cast<std::size_t>(n)][static_cast<std::size_t>(side_neighbour_side_[3 * e + static_cast<std::size_t>(k - 3)])];
    };
    const int used_slots = static_cast<int>(slots_per_alone_);  // the 3 across the sides: smoothed only
    for (std::size_t e = 0; e < ne; ++e)
        for (int k = 0; k < used_slots; ++k)
            if (const Index p = slot_particle(e, k); p >= 0) ++csr_begin_[static_cast<std::size_t>(p) + 1];
    for (std::size_t p = 0; p < np; ++p) csr_begin_[p + 1] += csr_begin_[p];
    csr_slot_.assign(static_cast<std::size_t>(csr_begin_[np]), 0);
    std::vector<Index> fill(csr_begin_.begin(), csr_begin_.end() - 1);
    for (std::size_t e = 0; e < ne; ++e)
        for (int k = 0; k < used_slots; ++k)
            if (const Index p = slot_particle(e, k); p >= 0)
                csr_slot_[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] = slot_offset(e, static_cast<std::size_t>(k));
    gather_plan_ = make_slot_gather_plan(static_cast<Index>(n_blocks), gather_ranges(), csr_begin_, csr_slot_);
}

int ShellElements::gather_ranges() const {
#ifdef _OPENMP
    if (size() >= k_parallel_min_elements) return omp_get_max_threads();
#endif
    return 1;
}

std::size_t ShellElements::slot_offset(std::size_t e, std::size_t k) const {
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    const Index at = block_lane_[e];
    const std::size_t slot = at >= 0 ? (3 * (static_cast<std::size_t>(at) / w) + k) * w + static_cast<std::size_t>(at) % w
                                     : 3 * block_elements_.size() +
                                           slots_per_alone_ * static_cast<std::size_t>(alone_position_[e]) + k;
    return slot / w * (k_slot_components * w) + slot % w;
}

Real ShellElements::bending_ratio(Index e, const std::vector<Vec3>& x) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    const auto& t = tri_[ue];
    const Vec3& p0 = x[static_cast<std::size_t>(t[0])];
    const Vec3& p1 = x[static_cast<std::size_t>(t[1])];
    const Vec3& p2 = x[static_cast<std::size_t>(t[2])];
    const std::size_t sec = static_cast<std::size_t>(section_[ue]);
    const Real membrane_dt = characteristic_length(p0, p1, p2) / wave_speed_[sec];
    // only min(1, bending_dt / membrane_dt) is used (element_dt): a bound suffices where the
    // bending modes are surely slower than the membrane
    const Real bending_dt = bending_critical_dt(bending_kernel_, local_shape(p0, p1, p2), bending_rigidity_[sec],
                                                node_mass_[ue], node_inertia_[ue], membrane_dt);
    return membrane_dt > 0 ? bending_dt / membrane_dt : 1.0;
}

Real ShellElements::current_length(Index e, const std::vector<Vec3>& x) const {
    const auto& t = tri_[static_cast<std::size_t>(e)];
    return characteristic_length(x[static_cast<std::size_t>(t[0])], x[static_cast<std::size_t>(t[1])],
                                 x[static_cast<std::size_t>(t[2])]);
}

void ShellElements::refresh_bending_ratio(Index e, const std::vector<Vec3>& x, Real lc) {
    const std::size_t ue = static_cast<std::size_t>(e);
    if (!(lc > 0) || std::abs(lc - bend_lc_[ue]) <= k_bending_ratio_drift * bend_lc_[ue]) return;
    bend_ratio_[ue] = bending_ratio(e, x);
    bend_lc_[ue] = lc;
}

Real ShellElements::element_dt(Index e, Real lc) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    const std::size_t sec = static_cast<std::size_t>(section_[ue]);
    // §6.4 membrane step L_c / c; the bending modes of thick elements (h / L_c > ~0.5) are
    // slower to integrate, bend_ratio_ < 1 (bending_time_step.hpp).
    Real dt = lc / wave_speed_[sec] * std::min(Real{1}, bend_ratio_[ue]);
    if (stiffness_damping_ > 0) {  // §6.4: dt <= (2/w)(sqrt(1+xi^2) - xi), w = 2/dt
        const Real xi = stiffness_damping_ / dt;
        dt *= std::sqrt(1.0 + xi * xi) - xi;
    }
    return dt;
}

Real ShellElements::plastic_strain(Index e, int k) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    if (point_fields(ue) == k_stress_fields) return 0.0;  // elastic
    const std::size_t nk = rules_[static_cast<std::size_t>(section_[ue])].through.size();
    Real sum = 0;
    std::size_t n = 0;
    for (std::size_t p = static_cast<std::size_t>(k); p < n_points_of(ue); p += nk, ++n) sum += point_state(ue, p).plastic_strain;
    return n > 0 ? sum / static_cast<Real>(n) : 0.0;
}

Real ShellElements::min_critical_dt(const std::vector<Vec3>& x, Index* where) const {
    Real best = std::numeric_limits<Real>::infinity();
    Index arg = -1;
    for (Index e = 0; e < size(); ++e) {
        const Real dt = critical_dt(e, x);
        if (dt < best) {
            best = dt;
            arg = e;
        }
    }
    if (where) *where = arg;
    return best;
}

ReversedTriangle ShellElements::reverse_element(std::size_t ue, const ParticleState& s) const {
    const auto& t = tri_[ue];
    std::array<Vec3, 3> base, cur, dth, drill;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t p = static_cast<std::size_t>(t[i]);
        base[i] = s.x_prev[p];
        cur[i] = s.x[p];
        dth[i] = s.dtheta[p];
        drill[i] = s.drill_axis[p];
    }
    return reverse_motion(base, cur, dth, drill);
}

ShellElements::ElementTotals ShellElements::compute_element(Index e, ParticleState& s, Real viscous_rate, Real dt) {
    const std::size_t ue = static_cast<std::size_t>(e);
    const ReversedTriangle rt = smoothed_membrane_ ? reversed_[ue] : reverse_element(ue, s);
    const Real lc = current_length(e, s.x);  // once per element and step
    refresh_bending_ratio(e, s.x, lc);
    ElementTotals totals;
    totals.dt = element_dt(e, lc);
    totals.dt_element = e;
    // the 3 slots across the sides exist (and are gathered) only with the smoothed membrane
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    const std::size_t used_slots = block_lane_[ue] >= 0 ? 3 : slots_per_alone_;
    for (std::size_t k = 0; k < used_slots; ++k)
        for (std::size_t c = 0, at = slot_offset(ue, k); c < k_slot_components; ++c) slot_loads_[at + c * w] = 0;
    // A tilt over 90 deg or an area change by a factor 2 within one step is no deformation a
    // stable step can produce: the run has diverged (theory.md §2.8).
    if (rt.degenerate || rt.normal_cosine < 0 || !(rt.area_ratio > 0.5 && rt.area_ratio < 2.0)) {
        totals.failed = e;
        return totals;
    }
    // Smoothed membrane strain (membrane_smoothing.hpp): the mean of the three side strains,
    // a side strain being the area-weighted mean of the CST strains of the two elements
    // there (the neighbour's unfolded into this frame), or this element's own on a side
    // without a smooth neighbour. Area weights keep the patch test.
    Voigt3 smoothed = Voigt3::Zero();
    Real own_share = 1;
    std::array<Mat3, 3> to_here;         // neighbour strain -> this frame, per side
    std::array<Real, 3> side_weight{};   // weight of the neighbour's strain, per side
    if (smoothed_membrane_) {
        own_share = 0;
        for (int i = 0; i < 3; ++i) {
            const Index n = side_neighbour_[3 * ue + static_cast<std::size_t>(i)];
            const ReversedTriangle* rn = n >= 0 ? &reversed_[static_cast<std::size_t>(n)] : nullptr;
            if (rn && !rn->degenerate &&
                rn->frame_current.row(2).dot(rt.frame_current.row(2)) >= k_smooth_cosine) {
                // the shared side runs from corner (i+1) to corner (i+2) here, from corner na to
                // corner nb in the neighbour (topology, fixed at construction)
                const int na = side_neighbour_corner_[2 * (3 * ue + static_cast<std::size_t>(i))];
                const int nb = side_neighbour_corner_[2 * (3 * ue + static_cast<std::size_t>(i)) + 1];
                const Real beta = side_angle(rt.x2, rt.x3, rt.y3, (i + 1) % 3, (i + 2) % 3) -
                                  side_angle(rn->x2, rn->x3, rn->y3, na, nb);
                to_here[static_cast<std::size_t>(i)] = strain_rotation(beta);
                const Real w_n = rn->area / (3.0 * (rt.area + rn->area));
                side_weight[static_cast<std::size_t>(i)] = w_n;
                own_share += 1.0 / 3.0 - w_n;
                smoothed += w_n * (to_here[static_cast<std::size_t>(i)] * cst_strain_[static_cast<std::size_t>(n)]);
            } else {
                own_share += 1.0 / 3.0;
            }
        }
        smoothed += own_share * cst_strain_[ue];
    }
    const std::size_t sec = static_cast<std::size_t>(section_[ue]);
    // the points of a plastic element computed alone are used in place; the others (elastic
    // stresses, block layout) go through material points for the general kernel
    const bool in_place = block_lane_[ue] < 0 && point_fields(ue) != k_stress_fields;
    std::span<MaterialPoint> pts(points_.data() + point_offset_[ue], point_offset_[ue + 1] - point_offset_[ue]);
    std::array<MaterialPoint, k_max_block_points> local_points;
    if (!in_place) {
        pts = std::span<MaterialPoint>(local_points.data(), n_points_of(ue));
        for (std::size_t p = 0; p < pts.size(); ++p) pts[p] = point_state(ue, p);
    }
    const ShellTriangleLoads loads =
        std::visit([&](const auto& material) {
            return shell_triangle_loads(rt, rules_[sec], material, pts, viscous_rate, dt, thickness_[ue],
                                        smoothed_membrane_ ? &smoothed : nullptr, own_share);
        }, materials_[sec]);
    if (!in_place)
        for (std::size_t p = 0; p < pts.size(); ++p) set_point_state(ue, p, pts[p]);
    if (thickness_update_) thickness_[ue] *= 1.0 + loads.thickness_strain;  // §3.4
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t at = slot_offset(ue, i);
        for (std::size_t c = 0; c < 3; ++c) {
            slot_loads_[at + c * w] = loads.force[i](static_cast<Eigen::Index>(c));
            slot_loads_[at + (3 + c) * w] = loads.moment[i](static_cast<Eigen::Index>(c));
        }
    }
    if (smoothed_membrane_) {
        // The neighbours' share of the membrane forces: A_e w_n B_n^T T^T N, in the
        // neighbour's frame, turned forward with it (§5).
        for (int i = 0; i < 3; ++i) {
            if (side_weight[static_cast<std::size_t>(i)] == 0) continue;
            const std::size_t n = static_cast<std::size_t>(side_neighbour_[3 * ue + static_cast<std::size_t>(i)]);
            const ReversedTriangle& rn = reversed_[n];
            const Voigt3 n_there = to_here[static_cast<std::size_t>(i)].transpose() * loads.membrane_resultant;
            const Eigen::Matrix<Real, 6, 1> f_local =
                (rt.area * side_weight[static_cast<std::size_t>(i)]) *
                (membrane_b(TriangleShape(rn.x2, rn.x3, rn.y3)).transpose() * n_there);
            const Mat3 to_global = rn.frame_current.transpose();
            for (int k = 0; k < 3; ++k) {
                const Vec3 f = to_global * Vec3(f_local(2 * k), f_local(2 * k + 1), 0.0);
                const Index p = tri_[n][static_cast<std::size_t>(k)];
                std::size_t slot = 3 + static_cast<std::size_t>(i);  // the node across side i
                for (std::size_t j = 0; j < 3; ++j)
                    if (tri_[ue][j] == p) slot = j;
                const std::size_t at = slot_offset(ue, slot);
                for (std::size_t c = 0; c < 3; ++c) slot_loads_[at + c * w] += f(static_cast<Eigen::Index>(c));
            }
        }
    }
    totals.strain_work = loads.strain_work;
    totals.damping_work = loads.damping_work;
    totals.plastic_work = loads.plastic_work;
    set_resultants(ue, loads.membrane_force, loads.bending_moment);
    return totals;
}

void ShellElements::ElementTotals::add(const ElementTotals& o) {
    strain_work += o.strain_work;
    damping_work += o.damping_work;
    plastic_work += o.plastic_work;
    // the lowest-numbered element among equals, as a scan in element order finds
    if (o.dt < dt || (o.dt == dt && o.dt_element >= 0 && (dt_element < 0 || o.dt_element < dt_element))) {
        dt = o.dt;
        dt_element = o.dt_element;
    }
    if (o.failed >= 0 && (failed < 0 || o.failed < failed)) failed = o.failed;
}

Voigt3 ShellElements::resultant(std::size_t e, std::size_t first) const {
    const Index at = block_lane_[e];
    if (at < 0) return first == 0 ? membrane_force_[e] : bending_moment_[e];
    const auto [b, l] = block_and_lane(at);
    const RealPack* r = block_resultants_.data() + 6 * b + first;
    return Voigt3(lane(r[0], l), lane(r[1], l), lane(r[2], l));
}

void ShellElements::set_resultants(std::size_t e, const Voigt3& n, const Voigt3& m) {
    const Index at = block_lane_[e];
    if (at < 0) {
        membrane_force_[e] = n;
        bending_moment_[e] = m;
        return;
    }
    const auto [b, l] = block_and_lane(at);
    RealPack* r = block_resultants_.data() + 6 * b;
    for (Eigen::Index c = 0; c < 3; ++c) {
        set_lane(r[c], l, n(c));
        set_lane(r[3 + c], l, m(c));
    }
}

void ShellElements::compute_block(Index b, ParticleState& s, Real viscous_rate, Real dt, Real* ring_slots) {
    const Index* ids = block_elements_.data() + static_cast<std::size_t>(b) * k_lanes;
    auto element = [ids](int l) { return static_cast<std::size_t>(ids[l]); };
    const std::size_t sec = static_cast<std::size_t>(section_[element(0)]);  // one per block
    const ElasticSectionConstants& constants = elastic_constants_[sec];
    // Gather the lanes (structure of arrays), compute, scatter the valid lanes.
    alignas(64) std::array<Real, k_lanes> buffer;
    auto load = [&](auto&& value) {
        for (int l = 0; l < k_lanes; ++l) buffer[static_cast<std::size_t>(l)] = value(l);
        return RealPack(buffer.data(), stdx::vector_aligned);
    };
    TriangleMotion<RealPack> motion;
    for (std::size_t i = 0; i < 3; ++i) {
        std::array<std::size_t, k_lanes> node;  // corner i of every lane
        for (int l = 0; l < k_lanes; ++l) node[static_cast<std::size_t>(l)] = static_cast<std::size_t>(tri_[element(l)][i]);
        auto gather = [&](const std::vector<Vec3>& field, V3<RealPack>& out) {
            out.x = load([&](int l) { return field[node[static_cast<std::size_t>(l)]].x(); });
            out.y = load([&](int l) { return field[node[static_cast<std::size_t>(l)]].y(); });
            out.z = load([&](int l) { return field[node[static_cast<std::size_t>(l)]].z(); });
        };
        gather(s.x_prev, motion.base[i]);
        gather(s.x, motion.current[i]);
        gather(s.dtheta, motion.dtheta[i]);
        gather(s.drill_axis, motion.drill_axis[i]);
    }
    // Without the thickness update (§3.4) every element keeps its section's thickness: a
    // broadcast, not a gather (whose pack, filled through memory, stalled the block: perf).
    const RealPack thickness = thickness_update_ ? load([&](int l) { return thickness_[element(l)]; })
                                                 : RealPack(rules_[sec].thickness);
    const std::size_t n_points = constants.inplane.size() * constants.through.size();
    // The points' state, whole packs in the block layout: [field][point] (point_fields), so
    // that a step streams only the fields it reads.
    const J2Plastic* j2 = std::get_if<J2Plastic>(&materials_[sec]);
    RealPack* state = block_state_.data() + block_state_offset_[static_cast<std::size_t>(b)];
    auto field = [&](std::size_t p, std::size_t f) -> RealPack& { return state[f * n_points + p]; };
    // isotropic hardening (beta = 1): the back stress stays zero and is neither read nor written
    const bool kinematic = j2 && j2->return_constants().beta != 1.0;
    // The fields this function reads of the next block's points (taken to be of this block's
    // section), fetched while this block computes: without it, the loads of the stresses
    // stalled on memory (perf: a fifth of this function's time on the elastic 10^5 plate).
    if (static_cast<std::size_t>(b) + 2 < block_state_offset_.size()) {
        const std::size_t next = block_state_offset_[static_cast<std::size_t>(b) + 1];
        const std::size_t end = block_state_offset_[static_cast<std::size_t>(b) + 2];
        auto prefetch = [&](std::size_t first_field, std::size_t n_fields) {
            const std::size_t from = std::min(end, next + first_field * n_points);
            prefetch_packs(block_state_.data() + from, std::min(end, from + n_fields * n_points) - from);
        };
        prefetch(k_stress, 3);
        if (kinematic) prefetch(k_back_stress, 3);
        if (j2) {
            prefetch(k_flow_radius, 1);
            if (j2->rate_dependent()) prefetch(k_strain_rate, 1);
        }
    }
    std::array<RealPack, 3 * k_max_block_points> stress;
    for (std::size_t p = 0; p < n_points; ++p)
        for (std::size_t r = 0; r < 3; ++r) stress[3 * p + r] = field(p, k_stress + r);
    // J2 sections: the yield surfaces of the points, kappa_n = flow radius at alpha_n (§7.3)
    std::array<RealPack, 3 * k_max_block_points> back_stress;
    std::array<RealPack, k_max_block_points> third_k2, strain_rate, new_strain_rate;
    YieldSurfaces<RealPack> yield{back_stress.data(), third_k2.data(), J2Plastic::k_yield_tolerance};
    if (j2) {
        for (std::size_t p = 0; p < n_points; ++p) {
            for (std::size_t r = 0; r < 3; ++r) back_stress[3 * p + r] = kinematic ? field(p, k_back_stress + r) : RealPack(0.0);
            const RealPack kappa = field(p, k_flow_radius);  // sigma_f(0) before the first yield (constructor)
            third_k2[p] = kappa * kappa * (1.0 / 3.0);
        }
        if (j2->rate_dependent()) {
            yield.rate = &j2->rate_factor();
            yield.strain_rate = strain_rate.data();
            yield.new_strain_rate = new_strain_rate.data();
            yield.dt = dt;
            yield.rate_filter = J2Plastic::k_rate_filter;
            for (std::size_t p = 0; p < n_points; ++p) strain_rate[p] = field(p, k_strain_rate);
        }
    }
    // The yielding points of J2 lanes: the return mapping of §7.3 on the yielding (point, lane)
    // pairs of the block, k_lanes pairs at a time (packed densely: the pairs of a block that
    // yields in part fill whole packs), in place in the block's state (a lane that takes this
    // path never falls back, so its old state is not needed again).
    auto return_mapping = [&](std::size_t n_pts, const RealPack::mask_type* yielding, const std::array<RealPack, 3>* d_eps,
                              const RealPack* rate_factor, RealPack* new_stress, RealPack* d_plastic_work) {
        constexpr int w = k_lanes;
        // the inputs of the batch, structure of arrays: stress 3, back stress 3, alpha, flow
        // radius, flow slope, strain increment 3, rate factor
        alignas(64) std::array<std::array<Real, w>, 13> in;
        std::array<std::size_t, w> batch_point;
        std::array<int, w> batch_lane;
        int n = 0;
        auto run_batch = [&] {
            for (int i = n; i < w; ++i)  // unused lanes compute on a copy of the first pair
                for (auto& input : in) input[static_cast<std::size_t>(i)] = input[0];
            auto pack = [&](std::size_t f) { return RealPack(in[f].data(), stdx::vector_aligned); };
            const J2PointState<RealPack> old{{pack(0), pack(1), pack(2)}, {pack(3), pack(4), pack(5)}, pack(6), pack(7), pack(8)};
            RealPack::mask_type used(false);
            for (int i = 0; i < n; ++i) used[static_cast<std::size_t>(i)] = true;
            const J2Return<RealPack> ret =
                j2_return_mapping(j2->return_constants(), old, {pack(9), pack(10), pack(11)}, pack(12), used);
            for (int i = 0; i < n; ++i) {
                const std::size_t p = batch_point[static_cast<std::size_t>(i)];
                const int l = batch_lane[static_cast<std::size_t>(i)];
                for (std::size_t r = 0; r < 3; ++r) set_lane(new_stress[3 * p + r], l, lane(ret.state.stress[r], i));
                if (!lane(ret.yielded, i)) continue;  // inside after all (rounding): the trial state
                set_lane(d_plastic_work[p], l, lane(ret.plastic_work, i));
                if (kinematic)
                    for (std::size_t r = 0; r < 3; ++r) set_lane(field(p, k_back_stress + r), l, lane(ret.state.back_stress[r], i));
                set_lane(field(p, k_plastic_strain), l, lane(ret.state.plastic_strain, i));
                set_lane(field(p, k_plastic_work), l, lane(field(p, k_plastic_work), l) + lane(ret.plastic_work, i));
                set_lane(field(p, k_flow_radius), l, lane(ret.state.flow_radius, i));
                set_lane(field(p, k_flow_slope), l, lane(ret.state.flow_slope, i));
            }
            n = 0;
        };
        for (std::size_t p = 0; p < n_pts; ++p) {
            if (!any_lane(yielding[p])) continue;
            for (int l = 0; l < k_lanes; ++l) {
                if (!lane(yielding[p], l)) continue;
                const auto i = static_cast<std::size_t>(n);
                for (std::size_t r = 0; r < 3; ++r) {
                    in[r][i] = lane(field(p, k_stress + r), l);  // the old stress: not stored yet
                    in[3 + r][i] = lane(back_stress[3 * p + r], l);
                    in[9 + r][i] = lane(d_eps[p][r], l);
                }
                in[6][i] = lane(field(p, k_plastic_strain), l);
                in[7][i] = lane(field(p, k_flow_radius), l);
                in[8][i] = lane(field(p, k_flow_slope), l);
                in[12][i] = lane(rate_factor[p], l);
                batch_point[i] = p;
                batch_lane[i] = l;
                if (++n == w) run_batch();
            }
        }
        if (n > 0) run_batch();
    };
    const ElasticTriangleLoads<RealPack> loads =
        j2 ? elastic_triangle_loads(motion, constants, thickness, stress.data(), viscous_rate, &yield, return_mapping)
           : elastic_triangle_loads(motion, constants, thickness, stress.data(), viscous_rate);

    // the new stresses (and filtered rates) of the valid lanes; an invalid lane's old state
    // stays for the general code
    for (std::size_t p = 0; p < n_points; ++p) {
        for (std::size_t r = 0; r < 3; ++r) stdx::where(loads.valid, field(p, k_stress + r)) = stress[3 * p + r];
        if (yield.new_strain_rate) stdx::where(loads.valid, field(p, k_strain_rate)) = new_strain_rate[p];
    }
    // the corner loads, 6 whole packs per corner, into the ring and (kept or without a ring)
    // into slot_loads_; an invalid lane's are rewritten below by the general code
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    Real* full_slots = slot_loads_.data() + 3 * static_cast<std::size_t>(b) * k_slot_components * w;
    auto store = [&](Real* slots) {
        for (std::size_t i = 0; i < 3; ++i) {
            const std::array<const RealPack*, k_slot_components> component{
                &loads.force[i].x, &loads.force[i].y, &loads.force[i].z, &loads.moment[i].x, &loads.moment[i].y, &loads.moment[i].z};
            for (std::size_t c = 0; c < k_slot_components; ++c)
                component[c]->copy_to(slots + (i * k_slot_components + c) * w, stdx::element_aligned);
        }
    };
    if (!ring_slots || gather_plan_.keep[static_cast<std::size_t>(b)]) store(full_slots);
    if (ring_slots) store(ring_slots);
    // N and M, whole packs (an invalid lane's are rewritten below by the general code)
    RealPack* resultants = block_resultants_.data() + 6 * static_cast<std::size_t>(b);
    for (std::size_t r = 0; r < 3; ++r) {
        resultants[r] = loads.membrane_force[r];
        resultants[3 + r] = loads.bending_moment[r];
    }
    // the block's totals, lane by lane in lane order
    ElementTotals totals;
    for (int l = 0; l < k_lanes; ++l) {
        const std::size_t ue = element(l);
        if (!lane(loads.valid, l)) {  // outside the block kernel's bounds: the general code
            totals.add(compute_element(static_cast<Index>(ue), s, viscous_rate, dt));
            // (which writes slot_loads_; the ring takes a copy of the lane)
            if (ring_slots)
                for (std::size_t k = 0; k < 3 * k_slot_components; ++k) ring_slots[k * w + static_cast<std::size_t>(l)] = full_slots[k * w + static_cast<std::size_t>(l)];
            continue;
        }
        const Real lc = lane(loads.characteristic_length, l);
        refresh_bending_ratio(static_cast<Index>(ue), s.x, lc);
        if (thickness_update_) thickness_[ue] *= 1.0 + lane(loads.thickness_strain, l);  // §3.4
        ElementTotals t;
        t.strain_work = lane(loads.strain_work, l);
        t.damping_work = lane(loads.damping_work, l);
        t.plastic_work = lane(loads.plastic_work, l);
        t.dt = element_dt(static_cast<Index>(ue), lc);
        t.dt_element = static_cast<Index>(ue);
        totals.add(t);
    }
    block_totals_[static_cast<std::size_t>(b)] = totals;
}

void ShellElements::gather_particle(std::size_t p, const Real* base, ParticleState& s) const {
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    Vec3 f = Vec3::Zero(), m = Vec3::Zero();
    for (Index k = csr_begin_[p]; k < csr_begin_[p + 1]; ++k) {
        const Real* slot = base + gather_plan_.offset[static_cast<std::size_t>(k)];
        f += Vec3(slot[0], slot[w], slot[2 * w]);
        m += Vec3(slot[3 * w], slot[4 * w], slot[5 * w]);
    }
    s.f_int[p] = f;
    s.m_int[p] = m;
}

ShellElements::StepTotals ShellElements::compute(ParticleState& s, Real viscous_rate, Real dt) {
    const Index ne = size();
    // Small models stay serial: a parallel region per step costs more than it saves there.
    [[maybe_unused]] const bool parallel = ne >= k_parallel_min_elements;
    // Phase 0 (smoothed membrane only): every element's path element and CST strain increment.
    if (smoothed_membrane_) {
#pragma omp parallel for schedule(static) if (parallel)
        for (Index e = 0; e < ne; ++e) {
            const std::size_t ue = static_cast<std::size_t>(e);
            reversed_[ue] = reverse_element(ue, s);
            const ReversedTriangle& rt = reversed_[ue];
            if (rt.degenerate) {
                cst_strain_[ue].setZero();
                continue;
            }
            Eigen::Matrix<Real, 6, 1> u_vec;
            for (int i = 0; i < 3; ++i) u_vec.segment<2>(2 * i) = rt.u[static_cast<std::size_t>(i)];
            cst_strain_[ue] = membrane_b(TriangleShape(rt.x2, rt.x3, rt.y3)) * u_vec;  // §3.1
        }
    }
    // Phase 1: every triangle writes its corner loads (and, smoothed, the loads on the nodes
    // across its sides) into its own slots: the elastic blocks k_lanes elements at a time
    // (elements/elastic_triangle_block.hpp), the other elements one by one. Phase 2: every
    // particle sums its slots in element order (bitwise thread-independent): as soon as its
    // last block is done where the plan allows (from the ring, still in the cache), the others
    // after the loop (slot_gather_plan.hpp).
    const Index n_blocks = static_cast<Index>(block_elements_.size()) / k_lanes;
    const Index n_scalar = static_cast<Index>(scalar_elements_.size());
    // (made at construction; remade only if the thread count has changed since)
    if (const int ranges = gather_ranges(); gather_plan_.ranges() != ranges)
        gather_plan_ = make_slot_gather_plan(n_blocks, ranges, csr_begin_, csr_slot_);
    const SlotGatherPlan& plan = gather_plan_;
    constexpr Index tile = SlotGatherPlan::k_tile_blocks, ring_blocks = SlotGatherPlan::k_ring_blocks;
#pragma omp parallel if (parallel)
    {
        // one range per thread (any team size gives the same sums: a range is a unit of work)
#pragma omp for schedule(static, 1) nowait
        for (int r = 0; r < plan.ranges(); ++r) {
            const auto ur = static_cast<std::size_t>(r);
            Real* ring = plan.use_ring() ? gather_plan_.rings[ur].data() : nullptr;
            const Index first = plan.range_begin[ur], end = plan.range_begin[ur + 1];
            for (Index t = plan.range_first_tile[ur]; t < plan.range_first_tile[ur + 1]; ++t) {
                const Index from = first + (t - plan.range_first_tile[ur]) * tile;
                for (Index b = from; b < std::min(end, from + tile); ++b)
                    compute_block(b, s, viscous_rate, dt,
                                  ring ? ring + static_cast<std::size_t>((b - first) % ring_blocks) * SlotGatherPlan::k_block_reals
                                       : nullptr);
                for (Index k = plan.ready_begin[static_cast<std::size_t>(t)]; k < plan.ready_begin[static_cast<std::size_t>(t) + 1]; ++k)
                    gather_particle(static_cast<std::size_t>(plan.ready[static_cast<std::size_t>(k)]), ring, s);
            }
        }
#pragma omp for schedule(static)
        for (Index i = 0; i < n_scalar; ++i)
            alone_totals_[static_cast<std::size_t>(i)] = compute_element(scalar_elements_[static_cast<std::size_t>(i)], s, viscous_rate, dt);
        // (the barrier of the loop above: every slot is written)
#pragma omp for schedule(static)
        for (Index k = 0; k < static_cast<Index>(plan.after.size()); ++k)
            gather_particle(static_cast<std::size_t>(plan.after[static_cast<std::size_t>(k)]), slot_loads_.data(), s);
    }
    // Totals over the blocks, then the elements computed alone, in fixed chunks of them
    // (core/chunked_loop.hpp): the same for any thread count.
    const Index n_units = n_blocks + n_scalar;
    const Index n_chunks = (n_units + k_chunk_size - 1) / k_chunk_size;
    chunk_totals_.resize(static_cast<std::size_t>(n_chunks));
#pragma omp parallel for schedule(static) if (parallel)
    for (Index c = 0; c < n_chunks; ++c) {
        ElementTotals t;
        for (Index u = c * k_chunk_size; u < std::min(n_units, (c + 1) * k_chunk_size); ++u)
            t.add(u < n_blocks ? block_totals_[static_cast<std::size_t>(u)] : alone_totals_[static_cast<std::size_t>(u - n_blocks)]);
        chunk_totals_[static_cast<std::size_t>(c)] = t;
    }
    ElementTotals all;
    for (const ElementTotals& t : chunk_totals_) all.add(t);
    StepTotals tot;
    tot.strain_work = all.strain_work;
    tot.damping_work = all.damping_work;
    tot.plastic_work = all.plastic_work;
    tot.min_dt = all.dt;
    tot.min_dt_element = all.dt_element;
    tot.failed_element = all.failed;
    return tot;
}

std::size_t ShellElements::n_points_of(std::size_t e) const {
    return static_cast<std::size_t>(rules_[static_cast<std::size_t>(section_[e])].n_points());
}

std::size_t ShellElements::point_fields(std::size_t e) const {
    return std::holds_alternative<LinearElastic>(materials_[static_cast<std::size_t>(section_[e])]) ? k_stress_fields
                                                                                                  : k_j2_fields;
}

MaterialPoint ShellElements::point_state(std::size_t e, std::size_t p) const {
    const Index at = block_lane_[e];
    const bool elastic = point_fields(e) == k_stress_fields;
    if (at < 0) {
        if (!elastic) return points_[point_offset_[e] + p];
        MaterialPoint mp;
        mp.stress = elastic_stress_[stress_offset_[e] + p];
        return mp;
    }
    const auto [b, l] = block_and_lane(at);
    const RealPack* base = block_state_.data() + block_state_offset_[b];
    const std::size_t n = n_points_of(e);
    auto f = [&](std::size_t k) { return lane(base[k * n + p], l); };  // field k, [field][point]
    MaterialPoint mp;
    mp.stress = Voigt3(f(k_stress), f(k_stress + 1), f(k_stress + 2));
    if (elastic) return mp;
    mp.back_stress = Voigt3(f(k_back_stress), f(k_back_stress + 1), f(k_back_stress + 2));
    mp.plastic_strain = f(k_plastic_strain);
    mp.plastic_work = f(k_plastic_work);
    mp.strain_rate = f(k_strain_rate);
    mp.flow_radius = f(k_flow_radius);
    mp.flow_slope = f(k_flow_slope);
    return mp;
}

void ShellElements::set_point_state(std::size_t e, std::size_t p, const MaterialPoint& mp) {
    const Index at = block_lane_[e];
    const bool elastic = point_fields(e) == k_stress_fields;
    if (at < 0) {
        if (elastic) elastic_stress_[stress_offset_[e] + p] = mp.stress;
        else points_[point_offset_[e] + p] = mp;
        return;
    }
    const auto [b, l] = block_and_lane(at);
    RealPack* base = block_state_.data() + block_state_offset_[b];
    const std::size_t n = n_points_of(e);
    auto set = [&](std::size_t k, Real v) { set_lane(base[k * n + p], l, v); };  // field k, [field][point]
    for (std::size_t r = 0; r < 3; ++r) set(k_stress + r, mp.stress(static_cast<Eigen::Index>(r)));
    if (elastic) return;
    for (std::size_t r = 0; r < 3; ++r) set(k_back_stress + r, mp.back_stress(static_cast<Eigen::Index>(r)));
    set(k_plastic_strain, mp.plastic_strain);
    set(k_plastic_work, mp.plastic_work);
    set(k_strain_rate, mp.strain_rate);
    // the block convention: the radius is valid before the first yield too (constructor)
    const Real initial_radius = std::get<J2Plastic>(materials_[static_cast<std::size_t>(section_[e])]).initial_flow_radius();
    set(k_flow_radius, mp.plastic_strain > 0 ? mp.flow_radius : initial_radius);
    set(k_flow_slope, mp.flow_slope);
}

// The restart file holds every plastic point, then every elastic point's stress, in element
// order (format 2), whatever the layout in memory.
void ShellElements::save(RestartWriter& out) const {
    std::vector<MaterialPoint> points;
    std::vector<Voigt3> stresses;
    points.reserve(n_plastic_points_);
    stresses.reserve(n_elastic_points_);
    for (std::size_t e = 0; e < thickness_.size(); ++e)
        for (std::size_t p = 0; p < n_points_of(e); ++p) {
            if (point_fields(e) == k_stress_fields) stresses.push_back(point_state(e, p).stress);
            else points.push_back(point_state(e, p));
        }
    std::vector<Voigt3> n(thickness_.size()), m(thickness_.size());
    for (std::size_t e = 0; e < thickness_.size(); ++e) {
        n[e] = resultant(e, 0);
        m[e] = resultant(e, 3);
    }
    auto& self = const_cast<ShellElements&>(*this);  // the archive's interface is shared with load
    out(points, stresses, self.thickness_, self.bend_ratio_, self.bend_lc_, n, m);
}

void ShellElements::load(RestartReader& in) {
    const std::size_t n_elements = thickness_.size();
    std::vector<MaterialPoint> points;
    std::vector<Voigt3> stresses, n, m;  // the resultants N, M of every element
    if (in.format() >= 2) {
        in(points, stresses, thickness_, bend_ratio_, bend_lc_, n, m);
    } else {  // format 1: no elastic stresses apart (restart_archive.cpp)
        if (n_elastic_points_ > 0)
            in.fail("restart file of format 1, which holds no elastic stresses apart: it can resume a model "
                    "without elastic sections only");
        in(points, thickness_, bend_ratio_, bend_lc_, n, m);
    }
    if (points.size() != n_plastic_points_ || stresses.size() != n_elastic_points_ || thickness_.size() != n_elements ||
        n.size() != n_elements || m.size() != n_elements)
        in.fail("restart file of a model with other elements or integration rules");
    for (std::size_t e = 0; e < n_elements; ++e) set_resultants(e, n[e], m[e]);
    std::size_t i = 0, j = 0;
    for (std::size_t e = 0; e < n_elements; ++e)
        for (std::size_t p = 0; p < n_points_of(e); ++p) {
            if (point_fields(e) == k_stress_fields) {
                MaterialPoint mp;
                mp.stress = stresses[j++];
                set_point_state(e, p, mp);
            } else {
                set_point_state(e, p, points[i++]);
            }
        }
}

}  // namespace fpmshell
