// Critical time step of the membrane modes of one triangle, exactly (theory.md eq. 6.4-3).
//
// The step L_c / c of §6.4 (LS-DYNA's for triangular shells) is not a bound for a triangle on
// its own: the highest membrane mode of an isolated lumped-mass CST has the step
// (0.83 ... 0.94) L_c / c, so at time_step_scale 0.9 a free equilateral triangle diverges. In a
// connected mesh the assembled modes are slower and L_c / c holds in practice; a sheet that
// separates (§7.7) leaves flaps and fragments whose modes reach the element's own, and its
// elements take this bound instead: dt = 2 / omega_e, omega_e^2 = (3 / rho) lambda_max(B B^T C)
// (B the CST strain matrix, the mass rho h A / 3 at each corner); the assembled omega_max never
// exceeds the largest element one.
#pragma once

#include "fpmshell/core/types.hpp"
#include "fpmshell/elements/triangle_shape.hpp"

namespace fpmshell {

/// The exact membrane critical step of the isolated lumped-mass triangle `s` over L_c / c
/// (L_c = 2A / longest side, c = sqrt(C_11 / rho)): 2 / (L_c sqrt(3 lambda_max(B B^T C / C_11))).
/// `elasticity` is the plane-stress C or any positive multiple of it (the bending rigidity
/// h^3/12 C serves). Infinite for a degenerate triangle.
[[nodiscard]] Real membrane_step_ratio(const TriangleShape& s, const Mat3& elasticity);

}  // namespace fpmshell
