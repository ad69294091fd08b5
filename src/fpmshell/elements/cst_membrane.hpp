// The CST membrane (theory.md §3.1, §3.3) of a path element's local triangle, node 1 at the
// origin and node 2 on x (x = (0, x2, x3), y = (0, 0, y3)), written once for a scalar type T:
// the element kernel (elastic_triangle_block.hpp) and the smoothed membrane
// (solver/shell_elements.cpp) use it.
#pragma once

#include <array>

#include "fpmshell/core/simd.hpp"

namespace fpmshell {

/// b_i / 2A and c_i / 2A with b_i = y_j - y_k, c_i = x_k - x_j (cyclic), 2A = x2 y3.
template <class T>
struct CstGradients {
    std::array<T, 3> bx, cy;
};

template <class T>
[[nodiscard]] FPMSHELL_INLINE CstGradients<T> cst_gradients(const T& x2, const T& x3, const T& y3,
                                                            const T& inv_two_area) {
    return {{-y3 * inv_two_area, y3 * inv_two_area, T(0.0)},
            {(x3 - x2) * inv_two_area, -x3 * inv_two_area, x2 * inv_two_area}};
}

/// eq. 3.1: the strain increment [d eps_xx, d eps_yy, d gamma_xy] of the deformation
/// displacements (u_1 = 0).
template <class T>
[[nodiscard]] FPMSHELL_INLINE std::array<T, 3> cst_strain(const CstGradients<T>& g,
                                                          const std::array<T, 3>& ux,
                                                          const std::array<T, 3>& uy) {
    return {g.bx[1] * ux[1] + g.bx[2] * ux[2], g.cy[1] * uy[1] + g.cy[2] * uy[2],
            g.cy[1] * ux[1] + g.cy[2] * ux[2] + g.bx[1] * uy[1] + g.bx[2] * uy[2]};
}

/// §3.3: B_m^T n, the nodal forces [fx1 fy1 fx2 fy2 fx3 fy3] of the membrane resultant n
/// (already multiplied by the area).
template <class T>
[[nodiscard]] FPMSHELL_INLINE std::array<T, 6> cst_nodal_forces(const CstGradients<T>& g,
                                                                const std::array<T, 3>& n) {
    std::array<T, 6> f;
    for (std::size_t i = 0; i < 3; ++i) {
        f[2 * i] = g.bx[i] * n[0] + g.cy[i] * n[2];
        f[2 * i + 1] = g.cy[i] * n[1] + g.bx[i] * n[2];
    }
    return f;
}

}  // namespace fpmshell
