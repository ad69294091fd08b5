// `type: power_law`: J2 plasticity on sigma = k (eps_0 + eps_p)^n (theory.md eq. 7.2-6);
// LS-DYNA's *MAT_POWER_LAW_PLASTICITY (018).
#pragma once

#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

[[nodiscard]] MaterialLaw power_law_law();

}  // namespace fpmshell
