// Evaluates the `output.histories` requests of the model on the solver state (history.csv).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fpmshell/driver/output_observer.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

/// Value of one quantity at one particle (model-format.md "History quantities").
/// Time levels after a cycle: positions t_{n+1}, velocity t_{n+1/2}, acceleration, reactions
/// and external forces t_n.
[[nodiscard]] Real particle_quantity(const ExplicitSolver& solver, Quantity q, Index p);

/// Value of a rigid-body quantity (Quantity::Rigid*) of body b, at the same time levels.
[[nodiscard]] Real body_quantity(const ExplicitSolver& solver, Quantity q, Index b);

/// One value per history request, reduced over its node set (sums exactly, core/exact_sum.hpp).
/// On several ranks collective: each rank reduces the particles it owns, and every rank gets
/// the values of a single process, bit for bit.
[[nodiscard]] std::vector<Real> sample_histories(const Model& model, const ExplicitSolver& solver);

/// A rank other than 0 of a distributed run: its part of every history row (sample_histories
/// is collective); rank 0's history.csv writes the row.
class HistoryShare final : public OutputObserver {
public:
    explicit HistoryShare(const Model& model) : model_(model) {}
    void sample(const ExplicitSolver& solver, Real time, std::optional<bool> converged) override;

private:
    const Model& model_;
};

}  // namespace fpmshell
