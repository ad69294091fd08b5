// energy.csv (model-format.md "Results in DIR"): the energy balance at every history sample.
#pragma once

#include <filesystem>
#include <vector>

#include "fpmshell/driver/csv_result_file.hpp"

namespace fpmshell {

class EnergyFile final : public CsvResultFile {
public:
    explicit EnergyFile(const std::filesystem::path& dir);

private:
    [[nodiscard]] std::vector<Real> row(const ExplicitSolver& solver, Real time,
                                        std::optional<bool> converged) const override;
};

}  // namespace fpmshell
