// Coulomb friction of the Lagrange-multiplier contacts (theory.md §8.4): the slip of a
// constraint's slave against its body or face point, and the tangential multiplier that stops it
// within the Coulomb cone, applied in the same Gauss-Seidel sweep as the normal one.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fpmshell/contact/contact_solver.hpp"

namespace fpmshell {

Vec3 ContactSolver::tangential_slip(const Constraint& c, const std::vector<Vec3>& x,
                                    const std::vector<Vec3>& x_pred,
                                    const std::vector<Vec3>& body_u_pred,
                                    const std::vector<RigidBodyState>& bodies) const {
    const auto us = static_cast<std::size_t>(c.slave);
    Vec3 slip = x_pred[us] - x[us];
    if (c.element >= 0)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto um = static_cast<std::size_t>(c.master[k]);
            slip -= c.xi[k] * (x_pred[um] - x[um]);
        }
    if (c.body >= 0) {
        const auto b = static_cast<std::size_t>(c.body);
        slip -= body_u_pred[b] - bodies[b].u;
    }
    return slip - c.normal.dot(slip) * c.normal;
}

Vec3 ContactSolver::slide(const Constraint& c, Vec3& lambda_t, const std::vector<Vec3>& x,
                          std::vector<Vec3>& x_pred, std::vector<Vec3>& body_u_pred,
                          const std::vector<RigidBodyState>& bodies, Real beta_particle,
                          Real beta_body, std::int64_t stamp) {
    const auto us = static_cast<std::size_t>(c.slave);
    const Real body_inv_mass = c.body >= 0 ? bodies[static_cast<std::size_t>(c.body)].inv_mass : 0;
    // the slave's slip against the body or the face point over the step (eq. 8.4-1)
    const Vec3 slip = tangential_slip(c, x, x_pred, body_u_pred, bodies);
    Vec3 trial = lambda_t;
    if (const Real length = slip.norm(); length > 0) {
        // the multiplier that stops the slip, with the weight along it (eq. 8.4-2)
        const Vec3 t = slip / length;
        const Real w = weight_along(c, t, beta_particle, beta_body, bodies);
        if (w > 0) trial += (length / w) * t;
    }
    // the Coulomb cone (eq. 8.4-3); no force without a normal one, whatever the coefficient
    const Real bound = c.lambda > 0 ? c.friction * c.lambda : 0.0;
    if (const Real size = trial.norm(); size > bound) trial *= bound / size;
    const Vec3 change = trial - lambda_t;
    if (change.squaredNorm() == 0) return change;
    lambda_t = trial;
    // the slave moves as under a force -change, the face's corners under xi_k change, the body
    // under change (eq. 8.4-4)
    x_pred[us] -= beta_particle * inv_mass_[us].cwiseProduct(change);
    particle_moved_at_[us] = stamp;
    if (c.element >= 0)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto um = static_cast<std::size_t>(c.master[k]);
            x_pred[um] += (beta_particle * c.xi[k]) * inv_mass_[um].cwiseProduct(change);
            particle_moved_at_[um] = stamp;
        }
    if (body_inv_mass > 0) {
        const auto b = static_cast<std::size_t>(c.body);
        body_u_pred[b] += (beta_body * body_inv_mass) * change;
        body_moved_at_[b] = stamp;
    }
    return change;
}

Vec3 ContactSolver::penalty_friction(const Constraint& c, const std::vector<Vec3>& v,
                                     const std::vector<RigidBodyState>& bodies, Real beta_particle,
                                     Real beta_body, Real dt_new) const {
    const ContactDefinition& def = definitions_[c.definition].def;
    if (!(def.friction > 0) || !(c.lambda > 0) || !(dt_new > 0)) return Vec3::Zero();
    // the slave's velocity v^{n-1/2} against the face point's or the body's, in the tangent plane
    const auto us = static_cast<std::size_t>(c.slave);
    Vec3 relative = v[us];
    if (c.element >= 0)
        for (std::size_t k = 0; k < 3; ++k)
            relative -= c.xi[k] * v[static_cast<std::size_t>(c.master[k])];
    if (c.body >= 0) relative -= bodies[static_cast<std::size_t>(c.body)].v;
    const Vec3 sliding = relative - c.normal.dot(relative) * c.normal;
    const Real speed = sliding.norm();
    if (!(speed > 0)) return Vec3::Zero();
    // eq. 8.4-6: Coulomb's mu lambda, at most the force that stops the sliding within the step
    // (the weight along it as eq. 8.4-2's), so that friction never turns the slip round
    const Vec3 t = sliding / speed;
    const Real w = weight_along(c, t, beta_particle, beta_body, bodies);
    const Real mu = def.friction_decay > 0
                        ? def.friction_dynamic + (def.friction - def.friction_dynamic) *
                                                     std::exp(-def.friction_decay * speed)
                        : def.friction;
    const Real stop = w > 0 ? speed * dt_new / w : std::numeric_limits<Real>::infinity();
    return -std::min(mu * c.lambda, stop) * t;
}

}  // namespace fpmshell
