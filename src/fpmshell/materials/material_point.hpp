// History stored at one integration point (in-plane point g, thickness point k) of an element.
// Components are in the convected element frame (theory.md §2.7), so they need no rotation.
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct MaterialPoint {
    Voigt3 stress = Voigt3::Zero();  ///< [sxx, syy, sxy]
};

}  // namespace fpmshell
