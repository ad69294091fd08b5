// Failure by plastic strain (theory.md §7.6): a point has failed once its equivalent plastic
// strain reaches the material's failure strain (LS-DYNA's *MAT_003 FS, *MAT_024 FAIL,
// *MAT_018 EPSF; OpenRadioss' eps_p_max of /MAT/LAW2).
#pragma once

#include "fpmshell/core/types.hpp"

namespace fpmshell {

struct PlasticStrainFailure {
    Real strain = 0;  ///< the failure strain, > 0

    [[nodiscard]] bool failed(Real plastic_strain) const { return plastic_strain >= strain; }
};

}  // namespace fpmshell
