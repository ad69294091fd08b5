// history.csv (model-format.md "Results in DIR"): the output.histories requests of the model,
// one column each after time (and, in relaxation, whether the load level converged).
#pragma once

#include <filesystem>
#include <vector>

#include "fpmshell/driver/csv_result_file.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class HistoryFile final : public CsvResultFile {
public:
    /// The largest magnitude of a history over the rows, and the time of its row.
    struct Peak {
        Real value = 0;
        Real time = 0;
    };

    HistoryFile(const Model& model, const std::filesystem::path& dir);

    /// One peak per history request, over every row so far (summary.json "peaks").
    [[nodiscard]] std::vector<Peak> peaks() const;

private:
    [[nodiscard]] std::vector<Real> row(const ExplicitSolver& solver, Real time,
                                        std::optional<bool> converged) const override;

    const Model& model_;
};

}  // namespace fpmshell
