// What differs between a dynamic step and an iteration of dynamic relaxation (theory.md §6.8,
// §6.9), decided once per call of the cycle instead of at every place it matters.
#pragma once

#include <algorithm>

#include "fpmshell/core/types.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct CyclePolicy {
    bool relaxation = false;
    /// Factor on the smallest element step (§6.4). Relaxation caps it at 0.75, inside the
    /// provably stable 0.8: with a mode close to its stability limit, kinetic damping never
    /// removes it and the residual stalls.
    Real step_scale = 0.9;
    bool cap_step_growth = true;  ///< dt_{n+1/2} <= 1.2 dt_{n-1/2} (dynamic)
    Real mass_damping = 0;        ///< a_m (§6.6); none in relaxation, kinetic damping instead
    /// The path element lasts dt_{n-1/2} and rates follow from it; relaxation steps are
    /// fictitious time without rate effects.
    bool rate_effects = true;
    /// Loads and prescribed motions at t_n, t_{n+1/2}, t_{n+1} (dynamic) or all at the load
    /// level (relaxation).
    bool advance_time = true;
    /// The out-of-balance force is summed in the particle update (the convergence test of the
    /// relaxation is its only reader).
    bool residual = false;

    static CyclePolicy dynamic(const Model& model) {
        CyclePolicy p;
        p.step_scale = model.control.time_step_scale;
        p.mass_damping = model.damping.mass;
        return p;
    }
    static CyclePolicy relaxing(const Model& model) {
        CyclePolicy p;
        p.relaxation = true;
        p.step_scale = std::min(model.control.time_step_scale, k_relaxation_step_scale);
        p.cap_step_growth = false;
        p.mass_damping = 0;
        p.rate_effects = false;
        p.advance_time = false;
        p.residual = true;
        return p;
    }
    static constexpr Real k_relaxation_step_scale = 0.75;
};

}  // namespace fpmshell
