// State of the particles, one contiguous array per field (structure of arrays: each particle
// loop streams only the fields it reads).
// Time levels: x = x^n, x_prev = x^{n-1}, v = v^{n-1/2} (before the update) / v^{n+1/2} (after),
// dtheta = rotation increment over the last step (input of the next path element, §6.6).
#pragma once

#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct ParticleState {
    std::vector<Vec3> x0;      ///< initial positions
    std::vector<Vec3> x;       ///< x^n
    std::vector<Vec3> x_prev;  ///< x^{n-1}: base configuration of the path element
    std::vector<Vec3> v;       ///< half-step velocity
    std::vector<Vec3> v_prev;  ///< previous half-step velocity (accelerations, kinetic energy)
    std::vector<Vec3> omega;   ///< half-step angular velocity (global vector, tangent plane)
    std::vector<Vec3> omega_prev;
    std::vector<Vec3> dtheta;    ///< rotation increment of the last step (global vector)
    std::vector<Quat> rotation;  ///< accumulated rotation, a unit quaternion (output only)
    std::vector<Vec3> normal;    ///< tangent-plane normal n_alpha at t_n (§1.3)
    /// Unit axis about which the rotation increment `dtheta` is no degree of freedom, zero where
    /// it is complete (§2.6, eq. 2.6c): the next path element gives the node its own rigid
    /// rotation about it. Derived from `normal` and the constraints (not in restart files).
    std::vector<Vec3> drill_axis;
    std::vector<Vec3> f_int, m_int;  ///< internal force / moment at t_n
    std::vector<Vec3> f_ext, m_ext;  ///< external force / moment at t_n
    std::vector<Vec3> f_ext_prev,
        m_ext_prev;  ///< the same at t_{n-1} (m_ext_prev kept with moment loads only)
    std::vector<Vec3> reaction, reaction_moment;  ///< constraint force / moment at t_n
    std::vector<Vec3> reaction_prev, reaction_moment_prev;
    std::vector<Vec3> f_contact, f_contact_prev;  ///< contact force at t_n, t_{n-1} (§8)
    std::vector<Real> mass;                       ///< m_alpha (§6.1)
    std::vector<Real> inertia;                    ///< J_alpha (§6.2, option B)
    std::vector<std::uint8_t> full_rotation;  ///< kink particle: 3 rotations, no projection (§1.3)

    void resize(std::size_t n);
    [[nodiscard]] std::size_t size() const { return x.size(); }
};

/// Every field, for a restart file (io/restart_archive.hpp).
template <class Archive>
void transfer(Archive& ar, ParticleState& s) {
    ar(s.x0, s.x, s.x_prev, s.v, s.v_prev, s.omega, s.omega_prev, s.dtheta);
    ar(s.rotation);
    ar(s.normal);
    ar(s.f_int, s.m_int, s.f_ext, s.m_ext, s.f_ext_prev, s.m_ext_prev, s.reaction,
       s.reaction_moment);
    ar(s.reaction_prev, s.reaction_moment_prev, s.f_contact, s.f_contact_prev, s.mass, s.inertia,
       s.full_rotation);
}

}  // namespace fpmshell
