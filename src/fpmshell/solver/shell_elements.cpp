#include "fpmshell/solver/shell_elements.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "fpmshell/core/byte_buffer.hpp"
#include "fpmshell/core/chunked_loop.hpp"
#include "fpmshell/core/communicator.hpp"
#include "fpmshell/core/exact_sum.hpp"
#include "fpmshell/elements/cst_membrane.hpp"
#include "fpmshell/elements/membrane_smoothing.hpp"
#include "fpmshell/io/restart_archive.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace fpmshell {
namespace {

constexpr Index k_parallel_min_elements = 2000;
constexpr std::size_t k_slot_components =
    CornerAssembly::k_components;  // force x y z, moment x y z
// Smoothed membrane: neighbours whose normals differ by more than this (a fold, such as a tube
// corner) are not averaged with (cos 20 deg, like the kink limit of §1.3).
constexpr Real k_smooth_cosine = 0.9397;

std::vector<std::unique_ptr<ElementGroup>> make_groups(const Model& model,
                                                       const ElementGroupFactory& make_group) {
    std::vector<std::unique_ptr<ElementGroup>> groups;
    for (std::size_t sec = 0; sec < model.sections.size(); ++sec)
        groups.push_back(make_group(model, sec));
    return groups;
}

ElementTimeSteps make_time_steps(const Model& model, const MeshTopology& topology,
                                 const std::vector<std::unique_ptr<ElementGroup>>& groups) {
    std::vector<Real> wave_speed;
    std::vector<Mat3> bending_rigidity;
    for (const auto& g : groups) {
        wave_speed.push_back(g->wave_speed());
        bending_rigidity.push_back(g->bending_rigidity());
    }
    return ElementTimeSteps(model, topology, std::move(wave_speed), std::move(bending_rigidity));
}

/// SIMD blocks: the elements of the groups with a block path whose rule the block kernel
/// takes, without the smoothed membrane (which couples neighbours).
ElementBlocks make_blocks(const Model& model,
                          const std::vector<std::unique_ptr<ElementGroup>>& groups, bool smoothed) {
    std::vector<bool> blockable;
    for (const auto& g : groups)
        blockable.push_back(!smoothed && g->has_block_path() &&
                            g->n_points() <= k_max_block_points);
    return assign_blocks(model.element_section, blockable);
}

}  // namespace

ElementBlocks element_units(const Model& model, const ElementGroupFactory& make_group) {
    return make_blocks(model, make_groups(model, make_group),
                       model.control.membrane == MembraneKernel::Smoothed);
}

ShellElements::ShellElements(const Model& model, const MeshTopology& topology,
                             const ElementGroupFactory& make_group, bool state_now)
    : tri_(model.triangles),
      section_(model.element_section),
      topology_(&topology),
      groups_(make_groups(model, make_group)),
      time_steps_(make_time_steps(model, topology, groups_)),
      assembly_(make_blocks(model, groups_, model.control.membrane == MembraneKernel::Smoothed),
                tri_, topology, model.control.membrane == MembraneKernel::Smoothed, state_now),
      thickness_update_(model.control.thickness_update),
      smoothed_membrane_(model.control.membrane == MembraneKernel::Smoothed) {
    const std::size_t ne = tri_.size();
    thickness_.resize(ne);
    for (std::size_t e = 0; e < ne; ++e)
        thickness_[e] = model.sections[static_cast<std::size_t>(section_[e])].thickness;
    init_erosion(model);  // §7.6
    if (smoothed_membrane_) {
        reversed_.resize(ne);
        cst_strain_.assign(ne, Voigt3::Zero());
    }
    const ElementBlocks& blocks = assembly_.blocks();
    if (state_now) allocate_state();
    membrane_force_.assign(static_cast<std::size_t>(blocks.n_alone()), Voigt3::Zero());
    bending_moment_.assign(static_cast<std::size_t>(blocks.n_alone()), Voigt3::Zero());
    alone_totals_.assign(static_cast<std::size_t>(blocks.n_alone()), ElementTotals{});
    assembly_.plan(gather_ranges());
}

int ShellElements::gather_ranges() const {
#ifdef _OPENMP
    if (size() >= k_parallel_min_elements) return omp_get_max_threads();
#endif
    return 1;
}

GroupPlace ShellElements::place_of(std::size_t e) const {
    const ElementBlocks& blocks = assembly_.blocks();
    const auto g = static_cast<std::size_t>(section_[e]);
    if (const Index at = blocks.block_lane[e]; at >= 0)
        return {true, static_cast<std::size_t>(at - blocks.group_first_block[g] * k_lanes)};
    return {false,
            static_cast<std::size_t>(blocks.alone_position[e] - blocks.group_first_alone[g])};
}

Real ShellElements::current_length(Index e, const std::vector<Vec3>& x) const {
    const auto& t = tri_[static_cast<std::size_t>(e)];
    return characteristic_length(x[static_cast<std::size_t>(t[0])],
                                 x[static_cast<std::size_t>(t[1])],
                                 x[static_cast<std::size_t>(t[2])]);
}

Real ShellElements::current_volume(Index e, const std::vector<Vec3>& x) const {
    const auto ue = static_cast<std::size_t>(e);
    const auto& t = tri_[ue];
    const Vec3& p0 = x[static_cast<std::size_t>(t[0])];
    return 0.5 *
           (x[static_cast<std::size_t>(t[1])] - p0)
               .cross(x[static_cast<std::size_t>(t[2])] - p0)
               .norm() *
           thickness_[ue];
}

Real ShellElements::plastic_strain(Index e, int k) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    const ElementGroup& group = group_of(ue);
    if (group.stress_only()) return 0.0;  // elastic
    const std::size_t nk = group.rule().through.size();
    const GroupPlace place = place_of(ue);
    Real sum = 0;
    std::size_t n = 0;
    for (std::size_t p = static_cast<std::size_t>(k); p < group.n_points(); p += nk, ++n)
        sum += group.plastic_strain(place, p);
    return n > 0 ? sum / static_cast<Real>(n) : 0.0;
}

Real ShellElements::mean_plastic_strain(Index e) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    const ElementGroup& group = group_of(ue);
    if (group.stress_only()) return 0.0;  // elastic
    const ShellRule& rule = group.rule();
    const GroupPlace place = place_of(ue);
    Real sum = 0;  // in-plane weights sum to 1, through-thickness ones to 2
    std::size_t p = 0;
    for (const TrianglePoint& g : rule.inplane)
        for (const ThicknessPoint& k : rule.through)
            sum += 0.5 * g.weight * k.weight * group.plastic_strain(place, p++);
    return sum;
}

Real ShellElements::min_critical_dt(const std::vector<Vec3>& x, Index* where) const {
    Real best = std::numeric_limits<Real>::infinity();
    Index arg = -1;
    for (Index e = 0; e < size(); ++e) {
        if (eroded(e)) continue;  // §7.6: no step of its own
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

void ShellElements::reverse_all_elements(const ParticleState& s, [[maybe_unused]] bool parallel) {
    const Index ne = size();
#pragma omp parallel for schedule(static) if (parallel)
    for (Index e = 0; e < ne; ++e) {
        const std::size_t ue = static_cast<std::size_t>(e);
        reversed_[ue] = reverse_element(ue, s);
        const LocalTriangle<Real>& t = reversed_[ue].local;
        if (!reversed_[ue].checks.within_step_bounds) {  // the run fails at this element
            cst_strain_[ue].setZero();
            continue;
        }
        const std::array<Real, 3> strain =
            cst_strain(cst_gradients(t.x2, t.x3, t.y3, 1.0 / (t.x2 * t.y3)), t.ux, t.uy);  // §3.1
        cst_strain_[ue] = Voigt3(strain[0], strain[1], strain[2]);
    }
}

// Smoothed membrane strain (membrane_smoothing.hpp): the mean of the three side strains, a side
// strain being the area-weighted mean of the CST strains of the two elements there (the
// neighbour's unfolded into this frame), or this element's own on a side without a smooth
// neighbour. Area weights keep the patch test.
ShellElements::SmoothedStrain ShellElements::smoothed_strain(std::size_t ue,
                                                             const LocalTriangle<Real>& rt) const {
    SmoothedStrain sm;
    sm.own_share = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t side = 3 * ue + i;
        const Index n = topology_->side_neighbour[side];
        const LocalTriangle<Real>* rn =
            n >= 0 && reversed_[static_cast<std::size_t>(n)].checks.within_step_bounds
                ? &reversed_[static_cast<std::size_t>(n)].local
                : nullptr;
        if (rn && dot(rn->frame_current.row[2], rt.frame_current.row[2]) >= k_smooth_cosine) {
            // the shared side runs from corner (i+1) to corner (i+2) here, from corner na to
            // corner nb in the neighbour (model/mesh_topology.hpp)
            const int na = topology_->side_neighbour_corner[2 * side];
            const int nb = topology_->side_neighbour_corner[2 * side + 1];
            const int ii = static_cast<int>(i);
            const Real beta = side_angle(rt.x2, rt.x3, rt.y3, (ii + 1) % 3, (ii + 2) % 3) -
                              side_angle(rn->x2, rn->x3, rn->y3, na, nb);
            sm.to_here[i] = strain_rotation(beta);
            const Real w_n = rn->area / (3.0 * (rt.area + rn->area));
            sm.side_weight[i] = w_n;
            sm.own_share += 1.0 / 3.0 - w_n;
            sm.strain += w_n * (sm.to_here[i] * cst_strain_[static_cast<std::size_t>(n)]);
        } else {
            sm.own_share += 1.0 / 3.0;
        }
    }
    sm.strain += sm.own_share * cst_strain_[ue];
    return sm;
}

// The neighbours' share of the membrane forces: A_e w_n B_n^T T^T N, in the neighbour's frame,
// turned forward with it (§5).
void ShellElements::add_neighbour_loads(std::size_t ue, const LocalTriangle<Real>& rt,
                                        const SmoothedStrain& sm,
                                        const Voigt3& membrane_resultant) {
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    Real* slots = assembly_.slots();
    for (std::size_t i = 0; i < 3; ++i) {
        if (sm.side_weight[i] == 0) continue;
        const std::size_t n = static_cast<std::size_t>(topology_->side_neighbour[3 * ue + i]);
        const LocalTriangle<Real>& rn = reversed_[n].local;
        const Voigt3 n_there =
            (rt.area * sm.side_weight[i]) * (sm.to_here[i].transpose() * membrane_resultant);
        const std::array<Real, 6> f_local =
            cst_nodal_forces(cst_gradients(rn.x2, rn.x3, rn.y3, 1.0 / (rn.x2 * rn.y3)),
                             {n_there(0), n_there(1), n_there(2)});  // §3.3
        for (std::size_t k = 0; k < 3; ++k) {
            const V3<Real> f = transpose_times(rn.frame_current,
                                               V3<Real>{f_local[2 * k], f_local[2 * k + 1], 0.0});
            const Index p = tri_[n][static_cast<std::size_t>(k)];
            std::size_t slot = 3 + i;  // the node across side i
            for (std::size_t j = 0; j < 3; ++j)
                if (tri_[ue][j] == p) slot = j;
            const std::size_t at = assembly_.slot_offset(ue, slot);
            for (std::size_t c = 0; c < 3; ++c) slots[at + c * w] += component(f, c);
        }
    }
}

ShellElements::ElementTotals ShellElements::compute_element(Index e, ParticleState& s,
                                                            Real viscous_rate, Real dt) {
    const std::size_t ue = static_cast<std::size_t>(e);
    if (!eroded_.empty() && eroded_[ue]) {  // §7.6: no loads, no step
        ElementTotals totals;
        book_last_half_step(ue, s, totals);
        constexpr auto lanes = static_cast<std::size_t>(k_lanes);
        const std::size_t used =
            assembly_.blocks().block_lane[ue] >= 0 ? 3 : assembly_.slots_per_alone();
        for (std::size_t k = 0; k < used; ++k)
            for (std::size_t c = 0, at = assembly_.slot_offset(ue, k); c < k_slot_components; ++c)
                assembly_.slots()[at + c * lanes] = 0;
        set_resultants(ue, Voigt3::Zero(), Voigt3::Zero());
        return totals;
    }
    const ReversedTriangle rt = smoothed_membrane_ ? reversed_[ue] : reverse_element(ue, s);
    const Real lc = rt.checks.characteristic_length;  // §6.4, once per element and step
    time_steps_.refresh(e, tri_[ue], s.x, lc);
    ElementTotals totals;
    // eq. 6.4-2: the current area A_b = (A_b / A_a) A_a, the thickness of the step's start
    const Real volume = rt.checks.area_ratio * rt.local.area * thickness_[ue];
    totals.dt = time_steps_.scaled_critical_dt(
        e, lc, ElementTimeSteps::volume_factor(time_steps_.initial_volume(ue), volume),
        totals.mass_scaled);
    totals.dt_element = e;
    // the 3 slots across the sides exist (and are gathered) only with the smoothed membrane
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    Real* slots = assembly_.slots();
    const std::size_t used_slots =
        assembly_.blocks().block_lane[ue] >= 0 ? 3 : assembly_.slots_per_alone();
    for (std::size_t k = 0; k < used_slots; ++k)
        for (std::size_t c = 0, at = assembly_.slot_offset(ue, k); c < k_slot_components; ++c)
            slots[at + c * w] = 0;
    // A tilt over 90 deg or an area change by a factor 2 within one step is no deformation a
    // stable step can produce: the run has diverged (theory.md §2.8).
    if (!rt.checks.within_step_bounds) {
        totals.failed = e;
        return totals;
    }
    const SmoothedStrain sm = smoothed_membrane_ ? smoothed_strain(ue, rt.local) : SmoothedStrain{};
    ElementFading fading;  // eq. 7.6-6
    const ShellTriangleLoads loads = groups_[static_cast<std::size_t>(section_[ue])]->element_loads(
        place_of(ue), rt, viscous_rate, dt, thickness_[ue],
        smoothed_membrane_ ? &sm.strain : nullptr, sm.own_share, element_fading(ue, fading));
    keep_element_fading(ue, fading);
    if (thickness_update_) thickness_[ue] *= 1.0 + loads.thickness_strain;  // §3.4
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t at = assembly_.slot_offset(ue, i);
        for (std::size_t c = 0; c < 3; ++c) {
            slots[at + c * w] = loads.force[i](static_cast<Eigen::Index>(c));
            slots[at + (3 + c) * w] = loads.moment[i](static_cast<Eigen::Index>(c));
        }
    }
    if (smoothed_membrane_) add_neighbour_loads(ue, rt.local, sm, loads.membrane_resultant);
    totals.strain_work = loads.strain_work;
    totals.damping_work = loads.damping_work;
    totals.plastic_work = loads.plastic_work;
    set_resultants(ue, loads.membrane_force, loads.bending_moment);
    if (!erosion_.empty()) {  // §7.6
        std::array<Real, 18> corner_loads;
        for (std::size_t i = 0; i < 3; ++i)
            for (Eigen::Index c = 0; c < 3; ++c) {
                corner_loads[6 * i + static_cast<std::size_t>(c)] = loads.force[i](c);
                corner_loads[6 * i + 3 + static_cast<std::size_t>(c)] = loads.moment[i](c);
            }
        check_erosion(ue, loads.strain_work, dt, totals, corner_loads);
    }
    return totals;
}

void ShellElements::ElementTotals::add(const ElementTotals& o) {
    strain_work += o.strain_work;
    damping_work += o.damping_work;
    plastic_work += o.plastic_work;
    mass_scaled += o.mass_scaled;
    eroded += o.eroded;
    eroded_work += o.eroded_work;
    // the lowest-numbered element among equals, as a scan in element order finds
    if (o.dt < dt ||
        (o.dt == dt && o.dt_element >= 0 && (dt_element < 0 || o.dt_element < dt_element))) {
        dt = o.dt;
        dt_element = o.dt_element;
    }
    if (o.failed >= 0 && (failed < 0 || o.failed < failed)) failed = o.failed;
}

Voigt3 ShellElements::resultant(std::size_t e, std::size_t first) const {
    const Index at = assembly_.blocks().block_lane[e];
    if (at < 0) {
        const auto a = static_cast<std::size_t>(assembly_.blocks().alone_position[e]);
        return first == 0 ? membrane_force_[a] : bending_moment_[a];
    }
    const auto b = static_cast<std::size_t>(at) / static_cast<std::size_t>(k_lanes);
    const int l =
        static_cast<int>(static_cast<std::size_t>(at) % static_cast<std::size_t>(k_lanes));
    const RealPack* r = block_resultants_.data() + 6 * kept_block(b) + first;
    return Voigt3(lane(r[0], l), lane(r[1], l), lane(r[2], l));
}

void ShellElements::set_resultants(std::size_t e, const Voigt3& n, const Voigt3& m) {
    const Index at = assembly_.blocks().block_lane[e];
    if (at < 0) {
        const auto a = static_cast<std::size_t>(assembly_.blocks().alone_position[e]);
        membrane_force_[a] = n;
        bending_moment_[a] = m;
        return;
    }
    const auto b = static_cast<std::size_t>(at) / static_cast<std::size_t>(k_lanes);
    const int l =
        static_cast<int>(static_cast<std::size_t>(at) % static_cast<std::size_t>(k_lanes));
    RealPack* r = block_resultants_.data() + 6 * kept_block(b);
    for (Eigen::Index c = 0; c < 3; ++c) {
        set_lane(r[c], l, n(c));
        set_lane(r[3 + c], l, m(c));
    }
}

void ShellElements::compute_block(Index b, ParticleState& s, Real viscous_rate, Real dt,
                                  Real* ring_slots) {
    const ElementBlocks& blocks = assembly_.blocks();
    const Index* ids = blocks.block_elements.data() + static_cast<std::size_t>(b) * k_lanes;
    auto element = [ids](int l) { return static_cast<std::size_t>(ids[l]); };
    const auto g = static_cast<std::size_t>(blocks.block_group[static_cast<std::size_t>(b)]);
    ElementGroup& group = *groups_[g];
    // Gather the lanes (structure of arrays), compute, scatter the valid lanes.
    alignas(64) std::array<Real, k_lanes> buffer;
    auto load = [&](auto&& value) {
        for (int l = 0; l < k_lanes; ++l) buffer[static_cast<std::size_t>(l)] = value(l);
        return RealPack(buffer.data(), stdx::vector_aligned);
    };
    TriangleMotion<RealPack> motion;
    for (std::size_t i = 0; i < 3; ++i) {
        std::array<std::size_t, k_lanes> node;  // corner i of every lane
        for (int l = 0; l < k_lanes; ++l)
            node[static_cast<std::size_t>(l)] = static_cast<std::size_t>(tri_[element(l)][i]);
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
    const RealPack thickness = thickness_update_
                                   ? load([&](int l) { return thickness_[element(l)]; })
                                   : RealPack(group.rule().thickness);
    StressFading<RealPack> fading;  // eq. 7.6-6
    const ElasticTriangleLoads<RealPack> loads =
        group.block_loads(static_cast<std::size_t>(b - blocks.group_first_block[g]), motion,
                          thickness, viscous_rate, dt, block_fading(b, fading));
    // the corner loads, 6 whole packs per corner, into the ring and (kept or without a ring)
    // into the full slot array; an invalid lane's are rewritten below by the general code
    constexpr auto w = static_cast<std::size_t>(k_lanes);
    Real* full_slots = assembly_.block_slots(b);
    auto store = [&](Real* slots) {
        for (std::size_t i = 0; i < 3; ++i) {
            const std::array<const RealPack*, k_slot_components> component{
                &loads.force[i].x,  &loads.force[i].y,  &loads.force[i].z,
                &loads.moment[i].x, &loads.moment[i].y, &loads.moment[i].z};
            for (std::size_t c = 0; c < k_slot_components; ++c)
                component[c]->copy_to(slots + (i * k_slot_components + c) * w,
                                      stdx::element_aligned);
        }
    };
    if (!ring_slots || assembly_.plan().keep[static_cast<std::size_t>(b)]) store(full_slots);
    if (ring_slots) store(ring_slots);
    // N and M, whole packs (an invalid lane's are rewritten below by the general code)
    RealPack* resultants = block_resultants_.data() + 6 * kept_block(static_cast<std::size_t>(b));
    for (std::size_t r = 0; r < 3; ++r) {
        resultants[r] = loads.membrane_force[r];
        resultants[3 + r] = loads.bending_moment[r];
    }
    // eq. 6.4-2 for the whole block at once, with the thickness of the step's start (as
    // compute_element): a division and a square root only where a lane's volume has grown
    const RealPack volume = loads.current_area * thickness;
    const RealPack& initial_volume = block_initial_volume_[kept_block(static_cast<std::size_t>(b))];
    const RealPack volume_factor = any_lane(volume > initial_volume)
                                       ? ElementTimeSteps::volume_factor(initial_volume, volume)
                                       : RealPack(1.0);
    // §7.6: the failure criteria of the whole block at once (a lane left to the general code
    // is judged there)
    std::array<bool, k_lanes> verdicts{};
    const bool judged = !erosion_.empty() && judge_block(b, dt, verdicts);
    // the block's totals, lane by lane in lane order
    ElementTotals totals;
    for (int l = 0; l < k_lanes; ++l) {
        const std::size_t ue = element(l);
        if (!eroded_.empty() && eroded_[ue]) {  // §7.6: its slots and resultants zero
            ElementTotals t;
            book_last_half_step(ue, s, t);
            totals.add(t);
            const auto ul = static_cast<std::size_t>(l);
            for (std::size_t k = 0; k < 3 * k_slot_components; ++k) {
                full_slots[k * w + ul] = 0;
                if (ring_slots) ring_slots[k * w + ul] = 0;
            }
            for (std::size_t r = 0; r < 6; ++r) set_lane(resultants[r], l, 0.0);
            continue;
        }
        if (!lane(loads.valid, l)) {  // outside the block kernel's bounds: the general code
            totals.add(compute_element(static_cast<Index>(ue), s, viscous_rate, dt));
            // (which writes the full slot array; the ring takes a copy of the lane)
            if (ring_slots)
                for (std::size_t k = 0; k < 3 * k_slot_components; ++k)
                    ring_slots[k * w + static_cast<std::size_t>(l)] =
                        full_slots[k * w + static_cast<std::size_t>(l)];
            continue;
        }
        const Real lc = lane(loads.characteristic_length, l);
        time_steps_.refresh(static_cast<Index>(ue), tri_[ue], s.x, lc);
        if (thickness_update_) thickness_[ue] *= 1.0 + lane(loads.thickness_strain, l);  // §3.4
        ElementTotals t;
        t.strain_work = lane(loads.strain_work, l);
        t.damping_work = lane(loads.damping_work, l);
        t.plastic_work = lane(loads.plastic_work, l);
        t.dt = time_steps_.scaled_critical_dt(static_cast<Index>(ue), lc, lane(volume_factor, l),
                                              t.mass_scaled);
        t.dt_element = static_cast<Index>(ue);
        if (!erosion_.empty()) {  // §7.6
            std::array<Real, 18> corner_loads;
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t k = 0; k < 2; ++k) {
                    const V3<RealPack>& v = k == 0 ? loads.force[i] : loads.moment[i];
                    corner_loads[6 * i + 3 * k] = lane(v.x, l);
                    corner_loads[6 * i + 3 * k + 1] = lane(v.y, l);
                    corner_loads[6 * i + 3 * k + 2] = lane(v.z, l);
                }
            check_erosion(ue, t.strain_work, dt, t, corner_loads,
                          judged ? &verdicts[static_cast<std::size_t>(l)] : nullptr);
        }
        totals.add(t);
    }
    block_totals_[kept_block(static_cast<std::size_t>(b))] = totals;
}

ShellElements::StepTotals ShellElements::compute(ParticleState& s, Real viscous_rate, Real dt) {
    const Index ne = size();
    // Small models stay serial: a parallel region per step costs more than it saves there.
    [[maybe_unused]] const bool parallel = ne >= k_parallel_min_elements;
    // Phase 0 (smoothed membrane only): every element's path element and CST strain increment.
    if (smoothed_membrane_) reverse_all_elements(s, parallel);
    // Phase 1: every triangle writes its corner loads (and, smoothed, the loads on the nodes
    // across its sides) into its own slots: the elastic blocks k_lanes elements at a time
    // (elements/elastic_triangle_block.hpp), the other elements one by one. Phase 2: every
    // particle sums its slots in element order (bitwise thread-independent): as soon as its
    // last block is done where the plan allows (from the ring, still in the cache), the others
    // after the loop (slot_gather_plan.hpp).
    const ElementBlocks& blocks = assembly_.blocks();
    const Index n_scalar = blocks.n_alone();
    // A distributed run (DomainDecomposition): this rank's units only. First the blocks at its
    // shared particles and its elements alone, whose slots then travel to the other ranks
    // while the interior blocks compute; their particles sum after the loop.
    const bool distributed = decomposition_ && decomposition_->distributed();
    const std::uint8_t* not_in_ring_loop = distributed ? not_in_ring_loop_.data() : nullptr;
    // (made at construction; remade only if the thread count has changed since)
    const SlotGatherPlan& plan = assembly_.plan(gather_ranges());
    Communicator::Pending slots_in_flight;
    if (distributed) {
        const DomainDecomposition& d = *decomposition_;
        const auto n_first = static_cast<Index>(d.boundary_blocks.size());
        const auto n_own_alone = static_cast<Index>(d.own_alone.size());
#pragma omp parallel if (parallel)
        {
#pragma omp for schedule(static) nowait
            for (Index i = 0; i < n_first; ++i)
                compute_block(d.boundary_blocks[static_cast<std::size_t>(i)], s, viscous_rate, dt,
                              nullptr);
#pragma omp for schedule(static)
            for (Index i = 0; i < n_own_alone; ++i) {
                const auto at = static_cast<std::size_t>(d.own_alone[static_cast<std::size_t>(i)]);
                alone_totals_[at] = compute_element(blocks.alone_elements[at], s, viscous_rate, dt);
            }
        }
        slots_in_flight = start_slot_exchange();
    }
    constexpr Index tile = SlotGatherPlan::k_tile_blocks,
                    ring_blocks = SlotGatherPlan::k_ring_blocks;
    // ranges of equal time rather than equal counts (range_balancer.hpp): tiles timed
    const bool balance = parallel && plan.ranges() > 1;
    using Clock = std::chrono::steady_clock;
#pragma omp parallel if (parallel)
    {
        // one range per thread (any team size gives the same sums: a range is a unit of work)
#pragma omp for schedule(static, 1) nowait
        for (int r = 0; r < plan.ranges(); ++r) {
            const auto ur = static_cast<std::size_t>(r);
            Real* ring = plan.use_ring() ? assembly_.ring(ur) : nullptr;
            const Index first = plan.range_begin[ur], end = plan.range_begin[ur + 1];
            for (Index t = plan.range_first_tile[ur]; t < plan.range_first_tile[ur + 1]; ++t) {
                const Index from = first + (t - plan.range_first_tile[ur]) * tile;
                const Clock::time_point start = balance ? Clock::now() : Clock::time_point{};
                for (Index b = from; b < std::min(end, from + tile); ++b)
                    if (!not_in_ring_loop || !not_in_ring_loop[b])
                        compute_block(
                            b, s, viscous_rate, dt,
                            ring ? ring + static_cast<std::size_t>((b - first) % ring_blocks) *
                                              SlotGatherPlan::k_block_reals
                                 : nullptr);
                for (Index k = plan.ready_begin[static_cast<std::size_t>(t)];
                     k < plan.ready_begin[static_cast<std::size_t>(t) + 1]; ++k)
                    assembly_.gather_particle(
                        static_cast<std::size_t>(plan.ready[static_cast<std::size_t>(k)]), ring, s);
                if (balance)
                    balancer_.record(from, std::min(end, from + tile),
                                     std::chrono::duration<double>(Clock::now() - start).count());
            }
        }
#pragma omp for schedule(static)
        for (Index i = 0; i < (distributed ? 0 : n_scalar); ++i)
            alone_totals_[static_cast<std::size_t>(i)] = compute_element(
                blocks.alone_elements[static_cast<std::size_t>(i)], s, viscous_rate, dt);
    }
    // every slot is written; in a distributed run, those of the shared particles from the
    // other ranks too (they are summed after the loop, from the full array)
    if (distributed) finish_slot_exchange(slots_in_flight);
#pragma omp parallel for schedule(static) if (parallel)
    for (Index k = 0; k < static_cast<Index>(plan.after.size()); ++k)
        assembly_.gather_particle(static_cast<std::size_t>(plan.after[static_cast<std::size_t>(k)]),
                                  assembly_.slots(), s);
    if (balance)
        if (std::optional<std::vector<Index>> ranges = balancer_.next_ranges(plan.range_begin))
            assembly_.set_ranges(*ranges);  // (plan, a reference to the old one, is not read again)
    return step_totals();
}

// Totals atom by atom (DomainDecomposition: k_atom_units consecutive units, summed in unit
// order), the atoms' works added exactly, then over the ranks: the same bits for any number
// of threads and ranks.
ShellElements::StepTotals ShellElements::step_totals() {
    const Index n_blocks = assembly_.blocks().n_blocks();
    const Index n_units = n_blocks + assembly_.blocks().n_alone();
    const bool distributed = decomposition_ && decomposition_->distributed();
    const Index n_atoms = distributed ? static_cast<Index>(decomposition_->own_atoms.size())
                                      : (n_units + k_atom_units - 1) / k_atom_units;
    ExactSum works[5];    // strain, damping, plastic work; the eroded elements' work and count
    ElementTotals least;  // the smallest step, the first failure, the scaled elements
    for (Index i = 0; i < n_atoms; ++i) {
        const Index a = distributed ? decomposition_->own_atoms[static_cast<std::size_t>(i)] : i;
        if (a * k_atom_units >= n_units) continue;  // the atom of the particles of no element
        ElementTotals t;
        for (Index u = a * k_atom_units; u < std::min(n_units, (a + 1) * k_atom_units); ++u)
            t.add(u < n_blocks ? block_totals_[kept_block(static_cast<std::size_t>(u))]
                               : alone_totals_[static_cast<std::size_t>(u - n_blocks)]);
        works[0].add(t.strain_work);
        works[1].add(t.damping_work);
        works[2].add(t.plastic_work);
        works[3].add(t.eroded_work);
        works[4].add(static_cast<Real>(t.eroded));
        t.strain_work = t.damping_work = t.plastic_work = t.eroded_work = 0;
        t.eroded = 0;
        least.add(t);
    }
    StepTotals tot;
    const Communicator& comm = Communicator::world();
    if (distributed) {
        comm.sum(works);
        std::tie(least.dt, least.dt_element) = comm.min_loc(least.dt, least.dt_element);
        least.failed = comm.min_loc(least.failed >= 0 ? 0.0 : 1.0, least.failed).second;
        least.mass_scaled = static_cast<Index>(comm.max(least.mass_scaled));
    }
    tot.strain_work = works[0].value();
    tot.damping_work = works[1].value();
    tot.plastic_work = works[2].value();
    tot.eroded_work = works[3].value();
    tot.eroded_elements = static_cast<Index>(works[4].value());
    tot.min_dt = least.dt;
    tot.min_dt_element = least.dt_element;
    tot.failed_element = least.failed;
    tot.mass_scaled = least.mass_scaled;
    return tot;
}

}  // namespace fpmshell
