#include "fpmshell/materials/tabulated/tabulated_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/lsdyna/deck_translator.hpp"
#include "fpmshell/io/yaml_access.hpp"

namespace fpmshell {

namespace {

std::string fmt_real(Real x) { return fmt::format("{:g}", x); }

/// `[[plastic strain, flow stress], ...]`: two points at least, from plastic strain 0, the
/// strains increasing, the stresses > 0 and not decreasing (the return mapping brackets its
/// solution on a curve that does not soften, theory.md §7.3a).
FlowCurvePoints read_flow_curve(const YamlValue& v) {
    FlowCurvePoints curve;
    const auto points = v.list("[plastic strain, flow stress] pairs");
    if (points.size() < 2)
        v.fail(
            "a flow curve needs at least two [plastic strain, flow stress] pairs, e.g. [[0, "
            "250e6], [0.2, 400e6]]");
    std::string previous_strain, previous_stress;
    for (const YamlValue& p : points) {
        const auto es = p.list_of(2, "two numbers [plastic strain, flow stress]",
                                  "a pair [plastic strain, flow stress]");
        const Real strain = es[0].real(), stress = es[1].real();
        if (curve.strain.empty()) {
            if (strain != 0.0)
                es[0].fail("the first point of a flow curve must be at plastic strain 0, got " +
                           es[0].describe());
            if (!(stress > 0.0))
                es[1].fail(
                    "the initial yield stress (the flow stress at plastic strain 0) must "
                    "be > 0, got " +
                    es[1].describe());
        } else {
            if (!(strain > curve.strain.back()))
                es[0].fail("the plastic strains of a flow curve must increase strictly, but " +
                           es[0].describe() + " follows " + previous_strain);
            if (!(stress >= curve.stress.back()))
                es[1].fail(
                    "the flow stress must not decrease along the curve (softening is not "
                    "supported), but " +
                    es[1].describe() + " follows " + previous_stress);
        }
        previous_strain = es[0].describe();
        previous_stress = es[1].describe();
        curve.strain.push_back(strain);
        curve.stress.push_back(stress);
    }
    return curve;
}

/// The first point where curve `high` lies below curve `low` (eq. 7.2-4: piecewise linear,
/// each extended past its last point), or a negative strain where it never does: the
/// difference is piecewise linear, so its breakpoints and its slope past the last decide.
Real first_crossing(const FlowCurvePoints& low, const FlowCurvePoints& high) {
    const PiecewiseLinearCurve a(low.strain, low.stress), b(high.strain, high.stress);
    std::vector<Real> at = low.strain;
    at.insert(at.end(), high.strain.begin(), high.strain.end());
    std::sort(at.begin(), at.end());
    for (Real alpha : at)
        if (b.at(alpha).value < a.at(alpha).value) return alpha;
    if (b.at(at.back()).slope < a.at(at.back()).slope) return at.back() + 1.0;  // past both
    return -1.0;
}

/// `flow_curves: [{strain_rate: r, points: [...]}, ...]`: the rates >= 0 and increasing, each
/// curve on or above the one before it (the element's trial check takes the first curve's
/// radius as a lower bound of every other, elements/elastic_triangle_block.hpp).
void read_flow_curves(const YamlValue& v, std::vector<FlowCurvePoints>& flow_curves) {
    const auto items = v.list("flow curves at increasing strain rates");
    if (items.empty())
        v.fail(
            "expected at least one {strain_rate: ..., points: [[plastic strain, flow stress], "
            "...]}");
    for (const YamlValue& item : items) {
        const YamlMap m = item.map({"strain_rate", "points"});
        const YamlValue rate = m.at("strain_rate", "the strain rate of this curve, a number >= 0");
        FlowCurvePoints curve =
            read_flow_curve(m.at("points", "[plastic strain, flow stress] pairs"));
        curve.strain_rate = rate.non_negative();
        if (!flow_curves.empty()) {
            const FlowCurvePoints& below = flow_curves.back();
            if (!(curve.strain_rate > below.strain_rate))
                rate.fail("the strain rates of the flow curves must increase, but " +
                          rate.describe() + " follows " + fmt_real(below.strain_rate));
            const Real crossing = first_crossing(below, curve);
            if (crossing >= 0.0)
                item.fail("the curve at strain rate " + rate.describe() +
                          " lies below the one at strain rate " + fmt_real(below.strain_rate) +
                          " near plastic strain " + fmt_real(crossing) +
                          "; the curves must not cross (a higher rate, a flow stress at least "
                          "as high)");
        }
        flow_curves.push_back(std::move(curve));
    }
}

void read_tabulated(const YamlMap& keys, Material& m) {
    set_j2_parameters(m, "tabulated", tabulated_parameters(keys));
}

}  // namespace

J2Parameters tabulated_parameters(const YamlMap& keys) {
    J2Parameters p;
    read_j2_common(keys, p);
    std::vector<FlowCurvePoints> curves;
    const auto one = keys.find("flow_curve"), table = keys.find("flow_curves");
    if (one && table)
        table->fail(
            "give either flow_curve (one curve) or flow_curves (one per strain rate), not both");
    if (table) {
        read_flow_curves(*table, curves);
        if (curves.size() > 1) {
            for (const char* key : {"cowper_symonds", "rate_scaling"})
                if (const auto cs = keys.find(key))
                    cs->fail(
                        "cannot be combined with flow_curves: the curves at their strain rates "
                        "give the rate dependence");
            if (const auto mix = keys.find("hardening_mix"); mix && p.hardening_mix != 1.0)
                mix->fail(
                    "must be 1 (isotropic) with flow_curves at several strain rates, as in "
                    "LS-DYNA's *MAT_024");
        }
    } else {
        curves.push_back(read_flow_curve(keys.at(
            "flow_curve", "a list of [plastic strain, flow stress] pairs (or flow_curves)")));
    }
    const Real mix = p.hardening_mix, r = p.normal_anisotropy;
    J2Parameters q = tabulated_flow(curves);
    q.hardening_mix = mix;
    q.normal_anisotropy = r;
    read_cowper_symonds(keys, q);
    return q;
}

namespace {

/// *MAT_PIECEWISE_LINEAR_PLASTICITY: MID, RO, E, PR, SIGY, ETAN, FAIL, TDEL; C, P, LCSS, LCSR,
/// VP; EPS1..EPS8; ES1..ES8. LCSR: a curve of the yield stress's factor against the strain rate
/// (`rate_scaling`).
void mat_piecewise_linear(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, SIGY, ETAN, FAIL, TDEL");
    const deck::Card g = card.optional(1);
    const deck::Card eps = card.optional(2), es = card.optional(3);
    card.id(f);
    card.plastic();
    const Real c = g.real(0, "C"), p = g.real(1, "P");
    const long long lcss = g.id(2, "LCSS");
    card.flow_curve_id(lcss);
    if (const long long lcsr = g.id(3, "LCSR"); lcsr != 0) {
        if (c > 0 || p > 0) g.fail("give C, P (Cowper-Symonds) or LCSR (a rate curve), not both");
        card.rate_curve_id(lcsr);
    }
    if (g.real(4, "VP") != 0) card.note(g, "VP = 1 read as the scaled yield stress (VP = 0)");
    card.failure_strain(f, 6, "FAIL");
    card.deletion_time_step(f, 7, "TDEL");
    std::vector<deck::Point2> points = deck::MaterialCard::curve_of(eps, es);
    const bool tabulated = lcss != 0 || points.size() >= 2;
    card.key(tabulated ? "type: tabulated" : "type: j2_plastic");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    if (!tabulated) {
        card.key("yield_stress: " + deck::num(f.real(4, "SIGY")));
        card.key("tangent_modulus: " + deck::num(f.real(5, "ETAN")));
    } else if (lcss == 0) {
        card.key("flow_curve: " + deck::MaterialCard::points_text(points));
    }
    if (c > 0 || p > 0)
        card.key("cowper_symonds: {D: " + deck::num(c) + ", q: " + deck::num(p) + "}");
}

/// *MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY: *MAT_024's cards with EPSTHIN, EPSMAJ, NUMINT
/// after VP on the second. EPSMAJ > 0 as `thresholds: {max_principal_strain}` (theory.md eq.
/// 7.6-5: the largest principal total strain, the thickness direction's included, which is the
/// in-plane major one wherever that is positive and the sheet thins), EPSTHIN > 0 as its
/// `thinning_strain` (-eps_zz, total), NUMINT > 0 as `points`; EPSTHIN < 0 (plastic thinning)
/// and EPSMAJ < 0 (filtered) refused.
void mat_modified_piecewise_linear(deck::MaterialCard& card) {
    mat_piecewise_linear(card);
    const deck::Card g = card.optional(1);
    const Real thin = g.real(5, "EPSTHIN"), major = g.real(6, "EPSMAJ");
    if (thin < 0)
        g.fail(
            "EPSTHIN < 0 (a plastic thinning strain) is not supported: give the total thinning "
            "strain (> 0)");
    if (major < 0)
        g.fail("EPSMAJ < 0 (a filtered major strain) is not supported: give the strain (> 0)");
    std::string thresholds;  // either fails a point (one condition)
    if (major > 0) thresholds += ", max_principal_strain: " + deck::num(major);
    if (thin > 0) thresholds += ", thinning_strain: " + deck::num(thin);
    if (!thresholds.empty()) card.failure("thresholds: {" + thresholds.substr(2) + "}");
    const long long numint = g.id(7, "NUMINT");
    if (numint < 0) g.fail("NUMINT < 0 is not supported (give the number of points, or 0)");
    if (numint > 0) card.failure_points(numint);
}

/// *MAT_TABULATED_JOHNSON_COOK (224): MID, RO, E, PR, CP, TR, BETA, NUMINT; LCK1, LCKT, LCF,
/// LCG, LCH, LCI; FAILOPT, NUMAVG, NCYFAIL, ERODE, LCPS. The flow stress of LCK1 (a curve, or a
/// table of curves per strain rate) as *MAT_024's LCSS; its failure strain f(eta) g(rate) i(size)
/// (LCF, LCG, LCI) as `failure: {tabulated}` (theory.md eq. 7.6-3), NUMINT > 0 as `points`,
/// < 0 as `layer_fraction`. Its temperature terms (LCKT, LCH) are refused; without them the
/// adiabatic heating (CP, TR, BETA) changes nothing.
void mat_tabulated_johnson_cook(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, CP, TR, BETA, NUMINT");
    const deck::Card g = card.required(1, "LCK1, LCKT, LCF, LCG, LCH, LCI");
    const deck::Card h = card.optional(2);
    card.id(f);
    card.plastic();
    const long long lck1 = g.id(0, "LCK1");
    if (lck1 <= 0) g.fail("LCK1 must be the *DEFINE_CURVE or *DEFINE_TABLE of the flow stress");
    if (g.id(1, "LCKT") != 0)
        g.fail("LCKT (flow curves per temperature) is not supported: give LCKT 0");
    if (g.id(4, "LCH") != 0)
        g.fail("LCH (the failure strain against temperature) is not supported: give LCH 0");
    if (g.id(6, "BFLGI") != 0) g.fail("BFLGI is not supported (0 only)");
    if (h.id(0, "FAILOPT") != 0) h.fail("FAILOPT is not supported (0 only)");
    if (h.id(3, "ERODE") != 0) h.fail("ERODE is not supported (0: failed elements erode)");
    if (h.id(4, "LCPS") != 0) h.fail("LCPS is not supported (0 only)");
    if (const long long numavg = h.id(1, "NUMAVG"), ncyfail = h.id(2, "NCYFAIL");
        numavg > 1 || ncyfail > 1)
        card.note(h, "NUMAVG, NCYFAIL ignored: the rate and the failure are those of each step");
    card.note(f,
              "CP, TR, BETA ignored: without LCKT and LCH the temperature changes nothing; the "
              "curves per rate are interpolated in the filtered strain rate (LS-DYNA's: the "
              "plastic strain rate)");
    card.key("type: tabulated");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    card.flow_curve_id(lck1);
    const long long lcf = g.id(2, "LCF"), lcg = g.id(3, "LCG"), lci = g.id(5, "LCI");
    if (lcf < 0 || lcg < 0 || lci < 0) g.fail("LCF, LCG and LCI must be curve IDs (> 0) or 0");
    if (lcf == 0 && lcg == 0 && lci == 0) return;  // no failure
    card.failure_curves(lcf, lcg, lci);
    const Real numint = f.real(7, "NUMINT", 1.0);
    if (numint > 0) card.failure_points(static_cast<long long>(std::llround(numint)));
    if (numint < 0) card.failure_layers(f, 7, "NUMINT");  // a percentage of the layers
}

/// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC: MID, RO, E, PR, SIGY, ETAN, R, HLCID;
/// IDSCALE, EA, COE, ICFLD, STRAINLT. Hill's normal anisotropy R (theory.md eq. 7.1-3) on a
/// bilinear curve (SIGY, ETAN) or the flow curve HLCID.
void mat_transversely_anisotropic(deck::MaterialCard& card) {
    const deck::Card f = card.required(0, "MID, RO, E, PR, SIGY, ETAN, R, HLCID");
    const deck::Card g = card.optional(1);
    card.id(f);
    card.plastic();
    for (std::size_t k = 0; k < 5; ++k)
        if (g.real(k, "IDSCALE, EA, COE, ICFLD, STRAINLT") != 0)
            g.fail(
                "IDSCALE, EA, COE, ICFLD, STRAINLT (a modulus that changes with plastic strain, "
                "a forming limit) are not supported");
    Real r = f.real(6, "R");
    if (r < 0) {
        r = -r;
        card.note(f, "R < 0 read as its magnitude " + deck::num(r));
    }
    if (!(r > 0)) f.fail("R must be the sheet's Lankford ratio, not 0");
    if (f.real(5, "ETAN") < 0)
        f.fail("ETAN < 0 (through-thickness normal stresses) is not supported");
    const long long hlcid = f.id(7, "HLCID");
    card.flow_curve_id(hlcid);
    card.key(hlcid != 0 ? "type: tabulated" : "type: j2_plastic");
    card.elastic(f, f.real(2, "E"), f.real(3, "PR"));
    if (hlcid == 0) {
        card.key("yield_stress: " + deck::num(f.real(4, "SIGY")));
        card.key("tangent_modulus: " + deck::num(f.real(5, "ETAN")));
    } else if (f.real(4, "SIGY") != 0 || f.real(5, "ETAN") != 0) {
        card.note(f, "SIGY and ETAN ignored: the curve HLCID gives the flow stress");
    }
    card.key("normal_anisotropy: " + deck::num(r));
}

}  // namespace

J2Parameters tabulated_flow(const std::vector<FlowCurvePoints>& curves) {
    std::vector<PiecewiseLinearCurve> pieces;
    std::vector<Real> rates;
    for (const FlowCurvePoints& c : curves) {
        pieces.emplace_back(c.strain, c.stress);
        rates.push_back(c.strain_rate);
    }
    J2Parameters p;
    if (pieces.size() > 1) {  // the rate selects the curve (eq. 7.2-5)
        p.rate.kind = RateFactor::Kind::Table;
        p.rate.table_rates = rates;
    }
    p.flow = FlowStress::tabulated(std::move(pieces), std::move(rates));
    return p;
}

J2Parameters& make_tabulated(Material& m, const std::vector<FlowCurvePoints>& curves) {
    return set_j2_parameters(m, "tabulated", tabulated_flow(curves));
}

MaterialLaw tabulated_law() {
    return {
        "tabulated",
        true,
        {"flow_curve", "flow_curves", "hardening_mix", "cowper_symonds", "rate_scaling",
         "normal_anisotropy"},
        read_tabulated,
        make_j2_group,
        {{{"MAT_PIECEWISE_LINEAR_PLASTICITY", "MAT_024"}, mat_piecewise_linear},
         {{"MAT_MODIFIED_PIECEWISE_LINEAR_PLASTICITY", "MAT_123"}, mat_modified_piecewise_linear},
         {{"MAT_TABULATED_JOHNSON_COOK", "MAT_224"}, mat_tabulated_johnson_cook},
         {{"MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC", "MAT_037"},
          mat_transversely_anisotropic}}};
}

}  // namespace fpmshell
