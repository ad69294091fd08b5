// energy.csv: the solver's energy balance per sample.
#include "fpmshell/driver/energy_file.hpp"

#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

EnergyFile::EnergyFile(const std::filesystem::path& dir)
    : CsvResultFile(dir / "energy.csv",
                    {"time", "kinetic", "internal", "plastic", "external_work", "damping",
                     "contact", "energy_error"},
                    "energy", "energy.csv columns") {}

std::vector<Real> EnergyFile::row(const ExplicitSolver& solver, Real time,
                                  std::optional<bool> /*converged*/) const {
    const EnergyBalance& e = solver.energy();
    return {time,      e.kinetic, e.internal, e.plastic, e.external_work,
            e.damping, e.contact, e.error()};
}

}  // namespace fpmshell
