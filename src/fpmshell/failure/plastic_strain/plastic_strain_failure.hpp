// Failure by plastic strain (theory.md §7.6): a point has failed once its equivalent plastic
// strain reaches the material's failure strain (`failure: {plastic_strain: eps_f}`; LS-DYNA's
// *MAT_003 FS, *MAT_024 FAIL, *MAT_018 EPSF; OpenRadioss' eps_p_max of /MAT/LAW2).
#pragma once

#include "fpmshell/failure/failure_criterion.hpp"

namespace fpmshell {

class PlasticStrainFailure final : public PointFailure {
public:
    explicit PlasticStrainFailure(Real strain) : strain_(strain) {}
    bool judge(const FailurePacks& in, Real /*dt*/, RealPack* /*state*/,
               MaskOf<RealPack>* failed) const override {
        bool any = false;
        for (std::size_t j = 0; j < in.m; ++j) {
            const MaskOf<RealPack> f = in.plastic_strain[j] >= strain_;
            if (!any_lane(f)) continue;
            failed[j] = failed[j] || f;
            any = true;
        }
        return any;
    }

private:
    Real strain_;  ///< the failure strain, > 0
};

[[nodiscard]] FailureCriterion plastic_strain_criterion();
/// Adds failure at that plastic strain to a material (models made in code).
void add_plastic_strain_failure(Material& m, Real strain);

}  // namespace fpmshell
