// The particle masses of a rigid section whose body's inertia is given (model.hpp
// RigidInertia, theory.md §6.11, eq. 6.11-9): the section's mass shared over its particles so
// that they hold its mass and its centre of mass exactly; the rest of its inertia tensor the
// rigid body adds itself (solver/nodal_rigid_bodies.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct RigidInertiaShares {
    std::vector<Index> particles;  ///< the section's particles, ascending
    std::vector<Real> mass;        ///< per particle of `particles`: its share of the mass
    std::vector<Real> inertia;     ///< its rotary inertia (positive; the body corrects for it)
    /// why the shares cannot hold the centre (it lies off the particles' plane, or so far from
    /// their mean that a share would be negative), if they cannot
    std::optional<std::string> problem;
};

/// Eq. 6.11-9 for section `section` (of a rigid material with has_inertia): the shares
/// m_i = M w_i (1 + a.(x_i - xbar)), w_i the particles' shares of the faces' area, xbar their
/// centre and a such that sum m_i x_i = M c.
[[nodiscard]] RigidInertiaShares rigid_inertia_shares(const Model& model, Index section);

}  // namespace fpmshell
