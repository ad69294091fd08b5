#include "fpmshell/failure/johnson_cook/johnson_cook_damage.hpp"

#include <algorithm>

#include "fpmshell/failure/damage_accumulation.hpp"
#include "fpmshell/io/yaml_access.hpp"
#include "fpmshell/materials/j2/j2_parameters.hpp"

namespace fpmshell {

bool JohnsonCookDamage::judge(const FailurePacks& in, Real dt, RealPack* state,
                              MaskOf<RealPack>* failed) const {
    return accumulate_damage(
        in, state, failed, [&](std::size_t j, const RealPack& d_alpha, const MaskOf<RealPack>&) {
            // the rate and the temperature only where their terms are (failure_strain reads
            // them there alone)
            const RealPack rate = p_.d4 != 0 && dt > 0 ? d_alpha * (1.0 / dt) : RealPack(0.0);
            const RealPack t_star =
                p_.d5 != 0 ? min(max(heating_ * in.plastic_work[j], RealPack(0.0)), RealPack(1.0))
                           : RealPack(0.0);
            return failure_strain(
                stress_triaxiality(in.stress[0][j], in.stress[1][j], in.stress[2][j]), rate,
                t_star);
        });
}

namespace {

/// `johnson_cook: {D1, D2, D3, D4, D5, reference_strain_rate, minimum_strain}`.
std::any read_johnson_cook(const YamlValue& v, const Material& material) {
    const YamlMap m =
        v.map({"D1", "D2", "D3", "D4", "D5", "reference_strain_rate", "minimum_strain"});
    JohnsonCookDamageParameters p;
    p.d1 = m.at("D1", "the failure strain constant D1").real();
    p.d2 = m.at("D2", "the failure strain constant D2 of the triaxiality term").real();
    p.d3 = m.at("D3", "the exponent D3 of the triaxiality term").real();
    p.d4 = m.real_or("D4", 0.0);
    p.d5 = m.real_or("D5", 0.0);
    // the law's own reference rate where it has one (johnson_cook with C)
    const J2Parameters* j2 = j2_parameters(material);
    const Real law_rate =
        j2 && j2->rate.kind == RateFactor::Kind::JohnsonCook ? j2->rate.reference_rate : 1.0;
    p.reference_strain_rate = m.positive_or("reference_strain_rate", law_rate);
    p.minimum_strain = m.positive_or("minimum_strain", p.minimum_strain);
    if (!(p.d1 + p.d2 * std::exp(p.d3 / 3.0) > 0))
        v.fail("gives no positive failure strain in uniaxial tension (D1 + D2 exp(D3 / 3) <= 0)");
    return p;
}

std::unique_ptr<PointFailure> make_johnson_cook(const std::any& parameters,
                                                const Material& material) {
    const J2Parameters* j2 = j2_parameters(material);
    const Real heating = j2 && j2->thermal.active ? j2->thermal.heating : 0.0;
    return std::make_unique<JohnsonCookDamage>(
        std::any_cast<const JohnsonCookDamageParameters&>(parameters), heating);
}

}  // namespace

FailureCriterion johnson_cook_criterion() {
    return {"johnson_cook", read_johnson_cook, make_johnson_cook};
}

}  // namespace fpmshell
