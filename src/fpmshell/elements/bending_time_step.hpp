// Critical time step of the bending modes of one triangle (theory.md §6.2, §6.4).
//
// The CST formula L_c / c of §6.4 bounds the membrane modes only. The bending modes of a
// Kirchhoff triangle couple the deflections w (lumped mass m) with the tangent rotations
// (rotary inertia J); with the scaled inertia of §6.2 option B they stay slower than the
// membrane while h / L_c < ~0.5, but for elements about as small as the thickness (a fine
// mesh of a thick shell: h / L_c ~ 1 on the spherical cap at 28 rings) their critical step
// falls to 0.5 L_c / c and the run diverges. This is the exact element bound
// dt = 2 / omega_max of the 9-DOF bending element [w_i, thx_i, thy_i], omega_max^2 =
// lambda_max(M^-1/2 K_b M^-1/2); the assembled omega_max never exceeds the largest element one.
#pragma once

#include <limits>

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/triangle_shape.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

using Mat99 = Eigen::Matrix<Real, 9, 9>;

/// 9-DOF bending stiffness [w1, thx1, thy1, w2, ...] in the local frame: the rotation-only
/// curvature matrix (§4.3 / §4.7) applied to the deformation rotations theta_i - theta_rigid(w),
/// theta_rigid = (w,y, -w,x) of the plane through the nodal deflections (§4.1), integrated with
/// the 3-point rule (exact: the curvature is linear over the element). bending_rigidity is
/// D_b = (h^3 / 12) C of §4.1.
[[nodiscard]] Mat99 bending_stiffness_9dof(BendingKernel kernel, const TriangleShape& s,
                                           const Eigen::Matrix<Real, 3, 3>& bending_rigidity);

/// Critical step 2 / omega_max of the bending modes of one element whose nodes carry the
/// translational mass node_mass and the rotary inertia node_inertia from this element (§6.1,
/// §6.2); infinite for a degenerate element.
/// sufficient: a caller that needs only min(step, sufficient) (the membrane step) passes it;
/// when the Frobenius norm of the scaled stiffness, an upper bound of omega_max^2, already
/// gives a step of at least `sufficient`, that lower bound of the step is returned and the
/// 9 x 9 eigenproblem, nearly all the cost, is skipped (the thin elements: h / L_c < ~0.3).
[[nodiscard]] Real bending_critical_dt(BendingKernel kernel, const TriangleShape& s,
                                       const Eigen::Matrix<Real, 3, 3>& bending_rigidity,
                                       Real node_mass, Real node_inertia,
                                       Real sufficient = std::numeric_limits<Real>::infinity());

}  // namespace fpmshell
