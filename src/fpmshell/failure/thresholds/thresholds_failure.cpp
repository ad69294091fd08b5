#include "fpmshell/failure/thresholds/thresholds_failure.hpp"

#include <cmath>
#include <string>

#include "fpmshell/core/simd_math.hpp"
#include "fpmshell/failure/tabulated/tabulated_failure.hpp"
#include "fpmshell/io/lsdyna/deck_failure_card.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

// eq. 7.6-5 at the state after the step. State [number][pack]: failed flag; with strain
// thresholds the plastic strain at the last step and the plastic strain tensor xx, yy, xy.
bool ThresholdsFailure::judge(const FailurePacks& in, Real /*dt*/, RealPack* state,
                              MaskOf<RealPack>* failed) const {
    const std::size_t m = in.m;
    RealPack* flag = state;
    bool any = false;
    const bool timed_out = p_.time && in.time >= *p_.time;
    for (std::size_t j = 0; j < m; ++j) {
        const RealPack sxx = in.stress[0][j], syy = in.stress[1][j], sxy = in.stress[2][j];
        RealPack passed(0.0);
        const auto count = [&](const MaskOf<RealPack>& over) {
            passed += select(over, RealPack(1.0), RealPack(0.0));
        };
        const RealPack pressure = -(sxx + syy) * (1.0 / 3.0);
        if (p_.max_pressure) count(pressure >= *p_.max_pressure);
        if (p_.min_pressure) count(pressure <= *p_.min_pressure);
        const RealPack q2 = sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy;  // sigma_vm^2
        if (p_.max_principal_stress) {
            const RealPack half = 0.5 * (sxx - syy);
            count(0.5 * (sxx + syy) + sqrt(half * half + sxy * sxy) >= *p_.max_principal_stress);
        }
        if (p_.max_von_mises_stress) count(sqrt(q2) >= *p_.max_von_mises_stress);
        if (p_.reads_strain()) {
            RealPack* last_alpha = state + m;
            RealPack* pxx = state + 2 * m;
            RealPack* pyy = state + 3 * m;
            RealPack* pxy = state + 4 * m;
            // the step's plastic strain along 3 s / (2 sigma_vm), s the deviator of the plane
            // stress (s_zz = -(s_xx + s_yy): incompressible)
            const RealPack d_alpha = in.plastic_strain[j] - last_alpha[j];
            const MaskOf<RealPack> flowing = d_alpha > 0.0 && q2 > 0.0;
            if (any_lane(flowing)) {
                const RealPack scale = select(
                    flowing, 1.5 * d_alpha * vector_rsqrt(select(flowing, q2, RealPack(1.0))),
                    RealPack(0.0));
                const RealPack mean = (sxx + syy) * (1.0 / 3.0);
                pxx[j] += scale * (sxx - mean);
                pyy[j] += scale * (syy - mean);
                pxy[j] += scale * sxy;
                last_alpha[j] = select(flowing, in.plastic_strain[j], last_alpha[j]);
            }
            // total strain: Hooke's law of the plane stress plus the plastic part (tensorial xy)
            const RealPack exx = (sxx - nu_ * syy) * (1.0 / e_) + pxx[j];
            const RealPack eyy = (syy - nu_ * sxx) * (1.0 / e_) + pyy[j];
            const RealPack exy = sxy * ((1.0 + nu_) / e_) + pxy[j];
            const RealPack ezz = (sxx + syy) * (-nu_ / e_) - pxx[j] - pyy[j];
            const RealPack centre = 0.5 * (exx + eyy), half = 0.5 * (exx - eyy);
            const RealPack radius = sqrt(half * half + exy * exy);
            const RealPack e1 = max(centre + radius, ezz), e3 = min(centre - radius, ezz);
            if (p_.max_principal_strain) count(e1 >= *p_.max_principal_strain);
            if (p_.min_principal_strain) count(e3 <= *p_.min_principal_strain);
            const RealPack volume = exx + eyy + ezz;
            if (p_.volumetric_strain)
                count(*p_.volumetric_strain > 0 ? volume >= *p_.volumetric_strain
                                                : volume <= *p_.volumetric_strain);
            if (p_.max_effective_strain) {  // sqrt(2/3 e:e), e the deviator
                const RealPack v3 = volume * (1.0 / 3.0);
                const RealPack dxx = exx - v3, dyy = eyy - v3, dzz = ezz - v3;
                count(sqrt((2.0 / 3.0) * (dxx * dxx + dyy * dyy + dzz * dzz + 2.0 * exy * exy)) >=
                      *p_.max_effective_strain);
            }
            if (p_.max_shear_strain) count(0.5 * (e1 - e3) >= *p_.max_shear_strain);
            if (p_.thinning_strain) count(-ezz >= *p_.thinning_strain);
        }
        MaskOf<RealPack> now = passed >= static_cast<Real>(p_.conditions);
        if (timed_out) now = MaskOf<RealPack>(true);
        flag[j] = select(now, RealPack(1.0), flag[j]);  // failed for good
        const MaskOf<RealPack> f = flag[j] > 0.0;
        if (!any_lane(f)) continue;
        failed[j] = failed[j] || f;
        any = true;
    }
    return any;
}

namespace {

/// `thresholds: {max_pressure, min_pressure, max_principal_stress, max_von_mises_stress,
/// max_principal_strain, min_principal_strain, max_effective_strain, volumetric_strain,
/// max_shear_strain, thinning_strain, time, conditions}`.
std::any read_thresholds(const YamlValue& v, const Material& /*material*/) {
    const YamlMap m =
        v.map({"max_pressure", "min_pressure", "max_principal_stress", "max_von_mises_stress",
               "max_principal_strain", "min_principal_strain", "max_effective_strain",
               "volumetric_strain", "max_shear_strain", "thinning_strain", "time", "conditions"});
    ThresholdsFailureParameters p;
    const auto real = [&](const char* key, std::optional<Real>& out) {
        if (const auto x = m.find(key)) out = x->real();
    };
    const auto positive = [&](const char* key, std::optional<Real>& out) {
        if (const auto x = m.find(key)) out = x->positive();
    };
    real("max_pressure", p.max_pressure);
    real("min_pressure", p.min_pressure);
    real("max_principal_stress", p.max_principal_stress);
    positive("max_von_mises_stress", p.max_von_mises_stress);
    real("max_principal_strain", p.max_principal_strain);
    real("min_principal_strain", p.min_principal_strain);
    positive("max_effective_strain", p.max_effective_strain);
    if (const auto x = m.find("volumetric_strain")) {
        p.volumetric_strain = x->real();
        if (*p.volumetric_strain == 0)
            x->fail("must not be 0 (> 0: a limit in tension, < 0: in compression)");
    }
    positive("max_shear_strain", p.max_shear_strain);
    positive("thinning_strain", p.thinning_strain);
    positive("time", p.time);
    const int given = static_cast<int>(p.max_pressure.has_value()) + p.min_pressure.has_value() +
                      p.max_principal_stress.has_value() + p.max_von_mises_stress.has_value() +
                      p.max_principal_strain.has_value() + p.min_principal_strain.has_value() +
                      p.max_effective_strain.has_value() + p.volumetric_strain.has_value() +
                      p.max_shear_strain.has_value() + p.thinning_strain.has_value();
    if (given == 0 && !p.time) v.fail("give at least one threshold or a time");
    if (const auto c = m.find("conditions")) {
        if (given == 0) c->fail("needs thresholds to count (a time alone takes none)");
        p.conditions = static_cast<int>(c->integer(1, given));  // NCS
    }
    return p;
}

std::unique_ptr<PointFailure> make_thresholds(const std::any& parameters,
                                              const Material& material) {
    return std::make_unique<ThresholdsFailure>(
        std::any_cast<const ThresholdsFailureParameters&>(parameters), material.youngs_modulus,
        material.poisson_ratio);
}

/// *MAT_ADD_EROSION: card 1: MID, EXCL, MXPRES, MNEPS, EFFEPS, VOLEPS, NUMFIP, NCS; card 2:
/// MNPRES, SIGP1, SIGVM, MXEPS, EPSSH, SIGTH, IMPULSE, FAILTM; card 3: IDAM (1: GISSMO as R10 and
/// before, with DMGTYP, LCSDG, ECRIT, DMGEXP, DCRIT, FADEXP, LCREGD), ... LCREGD; card 4: EPSTHIN
/// > 0 as `thinning_strain`; card 5: DTMIN > 0 as the material's `minimum_time_step`; the rest
/// of cards 4 to 6 (forming limits, nonlocal and size-dependent strains, filters, temperature,
/// functions) refused where set. A value equal to EXCL is left out; MXPRES, MNEPS, EFFEPS,
/// VOLEPS and FAILTM also at 0.
void mat_add_erosion(deck::FailureCard& card) {
    const deck::Card f = card.required(0, "MID, EXCL, MXPRES, MNEPS, EFFEPS, VOLEPS, NUMFIP, NCS");
    const deck::Card g = card.optional(1);
    const deck::Card h = card.optional(2);
    card.material(f);
    const Real excl = f.real(1, "EXCL");
    std::string keys;
    int given = 0;
    const auto take = [&](const deck::Card& c, std::size_t k, const char* name, const char* key,
                          bool zero_off) {
        const Real v = c.real(k, name);
        if (v == excl || (zero_off && v == 0)) return;
        keys += std::string(", ") + key + ": " + deck::num(v);
        ++given;
    };
    take(f, 2, "MXPRES", "max_pressure", true);
    take(f, 3, "MNEPS", "min_principal_strain", true);
    take(f, 4, "EFFEPS", "max_effective_strain", true);
    take(f, 5, "VOLEPS", "volumetric_strain", true);
    take(g, 0, "MNPRES", "min_pressure", false);
    for (const auto& [k, name] :
         {std::pair<std::size_t, const char*>{1, "SIGP1"}, {2, "SIGVM"}, {3, "MXEPS"}})
        if (const Real v = g.real(k, name); v < 0 && v != excl)
            g.fail(std::string(name) +
                   " < 0 (a curve of the effective strain rate) is not supported; give the value");
    take(g, 1, "SIGP1", "max_principal_stress", false);
    take(g, 2, "SIGVM", "max_von_mises_stress", false);
    take(g, 3, "MXEPS", "max_principal_strain", false);
    take(g, 4, "EPSSH", "max_shear_strain", false);
    for (const auto& [k, name] : {std::pair<std::size_t, const char*>{5, "SIGTH"}, {6, "IMPULSE"}})
        if (const Real v = g.real(k, name); v != excl && v != 0)
            g.fail(
                std::string(name) +
                ": the Tuler-Butcher criterion is not supported (leave SIGTH and IMPULSE blank)");
    if (const Real t = g.real(7, "FAILTM"); t != excl && t != 0) {
        if (t < 0)
            card.note(
                g, "FAILTM < 0: |FAILTM| taken (fpmshell has no dynamic relaxation phase to skip)");
        keys += ", time: " + deck::num(std::abs(t));
    }
    // card 4's EPSTHIN: the thinning strain of each point (< 0, from the element's thickness
    // change, refused)
    const deck::Card thin = card.optional(3);
    if (const Real v = thin.real(2, "EPSTHIN"); v != 0 && v != excl) {
        if (v < 0)
            thin.fail(
                "EPSTHIN < 0 (the thinning averaged over the element's thickness) is not "
                "supported; give EPSTHIN > 0 (each point's thinning)");
        keys += ", thinning_strain: " + deck::num(v);
        ++given;
    }
    const Real ncs = f.real(7, "NCS", 1.0);
    if (ncs != 1 && given > 0) {
        if (ncs < 1 || ncs > given || ncs != std::round(ncs))
            f.fail("NCS " + deck::num(ncs) + " is not a whole number from 1 to the " +
                   std::to_string(given) + " criteria given");
        keys += ", conditions: " + deck::num(ncs);
    }
    if (!keys.empty()) card.failure("thresholds: {" + keys.substr(2) + "}");
    const long long idam = h.id(0, "IDAM");
    if (idam ==
        1) {  // GISSMO as R10 and before: IDAM, DMGTYP, LCSDG, ECRIT, DMGEXP, DCRIT, FADEXP, LCREGD
        if (h.id(1, "DMGTYP") != 0)
            h.fail("DMGTYP " + std::to_string(h.id(1, "DMGTYP")) +
                   " is not supported (0: damage accumulated, failure at D = 1)");
        card.failure(tabulated_deck_failure(card, h, 2));
    } else if (idam != 0) {
        h.fail("IDAM " + std::to_string(idam) +
               " is not supported (0: none; 1: GISSMO; or *MAT_ADD_DAMAGE_GISSMO)");
    } else if (h.id(7, "LCREGD") != 0) {
        card.note(h,
                  "LCREGD without a damage model ignored (fpmshell regularizes GISSMO's "
                  "failure strain, IDAM 1)");
    }
    // card 5's DTMIN: an element erodes once its step falls below it (as *MAT_024's TDEL)
    const deck::Card filters = card.optional(4);
    const Real dtmin = filters.real(3, "DTMIN");
    if (dtmin < 0) filters.fail("DTMIN < 0 is not supported; give the minimum step (> 0)");
    if (dtmin > 0) {
        if (card.has_failure("minimum_time_step"))
            filters.fail("DTMIN: the material's own card gives a minimum step (TDEL) already");
        card.failure("minimum_time_step: " + deck::num(dtmin));
    }
    for (std::size_t c = 3; c < 6; ++c) {
        const deck::Card more = card.optional(c);
        for (std::size_t k = 0; k < 8; ++k)
            // NSFF has a default; EPSTHIN and DTMIN are read above
            if (more.real(k, "LCFLD .. EDGER") != 0 && !(c == 3 && (k == 1 || k == 2)) &&
                !(c == 4 && k == 3))
                more.fail(
                    "the criteria of this card (forming limits, nonlocal, size-dependent "
                    "strains, filters, temperature, functions) are not supported; leave them "
                    "blank");
    }
    const Real numfip = f.real(6, "NUMFIP", 1.0);
    if (numfip > 0 && (!keys.empty() || idam == 1))
        card.failure_points(static_cast<long long>(std::llround(numfip)));
    if (numfip < 0 && (!keys.empty() || idam == 1))
        card.failure_layers(f, 6, "NUMFIP");  // a percentage of the layers
    if (keys.empty() && idam == 0 && !(dtmin > 0))
        card.note(f, "no criterion is set (every value blank, 0 or EXCL): nothing erodes");
}

}  // namespace

FailureCriterion thresholds_criterion() {
    return {
        "thresholds", read_thresholds, make_thresholds, {{{"MAT_ADD_EROSION"}, mat_add_erosion}}};
}

}  // namespace fpmshell
