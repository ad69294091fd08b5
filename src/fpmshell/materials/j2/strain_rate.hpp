// The effective plastic strain rate a rate-dependent section sees (theory.md §7.4), written
// once for a scalar type T: the J2 point update (j2_plastic.cpp) and the SIMD trial check
// (elements/elastic_triangle_block.hpp) use it.
#pragma once

#include <array>
#include <cmath>

#include "fpmshell/core/simd.hpp"

namespace fpmshell {

/// The equivalent (von Mises) rate of the total strain increment d_eps = [d eps_xx, d eps_yy,
/// d gamma_xy] over dt under plane stress and incompressibility,
/// (2/sqrt 3) sqrt(e11^2 + e22^2 + e11 e22 + e12^2) / dt with e12 = gamma_xy / 2; 0 for
/// dt <= 0 (a path element without duration: no rate).
template <class T>
[[nodiscard]] FPMSHELL_INLINE T effective_strain_rate(const std::array<T, 3>& d_eps, Real dt) {
    if (!(dt > 0)) return T(0.0);
    const T e12 = 0.5 * d_eps[2];
    const T q = d_eps[0] * d_eps[0] + d_eps[1] * d_eps[1] + d_eps[0] * d_eps[1] + e12 * e12;
    return sqrt(max(T(0.0), q)) * ((2.0 / std::sqrt(3.0)) / dt);  // one scalar division
}

}  // namespace fpmshell
