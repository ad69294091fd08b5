// energy.csv: the solver's energy balance per sample.
#include "fpmshell/driver/energy_file.hpp"

#include <string>

#include "fpmshell/failure/element_erosion.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {
namespace {

std::vector<std::string> energy_columns(bool mass_scaling, bool erosion) {
    std::vector<std::string> columns = {"time",          "kinetic", "internal", "plastic",
                                        "external_work", "damping", "contact",  "energy_error"};
    if (mass_scaling) columns.emplace_back("added_mass");
    if (erosion) columns.emplace_back("eroded_internal");
    return columns;
}

}  // namespace

EnergyFile::EnergyFile(const Model& model, const std::filesystem::path& dir)
    : CsvResultFile(
          dir / "energy.csv",
          energy_columns(model.control.mass_scaling.time_step > 0, model_can_erode(model)),
          "energy", "energy.csv columns"),
      mass_scaling_(model.control.mass_scaling.time_step > 0),
      erosion_(model_can_erode(model)) {}

std::vector<Real> EnergyFile::row(const ExplicitSolver& solver, Real time,
                                  std::optional<bool> /*converged*/) const {
    const EnergyBalance& e = solver.energy();
    std::vector<Real> values = {time,      e.kinetic,       e.internal,
                                e.plastic, e.external_work, e.dissipated_by_damping(),
                                e.contact, e.error()};
    if (mass_scaling_) values.push_back(solver.added_mass().total_added());
    if (erosion_) values.push_back(e.eroded_internal);
    return values;
}

}  // namespace fpmshell
