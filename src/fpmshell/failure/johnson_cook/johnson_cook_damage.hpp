// Johnson-Cook damage (theory.md eq. 7.6-2; Johnson & Cook 1985; LS-DYNA's *MAT_015 D1..D5,
// OpenRadioss /FAIL/JOHNSON): a point accumulates D = sum d alpha / eps_f, the plastic strain
// of each step over the failure strain at that step's state,
//   eps_f = max(eps_min, [D1 + D2 exp(D3 eta)] [1 + D4 ln max(rate / rate_0, 1)] [1 + D5 T*]),
// eta = sigma_m / sigma_vm the stress triaxiality (tension positive), rate the plastic strain
// rate, T* the homologous temperature of the law's adiabatic heating (0 without it); it fails
// at D = 1. Its state per point: D and the plastic strain at the last step.
#pragma once

#include <cmath>

#include "fpmshell/core/simd.hpp"
#include "fpmshell/core/simd_math.hpp"
#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/failure/stress_triaxiality.hpp"

namespace fpmshell {

struct JohnsonCookDamageParameters {
    Real d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;
    Real reference_strain_rate = 1;  ///< rate_0
    Real minimum_strain = 1e-6;      ///< eps_min (LS-DYNA's EFMIN and its default)
};

class JohnsonCookDamage final : public PointFailure {
public:
    /// heating: dT*/dW_p of the law's adiabatic heating (ThermalSoftening::heating), 0 without
    JohnsonCookDamage(const JohnsonCookDamageParameters& p, Real heating)
        : p_(p), heating_(heating) {}

    [[nodiscard]] std::size_t state_fields() const override { return 2; }
    [[nodiscard]] bool reads_point() const override { return true; }
    /// eq. 7.6-2 at the state after the step, a pack of points at a time (core/simd_math.hpp:
    /// a point's bits do not depend on its lane or its neighbours).
    bool judge(const FailurePacks& in, Real dt, RealPack* state,
               MaskOf<RealPack>* failed) const override;

    /// eps_f at triaxiality eta, plastic strain rate `rate` and homologous temperature t_star,
    /// on every lane of T.
    template <class T>
    [[nodiscard]] FPMSHELL_INLINE T failure_strain(const T& eta, const T& rate,
                                                   const T& t_star) const {
        T eps = p_.d1 + p_.d2 * vector_exp(p_.d3 * eta);
        if (p_.d4 != 0)  // 1 + D4 ln max(rate / rate_0, 1)
            eps *= 1.0 + p_.d4 * vector_log(max(rate * (1.0 / p_.reference_strain_rate), T(1.0)));
        if (p_.d5 != 0) eps *= 1.0 + p_.d5 * t_star;
        return max(eps, T(p_.minimum_strain));
    }

private:
    JohnsonCookDamageParameters p_;
    Real heating_;
};

[[nodiscard]] FailureCriterion johnson_cook_criterion();

}  // namespace fpmshell
