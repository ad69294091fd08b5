// Erosion in the element loop (theory.md §7.6): which elements have eroded, the booking of
// their work, and the check after each element's step.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fpmshell/core/kept_places.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace fpmshell {

void ShellElements::init_erosion(const Model& model) {
    const std::size_t ne = tri_.size();
    bool can_fail = false, has_state = false, separates = false;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
        const Material& mat = model.materials[static_cast<std::size_t>(model.sections[g].material)];
        const ShellRule& rule = groups_[g]->rule();
        erosion_.emplace_back(mat, static_cast<int>(rule.inplane.size()),
                              static_cast<int>(rule.through.size()));
        // compared with the elements' unscaled critical steps, as set_erosion_step's
        material_erosion_step_.push_back(erosion_.back().minimum_step() /
                                         model.control.time_step_scale);
        can_fail = can_fail || erosion_.back().active();
        has_state = has_state || erosion_.back().fields() > 0;
        separates = separates || erosion_.back().separates();
    }
    // or with control.minimum_time_step's erode: any element may erode (set_erosion_step)
    can_fail = can_fail || model_can_erode(model);
    if (!can_fail) {
        erosion_.clear();
        material_erosion_step_.clear();
        return;
    }
    eroded_.assign(ne, 0);
    gone_.assign(ne, 0);
    if (separates) cracked_.assign(ne, 0);
    element_work_.assign(ne, 0.0);
    last_loads_.assign(ne, std::array<Real, 18>{});
    element_size_.resize(ne);
    for (std::size_t e = 0; e < ne; ++e) {  // sqrt(2 A_0): a square's side for either half
        const auto& t = tri_[e];
        const Vec3& a = model.nodes[static_cast<std::size_t>(t[0])];
        const Vec3 n = (model.nodes[static_cast<std::size_t>(t[1])] - a)
                           .cross(model.nodes[static_cast<std::size_t>(t[2])] - a);
        element_size_[e] = std::sqrt(n.norm());
    }
    keeps_failure_state_ = has_state;
}

void ShellElements::allocate_failure_state() {
    if (!keeps_failure_state_) return;
    // the blocks' state first, block by block, then the elements computed alone: of the units
    // this rank computes (the others' elements are never judged here)
    const ElementBlocks& blocks = assembly_.blocks();
    failure_state_at_.assign(tri_.size(), k_not_kept);
    std::size_t packs = 0;
    for (std::size_t b = 0; b < blocks.block_group.size(); ++b) {
        if (!computes_unit(b)) continue;
        for (int l = 0; l < k_lanes; ++l)
            failure_state_at_[static_cast<std::size_t>(
                blocks.block_elements[b * static_cast<std::size_t>(k_lanes) +
                                      static_cast<std::size_t>(l)])] = packs;
        packs += erosion_[static_cast<std::size_t>(blocks.block_group[b])].block_state_packs();
    }
    for (std::size_t a = 0; a < blocks.alone_elements.size(); ++a) {
        if (!computes_unit(blocks.block_group.size() + a)) continue;
        const auto e = static_cast<std::size_t>(blocks.alone_elements[a]);
        failure_state_at_[e] = packs;
        packs += erosion_[static_cast<std::size_t>(section_[e])].alone_state_packs();
    }
    failure_state_.assign(packs, RealPack(0.0));
}

Real& ShellElements::failure_number(std::size_t e, std::size_t i) {
    const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
    const std::size_t n = rule.n_points(), f = i / n, p = i % n;
    RealPack* base = failure_state_.data() + failure_state_at_[e];
    const GroupPlace place = place_of(e);
    Real* lanes;
    int l;
    if (place.in_block) {  // [number][point], a lane per element
        lanes = reinterpret_cast<Real*>(base + f * n + p);
        l = static_cast<int>(place.index % static_cast<std::size_t>(k_lanes));
    } else {  // [number][pack of points]
        const auto w = static_cast<std::size_t>(k_lanes);
        lanes = reinterpret_cast<Real*>(base + f * rule.point_packs() + p / w);
        l = static_cast<int>(p % w);
    }
    return lanes[l];
}

bool ShellElements::judge_block(Index b, Real dt, std::array<bool, k_lanes>& erodes) {
    const ElementBlocks& blocks = assembly_.blocks();
    const auto g = static_cast<std::size_t>(blocks.block_group[static_cast<std::size_t>(b)]);
    const ElementErosion& rule = erosion_[g];
    erodes.fill(false);
    if (!rule.active()) return true;
    FailurePacks in =
        groups_[g]->block_failure_packs(static_cast<std::size_t>(b - blocks.group_first_block[g]));
    if (in.m == 0) return false;
    in.element_size = block_element_size_[kept_block(static_cast<std::size_t>(b))];
    in.time = time_;
    const std::size_t first =
        blocks.block_elements[static_cast<std::size_t>(b) * static_cast<std::size_t>(k_lanes)];
    RealPack* state =
        !keeps_failure_state_ ? nullptr : failure_state_.data() + failure_state_at_[first];
    rule.judge_block(in, dt, state, erodes);
    return true;
}

const StressFading<RealPack>* ShellElements::block_fading(Index b, StressFading<RealPack>& out) {
    if (!keeps_failure_state_) return nullptr;
    const ElementBlocks& blocks = assembly_.blocks();
    const ElementErosion& rule =
        erosion_[static_cast<std::size_t>(blocks.block_group[static_cast<std::size_t>(b)])];
    const std::size_t f = rule.fading_field(), n = rule.n_points();
    if (f == PointFailure::k_no_field) return nullptr;
    RealPack* state =
        failure_state_.data() +
        failure_state_at_[static_cast<std::size_t>(
            blocks
                .block_elements[static_cast<std::size_t>(b) * static_cast<std::size_t>(k_lanes)])];
    out = {state + f * n, state + (f + 1) * n};  // [number][point], a lane per element
    return &out;
}

const StressFading<Real>* ShellElements::element_fading(std::size_t e, ElementFading& f) {
    if (!keeps_failure_state_) return nullptr;
    const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
    const std::size_t field = rule.fading_field(), n = rule.n_points();
    if (field == PointFailure::k_no_field) return nullptr;
    for (std::size_t p = 0; p < n; ++p) {
        f.next[p] = failure_number(e, field * n + p);
        f.applied[p] = failure_number(e, (field + 1) * n + p);
    }
    f.view = {f.next.data(), f.applied.data()};
    return &f.view;
}

void ShellElements::keep_element_fading(std::size_t e, const ElementFading& f) {
    if (!f.view.applied) return;
    const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
    const std::size_t n = rule.n_points();
    for (std::size_t p = 0; p < n; ++p)
        failure_number(e, (rule.fading_field() + 1) * n + p) = f.applied[p];
}

std::vector<Index> ShellElements::eroded_in_last_step() const {
    std::vector<Index> out;
    for (std::size_t e = 0; e < eroded_.size(); ++e)
        if (eroded_[e] == k_eroded_pending) out.push_back(static_cast<Index>(e));
    return out;
}

std::vector<Index> ShellElements::failed_unopened() const {
    std::vector<Index> out;
    for (std::size_t e = 0; e < cracked_.size(); ++e)
        if (cracked_[e] == k_failed) out.push_back(static_cast<Index>(e));
    return out;
}

std::vector<Index> ShellElements::eroded_so_far() const {
    std::vector<Index> out;
    for (std::size_t e = 0; e < eroded_.size(); ++e)
        if (eroded_[e] != 0) out.push_back(static_cast<Index>(e));
    return out;
}

void ShellElements::steady_small_pieces(const std::vector<Index>& eroded,
                                        const std::vector<Vec3>& x) {
    for (const Index e : eroded) gone_[static_cast<std::size_t>(e)] = 1;
    const auto live = [&](Index f) { return !gone(f); };
    const std::vector<Index>& sides = topology_->side_neighbour;
    const auto take = [&](Index f) {
        if (!time_steps_.exact_membrane(f))
            time_steps_.take_exact_membrane(f, tri_[static_cast<std::size_t>(f)], x);
    };
    for (const Index e : eroded)  // eroded is sorted: the same order on every rank
        for (std::size_t i = 0; i < 3; ++i) {
            const Index f = sides[3 * static_cast<std::size_t>(e) + i];
            if (f < 0 || !live(f) || !in_small_piece(sides, f, live)) continue;
            take(f);
            for (std::size_t k = 0; k < 3; ++k)  // its partner in a piece of two
                if (const Index g = sides[3 * static_cast<std::size_t>(f) + k]; g >= 0 && live(g))
                    take(g);
        }
}

void ShellElements::mark_small_pieces(const std::vector<Index>& eroded) {
    if (gone_.empty()) return;
    for (const Index e : eroded) gone_[static_cast<std::size_t>(e)] = 1;
    const auto live = [&](Index f) { return !gone(f); };
    for (std::size_t f = 0; f < gone_.size(); ++f)
        if (gone_[f] == 0 && in_small_piece(topology_->side_neighbour, static_cast<Index>(f), live))
            time_steps_.mark_exact_membrane(static_cast<Index>(f));
}

// The loads of the step an element erodes in stand (the particles take them over the next
// half step); the element's work over that half step, 1/2 f . dx + 1/2 m . dtheta (the second
// half of the trapezoid eq. 6.8-1 books for its loads), is booked one step later from them.
void ShellElements::book_last_half_step(std::size_t e, const ParticleState& s, ElementTotals& t) {
    if (eroded_[e] != k_eroded_pending) return;
    const std::array<Real, 18>& loads = last_loads_[e];
    Real work = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto p = static_cast<std::size_t>(tri_[e][i]);
        const Vec3 dx = s.x[p] - s.x_prev[p];
        for (std::size_t c = 0; c < 3; ++c)
            work += loads[6 * i + c] * dx(static_cast<Eigen::Index>(c)) +
                    loads[6 * i + 3 + c] * s.dtheta[p](static_cast<Eigen::Index>(c));
    }
    t.strain_work += 0.5 * work;
    t.eroded_work += 0.5 * work;
    eroded_[e] = k_eroded;
}

void ShellElements::check_erosion(std::size_t e, Real work, Real dt, ElementTotals& t,
                                  const std::array<Real, 18>& loads, const bool* verdict) {
    const auto section = static_cast<std::size_t>(section_[e]);
    const ElementErosion& rule = erosion_[section];
    // control.minimum_time_step's with erode, or its material's (LS-DYNA's TDEL)
    const Real floor = std::max(erosion_step_, material_erosion_step_[section]);
    if (!rule.active() && !(floor > 0)) return;
    element_work_[e] += work;  // (of every element where any may erode below the step)
    if (t.dt < floor) {        // it erodes, whatever its points
        t.dt = std::numeric_limits<Real>::infinity();  // and no longer sets the step
        t.dt_element = -1;
    } else {
        if (!rule.active()) return;
        if (rule.separates() && cracked_[e] != 0) return;  // §7.7: failed before
        if (verdict ? !*verdict : !erodes_alone(e, dt)) return;
        if (rule.separates()) {  // §7.7: it keeps acting, and opens an edge
            cracked_[e] = k_failed;
            return;
        }
    }
    eroded_[e] = k_eroded_pending;  // from the next step on (this step's loads stand)
    last_loads_[e] = loads;
    ++t.eroded;
    t.eroded_work += element_work_[e];
}

// One element's criteria, its points a pack at a time: its state in place where it is computed
// alone, a copy of its lane of its block's where the block kernel left it to the general code.
bool ShellElements::erodes_alone(std::size_t e, Real dt) {
    const ElementErosion& rule = erosion_[static_cast<std::size_t>(section_[e])];
    const ElementGroup& group = group_of(e);
    const GroupPlace place = place_of(e);
    const auto fill = [&](ElementFailurePoints& points) {
        group.failure_points(place, rule.reads_point(), points);
    };
    const Real size = element_size_[e];
    if (!keeps_failure_state_) return rule.erodes(fill, dt, nullptr, size, time_);
    if (!place.in_block)
        return rule.erodes(fill, dt, failure_state_.data() + failure_state_at_[e], size, time_);
    const std::size_t n = rule.n_points(), w = static_cast<std::size_t>(k_lanes);
    std::vector<RealPack> state(rule.alone_state_packs(), RealPack(0.0));
    for (std::size_t i = 0; i < rule.fields() * n; ++i)
        set_lane(state[i / n * rule.point_packs() + i % n / w], static_cast<int>(i % n % w),
                 failure_number(e, i));
    const bool erodes = rule.erodes(fill, dt, state.data(), size, time_);
    for (std::size_t i = 0; i < rule.fields() * n; ++i)
        failure_number(e, i) =
            lane(state[i / n * rule.point_packs() + i % n / w], static_cast<int>(i % n % w));
    return erodes;
}

}  // namespace fpmshell
