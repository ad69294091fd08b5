#include "fpmshell/materials/elastic/elastic_law.hpp"

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/materials/elastic/elastic_block_loads.hpp"
#include "fpmshell/solver/element_group.hpp"

namespace fpmshell {

namespace {

void read_nothing(const YamlMap& /*keys*/, Material& /*material*/) {}

/// *MAT_ELASTIC: MID, RO, E, PR.
void mat_elastic(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR");
    card.id(f);
    card.key("type: elastic");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
}

}  // namespace

std::unique_ptr<ElementGroup> make_elastic_group(const Model& model, std::size_t section) {
    const Material& m = model.materials[static_cast<std::size_t>(model.sections[section].material)];
    return std::make_unique<MaterialGroup<LinearElastic>>(
        LinearElastic(m.youngs_modulus, m.poisson_ratio), model, section);
}

MaterialLaw elastic_law() {
    return {"elastic",
            false,
            {},
            read_nothing,
            make_elastic_group,
            {{{"MAT_ELASTIC", "MAT_001"}, mat_elastic}}};
}

}  // namespace fpmshell
