#include "fpmshell/io/lsdyna/deck_failure_card.hpp"

#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

FailureCard::FailureCard(DeckTranslator& translator, const DeckBlock& block, std::size_t first)
    : translator_(translator), block_(block), first_(first) {}

Card FailureCard::required(std::size_t k, const char* what) const {
    return translator_.required_card(block_, first_ + k, what);
}

Card FailureCard::optional(std::size_t k) const { return translator_.card(block_, first_ + k); }

void FailureCard::note(const Card& c, const std::string& what) const {
    translator_.note(block_, c.line(), what);
}

void FailureCard::material(const Card& c, std::size_t k) {
    const long long mid = c.id(k, "MID");
    material_ = translator_.material_def(mid);
    if (!material_) c.fail("MID " + std::to_string(mid) + ": no *MAT_ card of the deck defines it");
    if (!material_->plastic)
        c.fail("material " + std::to_string(mid) + " (*" + material_->keyword +
               ") is not plastic: its damage would grow with a plastic strain it does not have");
}

void FailureCard::failure(const std::string& criterion) { material_->failure.push_back(criterion); }

bool FailureCard::has_failure(const std::string& key) const {
    for (const std::string& c : material_->failure)
        if (c.rfind(key + ":", 0) == 0) return true;
    return false;
}

void FailureCard::failure_points(long long points) {
    material_->failure_points = "points: " + std::to_string(points);
}

void FailureCard::failure_layers(const Card& c, std::size_t k, const char* name) {
    material_->failure_points = layer_fraction_key(c, k, name);
}

Real FailureCard::curve_first_abscissa(const Card& c, long long id, const char* name) const {
    const std::vector<Point2>* points = translator_.curve_points(id);
    if (!points || points->empty())
        c.fail(std::string(name) + " " + std::to_string(id) + ": no *DEFINE_CURVE defines it");
    return points->front().x;
}

std::string FailureCard::curve_points(const Card& c, long long id, const char* name) const {
    const std::vector<Point2>* points = translator_.curve_points(id);
    if (!points)
        c.fail(std::string(name) + " " + std::to_string(id) + ": no *DEFINE_CURVE defines it");
    return DeckTranslator::points_text(*points);
}

}  // namespace fpmshell::deck
