// `type: johnson_cook`: J2 plasticity on sigma = (A + B eps_p^n)(1 + C ln(rate / rate_0)),
// optionally times 1 - T*^m with the temperature of adiabatic heating (theory.md §7.2, eqs.
// 7.4-1, 7.4-2); LS-DYNA's *MAT_JOHNSON_COOK (015).
#pragma once

#include "fpmshell/materials/j2/j2_parameters.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell {

[[nodiscard]] MaterialLaw johnson_cook_law();
/// Makes `m` a johnson_cook material of A, B, n (rate term C at reference_rate where C > 0);
/// returns its J2 constants for further changes.
J2Parameters& make_johnson_cook(Material& m, Real a, Real b, Real n, Real c = 0,
                                Real reference_rate = 1);
/// Thermal softening by adiabatic heating (eq. 7.4-2): the exponent m, the melting and room
/// temperatures, the specific heat and the Taylor-Quinney fraction chi, for the density rho.
[[nodiscard]] ThermalSoftening adiabatic_softening(Real m, Real melt_temperature,
                                                   Real room_temperature, Real specific_heat,
                                                   Real taylor_quinney, Real density);

}  // namespace fpmshell
