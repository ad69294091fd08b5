#include "fpmshell/loads/blast/friedlander_pulse.hpp"

#include <cmath>

namespace fpmshell {

Real friedlander_impulse_ratio(Real b) {
    // its series near b = 0, where b - 1 + e^-b loses its digits: sum_k (-b)^k 2 / (k + 2)!
    if (std::abs(b) < 1e-3) return 0.5 - b / 6.0 + b * b / 24.0 - b * b * b / 120.0;
    return (b - 1.0 + std::exp(-b)) / (b * b);
}

Real friedlander_decay(Real peak, Real duration, Real impulse) {
    const Real ratio = impulse / (peak * duration);
    // bisection on a bracket of the decreasing ratio (g(-4) = 12.9 > 0.99, g(1e4) < 1e-4),
    // then it has the bits it can have
    Real low = -4.0, high = 1e4;
    for (int k = 0; k < 200 && high - low > 1e-14 * (1.0 + std::abs(low)); ++k) {
        const Real mid = 0.5 * (low + high);
        if (friedlander_impulse_ratio(mid) > ratio)
            low = mid;
        else
            high = mid;
    }
    return 0.5 * (low + high);
}

Real friedlander_pressure(Real peak, Real duration, Real decay, Real tau) {
    if (tau < 0 || tau > duration) return 0.0;
    const Real x = tau / duration;
    return peak * (1.0 - x) * std::exp(-decay * x);
}

}  // namespace fpmshell
