// The penalty contact (theory.md §8.2, the fallback of the Lagrange multipliers): a force at t_n
// proportional to each pair's penetration, with its explicit friction (eq. 8.4-6).
#include <algorithm>

#include "fpmshell/contact/contact_solver.hpp"
#include "fpmshell/contact/stopwatch.hpp"

namespace fpmshell {

void ContactSolver::penalty_forces(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                   const std::vector<Vec3>& body_u,
                                   std::vector<RigidBodyState>& bodies, Real beta_particle,
                                   Real beta_body, Real dt_new, Real motion, long step,
                                   std::vector<Vec3>& f_contact) {
    Stopwatch watch(stats_.seconds);
    constraints_.clear();
    for (Definition& d : definitions_) {
        if (d.def.method != ContactMethod::Penalty) continue;
        const std::size_t first = constraints_.size();
        slave_force_[definition_index(d)].setZero();
        if (d.def.type == ContactType::Self) {
            prepare_search(d, x, motion);
            collect_self(d, x, x, false, constraints_, closed_);
        } else {
            collect_rigid(d, x, body_u, false, constraints_);
        }
        for (std::size_t i = first; i < constraints_.size(); ++i) {
            Constraint& c = constraints_[i];
            c.definition = definition_index(d);
            const Real w = weight(c, beta_particle, beta_body, bodies);
            if (!(w > 0) || !(c.gap < 0)) continue;
            // scale x the force that would remove the whole penetration in one step
            c.lambda = d.def.penalty_scale * (-c.gap) / w;
            note_penetration(-c.gap, c, step);
        }
    }
    for (const Constraint& c : constraints_) {
        const Vec3 force =
            c.lambda * c.normal + penalty_friction(c, v, bodies, beta_particle, beta_body, dt_new);
        f_contact[static_cast<std::size_t>(c.slave)] += force;
        slave_force_[c.definition] += force;
        if (c.element >= 0)
            for (std::size_t k = 0; k < 3; ++k)
                f_contact[static_cast<std::size_t>(c.master[k])] -= c.xi[k] * force;
        if (c.body >= 0) bodies[static_cast<std::size_t>(c.body)].force -= force;
    }
    stats_.active =
        static_cast<long>(std::count_if(constraints_.begin(), constraints_.end(),
                                        [](const Constraint& c) { return c.lambda > 0; }));
    stats_.max_active = std::max(stats_.max_active, stats_.active);
}

}  // namespace fpmshell
