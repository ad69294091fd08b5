// The distance of a double from a reference in units of the reference's last place: the
// accuracy measure of the floating-point helpers of core/ (simd_math.hpp, simd.hpp).
#pragma once

#include <cmath>
#include <limits>

#include "fpmshell/core/types.hpp"

namespace fpmshell::test {

/// |a - b| in units of the last place of b.
inline Real ulps(Real a, Real b) {
    const Real ulp =
        std::nextafter(std::abs(b), std::numeric_limits<Real>::infinity()) - std::abs(b);
    return std::abs(a - b) / ulp;
}

}  // namespace fpmshell::test
