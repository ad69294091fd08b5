// Evaluates the `output.histories` requests of the model on the solver state (history.csv).
#pragma once

#include <string>
#include <vector>

#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

/// Value of one quantity at one particle (model-format.md "History quantities").
/// Time levels after a cycle: positions t_{n+1}, velocity t_{n+1/2}, acceleration, reactions
/// and external forces t_n.
[[nodiscard]] Real particle_quantity(const ExplicitSolver& solver, Quantity q, Index p);

/// Value of a rigid-body quantity (Quantity::Rigid*) of body b, at the same time levels.
[[nodiscard]] Real body_quantity(const ExplicitSolver& solver, Quantity q, Index b);

/// One value per history request, reduced over its node set.
[[nodiscard]] std::vector<Real> sample_histories(const Model& model, const ExplicitSolver& solver);

}  // namespace fpmshell
