// `type: elastic`: isotropic linear elasticity in plane stress (theory.md §3.2); LS-DYNA's
// *MAT_ELASTIC (001).
#pragma once

#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

[[nodiscard]] MaterialLaw elastic_law();
/// The element group of a section of an elastic (or rigid) material.
[[nodiscard]] std::unique_ptr<ElementGroup> make_elastic_group(const Model& model,
                                                               std::size_t section);

}  // namespace fpmshell
