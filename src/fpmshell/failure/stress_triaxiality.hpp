// The stress triaxiality eta = sigma_m / sigma_vm of a plane stress (theory.md §7.6), which the
// damage criteria take their failure strain at.
#pragma once

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/simd_math.hpp"

namespace fpmshell {

/// sigma_m / sigma_vm of a plane stress [sxx, syy, sxy] (tension positive; 0 for a zero stress),
/// on every lane of T; to 1e-15 (vector_rsqrt: no division).
template <class T>
[[nodiscard]] FPMSHELL_INLINE T stress_triaxiality(const T& sxx, const T& syy, const T& sxy) {
    const T q = sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy;  // sigma_vm^2
    const MaskOf<T> loaded = q > 0.0;
    return select(loaded, (sxx + syy) * (1.0 / 3.0) * vector_rsqrt(select(loaded, q, T(1.0))),
                  T(0.0));
}

}  // namespace fpmshell
