// The Friedlander pulse of a blast's positive phase (theory.md §6.13, eq. 6.13-3):
//   p(tau) = P (1 - tau / t0) exp(-b tau / t0),  0 <= tau <= t0,
// whose impulse over the phase is I = P t0 (b - 1 + e^-b) / b^2; the decay b is solved so that
// it is the fit's (Kingery & Bulmash give the peak, the duration and the impulse apart). The
// negative phase, where asked for, is the same curve continued past t0 (eq. 6.13-5).
#pragma once

#include <cmath>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// (b - 1 + e^-b) / b^2, the impulse of the unit pulse of decay b (1/2 at b = 0: a triangle);
/// decreasing in b.
[[nodiscard]] Real friedlander_impulse_ratio(Real b);

/// The decay b whose pulse of peak `peak` and duration `duration` has impulse `impulse`
/// (b < 0 where the impulse exceeds the triangle's, peak duration / 2: the pulse then bulges);
/// by Newton's method in a shrinking bracket, to 1e-15. Requires impulse / (peak duration)
/// in (1e-4, 12).
[[nodiscard]] Real friedlander_decay(Real peak, Real duration, Real impulse);

/// p(tau) of eq. 6.13-3: 0 before the arrival (tau < 0); after the positive phase 0, or with
/// `negative_phase` the curve continued (eq. 6.13-5: below zero where the decay b > 0; a pulse
/// of b <= 0 has none, its continuation growing without bound).
[[nodiscard]] inline Real friedlander_pressure(Real peak, Real duration, Real decay, Real tau,
                                               bool negative_phase = false) {
    if (tau < 0 || (tau > duration && !(negative_phase && decay > 0))) return 0.0;
    const Real x = tau / duration;
    return peak * (1.0 - x) * std::exp(-decay * x);
}

/// The impulse of the continued curve past t0, -P t0 e^-b / b^2 (b > 0), without a floor.
[[nodiscard]] inline Real friedlander_negative_impulse(Real peak, Real duration, Real decay) {
    return -peak * duration * std::exp(-decay) / (decay * decay);
}

}  // namespace fpmshell
