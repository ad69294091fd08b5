// A material law as the rest of the code sees it: its name in the model file, its keys and
// their checks, the deck cards that map to it, and the element group of its sections (its
// point-state layout and its return mapping, solver/element_group.hpp). Each law is a folder
// under materials/ that makes one MaterialLaw, and one line of material_laws.cpp lists it.
//
// A law outside the library (a test's, a user's build) joins with register_material_law before
// the model is read.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fpmshell/model/model.hpp"

namespace fpmshell {

class ElementGroup;
class YamlMap;
namespace deck {
class MaterialCard;
}

/// A card of an LS-DYNA deck that becomes a material of this law: its keywords (the long name
/// first, then the numbered alias, without `*` and `_TITLE`), and its translation into the
/// law's keys (io/lsdyna/deck_material_card.hpp).
struct DeckMaterialCard {
    std::vector<std::string> keywords;
    void (*translate)(deck::MaterialCard& card) = nullptr;
};

struct MaterialLaw {
    std::string name;  ///< its `type` in the model file
    /// a plastic law: it dissipates plastic work, takes `failure`, and its sections default
    /// to 5 points through the thickness
    bool plastic = false;
    /// its keys beyond type, density, youngs_modulus and poisson_ratio (and `failure` for a
    /// plastic law)
    std::vector<std::string> keys;
    /// Reads its keys, checked, into the material (`parameters` and whatever of the common
    /// members it sets); density, youngs_modulus and poisson_ratio are read before.
    void (*read)(const YamlMap& keys, Material& material) = nullptr;
    /// The element group of section `section` of the model (a section of this law).
    std::unique_ptr<ElementGroup> (*make_group)(const Model& model, std::size_t section) = nullptr;
    /// The deck cards that map to it (none: it is not read from decks).
    std::vector<DeckMaterialCard> deck_cards{};
};

/// Every law, those of material_laws.cpp first, then those registered, in their order.
[[nodiscard]] const std::vector<MaterialLaw>& material_laws();
/// The law of that name, nullptr if none.
[[nodiscard]] const MaterialLaw* find_material_law(std::string_view name);
/// The law of a material of the model (its `law` must be a known one: the model reader checks).
[[nodiscard]] const MaterialLaw& material_law(const Material& material);
/// Adds a law (before any model is read; a second law of the same name is refused with
/// std::logic_error). Returns true, for a registration at namespace scope.
bool register_material_law(MaterialLaw law);

}  // namespace fpmshell
