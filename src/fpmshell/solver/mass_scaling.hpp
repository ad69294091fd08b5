// Mass scaling (theory.md §6.10; LS-DYNA's *CONTROL_TIMESTEP DT2MS < 0, OpenRadioss's
// /DT/NODA/CST): the elements whose critical step is below the target
// control.mass_scaling.time_step get their mass and rotary inertia shares multiplied by the
// factor that brings their step to it; everything else keeps its physical mass. This file
// scales the elements at the initial geometry; during the run the element loop scales those
// whose step falls below the target as they deform (ElementTimeSteps::scaled_critical_dt,
// ExplicitSolver).
#pragma once

#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/model/model.hpp"
#include "fpmshell/solver/element_time_steps.hpp"

namespace fpmshell {

/// The mass added by mass scaling, per section (in the order of the model file's `sections`).
struct AddedMass {
    std::vector<Real> added;     ///< the mass added to the section's elements
    std::vector<Real> physical;  ///< the section's elements' mass without it
    /// The kinetic energy the mass added during the run brought with it, 1/2 dm |v|^2 + 1/2 dJ
    /// |w|^2 at the particle's velocity (eq. 6.10b), booked as external work.
    Real kinetic_energy = 0;
    [[nodiscard]] Real total_added() const;
    [[nodiscard]] Real total_physical() const;
    /// The sections whose added mass exceeds control.mass_scaling.added_mass_limit times
    /// their physical mass.
    [[nodiscard]] std::vector<Index> over_limit(const Model& model) const;
};

/// Members for a restart file (io/restart_archive.hpp).
template <class Archive>
void transfer(Archive& ar, AddedMass& a) {
    ar(a.added, a.physical, a.kinetic_energy);
}

/// Applies control.mass_scaling to the element shares of topology (and the particle sums) and
/// to steps (the critical steps follow the scaled masses); without it only measures the
/// physical mass per section. The target of the critical step is time_step / time_step_scale,
/// so that the run's step, time_step_scale x the smallest critical step, is time_step.
[[nodiscard]] AddedMass apply_mass_scaling(const Model& model, MeshTopology& topology,
                                           ElementTimeSteps& steps);

}  // namespace fpmshell
