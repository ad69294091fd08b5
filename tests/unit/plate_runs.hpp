// Helpers of the solver tests that run a plate: its supports and the energy check of a run.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell::test {

/// Simply supported edges (uz on the node set "boundary"), in-plane motion free except what
/// removes the rigid modes (ux, uy of node 0).
inline void simply_support(Model& m) {
    BoundaryCondition bc;
    bc.nodes = m.node_sets.at("boundary");
    bc.fixed = {false, false, true, false, false, false};
    m.boundary.push_back(bc);
    BoundaryCondition corner;
    corner.nodes = {0};
    corner.fixed = {true, true, false, false, false, false};
    m.boundary.push_back(corner);
}

/// Runs n steps; returns the largest |energy error| seen, or +inf if the run failed.
inline Real max_energy_error(const Model& m, int n_steps) {
    ExplicitSolver s(m);
    Real worst = 0;
    try {
        for (int i = 0; i < n_steps; ++i) {
            s.step(1e30);
            worst = std::max(worst, std::abs(s.energy().error()));
        }
    } catch (const RunFailure&) {
        return std::numeric_limits<Real>::infinity();
    }
    return worst;
}

}  // namespace fpmshell::test
