// Mass scaling (theory.md §6.10; LS-DYNA's *CONTROL_TIMESTEP DT2MS < 0, OpenRadioss's
// /DT/NODA/CST): the elements whose critical step at the initial geometry is below the target
// control.mass_scaling.time_step get their mass and rotary inertia shares multiplied by the
// factor that brings their step to it; everything else keeps its physical mass.
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
    [[nodiscard]] Real total_added() const;
    [[nodiscard]] Real total_physical() const;
    /// The sections whose added mass exceeds control.mass_scaling.added_mass_limit times
    /// their physical mass.
    [[nodiscard]] std::vector<Index> over_limit(const Model& model) const;
};

/// Applies control.mass_scaling to the element shares of topology (and the particle sums) and
/// to steps (the critical steps follow the scaled masses); without it only measures the
/// physical mass per section. The target of the critical step is time_step / time_step_scale,
/// so that the run's step, time_step_scale x the smallest critical step, is time_step.
[[nodiscard]] AddedMass apply_mass_scaling(const Model& model, MeshTopology& topology,
                                           ElementTimeSteps& steps);

}  // namespace fpmshell
