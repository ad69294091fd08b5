// `type: j2_plastic`: J2 plasticity on a bilinear curve, sigma_y past which the stress grows
// with the tangent modulus E_t (theory.md §7.2); LS-DYNA's *MAT_PLASTIC_KINEMATIC (003).
#pragma once

#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

[[nodiscard]] MaterialLaw bilinear_law();
/// Makes `m` (its E already set) a j2_plastic material of that yield stress and tangent
/// modulus (0: perfectly plastic), isotropic; returns its J2 constants for further changes.
J2Parameters& make_bilinear(Material& m, Real yield_stress, Real tangent_modulus);

}  // namespace fpmshell
