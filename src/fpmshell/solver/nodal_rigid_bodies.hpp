// Nodal rigid bodies (model-format.md `constraints`, theory.md §6.11): groups of particles that
// move as one rigid body, as LS-DYNA's *CONSTRAINED_NODAL_RIGID_BODY and its spot welds do, and
// the sections of a rigid material (LS-DYNA's *MAT_RIGID parts). Each
// step, after the particles' free velocity update, the velocities of a body's particles are
// replaced by the rigid motion of the same linear and angular momentum, with the rotation
// applied exactly so that the body keeps its shape to rounding.
#pragma once

#include <array>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct ParticleState;

class NodalRigidBodies {
public:
    /// The model's groups (`constraints` of type rigid, and the particles of each section of a
    /// rigid material), those that share a particle merged into one body (two rigid bodies
    /// joined at a particle are one).
    explicit NodalRigidBodies(const Model& model);

    [[nodiscard]] bool empty() const { return bodies_.empty(); }
    /// The bodies after merging, each a sorted list of particles.
    [[nodiscard]] const std::vector<std::vector<Index>>& bodies() const { return bodies_; }
    /// Per body, its velocity components held at zero (x, y, z, then rotations about them):
    /// those of the rigid materials merged into it (eq. 6.11-6).
    [[nodiscard]] const std::vector<std::array<bool, 6>>& fixed() const { return fixed_; }

    /// The mass the contact gives each particle (eq. 6.11-5): that of its body, or its own
    /// (`mass`) outside the bodies.
    [[nodiscard]] std::vector<Real> contact_masses(const std::vector<Real>& mass) const;

    /// Eqs. 6.11-1 to 6.11-4 (6.11-6 for a body with fixed components): the half-step velocities
    /// v^{n+1/2} and the tangent-plane angular velocities of every body's particles become one
    /// rigid motion with their linear and angular momentum about the centre of mass at x^n, such
    /// that x^{n+1} = x^n + dt v is that rigid motion exactly. The bodies run in parallel (each
    /// writes its own particles).
    void make_rigid(ParticleState& s, Real dt_new) const;

private:
    std::vector<std::vector<Index>> bodies_;
    std::vector<std::array<bool, 6>> fixed_;
};

}  // namespace fpmshell
