// Parallel loops over particles or elements whose bodies touch only their own index: results
// bitwise the same for any number of threads. (Sums over the particles are made atom by atom and
// added exactly: ExplicitSolver::atom_sums, solver/domain_decomposition.hpp.)
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// Runs body(i) for i in [0, n), in parallel when asked; the body must touch only index i's data.
template <class Body>
void parallel_for_each(Index n, [[maybe_unused]] bool parallel, Body&& body) {
#pragma omp parallel for schedule(static) if (parallel)
    for (Index i = 0; i < n; ++i) body(i);
}

}  // namespace fpmshell
