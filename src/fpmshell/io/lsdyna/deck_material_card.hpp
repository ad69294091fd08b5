// What a material law's deck card translation (materials/<law>/, material_law.hpp) sees of the
// deck: the card's block and its data cards, the material definition it fills with the law's
// model keys, and the translator's notes.
#pragma once

#include <string>
#include <vector>

#include "fpmshell/io/lsdyna/deck_card.hpp"

namespace fpmshell::deck {

class DeckTranslator;
struct MaterialDef;
struct Point2;

class MaterialCard {
public:
    /// `first`: the first data card of the block (1 after the title of a _TITLE keyword).
    MaterialCard(DeckTranslator& translator, const DeckBlock& block, std::size_t first,
                 MaterialDef& material);

    /// Data card k (0: the first after any title); refused with `what` (its fields) if absent.
    [[nodiscard]] Card required(std::size_t k, const char* what) const;
    /// Data card k, blank fields where the deck leaves it out.
    [[nodiscard]] Card optional(std::size_t k) const;
    /// A note on the translation, at card c.
    void note(const Card& c, const std::string& what) const;
    /// The material's id (MID), read from card c's field k; its definition starts at c.
    void id(const Card& c, std::size_t k = 0);
    /// One model key, "name: value".
    void key(const std::string& text);
    /// density (RO in field 1 of card f), youngs_modulus and poisson_ratio.
    void elastic(const Card& f, Real youngs_modulus, Real poisson_ratio);
    /// A plastic law's card (its parts take 5 points through the thickness unless NIP says).
    void plastic();
    /// The plastic strain at failure in field k of card c (*MAT_003 FS, *MAT_018 EPSF, *MAT_024
    /// FAIL, *MAT_098 PSFAIL; theory.md §7.6): > 0 erodes the elements whose points reach it,
    /// 0 or 1e16 and above none (LS-DYNA's defaults 1e21, 1e17 written out), < 0 refused.
    void failure_strain(const Card& c, std::size_t k, const char* name);
    /// Field k of c (`name`, *MAT_024's and *MAT_081's TDEL) as `failure: {minimum_time_step}`
    /// where > 0: an element erodes once its step falls below it.
    void deletion_time_step(const Card& c, std::size_t k, const char* name);
    /// A failure criterion, "name: value" (the material's `failure` key joins them), and the
    /// failed points that erode an element (> 0).
    void failure(const std::string& criterion);
    void failure_points(long long points);
    /// A negative NUMINT (field k of c, `name`): -NUMINT per cent of the layers through the
    /// thickness erode an element (`layer_fraction`; below -100 refused).
    void failure_layers(const Card& c, std::size_t k, const char* name);
    /// *MAT_224's LCF, LCG, LCI: its failure written from the deck's curves once they are known.
    void failure_curves(long long lcf, long long lcg, long long lci);
    /// The curve or table of the flow stress (*MAT_024 LCSS): written with the material once the
    /// deck's curves are known.
    void flow_curve_id(long long lcss);
    /// The curve of the yield stress's factor against the strain rate (*MAT_024 LCSR), written
    /// as `rate_scaling` once the deck's curves are known.
    void rate_curve_id(long long lcsr);
    /// The points (EPS_k, ES_k) of the cards eps (EPS1..EPS8) and es (ES1..ES8) of *MAT_024 and
    /// *MAT_081: the first, and every other not both 0.
    [[nodiscard]] static std::vector<Point2> curve_of(const Card& eps, const Card& es);
    /// `[[x, y], ...]`
    [[nodiscard]] static std::string points_text(const std::vector<Point2>& points);

private:
    DeckTranslator& translator_;
    const DeckBlock& block_;
    std::size_t first_;
    MaterialDef& material_;
};

}  // namespace fpmshell::deck
