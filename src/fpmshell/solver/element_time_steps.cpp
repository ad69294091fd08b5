#include "fpmshell/solver/element_time_steps.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "fpmshell/elements/bending_time_step.hpp"
#include "fpmshell/elements/membrane_time_step.hpp"
#include "fpmshell/elements/path_element.hpp"
#include "fpmshell/elements/triangle_shape.hpp"

namespace fpmshell {
namespace {

/// Models below this many elements (or shape classes) are set up serially (read by the OpenMP
/// pragmas only: unused in a build without OpenMP).
[[maybe_unused]] constexpr Index k_parallel_min_elements = 2000;

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
    return static_cast<std::int64_t>((std::bit_cast<std::uint64_t>(v) + (std::uint64_t{1} << 19)) >>
                                     20);
}

std::array<Vec3, 3> corners_of(const std::array<Index, 3>& t, const std::vector<Vec3>& x) {
    return {x[static_cast<std::size_t>(t[0])], x[static_cast<std::size_t>(t[1])],
            x[static_cast<std::size_t>(t[2])]};
}

}  // namespace

Real characteristic_length(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    return characteristic_length(to_v3(p0), to_v3(p1), to_v3(p2));  // path_element.hpp, §6.4
}

ElementTimeSteps::ElementTimeSteps(const Model& model, const MeshTopology& topology,
                                   std::vector<Real> wave_speed, std::vector<Mat3> bending_rigidity)
    : section_(model.element_section),
      wave_speed_(std::move(wave_speed)),
      bending_rigidity_(std::move(bending_rigidity)),
      node_mass_(topology.element_node_mass),
      node_inertia_(topology.element_node_inertia),
      bending_kernel_(model.control.bending),
      stiffness_damping_(model.damping.stiffness) {
    for (const Section& sec : model.sections) {
        const Material& mat = model.materials[static_cast<std::size_t>(sec.material)];
        rigid_section_.push_back(mat.rigid ? 1 : 0);
        exact_membrane_.push_back(mat.failure.active() && mat.failure.separates ? 1 : 0);
    }
    // eq. 6.4-3: the elements of a piece of one or two (joined by their sides)
    exact_element_.assign(model.triangles.size(), 0);
    const auto live = [](Index) { return true; };
    for (std::size_t e = 0; e < model.triangles.size(); ++e)
        if (in_small_piece(topology.side_neighbour, static_cast<Index>(e), live))
            exact_element_[e] = 1;
    initial_volume_.resize(model.triangles.size());
    for (std::size_t e = 0; e < model.triangles.size(); ++e) {
        const auto [p0, p1, p2] = corners_of(model.triangles[e], model.nodes);
        initial_volume_[e] = 0.5 * (p1 - p0).cross(p2 - p0).norm() *
                             model.sections[static_cast<std::size_t>(section_[e])].thickness;
    }
    share_initial_ratios(model);
}

// The step ratio needs a 9 x 9 eigenproblem per element where h / L_c is near 1
// (nearly all the set-up's time on a fine mesh). It depends on the section and the local
// shape only, and the elements of a structured mesh come in a few shapes: it is computed
// once per section and shape class (local coordinates equal to 2^-32 relative, far below
// the 5 % drift the ratio is allowed before it is re-evaluated), for the lowest-numbered
// element of the class, and shared by the others.
void ElementTimeSteps::share_initial_ratios(const Model& model) {
    const std::size_t ne = model.triangles.size();
    step_ratio_.assign(ne, 1.0);
    ratio_lc_.assign(ne, 0.0);
    std::vector<std::array<std::int64_t, 4>> shape_key(ne);
    std::vector<Real> initial_lc(ne);
#pragma omp parallel for schedule(static) if (static_cast <Index>(ne) >= k_parallel_min_elements)
    for (std::size_t e = 0; e < ne; ++e) {
        const auto [p0, p1, p2] = corners_of(model.triangles[e], model.nodes);
        initial_lc[e] = characteristic_length(p0, p1, p2);
        const TriangleShape shape = local_shape(p0, p1, p2);
        shape_key[e] = {2 * section_[e] + exact_element_[e], shape_class(shape.x[1]),
                        shape_class(shape.x[2]), shape_class(shape.y[2])};
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
        if (i == 0 || shape_key[static_cast<std::size_t>(by_shape[i])] !=
                          shape_key[static_cast<std::size_t>(by_shape[i - 1])])
            class_begin.push_back(i);
    class_begin.push_back(by_shape.size());
    const auto n_classes = static_cast<Index>(class_begin.size()) - 1;
#pragma omp parallel for schedule(dynamic, 64) if (n_classes >= k_parallel_min_elements)
    for (Index c = 0; c < n_classes; ++c) {
        const auto first = class_begin[static_cast<std::size_t>(c)],
                   end = class_begin[static_cast<std::size_t>(c) + 1];
        const Index lead = by_shape[first];
        const Real ratio = step_ratio(
            lead, corners_of(model.triangles[static_cast<std::size_t>(lead)], model.nodes));
        for (std::size_t i = first; i < end; ++i) {
            const auto e = static_cast<std::size_t>(by_shape[i]);
            step_ratio_[e] = ratio;
            ratio_lc_[e] = initial_lc[e];
        }
    }
}

Real ElementTimeSteps::step_ratio(Index e, const std::array<Vec3, 3>& corners) const {
    const std::size_t ue = static_cast<std::size_t>(e);
    const auto& [p0, p1, p2] = corners;
    const std::size_t sec = static_cast<std::size_t>(section_[ue]);
    Real membrane_dt = characteristic_length(p0, p1, p2) / wave_speed_[sec];
    if (!mass_scale_.empty()) membrane_dt *= mass_scale_[ue];  // §6.10, as node_mass_
    // only min(1, bending_dt / membrane_dt) is used (critical_dt): a bound suffices where the
    // bending modes are surely slower than the membrane
    const TriangleShape shape = local_shape(p0, p1, p2);
    const Real bending_dt = bending_critical_dt(bending_kernel_, shape, bending_rigidity_[sec],
                                                node_mass_[ue], node_inertia_[ue], membrane_dt);
    const Real ratio = membrane_dt > 0 ? bending_dt / membrane_dt : 1.0;
    // eq. 6.4-3: the ratio of the exact membrane step does not depend on the mass scaling (the
    // mass and L_c / c both scale by f_e)
    if (exact_membrane(e))
        return std::min(ratio, membrane_step_ratio(shape, bending_rigidity_[sec]));
    return ratio;
}

void ElementTimeSteps::reevaluate(Index e, const std::array<Index, 3>& t,
                                  const std::vector<Vec3>& x, Real lc) {
    const std::size_t ue = static_cast<std::size_t>(e);
    step_ratio_[ue] = step_ratio(e, corners_of(t, x));
    ratio_lc_[ue] = lc;
}

void ElementTimeSteps::take_exact_membrane(Index e, const std::array<Index, 3>& t,
                                           const std::vector<Vec3>& x) {
    mark_exact_membrane(e);
    const auto [p0, p1, p2] = corners_of(t, x);
    reevaluate(e, t, x, characteristic_length(p0, p1, p2));
}

// §6.10 eq. 6.10a: with the stiffness damping a_s of §6.4 the critical step is
// sqrt(dt^2 + a_s^2) - a_s for the undamped step dt, so the undamped step that reaches `step`
// is sqrt((step + a_s)^2 - a_s^2); the undamped step grows by sqrt(f_e).
Real ElementTimeSteps::undamped_target(Real step) const {
    const Real a = stiffness_damping_;
    return std::sqrt((step + a) * (step + a) - a * a);
}

std::vector<Real> ElementTimeSteps::mass_scaling_factors(
    Real step, const std::vector<std::array<Index, 3>>& triangles,
    const std::vector<Vec3>& x) const {
    const Real needed = undamped_target(step);
    std::vector<Real> factor(triangles.size(), 1.0);
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const auto [p0, p1, p2] = corners_of(triangles[e], x);
        // at the set-up's positions every element has its initial volume
        const Real dt = undamped_dt(static_cast<Index>(e), characteristic_length(p0, p1, p2), 1.0);
        if (dt > 0 && dt < needed) factor[e] = (needed / dt) * (needed / dt);
    }
    return factor;
}

void ElementTimeSteps::enable_run_scaling(Real step) {
    run_target_ = undamped_target(step);
    pending_.assign(section_.size(), 0.0);
    if (mass_scale_.empty()) mass_scale_.assign(section_.size(), 1.0);
}

std::vector<ElementTimeSteps::CornerAddition> ElementTimeSteps::take_pending_scaling() {
    std::vector<CornerAddition> added;
    for (std::size_t e = 0; e < pending_.size(); ++e) {
        const Real f = pending_[e];
        if (f == 0) continue;
        pending_[e] = 0;
        added.push_back(
            {static_cast<Index>(e), node_mass_[e] * (f - 1.0), node_inertia_[e] * (f - 1.0)});
        scale_element(e, f);
    }
    return added;
}

void ElementTimeSteps::scale_masses(const std::vector<Real>& factor) {
    if (mass_scale_.empty()) mass_scale_.assign(factor.size(), 1.0);
    for (std::size_t e = 0; e < factor.size(); ++e) scale_element(e, factor[e]);
}

void ElementTimeSteps::scale_element(std::size_t e, Real f) {
    node_mass_[e] *= f;
    node_inertia_[e] *= f;
    mass_scale_[e] *= std::sqrt(f);
}

}  // namespace fpmshell
