// `type: rigid`: each section of it moves as one rigid body (solver/nodal_rigid_bodies.hpp,
// theory.md §6.11), with the elastic constants its contact and time step read; LS-DYNA's
// *MAT_RIGID (020).
#pragma once

#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

[[nodiscard]] MaterialLaw rigid_law();

}  // namespace fpmshell
