// Fictitious reverse motion of a triangular path element (theory.md §2): removes the rigid
// translation, out-of-plane and in-plane rotation between the base configuration (t_{n-1}) and
// the current one (t_n), leaving the pure deformation displacements and rotations in the
// element deformation frame of the base configuration.
#pragma once

#include <array>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Result of the reverse motion. Local frame: node 1 at the origin, edge 1->2 along x (§2.5).
struct ReversedTriangle {
    Real x2 = 0, x3 = 0, y3 = 0;  ///< base local coordinates (x1 = y1 = y2 = 0), y3 > 0
    Real area = 0;                ///< A_a, base area
    std::array<Vec2, 3> u;        ///< deformation displacements (u_1 = 0), §2.4
    std::array<Vec2, 3> theta;    ///< deformation rotations [theta_x, theta_y], §2.6
    std::array<Vec3, 3> drill_local{
        Vec3::Zero(), Vec3::Zero(),
        Vec3::Zero()};   ///< the nodes' drill axes in the local frame (§4.6, eq. 4.6b)
    Mat3 frame_current;  ///< T_t (rows x_t, y_t, z_t): local -> global is T_t^T, §2.7
    Real normal_cosine =
        1;  ///< n_a . n: the solver treats < 0 (a tilt over 90 deg in one step) as a failure
    Real area_ratio = 1;      ///< current / base area: far from 1 within one step = divergence
    bool degenerate = false;  ///< zero-area base or current triangle (§2.8)
};

/// The drill axes of three nodes whose rotation increments are complete (kinks, prescribed
/// rotations, or a single element's test): none.
inline const std::array<Vec3, 3> k_no_drill_axes{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};

/// Reverse motion of one triangle (theory.md §2.1-§2.7).
/// base: node positions at t_{n-1}; current: at t_n; dtheta: nodal rotation increments
/// (global rotation vectors) over the step. drill_axis: per node, the unit axis about which
/// its rotation is not a degree of freedom (the particle normal of the step; zero where the
/// increment is complete): the node's rotation about it is the element's own rigid rotation
/// (§2.6, eq. 2.6c). Frame: global in, element-local out.
[[nodiscard]] ReversedTriangle reverse_motion(const std::array<Vec3, 3>& base,
                                              const std::array<Vec3, 3>& current,
                                              const std::array<Vec3, 3>& dtheta,
                                              const std::array<Vec3, 3>& drill_axis);

}  // namespace fpmshell
