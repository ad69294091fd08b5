// `type: plastic_damage`: a tabulated J2 law whose stress is reduced by damage rising linearly
// in the plastic strain (plastic_damage.hpp, theory.md eq. 7.6-4); LS-DYNA's *MAT_081 and
// *MAT_082 (PLASTICITY_WITH_DAMAGE, _ORTHO read as isotropic).
#pragma once

#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

/// The law's constants (Material::parameters).
struct PlasticDamageParameters {
    J2Parameters j2;
    Real start = 0;    ///< the plastic strain where damage starts (EPPF)
    Real rupture = 0;  ///< the plastic strain of rupture, D = 1 (EPPFR), > start
};

[[nodiscard]] MaterialLaw plastic_damage_law();

}  // namespace fpmshell
