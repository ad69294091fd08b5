// `type: tabulated`: J2 plasticity on a piecewise-linear flow curve, or one per strain rate
// (theory.md §7.2, eqs. 7.2-4, 7.2-5); LS-DYNA's *MAT_PIECEWISE_LINEAR_PLASTICITY (024) and,
// with Hill's normal anisotropy, *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037) (each a
// j2_plastic material where its card gives SIGY and ETAN instead of a curve).
#pragma once

#include <vector>

#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

/// A tabulated flow curve: the flow stress at increasing plastic strains from 0, not
/// decreasing, at one strain rate.
struct FlowCurvePoints {
    Real strain_rate = 0;
    std::vector<Real> strain, stress;
};

[[nodiscard]] MaterialLaw tabulated_law();
/// The J2 constants of its keys (flow_curve or flow_curves, hardening_mix, cowper_symonds,
/// normal_anisotropy), checked: for the laws built on its curves.
[[nodiscard]] J2Parameters tabulated_parameters(const YamlMap& keys);
/// The J2 constants of one curve, or of one per rate (rates increasing).
[[nodiscard]] J2Parameters tabulated_flow(const std::vector<FlowCurvePoints>& curves);
/// Makes `m` a tabulated material of one curve, or of one per rate (rates increasing); returns
/// its J2 constants for further changes.
J2Parameters& make_tabulated(Material& m, const std::vector<FlowCurvePoints>& curves);

}  // namespace fpmshell
