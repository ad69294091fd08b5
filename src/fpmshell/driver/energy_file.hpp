// energy.csv (model-format.md "Results in DIR"): the energy balance at every history sample.
#pragma once

#include <filesystem>
#include <vector>

#include "fpmshell/driver/csv_result_file.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class EnergyFile final : public CsvResultFile {
public:
    /// With control.mass_scaling the file has the column added_mass after the energies.
    EnergyFile(const Model& model, const std::filesystem::path& dir);

private:
    [[nodiscard]] std::vector<Real> row(const ExplicitSolver& solver, Real time,
                                        std::optional<bool> converged) const override;
    bool mass_scaling_;
    bool erosion_;  ///< a material can fail: the column eroded_internal (theory.md §7.6)
};

}  // namespace fpmshell
