// The rotation-only DKT curvature matrix (theory.md §4.7; Batoz, Bathe & Ho 1980), written once
// for a scalar type T: Real in bending_b_dkt (triangle_shape.cpp), RealPack at the corners of
// the SIMD blocks (elastic_triangle_block.hpp). The local triangle has node 1 at the origin and
// node 2 on x: x = (0, x2, x3), y = (0, 0, y3).
#pragma once

#include <array>
#include <cstddef>

#include "fpmshell/core/simd.hpp"

namespace fpmshell {

/// b_k, c_k, e_k of the sides k = 4, 5, 6 (ij = 23, 31, 12); a_k and d_k multiply only the
/// deflections, which are zero after the reverse motion.
template <class T>
struct DktSides {
    std::array<T, 3> cb, cc, ce;
};

template <class T>
[[nodiscard]] FPMSHELL_INLINE DktSides<T> dkt_sides(const T& x2, const T& x3, const T& y3) {
    // sides 23, 31, 12: (x_i - x_j, y_i - y_j)
    const std::array<T, 3> xij{x2 - x3, x3, -x2}, yij{-y3, y3, T(0.0)};
    std::array<T, 3> l2;
    for (std::size_t s = 0; s < 3; ++s) l2[s] = xij[s] * xij[s] + yij[s] * yij[s];
    const T inv_product = 1.0 / (l2[0] * l2[1] * l2[2]);  // one division for the three sides
    const std::array<T, 3> inv_l2{l2[1] * l2[2] * inv_product, l2[0] * l2[2] * inv_product,
                                  l2[0] * l2[1] * inv_product};
    DktSides<T> d;
    for (std::size_t s = 0; s < 3; ++s) {
        d.cb[s] = 0.75 * xij[s] * yij[s] * inv_l2[s];
        d.cc[s] = (0.25 * xij[s] * xij[s] - 0.5 * yij[s] * yij[s]) * inv_l2[s];
        d.ce[s] = (0.25 * yij[s] * yij[s] - 0.5 * xij[s] * xij[s]) * inv_l2[s];
    }
    return d;
}

/// The derivatives N,xi and N,eta of the six quadratic shape functions at the area coordinates
/// L (xi = L_2, eta = L_3).
struct DktDerivatives {
    std::array<Real, 6> n_xi, n_eta;
};

[[nodiscard]] constexpr DktDerivatives dkt_derivatives(const std::array<Real, 3>& L) {
    const Real xi = L[1], eta = L[2];
    return {{-3 + 4 * xi + 4 * eta, 4 * xi - 1, 0.0, 4 * eta, -4 * eta, 4 * (1 - 2 * xi - eta)},
            {-3 + 4 * xi + 4 * eta, 0.0, 4 * eta - 1, 4 * xi, 4 * (1 - xi - 2 * eta), -4 * xi}};
}

/// Rows kxx, kyy, kxy of the curvature matrix [thx1 thy1 ... thy3] at the point of `n`.
/// inv_two_area = 1 / (x2 y3).
template <class T>
[[nodiscard]] FPMSHELL_INLINE std::array<std::array<T, 6>, 3> dkt_curvature(
    const DktDerivatives& n, const DktSides<T>& d, const T& x2, const T& x3, const T& y3,
    const T& inv_two_area) {
    const std::array<T, 3>&cb = d.cb, &cc = d.cc, &ce = d.ce;
    // Hx, Hy at the rotation DOFs (the w columns are dropped: the deformation deflections are
    // zero) evaluated on derivative arrays N
    auto h_of = [&](const std::array<Real, 6>& nn, std::array<T, 6>& hx, std::array<T, 6>& hy) {
        const Real n1 = nn[0], n2 = nn[1], n3 = nn[2], n4 = nn[3], n5 = nn[4], n6 = nn[5];
        hx = {cb[1] * n5 + cb[2] * n6, n1 - cc[1] * n5 - cc[2] * n6,
              cb[2] * n6 + cb[0] * n4, n2 - cc[2] * n6 - cc[0] * n4,
              cb[0] * n4 + cb[1] * n5, n3 - cc[0] * n4 - cc[1] * n5};
        hy = {-n1 + ce[1] * n5 + ce[2] * n6, -(cb[1] * n5) - cb[2] * n6,
              -n2 + ce[2] * n6 + ce[0] * n4, -(cb[2] * n6) - cb[0] * n4,
              -n3 + ce[0] * n4 + ce[1] * n5, -(cb[0] * n4) - cb[1] * n5};
    };
    std::array<T, 6> hx_xi, hy_xi, hx_eta, hy_eta;
    h_of(n.n_xi, hx_xi, hy_xi);
    h_of(n.n_eta, hx_eta, hy_eta);
    // x31 = x3, y31 = y3, x12 = -x2, y12 = 0 in the local frame
    std::array<std::array<T, 6>, 3> rows;
    for (std::size_t q = 0; q < 6; ++q) {
        rows[0][q] = (y3 * hx_xi[q]) * inv_two_area;
        rows[1][q] = (-(x3 * hy_xi[q]) + x2 * hy_eta[q]) * inv_two_area;
        rows[2][q] = (-(x3 * hx_xi[q]) + x2 * hx_eta[q] + y3 * hy_xi[q]) * inv_two_area;
    }
    return rows;
}

}  // namespace fpmshell
