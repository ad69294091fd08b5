// The BCIZ curvature matrix (theory.md §4.2-§4.3) written once for a scalar type T: Real in
// bending_b_bciz (triangle_shape.cpp), RealPack at the corners of the SIMD blocks
// (elastic_triangle_block.hpp).
#pragma once

#include <array>
#include <cstddef>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Rows kxx, kyy, kxy of the rotation-only BCIZ curvature matrix [thx1 thy1 ... thy3] at the
/// area coordinates L. b, c: b_i = y_j - y_k, c_i = x_k - x_j of the local triangle;
/// f = -1 / (2A)^2. Second derivatives in closed form (§4.3): for u, v in {b, c},
///   u.H(g_ij).v = 2 L_j u_i v_i + 2 L_i (u_i v_j + u_j v_i)       (g_ij = L_i^2 L_j)
///   u.H(B).v    = L3 (u1 v2 + u2 v1) + L2 (u1 v3 + u3 v1) + L1 (u2 v3 + u3 v2)
/// and f,xx = b.H.b / (2A)^2, f,yy = c.H.c / (2A)^2, f,xy = b.H.c / (2A)^2.
template <class T>
[[nodiscard]] inline std::array<std::array<T, 6>, 3> bciz_curvature(const std::array<Real, 3>& L,
                                                                    const std::array<T, 3>& b,
                                                                    const std::array<T, 3>& c,
                                                                    const T& f) {
    auto q_g = [&L](std::size_t i, std::size_t j, const std::array<T, 3>& u,
                    const std::array<T, 3>& v) {
        return 2 * L[j] * u[i] * v[i] + 2 * L[i] * (u[i] * v[j] + u[j] * v[i]);
    };
    auto q_bubble = [&L](const std::array<T, 3>& u, const std::array<T, 3>& v) {
        return L[2] * (u[0] * v[1] + u[1] * v[0]) + L[1] * (u[0] * v[2] + u[2] * v[0]) +
               L[0] * (u[1] * v[2] + u[2] * v[1]);
    };
    const T bub_bb = q_bubble(b, b), bub_cc = q_bubble(c, c), bub_bc = q_bubble(b, c);
    std::array<std::array<T, 6>, 3> rows;
    static constexpr std::array<std::array<std::size_t, 3>, 3> k_cyclic{
        {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}};
    for (const auto& [i, j, k] : k_cyclic) {
        const T gik_bb = q_g(i, k, b, b), gik_cc = q_g(i, k, c, c), gik_bc = q_g(i, k, b, c);
        const T gij_bb = q_g(i, j, b, b), gij_cc = q_g(i, j, c, c), gij_bc = q_g(i, j, b, c);
        // N_i^thx = b_j g_ik - b_k g_ij + (b_j - b_k)/2 B; N_i^thy likewise with c (§4.2)
        for (std::size_t col = 0; col < 2; ++col) {
            const std::array<T, 3>& w = col == 0 ? b : c;
            const T hb = 0.5 * (w[j] - w[k]);
            rows[0][2 * i + col] = f * (w[j] * gik_bb - w[k] * gij_bb + hb * bub_bb);
            rows[1][2 * i + col] = f * (w[j] * gik_cc - w[k] * gij_cc + hb * bub_cc);
            rows[2][2 * i + col] = 2 * f * (w[j] * gik_bc - w[k] * gij_bc + hb * bub_bc);
        }
    }
    return rows;
}

}  // namespace fpmshell
