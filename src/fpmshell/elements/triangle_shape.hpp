// Shape-function derivatives of the flat triangle in its local frame, node 1 at the origin and
// edge 1->2 along x (theory.md §3.1, §4.3, §4.7). The membrane part is the CST; the bending
// part maps the 6 deformation rotations [thx1, thy1, thx2, thy2, thx3, thy3] to the curvature
// [kxx, kyy, kxy] (kxy = -2 w,xy) at a point given by its area coordinates.
#pragma once

#include <array>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

using Mat36 = Eigen::Matrix<Real, 3, 6>;

/// Local geometry: b_i = y_j - y_k, c_i = x_k - x_j (cyclic), 2A = x2 y3.
struct TriangleShape {
    std::array<Real, 3> x, y;  ///< local nodal coordinates
    std::array<Real, 3> b, c;
    Real two_area;

    TriangleShape(Real x2, Real x3, Real y3);
};

/// CST strain matrix B_m (theory.md §3.1): eps = B_m [u1x u1y u2x u2y u3x u3y].
[[nodiscard]] Mat36 membrane_b(const TriangleShape& s);

/// BCIZ curvature matrix with the 6 rotation DOFs (theory.md §4.2-§4.3).
[[nodiscard]] Mat36 bending_b_bciz(const TriangleShape& s, const std::array<Real, 3>& L);

/// The shape-only part of the DKT curvature matrix: the side coefficients a_k..e_k of Batoz,
/// Bathe & Ho (1980) and the Jacobian terms. Computed once per element and step; the matrix
/// at each in-plane point is then a few products (bending_b_dkt below).
struct DktShape {
    /// b_k, c_k, e_k per side k = 4, 5, 6 (ij = 23, 31, 12); a_k and d_k multiply only the
    /// deflections, which are zero after the reverse motion.
    std::array<Real, 3> cb, cc, ce;
    Real x31, y31, x12, y12;
    Real inv_two_area;  ///< 1 / (x31 y12 - x12 y31)
};
[[nodiscard]] DktShape dkt_shape(const TriangleShape& s);

/// Rotation-only DKT curvature matrix (theory.md §4.7; Batoz, Bathe & Ho 1980).
[[nodiscard]] Mat36 bending_b_dkt(const DktShape& d, const std::array<Real, 3>& L);
[[nodiscard]] inline Mat36 bending_b_dkt(const TriangleShape& s, const std::array<Real, 3>& L) {
    return bending_b_dkt(dkt_shape(s), L);
}

}  // namespace fpmshell
