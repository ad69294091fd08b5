// Johnson-Cook's thermal softening with adiabatic heating (theory.md §7.4, eq. 7.4-2): the
// flow stress times 1 - T*^m, the homologous temperature T* = (T - T_r) / (T_m - T_r) risen
// from the room temperature by the plastic work a point has dissipated,
// T = T_r + chi W_p / (rho c_p) (chi: the Taylor-Quinney fraction of it that heats).
#pragma once

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/simd_math.hpp"
#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct ThermalSoftening {
    /// The factor's floor: a point at its melting temperature keeps this fraction of its flow
    /// stress, so that the return mapping keeps a yield surface to return to (a melted point
    /// is a failure, which a failure criterion deletes).
    static constexpr Real k_min_factor = 1e-3;

    bool active = false;
    Real m = 1;        ///< the exponent of T*
    Real heating = 0;  ///< dT* / dW_p = chi / (rho c_p (T_m - T_r))

    /// 1 - T*^m at the plastic work per unit volume w (T* clamped to [0, 1]), on every lane
    /// of T (core/simd.hpp): a point computed alone gets its lane's factor.
    template <class T>
    [[nodiscard]] T factor(const T& w) const {
        const T t_star = min(max(heating * w, T(0.0)), T(1.0));
        const MaskOf<T> heated = t_star > 0.0;
        // vector_pow takes a positive argument: 1 where nothing has heated the point yet
        const T power = vector_pow(select(heated, t_star, T(1.0)), T(m));
        return max(select(heated, 1.0 - power, T(1.0)), T(k_min_factor));
    }
};

}  // namespace fpmshell
