// The rigid bodies of a model (theory.md §6.11): the `constraints` of type rigid and the
// particles of each section of a rigid material, merged where they share a particle, with the
// components their materials and the `boundary` entries of type rigid_body hold or prescribe.
// The solver moves them (solver/nodal_rigid_bodies.hpp); the model reader checks the entries
// with it, so that an error names the entry's line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

/// A component of a body's motion a `boundary` entry prescribes (eq. 6.11-7).
struct RigidPrescription {
    PrescribedKind kind = PrescribedKind::None;
    Real value = 0;
    Index curve = -1;
};

struct RigidBodyPartition {
    /// each body's particles, ascending; the bodies in the order of their smallest particle
    std::vector<std::vector<Index>> bodies;
    std::vector<Index> body_of_particle;  ///< -1 outside the bodies
    /// per body, its components held (x, y, z, rotations about them): at zero or prescribed
    std::vector<std::array<bool, 6>> held;
    /// per body and component, what is prescribed (kind None: held at zero or free)
    std::vector<std::array<RigidPrescription, 6>> prescribed;
    /// the first `boundary` entry that cannot be applied (its index and why), if any
    std::optional<std::pair<std::size_t, std::string>> problem;
};

/// `let_go`: per entry of Model::nodal_rigid_bodies, nonzero for a spot weld that has failed
/// (eq. 6.11-13), left out of the bodies; empty: none has.
[[nodiscard]] RigidBodyPartition rigid_body_partition(const Model& model,
                                                      const std::vector<std::uint8_t>& let_go = {});

/// A group of particles that moves rigidly: an entry of Model::nodal_rigid_bodies (`entry` its
/// index) or the particles of a section of a rigid material (`entry` -1), with the components
/// its material holds fixed.
struct RigidGroup {
    std::vector<Index> nodes;  ///< sorted
    std::array<bool, 6> fixed{};
    long entry = -1;
};

/// The groups of the model, the failed spot welds (`let_go`) left out.
[[nodiscard]] std::vector<RigidGroup> rigid_groups(const Model& model,
                                                   const std::vector<std::uint8_t>& let_go = {});

}  // namespace fpmshell
