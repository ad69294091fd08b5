// Smoothed membrane strain (control.membrane: smoothed): the membrane strain increment of an
// element is the average of the strains at its three sides, each side's strain the area-
// weighted mean of the two CST strains that meet there (the assumed membrane strain of Flores &
// Onate's CBST in small-strain, incremental form; the side strains are those of edge-based
// smoothing): d_eps~_e = 1/3 sum_i (A_e d_eps_e + A_n T_i d_eps_n) / (A_e + A_n), the
// neighbour's strain turned into the element's frame (T_i) by unfolding about the shared side.
// A side without a smooth neighbour (boundary, fold, non-manifold edge) counts the element's
// own strain. The nodal forces are the transposed operator (virtual work), so energy is
// conserved and, with the area weights, the membrane patch test is kept.
// The CST is a constant-strain element: on a flat-faceted twisted surface it needs membrane
// strain gradients across a few elements it cannot represent, and locks (slit annular plate).
#pragma once

#include <cmath>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Strain transformation (engineering shear) for components in a frame turned by beta:
/// eps' = T eps when vectors map by v' = R(beta) v.
[[nodiscard]] inline Mat3 strain_rotation(Real beta) {
    const Real c = std::cos(beta), s = std::sin(beta);
    Mat3 t;
    t << c * c, s * s, -c * s, s * s, c * c, c * s, 2 * c * s, -2 * c * s, c * c - s * s;
    return t;
}

/// Direction angle of the side from local node a to local node b of a triangle whose local
/// coordinates are (0, 0), (x2, 0), (x3, y3) (theory.md §2.5).
[[nodiscard]] inline Real side_angle(Real x2, Real x3, Real y3, int a, int b) {
    const Real xs[3] = {0, x2, x3}, ys[3] = {0, 0, y3};
    return std::atan2(ys[b] - ys[a], xs[b] - xs[a]);
}

}  // namespace fpmshell
