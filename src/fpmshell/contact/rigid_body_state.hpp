// Motion of the rigid bodies (model-format.md `rigid_bodies`): each is one extra particle of
// mass M with translations only (theory.md §8.3), moved by the central difference like the
// shell particles and by the contact forces it receives; a fixed body has 1/M = 0.
#pragma once

#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct RigidBodyState {
    Vec3 u = Vec3::Zero();       ///< displacement of the face point at t_n
    Vec3 u_prev = Vec3::Zero();  ///< at t_{n-1}
    Vec3 v = Vec3::Zero();       ///< v^{n+1/2} after the cycle
    Vec3 v_prev = Vec3::Zero();  ///< v^{n-1/2}
    Vec3 force = Vec3::Zero();   ///< contact force on the body at t_n
    Vec3 force_prev = Vec3::Zero();
    Real inv_mass = 0;  ///< 0 for a fixed body
    Real mass = 0;      ///< 0 for a fixed body (kinetic energy not counted)

    [[nodiscard]] static std::vector<RigidBodyState> from_model(const Model& model) {
        std::vector<RigidBodyState> bodies;
        for (const RigidBody& b : model.rigid_bodies) {
            RigidBodyState s;
            s.v = s.v_prev = b.velocity;
            s.mass = b.fixed ? 0.0 : b.mass;
            s.inv_mass = b.fixed ? 0.0 : 1.0 / b.mass;
            bodies.push_back(s);
        }
        return bodies;
    }
};

/// Members for a restart file (io/restart_archive.hpp).
template <class Archive>
void transfer(Archive& ar, RigidBodyState& b) {
    ar(b.u, b.u_prev, b.v, b.v_prev, b.force, b.force_prev, b.inv_mass, b.mass);
}

}  // namespace fpmshell
