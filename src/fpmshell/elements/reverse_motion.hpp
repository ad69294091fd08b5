// The path element of the general element (theory.md §2): path_element.hpp with the rotations
// for any angle, on one element given in the Eigen types of the solver and the tests.
#pragma once

#include <array>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/path_element.hpp"

namespace fpmshell {

/// The path element in its local frame and its checks (§2.8: the solver treats an element
/// outside checks.within_step_bounds as a diverged run).
struct ReversedTriangle {
    LocalTriangle<Real> local{};
    PathElementChecks<Real> checks{};
};

/// The drill axes of three nodes whose rotation increments are complete (kinks, prescribed
/// rotations, or a single element's test): none.
inline const std::array<Vec3, 3> k_no_drill_axes{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};

/// Reverse motion of one triangle (§2.1-§2.7). base: node positions at t_{n-1}; current: at
/// t_n; dtheta: nodal rotation increments (global rotation vectors) over the step;
/// drill_axis: per node, as TriangleMotion's.
[[nodiscard]] ReversedTriangle reverse_motion(const std::array<Vec3, 3>& base,
                                              const std::array<Vec3, 3>& current,
                                              const std::array<Vec3, 3>& dtheta,
                                              const std::array<Vec3, 3>& drill_axis);

}  // namespace fpmshell
