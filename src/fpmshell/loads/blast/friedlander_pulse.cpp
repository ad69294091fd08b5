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
    // Newton's method on the decreasing ratio g(b), kept inside a bracket that shrinks with
    // each step (g(-4) = 12.9 > 0.99, g(1e4) < 1e-4): a step that leaves it bisects instead
    Real low = -4.0, high = 1e4, b = 1.0;
    for (int k = 0; k < 200; ++k) {
        const Real g = friedlander_impulse_ratio(b) - ratio;
        if (g > 0)
            low = b;
        else
            high = b;
        // g'(b) = [(1 - e^-b) b - 2 (b - 1 + e^-b)] / b^3 (-1/6 + b/12 near 0)
        const Real slope =
            std::abs(b) < 1e-3
                ? -1.0 / 6.0 + b / 12.0
                : ((1.0 - std::exp(-b)) * b - 2.0 * (b - 1.0 + std::exp(-b))) / (b * b * b);
        Real next = slope < 0 ? b - g / slope : 0.5 * (low + high);
        if (!(next > low && next < high)) next = 0.5 * (low + high);
        if (std::abs(next - b) <= 1e-15 * (1.0 + std::abs(b))) return next;
        b = next;
    }
    return b;
}

}  // namespace fpmshell
