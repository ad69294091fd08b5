// Energy bookkeeping of a run (energy.csv columns of model-format.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct EnergyBalance {
    Real kinetic = 0;  ///< at t_n: 1/2 v^{n-1/2}.M v^{n+1/2} (+ rotational), the leapfrog invariant
    Real internal = 0;       ///< work of the stresses (strain energy for elastic material)
    Real plastic = 0;        ///< dissipated by plasticity (0 for elastic material)
    Real external_work = 0;  ///< work of loads and supports, plus the initial kinetic energy
    Real damping = 0;        ///< dissipated by Rayleigh damping
    Real contact = 0;        ///< dissipated by contact (0 without contact)
    /// the strain work of the elements eroded so far (theory.md §7.6), no longer in `internal`
    Real eroded_internal = 0;
    /// What rounding alone can put into the balance so far (theory.md eq. 6.8-2): the steps
    /// taken times this step's rounding of the works. Not a result: it is recomputed every step
    /// (and not kept in restart files).
    Real rounding = 0;
    /// The part of `damping` booked ahead of the kinetic energy (theory.md eq. 6.8-4): the sum
    /// over the particles of a_m dt_n m v^{n+1/2}.vbar^n / 2. Recomputed every step (not kept
    /// in restart files).
    Real damping_ahead = 0;

    /// What mass and stiffness damping have dissipated up to t_n, in step with the leapfrog
    /// kinetic energy (eq. 6.8-4).
    [[nodiscard]] Real dissipated_by_damping() const { return damping - damping_ahead; }

    /// (kinetic + internal + eroded internal - external work + damped + contact) / max(kinetic,
    /// internal, external, rounding) (theory.md eq. 6.8-1). The rounding floor keeps the ratio of a
    /// model that does not move (held by friction, in equilibrium) from being a ratio of rounding
    /// errors: there every energy is of the order of the last bits of the positions.
    [[nodiscard]] Real error() const {
        const Real scale =
            std::max({std::abs(kinetic), std::abs(internal), std::abs(external_work), rounding});
        if (scale <= 0) return 0;
        return (kinetic + internal + eroded_internal - external_work + dissipated_by_damping() +
                contact) /
               scale;
    }
};

/// Members for a restart file (io/restart_archive.hpp).
template <class Archive>
void transfer(Archive& ar, EnergyBalance& e) {
    ar(e.kinetic, e.internal, e.plastic, e.external_work, e.damping, e.contact, e.eroded_internal);
}

}  // namespace fpmshell
