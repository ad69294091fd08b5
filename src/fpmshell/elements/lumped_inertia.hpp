// Share of one triangle in the lumped mass and rotary inertia of each of its nodes (theory.md
// §6.1 row-sum lumping, §6.2 option B scaled rotary inertia).
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct NodeInertiaShare {
    Real mass;  ///< rho h A / 3                   (§6.1)
    Real
        inertia;  ///< (rho h A / 3)(A/8 + h^2/12)   (§6.2 option B, Kennedy, Belytschko & Lin 1986)
    Real gyration2;  ///< A/8 + h^2/12, inertia / mass
};

[[nodiscard]] inline NodeInertiaShare lumped_node_share(Real density, Real thickness, Real area) {
    const Real m3 = density * thickness * area / 3.0;
    const Real gyration2 = area / 8.0 + thickness * thickness / 12.0;
    return {m3, m3 * gyration2, gyration2};
}

}  // namespace fpmshell
