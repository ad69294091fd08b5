// The bending matrices of the flat triangle in its local frame, node 1 at the origin and edge
// 1->2 along x (theory.md §4.3, §4.7), as Eigen matrices for the bending time step (§6.4) and
// the tests: they map the 6 deformation rotations [thx1, thy1, thx2, thy2, thx3, thy3] to the
// curvature [kxx, kyy, kxy] (kxy = -2 w,xy) at a point given by its area coordinates. The
// curvatures themselves are bciz_curvature.hpp's and dkt_curvature.hpp's.
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

/// BCIZ curvature matrix with the 6 rotation DOFs (theory.md §4.2-§4.3).
[[nodiscard]] Mat36 bending_b_bciz(const TriangleShape& s, const std::array<Real, 3>& L);

/// Rotation-only DKT curvature matrix (theory.md §4.7; Batoz, Bathe & Ho 1980).
[[nodiscard]] Mat36 bending_b_dkt(const TriangleShape& s, const std::array<Real, 3>& L);

}  // namespace fpmshell
