// The material model of a section, built from the model's material constants: elastic, or
// J2 plastic with a bilinear, Johnson-Cook, power-law or tabulated flow curve and an optional
// rate factor.
#pragma once

#include <utility>
#include <variant>
#include <vector>

#include "fpmshell/materials/j2_plastic.hpp"
#include "fpmshell/materials/linear_elastic.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell {

using SectionMaterial = std::variant<LinearElastic, J2Plastic>;

[[nodiscard]] inline SectionMaterial make_section_material(const Material& m) {
    if (!m.plastic()) return LinearElastic(m.youngs_modulus, m.poisson_ratio);
    FlowStress flow;
    RateFactor rate;
    ThermalSoftening thermal;
    if (m.type == MaterialType::JohnsonCook) {
        if (m.thermal) {  // eq. 7.4-2
            thermal.active = true;
            thermal.m = m.jc_m;
            thermal.heating = m.taylor_quinney / (m.density * m.specific_heat *
                                                  (m.melt_temperature - m.room_temperature));
        }
        flow.kind = FlowStress::Kind::JohnsonCook;
        flow.a = m.jc_a;
        flow.b = m.jc_b;
        flow.n = m.jc_n;
        if (m.jc_c > 0) {
            rate.kind = RateFactor::Kind::JohnsonCook;
            rate.c = m.jc_c;
            rate.reference_rate = m.reference_strain_rate;
        }
    } else if (m.type == MaterialType::PowerLaw) {
        flow.kind = FlowStress::Kind::PowerLaw;
        flow.b = m.power_k;
        flow.n = m.power_n;
        flow.strain_offset = m.power_strain_offset;
    } else if (m.type == MaterialType::Tabulated) {
        std::vector<PiecewiseLinearCurve> curves;
        std::vector<Real> rates;
        for (const FlowCurvePoints& c : m.flow_curves) {
            curves.emplace_back(c.strain, c.stress);
            rates.push_back(c.strain_rate);
        }
        if (curves.size() > 1) {  // the rate selects the curve (eq. 7.2-5)
            rate.kind = RateFactor::Kind::Table;
            rate.table_rates = rates;
        }
        flow = FlowStress::tabulated(std::move(curves), std::move(rates));
    } else {
        flow.yield_stress = m.yield_stress;
        // bilinear curve: sigma = sigma_y + E_t eps_total beyond yield <=> plastic modulus
        // H = E E_t / (E - E_t) against the plastic strain
        flow.hardening = m.tangent_modulus > 0 ? m.youngs_modulus * m.tangent_modulus /
                                                     (m.youngs_modulus - m.tangent_modulus)
                                               : 0.0;
    }
    if (m.cowper_symonds) {
        rate.kind = RateFactor::Kind::CowperSymonds;
        rate.d = m.cs_d;
        rate.q = m.cs_q;
    }
    return J2Plastic(m.youngs_modulus, m.poisson_ratio, flow, rate, m.hardening_mix,
                     m.normal_anisotropy, thermal);
}

[[nodiscard]] inline const Mat3& elastic_stiffness(const SectionMaterial& m) {
    return std::visit([](const auto& mat) -> const Mat3& { return mat.stiffness(); }, m);
}

}  // namespace fpmshell
