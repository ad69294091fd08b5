// The sweeps of the cycle over the particles (theory.md §6.6-§6.8): the central difference for
// translations and tangent-plane rotations with the constraints and their reactions, and the
// energies at t_n with the new positions x^{n+1}. Every particle on its own; sums atom by atom
// (atom_sums), so that they depend neither on the thread count nor on the ranks.
#include <algorithm>
#include <limits>

#include "fpmshell/core/exact_sum.hpp"
#include "fpmshell/core/rotation.hpp"
#include "fpmshell/solver/explicit_solver.hpp"

namespace fpmshell {

inline void ExplicitSolver::update_particle_velocity(std::size_t p, const CyclePolicy& policy,
                                                     const StepLengths& dt, Real* residual) {
    const BoundaryConditions& bc = *bc_;
    Vec3 force = s_.f_ext[p] - s_.f_int[p];
    if (contact_) force += s_.f_contact[p];
    const Real m = s_.mass[p];
    const bool constrained = bc.constrained(p);
    // v^{n+1/2} = c1 [c2 v^{n-1/2} + dt_n F / m] (§6.6); prescribed values come later.
    const Vec3 v_free = dt.c1 * (dt.c2 * s_.v_prev[p] + (dt.dt_n / m) * force);
    const Vec3 v_new = bc.without_fixed_translation(p, v_free);
    s_.v[p] = v_new;
    if (constrained) s_.reaction[p] = (m / (dt.c1 * dt.dt_n)) * (v_new - v_free);

    // Rotations in the tangent plane: w^{n+1/2} = c1 [c2 P w^{n-1/2} + dt_n P M / J] (§6.6),
    // or about the free axis of a symmetry plane.
    const Vec3 moment =
        loads_->has_moment_loads() ? Vec3(s_.m_ext[p] - s_.m_int[p]) : Vec3(-s_.m_int[p]);
    const Vec3& normal = s_.normal[p];
    const Vec3 moment_tangent = bc.tangent_part(p, moment, normal);
    const Vec3 omega_tangent = bc.tangent_part(p, s_.omega_prev[p], normal);
    const Real j = s_.inertia[p];
    // a particle of no element (a point mass alone, model-format.md `masses`) has no rotary
    // inertia: no moment turns it
    const Real turn = j > 0 ? dt.dt_n / j : Real(0);
    const Vec3 w_free = dt.c1 * (dt.c2 * omega_tangent + turn * moment_tangent);
    const Vec3 w_new =
        bc.tangent_plane_only(p) ? w_free : bc.without_constrained_rotation(p, w_free, normal);
    s_.omega[p] = w_new;
    if (constrained) s_.reaction_moment[p] = (j / (dt.c1 * dt.dt_n)) * (w_new - w_free);
    if (!policy.residual) return;

    // Out-of-balance force and moment on the free directions, against the applied ones.
    const Vec3 force_free = bc.without_constrained_translation(p, force);
    residual[0] += force_free.squaredNorm();
    residual[1] += s_.f_ext[p].squaredNorm() + (force - force_free).squaredNorm();
    const Vec3 moment_free = bc.prescribed_rotation(p)
                                 ? Vec3::Zero()
                                 : bc.without_constrained_rotation(p, moment_tangent, normal);
    const Real ls2 = length_scale_ * length_scale_;
    residual[0] += moment_free.squaredNorm() / ls2;
    residual[1] += (s_.m_ext[p].squaredNorm() + (moment_tangent - moment_free).squaredNorm()) / ls2;
}

inline void ExplicitSolver::advance_particle(std::size_t p, const StepLengths& dt, Real* energy) {
    // Energies at t_n (§6.8): leapfrog kinetic energy, work of loads and reactions over
    // [t_{n-1}, t_n] (trapezoidal), mass-damping dissipation over dt_n. A free particle has
    // no reactions; without moment loads m_ext stays zero.
    energy[0] += 0.5 * s_.mass[p] * s_.v_prev[p].dot(s_.v[p]) +
                 0.5 * s_.inertia[p] * s_.omega_prev[p].dot(s_.omega[p]);
    const bool constrained = bc_->constrained(p);
    const Real w = dt.prev_weight;  // 1, or 1/2 in the second cycle (eq. 6.8-3)
    Vec3 force_sum = w * s_.f_ext_prev[p] + s_.f_ext[p];
    Vec3 moment_sum =
        loads_->has_moment_loads() ? Vec3(w * s_.m_ext_prev[p] + s_.m_ext[p]) : Vec3::Zero();
    if (constrained) {
        force_sum = force_sum + w * s_.reaction_prev[p] + s_.reaction[p];
        moment_sum = moment_sum + w * s_.reaction_moment_prev[p] + s_.reaction_moment[p];
    }
    // The step's displacement and turn; in the first cycle those of v^{-1/2} := v^0 over dt_n,
    // with which the leapfrog kinetic energy 1/2 m v^{-1/2} v^{1/2} of t_0 counts the forces of
    // t_0 (eq. 6.8-3): an impact or a drive that acts at once is booked whole.
    const Vec3 dx = dt.first ? Vec3(dt.dt_n * s_.v_prev[p]) : Vec3(s_.x[p] - s_.x_prev[p]);
    const Vec3 dtheta = dt.first ? Vec3(dt.dt_n * s_.omega_prev[p]) : s_.dtheta[p];
    energy[1] += 0.5 * force_sum.dot(dx) + 0.5 * moment_sum.dot(dtheta);
    // The works' rounding (eq. 6.8-2): the step's displacement is a difference of positions,
    // each rounded to eps |x|, and every force the balance books acts over it.
    Real forces = 0.5 * force_sum.cwiseAbs().sum() + s_.f_int[p].cwiseAbs().sum();
    if (contact_) {
        const Vec3 contact_sum = w * s_.f_contact_prev[p] + s_.f_contact[p];
        energy[2] += 0.5 * contact_sum.dot(dx);
        forces += 0.5 * contact_sum.cwiseAbs().sum();
    }
    energy[5] += std::numeric_limits<Real>::epsilon() * s_.x[p].cwiseAbs().maxCoeff() * forces;
    if (dt.a_m > 0) {
        const Vec3 vbar = 0.5 * (s_.v_prev[p] + s_.v[p]);
        const Vec3 wbar = 0.5 * (s_.omega_prev[p] + s_.omega[p]);
        energy[3] += dt.a_m * dt.dt_n *
                     (s_.mass[p] * vbar.squaredNorm() + s_.inertia[p] * wbar.squaredNorm());
        // eq. 6.8-4: the half of the last term that the kinetic energy of t_n has not yet seen
        energy[6] += 0.5 * dt.a_m * dt.dt_n *
                     (s_.mass[p] * s_.v[p].dot(vbar) + s_.inertia[p] * s_.omega[p].dot(wbar));
    }
    if (constrained) {
        s_.reaction_prev[p] = s_.reaction[p];
        s_.reaction_moment_prev[p] = s_.reaction_moment[p];
    }
    // x^{n+1} = x^n + dt v^{n+1/2} (§6.6), written over x^{n-1} (the arrays are exchanged
    // at the end of the cycle); the rotation increment of the next path element.
    s_.x_prev[p] = s_.x[p] + dt.dt_new * s_.v[p];
    s_.dtheta[p] = dt.dt_new * s_.omega[p];
    s_.rotation[p] = rotation_quaternion(s_.dtheta[p]) * s_.rotation[p];
    if (!finite_state(p, s_.x_prev[p])) energy[4] += 1;
}

// The sums of a sweep atom by atom (solver/domain_decomposition.hpp): each atom sums its
// particles in their order, the atoms' sums are added exactly and, distributed, over the ranks:
// the same bits for any number of threads and ranks. The particles held here that another rank
// owns are updated too (their sums are that rank's).
template <int N, class Body>
std::array<Real, N> ExplicitSolver::atom_sums(std::vector<std::array<Real, N>>& scratch,
                                              Body&& body) {
    const DomainDecomposition& d = ranks_.decomposition();
    const auto n_atoms = static_cast<Index>(d.own_atoms.size());
    const auto n_shared = static_cast<Index>(d.held_not_owned.size());
    scratch.resize(static_cast<std::size_t>(n_atoms));
    [[maybe_unused]] const bool parallel = parallel_particles_;
#pragma omp parallel if (parallel)
    {
#pragma omp for schedule(static) nowait
        for (Index i = 0; i < n_atoms; ++i) {
            const auto a = static_cast<std::size_t>(d.own_atoms[static_cast<std::size_t>(i)]);
            std::array<Real, N> acc{};
            for (Index k = d.atom_particle_begin[a]; k < d.atom_particle_begin[a + 1]; ++k)
                body(d.atom_particles[static_cast<std::size_t>(k)], acc);
            scratch[static_cast<std::size_t>(i)] = acc;
        }
#pragma omp for schedule(static)
        for (Index i = 0; i < n_shared; ++i) {
            std::array<Real, N> ignored{};
            body(d.held_not_owned[static_cast<std::size_t>(i)], ignored);
        }
    }
    std::array<ExactSum, N> exact;
    for (const std::array<Real, N>& part : scratch)
        for (std::size_t k = 0; k < exact.size(); ++k) exact[k].add(part[k]);
    ranks_.sum(exact);
    std::array<Real, N> total{};
    for (std::size_t k = 0; k < total.size(); ++k) total[k] = exact[k].value();
    return total;
}

ExplicitSolver::ParticleSums ExplicitSolver::update_velocities_and_advance_particles(
    const CyclePolicy& policy, const StepLengths& dt) {
    // v^{n-1/2} and w^{n-1/2} become the previous half-step values by exchanging the arrays
    // (every particle's new value is written below).
    std::swap(s_.v, s_.v_prev);
    std::swap(s_.omega, s_.omega_prev);
    // the energies of advance_particle in 0 ... 6, the residuals in 7 and 8
    const std::array<Real, 9> sums = atom_sums<9>(sums9_, [&](Index ip, std::array<Real, 9>& acc) {
        const std::size_t p = static_cast<std::size_t>(ip);
        update_particle_velocity(p, policy, dt, acc.data() + 7);
        advance_particle(p, dt, acc.data());
    });
    return {sums[0], sums[1], sums[2], sums[3], sums[4], sums[5], sums[7], sums[8], sums[6]};
}

ExplicitSolver::ParticleSums ExplicitSolver::update_velocities(const CyclePolicy& policy,
                                                               const StepLengths& dt) {
    std::swap(s_.v, s_.v_prev);
    std::swap(s_.omega, s_.omega_prev);
    const std::array<Real, 2> residual =
        atom_sums<2>(sums2_, [&](Index ip, std::array<Real, 2>& acc) {
            update_particle_velocity(static_cast<std::size_t>(ip), policy, dt, acc.data());
        });
    ParticleSums sums;
    sums.residual2 = residual[0];
    sums.reference2 = residual[1];
    return sums;
}

Real ExplicitSolver::kinetic_measure() {
    return atom_sums<1>(sums1_, [&](Index ip, std::array<Real, 1>& acc) {
        const auto p = static_cast<std::size_t>(ip);
        acc[0] += s_.mass[p] * s_.v[p].squaredNorm() + s_.inertia[p] * s_.omega[p].squaredNorm();
    })[0];
}

void ExplicitSolver::advance_particles(const StepLengths& dt, ParticleSums& sums) {
    const std::array<Real, 7> energy =
        atom_sums<7>(sums7_, [&](Index ip, std::array<Real, 7>& acc) {
            advance_particle(static_cast<std::size_t>(ip), dt, acc.data());
        });
    sums.kinetic = energy[0];
    sums.external_work = energy[1];
    sums.contact_work = energy[2];
    sums.damping = energy[3];
    sums.non_finite = energy[4];
    sums.rounding = energy[5];
    sums.damping_ahead = energy[6];
}

}  // namespace fpmshell
