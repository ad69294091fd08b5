#include "fpmshell/materials/j2/j2_parameters.hpp"

#include <fmt/format.h>

#include <utility>
#include <vector>

#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/materials/j2/j2_block_loads.hpp"
#include "fpmshell/solver/element_group.hpp"

namespace fpmshell {

J2Parameters& set_j2_parameters(Material& m, const std::string& law, const J2Parameters& p) {
    m.law = law;
    m.plastic_law = true;
    m.parameters = p;
    return std::any_cast<J2Parameters&>(m.parameters);
}

void read_j2_common(const YamlMap& keys, J2Parameters& p) {
    if (const auto r = keys.find("normal_anisotropy"))  // Hill's R (eq. 7.1-3)
        p.normal_anisotropy = r->positive();
    if (const auto mix = keys.find("hardening_mix")) {
        p.hardening_mix = mix->real();
        if (!(p.hardening_mix >= 0 && p.hardening_mix <= 1))
            mix->fail("must be in [0, 1] (1 isotropic, 0 kinematic hardening), got " +
                      mix->describe());
    }
}

void read_cowper_symonds(const YamlMap& keys, J2Parameters& p) {
    const auto cs = keys.find("cowper_symonds");
    if (const auto curve = keys.find("rate_scaling")) {
        if (cs) curve->fail("give either cowper_symonds or rate_scaling, not both");
        read_rate_scaling(*curve, p);
        return;
    }
    if (!cs) return;
    const YamlMap c = cs->map({"D", "q"});
    p.rate.kind = RateFactor::Kind::CowperSymonds;
    p.rate.d = c.at("D", "the Cowper-Symonds rate constant D [1/time], a number > 0").positive();
    p.rate.q = c.at("q", "the Cowper-Symonds exponent q, a number > 0").positive();
}

void read_rate_scaling(const YamlValue& v, J2Parameters& p) {
    const auto points = v.list("[strain rate, factor] pairs");
    if (points.size() < 2)
        v.fail(
            "a rate scaling needs at least two [strain rate, factor] pairs, e.g. [[0, 1], "
            "[100, 1.3]]");
    std::vector<Real> rates, factors;
    for (const YamlValue& pt : points) {
        const auto rf =
            pt.list_of(2, "two numbers [strain rate, factor]", "a pair [strain rate, factor]");
        const Real rate = rf[0].non_negative(), factor = rf[1].positive();
        if (!rates.empty() && !(rate > rates.back()))
            rf[0].fail("the strain rates must increase, but " + rf[0].describe() + " follows " +
                       fmt::format("{:g}", rates.back()));
        if (!factors.empty() && factor < factors.back())
            rf[1].fail(
                "the factors must not decrease (a faster rate, a yield stress at least "
                "as high), but " +
                rf[1].describe() + " follows " + fmt::format("{:g}", factors.back()));
        rates.push_back(rate);
        factors.push_back(factor);
    }
    p.rate.kind = RateFactor::Kind::Curve;
    p.rate.scaling = PiecewiseLinearCurve(std::move(rates), std::move(factors));
}

J2Plastic make_j2_plastic(const Material& m) {
    const J2Parameters& p = *j2_parameters(m);
    return J2Plastic(m.youngs_modulus, m.poisson_ratio, p.flow, p.rate, p.hardening_mix,
                     p.normal_anisotropy, p.thermal);
}

std::unique_ptr<ElementGroup> make_j2_group(const Model& model, std::size_t section) {
    const Material& m = model.materials[static_cast<std::size_t>(model.sections[section].material)];
    return std::make_unique<MaterialGroup<J2Plastic>>(make_j2_plastic(m), model, section);
}

}  // namespace fpmshell
