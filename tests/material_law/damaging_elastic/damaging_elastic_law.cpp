// The test-only law's model keys, its element group, and its registry line.
#include <memory>

#include "damaging_elastic.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/materials/material_law.hpp"
#include "fpmshell/solver/element_group.hpp"

namespace fpmshell::test {

namespace {

/// `damage_strain` (kappa_0 > 0) and `residual_fraction` (r in (0, 1]).
void read_damaging_elastic(const YamlMap& keys, Material& m) {
    DamagingElasticParameters p;
    p.damage_strain =
        keys.at("damage_strain", "the strain norm where damage starts, > 0").positive();
    const YamlValue r =
        keys.at("residual_fraction", "the stiffness left at full damage, in (0, 1]");
    p.residual_fraction = r.positive();
    if (p.residual_fraction > 1) r.fail("must be in (0, 1], got " + r.describe());
    m.parameters = p;
}

std::unique_ptr<ElementGroup> make_damaging_elastic_group(const Model& model, std::size_t section) {
    const Material& m = model.materials[static_cast<std::size_t>(model.sections[section].material)];
    return std::make_unique<MaterialGroup<DamagingElastic>>(
        DamagingElastic(m.youngs_modulus, m.poisson_ratio,
                        std::any_cast<const DamagingElasticParameters&>(m.parameters)),
        model, section);
}

}  // namespace

// The registry line: the law joins those of src/fpmshell/materials/material_laws.cpp.
[[maybe_unused]] const bool k_registered =
    register_material_law({"damaging_elastic_test",
                           false,
                           {"damage_strain", "residual_fraction"},
                           read_damaging_elastic,
                           make_damaging_elastic_group});

}  // namespace fpmshell::test
