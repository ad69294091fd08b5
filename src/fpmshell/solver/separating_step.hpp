// A dynamic step with fracture by particle separation (theory.md §7.7): the solver steps, and
// where the sides its failed elements opened call for a separation, the run goes on with the
// solver of the separated model, which takes over the state.
#pragma once

#include <memory>

#include "fpmshell/model/separated_model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

/// One step of `solver` (ExplicitSolver::step); after a separation, `solver` is the separated
/// model's, `separated` that model (the old solver released first, then the old model).
/// Whether the particles separated.
inline bool separating_step(std::unique_ptr<ExplicitSolver>& solver,
                            std::unique_ptr<Model>& separated, Real max_dt) {
    solver->step(max_dt);
    const Separation* separation = solver->separation_due();
    if (!separation) return false;
    auto model = std::make_unique<Model>(separated_model(solver->model(), *separation));
    auto next = std::make_unique<ExplicitSolver>(*model, *solver, *separation);
    solver = std::move(next);
    separated = std::move(model);
    return true;
}

}  // namespace fpmshell
