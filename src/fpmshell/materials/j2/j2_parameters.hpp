// The constants of the J2 laws (j2_plastic, johnson_cook, tabulated, power_law; theory.md §7):
// the flow curve each law's folder builds, the rate and temperature factors, the hardening
// mix and Hill's R; and what the laws share: their common keys and their element group.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "fpmshell/materials/j2/flow_stress.hpp"
#include "fpmshell/materials/j2/j2_plastic.hpp"
#include "fpmshell/materials/j2/thermal_softening.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

class ElementGroup;
class YamlMap;
class YamlValue;

struct J2Parameters {
    FlowStress flow;
    RateFactor rate;
    ThermalSoftening thermal;
    Real hardening_mix = 1;      ///< beta: 1 isotropic, 0 kinematic (§7.2)
    Real normal_anisotropy = 1;  ///< Hill's R (eq. 7.1-3); 1: von Mises
};

/// The J2 constants of a material, nullptr if its law is not a J2 law.
[[nodiscard]] inline const J2Parameters* j2_parameters(const Material& m) {
    return std::any_cast<J2Parameters>(&m.parameters);
}
/// Makes `m` a material of the J2 law `law` with the constants p; returns them for changes.
J2Parameters& set_j2_parameters(Material& m, const std::string& law, const J2Parameters& p);

/// The keys every J2 law reads: hardening_mix and normal_anisotropy.
void read_j2_common(const YamlMap& keys, J2Parameters& p);
/// `cowper_symonds: {D, q}` or `rate_scaling: [[rate, factor], ...]` (the laws without a rate
/// term of their own; not both).
void read_cowper_symonds(const YamlMap& keys, J2Parameters& p);
/// `rate_scaling`: the factor on the yield stress against the strain rate (eq. 7.4-3).
void read_rate_scaling(const YamlValue& v, J2Parameters& p);

/// The J2 material of a material of a J2 law (its scalar update and its block path).
[[nodiscard]] J2Plastic make_j2_plastic(const Material& m);
/// The element group of a section of a J2 law (the SIMD block path of j2_block_loads.hpp).
[[nodiscard]] std::unique_ptr<ElementGroup> make_j2_group(const Model& model, std::size_t section);

}  // namespace fpmshell
