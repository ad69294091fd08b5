#include "fpmshell/io/lsdyna/deck_material_card.hpp"

#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

MaterialCard::MaterialCard(DeckTranslator& translator, const DeckBlock& block, std::size_t first,
                           MaterialDef& material)
    : translator_(translator), block_(block), first_(first), material_(material) {}

Card MaterialCard::required(std::size_t k, const char* what) const {
    return translator_.required_card(block_, first_ + k, what);
}

Card MaterialCard::optional(std::size_t k) const { return translator_.card(block_, first_ + k); }

void MaterialCard::note(const Card& c, const std::string& what) const {
    translator_.note(block_, c.line(), what);
}

void MaterialCard::id(const Card& c, std::size_t k) {
    material_.id = c.id(k, "MID");
    material_.at = {&block_, c.line()};
}

void MaterialCard::key(const std::string& text) { material_.keys.push_back(text); }

void MaterialCard::elastic(const Card& f, Real youngs_modulus, Real poisson_ratio) {
    key("density: " + num(f.real(1, "RO")));
    key("youngs_modulus: " + num(youngs_modulus));
    key("poisson_ratio: " + num(poisson_ratio));
}

void MaterialCard::plastic() { material_.plastic = true; }

void MaterialCard::failure_strain(const Card& c, std::size_t k, const char* name) {
    const Real strain = c.real(k, name);
    if (strain < 0)
        c.fail(std::string(name) +
               " < 0 (a user failure routine or a failure time) is not supported; give the "
               "plastic strain at failure (> 0) or 0 for none");
    // 1e16 and above is never reached: LS-DYNA's own defaults (*MAT_024's 1e21, *MAT_098's
    // 1e17), written out by deck generators, are no criterion
    if (strain > 0 && strain < 1e16) failure("plastic_strain: " + num(strain));
}

void MaterialCard::deletion_time_step(const Card& c, std::size_t k, const char* name) {
    const Real step = c.real(k, name);
    if (step < 0) c.fail(std::string(name) + " must be >= 0 (0: no element deletion by its step)");
    if (step > 0) failure("minimum_time_step: " + num(step));
}

void MaterialCard::failure(const std::string& criterion) { material_.failure.push_back(criterion); }

void MaterialCard::failure_points(long long points) {
    material_.failure_points = "points: " + std::to_string(points);
}

void MaterialCard::failure_layers(const Card& c, std::size_t k, const char* name) {
    material_.failure_points = layer_fraction_key(c, k, name);
}

void MaterialCard::failure_curves(long long lcf, long long lcg, long long lci) {
    material_.failure_curve = lcf;
    material_.failure_rate_curve = lcg;
    material_.failure_size_curve = lci;
}

void MaterialCard::flow_curve_id(long long lcss) { material_.lcss = lcss; }

void MaterialCard::rate_curve_id(long long lcsr) { material_.lcsr = lcsr; }

std::vector<Point2> MaterialCard::curve_of(const Card& eps, const Card& es) {
    std::vector<Point2> points;
    for (std::size_t k = 0; k < 8; ++k) {
        const Real x = eps.real(k, "EPS1..EPS8"), y = es.real(k, "ES1..ES8");
        if (k == 0 || x != 0 || y != 0) points.push_back({x, y});
    }
    return points;
}

std::string MaterialCard::points_text(const std::vector<Point2>& points) {
    return DeckTranslator::points_text(points);
}

}  // namespace fpmshell::deck
