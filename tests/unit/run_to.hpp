// Steps a solver to a time, for the tests that compare a state at a time with a closed form.
#pragma once

#include <algorithm>

#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell::test {

/// Runs s until its time reaches t; returns the largest step taken.
inline Real run_to(ExplicitSolver& s, Real t) {
    Real dt_max = 0;
    while (s.time() < t) {
        const Real before = s.time();
        s.step(1e30);
        dt_max = std::max(dt_max, s.time() - before);
    }
    return dt_max;
}

}  // namespace fpmshell::test
