#include "fpmshell/solver/particle_state.hpp"

namespace fpmshell {

void ParticleState::resize(std::size_t n) {
    for (auto* f : {&x0,
                    &x,
                    &x_prev,
                    &v,
                    &v_prev,
                    &omega,
                    &omega_prev,
                    &dtheta,
                    &normal,
                    &drill_axis,
                    &f_int,
                    &m_int,
                    &f_ext,
                    &m_ext,
                    &f_ext_prev,
                    &m_ext_prev,
                    &reaction,
                    &reaction_moment,
                    &reaction_prev,
                    &reaction_moment_prev,
                    &f_contact,
                    &f_contact_prev})
        f->assign(n, Vec3::Zero());
    rotation.assign(n, Quat::Identity());
    mass.assign(n, 0.0);
    inertia.assign(n, 0.0);
    full_rotation.assign(n, 0);
}

}  // namespace fpmshell
