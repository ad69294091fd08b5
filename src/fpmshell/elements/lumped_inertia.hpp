// Share of one triangle in the lumped mass and rotary inertia of each of its nodes (theory.md
// §6.1 row-sum lumping, §6.2 the scaled rotary inertias).
#pragma once

#include <cmath>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct NodeInertiaShare {
    Real mass;       ///< rho h A / 3                          (§6.1)
    Real inertia;    ///< (rho h A / 3) gyration2               (§6.2)
    Real gyration2;  ///< inertia / mass, e.g. A/8 + h^2/12 (option B)
};

/// §6.2 option B (Kennedy, Belytschko & Lin 1986): J = (rho h A / 3)(A/8 + h^2/12).
[[nodiscard]] inline NodeInertiaShare lumped_node_share(Real density, Real thickness, Real area) {
    const Real m3 = density * thickness * area / 3.0;
    const Real gyration2 = area / 8.0 + thickness * thickness / 12.0;
    return {m3, m3 * gyration2, gyration2};
}

/// The Abaqus/Explicit factor on the physical rotary inertia rho A h^3 / 12 of a triangle
/// (§6.2, eq. 6.2a): R = [16 + (3 L^2 / (4 h^2))^4]^(1/4), L its shortest edge; R >= 2, and
/// R ~ 3 L^2 / (4 h^2) for a thin element (written so that q^4 cannot overflow there).
[[nodiscard]] inline Real abaqus_rotary_factor(Real thickness, Real shortest_edge) {
    const Real q = 0.75 * shortest_edge * shortest_edge / (thickness * thickness);
    if (q <= 2) return std::sqrt(std::sqrt(16.0 + q * q * q * q));
    const Real r = 2.0 / q;  // 16 / q^4 = r^4
    return q * std::sqrt(std::sqrt(1.0 + r * r * r * r));
}

/// The share of control.rotary_inertia `kind` (§6.2): mass rho h A / 3 and
///   belytschko  J = m (A/8 + h^2/12)       (option B, lumped_node_share)
///   abaqus      J = m R h^2 / 12           (eq. 6.2a; R from the shortest edge)
///   radioss     J = m (A/4.5 + h^2/12)     (eq. 6.2b, OpenRadioss starter c3inmas.F)
[[nodiscard]] inline NodeInertiaShare node_inertia_share(RotaryInertia kind, Real density,
                                                         Real thickness, Real area,
                                                         Real shortest_edge) {
    switch (kind) {
        case RotaryInertia::Abaqus: {
            const Real m3 = density * thickness * area / 3.0;
            const Real gyration2 =
                abaqus_rotary_factor(thickness, shortest_edge) * thickness * thickness / 12.0;
            return {m3, m3 * gyration2, gyration2};
        }
        case RotaryInertia::Radioss: {
            const Real m3 = density * thickness * area / 3.0;
            const Real gyration2 = area / 4.5 + thickness * thickness / 12.0;
            return {m3, m3 * gyration2, gyration2};
        }
        case RotaryInertia::Belytschko:
            break;
    }
    return lumped_node_share(density, thickness, area);
}

}  // namespace fpmshell
