// The damage of the criteria that sum the plastic strain over a failure strain (theory.md eqs.
// 7.6-2, 7.6-3): per point, D += d alpha / eps_f over the steps where the point flows, the
// failure strain at the state after the step; failed at D = 1. Their state per point: D, then
// the plastic strain at the last step ([number][pack]).
#pragma once

#include "fpmshell/failure/failure_criterion.hpp"

namespace fpmshell {

/// The step of `in`'s points (state: 2 x in.m packs), failure_strain(j, d_alpha, flowing) the
/// failure strain of pack j's flowing lanes (its other lanes are not read). Adds the failed
/// lanes to `failed`; whether some lane has failed.
template <class FailureStrain>
bool accumulate_damage(const FailurePacks& in, RealPack* state, MaskOf<RealPack>* failed,
                       const FailureStrain& failure_strain) {
    RealPack* damage = state;              // D of every point
    RealPack* last_strain = state + in.m;  // the plastic strain at the last step
    bool any = false;
    for (std::size_t j = 0; j < in.m; ++j) {
        const RealPack alpha = in.plastic_strain[j];
        const RealPack d_alpha = alpha - last_strain[j];
        const MaskOf<RealPack> flowing = d_alpha > 0.0;
        if (any_lane(flowing)) {  // a point that does not flow costs this comparison alone
            const RealPack eps = failure_strain(j, d_alpha, flowing);
            damage[j] += select(flowing, d_alpha / eps, RealPack(0.0));
            last_strain[j] = select(flowing, alpha, last_strain[j]);
        }
        const MaskOf<RealPack> f = damage[j] >= 1.0;
        if (!any_lane(f)) continue;
        failed[j] = failed[j] || f;
        any = true;
    }
    return any;
}

}  // namespace fpmshell
