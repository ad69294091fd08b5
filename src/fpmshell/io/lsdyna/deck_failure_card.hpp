// What a failure criterion's deck card translation (failure/<criterion>/, failure_criterion.hpp)
// sees of the deck: the card's block and data cards, the material it adds failure to, the
// deck's curves, and the translator's notes.
#pragma once

#include <string>

#include "fpmshell/io/lsdyna/deck_card.hpp"

namespace fpmshell::deck {

class DeckTranslator;
struct MaterialDef;

class FailureCard {
public:
    FailureCard(DeckTranslator& translator, const DeckBlock& block, std::size_t first);

    /// Data card k (0: the first after any title); refused with `what` (its fields) if absent.
    [[nodiscard]] Card required(std::size_t k, const char* what) const;
    /// Data card k, blank fields where the deck leaves it out.
    [[nodiscard]] Card optional(std::size_t k) const;
    /// A note on the translation, at card c.
    void note(const Card& c, const std::string& what) const;
    /// The plastic material MID of card c's field k, which the criterion joins (refused where
    /// the deck defines none, or it is not plastic).
    void material(const Card& c, std::size_t k = 0);
    /// Adds a criterion "name: value" to the material's `failure`, and the failed points that
    /// erode an element.
    void failure(const std::string& criterion);
    /// Whether the material's `failure` has the key already (from its own card or another).
    [[nodiscard]] bool has_failure(const std::string& key) const;
    void failure_points(long long points);
    /// NUMFIP < 0 in field k of card c (`name`): -NUMFIP per cent of the layers through the
    /// thickness erode an element (`layer_fraction`; below -100 refused).
    void failure_layers(const Card& c, std::size_t k, const char* name);
    /// `[[x, y], ...]` of the *DEFINE_CURVE `id` (field `name` of card c; refused where none).
    [[nodiscard]] std::string curve_points(const Card& c, long long id, const char* name) const;
    /// The first x of that *DEFINE_CURVE (refused where none).
    [[nodiscard]] Real curve_first_abscissa(const Card& c, long long id, const char* name) const;

private:
    DeckTranslator& translator_;
    const DeckBlock& block_;
    std::size_t first_;
    MaterialDef* material_ = nullptr;
};

}  // namespace fpmshell::deck
