// The model after a particle separation (theory.md §7.7): the separation's triangles, each new
// particle at its parent's initial position, and the model's lists of particles extended by the
// rules below. The solver of the separated mesh is built from it.
//
// A new particle joins every node set, boundary condition, gravity load and rigid contact of
// its parent (a clamped particle stays clamped on both sides of a crack, gravity pulls on every
// part); forces and moments, point masses, initial velocities and histories stay on the parent
// (a load is not doubled, a history keeps its particle). Particles of nodal rigid bodies and
// ties never split (the edge criterion leaves their edges closed).
#pragma once

#include "fpmshell/model/model.hpp"
#include "fpmshell/model/particle_separation.hpp"

namespace fpmshell {

[[nodiscard]] Model separated_model(const Model& model, const Separation& separation);

/// The model of a run after the separations of `history` (a restart file's), made again from
/// the model as read: each the separation of the model before it along the sides opened before
/// it (the same particles, in the same numbering, as the run's).
[[nodiscard]] Model replay_separations(const Model& model, const SeparationHistory& history);

}  // namespace fpmshell
