// Thresholds on a point's stress and strain (theory.md eq. 7.6-5; LS-DYNA's *MAT_ADD_EROSION
// MXPRES, MNPRES, SIGP1, SIGVM, MXEPS, MNEPS, EFFEPS, VOLEPS, EPSSH, FAILTM, NCS): a point fails
// for good once `conditions` of its thresholds are passed at once, or once the time reaches
// `time`. The stress is the point's plane stress (pressure p = -(sxx + syy) / 3); the strain is
// its total strain, the elastic part from the stress by Hooke's law and the plastic part summed
// from the step's plastic strain along the flow direction 3 s / (2 sigma_vm) at the end of the
// step (the direction of the radial return), its through-thickness component from plastic
// incompressibility. Its state per point: the failed flag, and with strain thresholds the
// plastic strain at the last step and the plastic strain tensor (xx, yy, xy).
#pragma once

#include <optional>

#include "fpmshell/failure/failure_criterion.hpp"

namespace fpmshell {

struct ThresholdsFailureParameters {
    std::optional<Real> max_pressure, min_pressure;                  ///< MXPRES, MNPRES
    std::optional<Real> max_principal_stress, max_von_mises_stress;  ///< SIGP1, SIGVM
    std::optional<Real> max_principal_strain, min_principal_strain;  ///< MXEPS, MNEPS
    std::optional<Real> max_effective_strain;                        ///< EFFEPS
    std::optional<Real> volumetric_strain;  ///< VOLEPS: > 0 in tension, < 0 in compression
    std::optional<Real> max_shear_strain;   ///< EPSSH, tensorial: (eps_1 - eps_3) / 2
    std::optional<Real> thinning_strain;    ///< *MAT_123 EPSTHIN: -eps_zz at failure (> 0)
    std::optional<Real> time;               ///< FAILTM
    int conditions = 1;                     ///< NCS: thresholds passed at once to fail

    [[nodiscard]] bool reads_strain() const {
        return max_principal_strain || min_principal_strain || max_effective_strain ||
               volumetric_strain || max_shear_strain || thinning_strain;
    }
};

class ThresholdsFailure final : public PointFailure {
public:
    ThresholdsFailure(const ThresholdsFailureParameters& p, Real youngs_modulus, Real poisson_ratio)
        : p_(p), e_(youngs_modulus), nu_(poisson_ratio) {}

    [[nodiscard]] std::size_t state_fields() const override { return p_.reads_strain() ? 5 : 1; }
    [[nodiscard]] bool reads_point() const override { return true; }
    bool judge(const FailurePacks& in, Real dt, RealPack* state,
               MaskOf<RealPack>* failed) const override;

private:
    ThresholdsFailureParameters p_;
    Real e_, nu_;
};

[[nodiscard]] FailureCriterion thresholds_criterion();

}  // namespace fpmshell
