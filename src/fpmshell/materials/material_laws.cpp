// The registry of material laws: one line per law folder (material_law.hpp).
#include <stdexcept>

#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/materials/elastic/elastic_law.hpp"
#include "fpmshell/materials/johnson_cook/johnson_cook_law.hpp"
#include "fpmshell/materials/material_law.hpp"
#include "fpmshell/materials/plastic_damage/plastic_damage_law.hpp"
#include "fpmshell/materials/power_law/power_law_law.hpp"
#include "fpmshell/materials/rigid/rigid_law.hpp"
#include "fpmshell/materials/tabulated/tabulated_law.hpp"

namespace fpmshell {

namespace {
std::vector<MaterialLaw>& registry() {
    static std::vector<MaterialLaw> laws = {
        elastic_law(),         // materials/elastic
        bilinear_law(),        // materials/bilinear: j2_plastic
        johnson_cook_law(),    // materials/johnson_cook
        tabulated_law(),       // materials/tabulated
        power_law_law(),       // materials/power_law
        plastic_damage_law(),  // materials/plastic_damage
        rigid_law(),           // materials/rigid
    };
    return laws;
}
}  // namespace

const std::vector<MaterialLaw>& material_laws() { return registry(); }

const MaterialLaw* find_material_law(std::string_view name) {
    for (const MaterialLaw& law : registry())
        if (law.name == name) return &law;
    return nullptr;
}

const MaterialLaw& material_law(const Material& material) {
    const MaterialLaw* law = find_material_law(material.law);
    if (!law) throw std::logic_error("material '" + material.name + "' of no known law");
    return *law;
}

bool register_material_law(MaterialLaw law) {
    if (find_material_law(law.name))
        throw std::logic_error("a second material law named '" + law.name + "'");
    registry().push_back(std::move(law));
    return true;
}

}  // namespace fpmshell
