// Shell sections of a deck and their rules through the thickness: *SECTION_SHELL (NIP, QR/IRID),
// *INTEGRATION_SHELL (a user rule), *CONTROL_SHELL INTGRD (Gauss or Lobatto), and the
// `sections` block they become (model-format.md `thickness_points`, `thickness_rule`).
#include <cmath>

#include "fpmshell/elements/quadrature.hpp"
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

void DeckTranslator::section_shell(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const std::size_t first = opt.count("TITLE") ? 1 : 0;
    for (const std::string& o : opt)
        if (o != "TITLE") refuse(b, "*SECTION_SHELL_" + o + " is not supported");
    const Card f = required_card(b, first, "SECID, ELFORM, SHRF, NIP, PROPT, QR");
    const Card t = required_card(b, first + 1, "T1, T2, T3, T4, NLOC, MAREA");
    const long long id = f.id(0, "SECID");
    const long long elform = f.id(1, "ELFORM", 2);
    long long nip = f.id(3, "NIP", 2);
    if (nip == 0) nip = 2;  // LS-DYNA's default
    const long long qr = f.id(5, "QR/IRID");
    // ICOMP 1: a material angle per point (the cards after the second, not read): every law of
    // fpmshell is isotropic in the plane of the shell, so the angles change nothing
    const long long icomp = f.id(6, "ICOMP");
    if (icomp != 0 && icomp != 1) f.fail("ICOMP must be 0 or 1");
    if (icomp == 1)
        note(b, f.line(),
             "ICOMP 1: the points' material angles ignored (fpmshell's materials are isotropic in "
             "the plane of the shell, so the angles change nothing)");
    if (qr > 0)
        f.fail("QR " + std::to_string(qr) +
               ": the trapezoidal rule is not supported (QR 0: Gauss or Lobatto, QR < 0: a "
               "*INTEGRATION_SHELL rule)");
    if (qr == 0 && (nip < 1 || nip > k_max_thickness_points))
        f.fail("NIP " + std::to_string(nip) + ": LS-DYNA's Gauss and Lobatto rules have 1 to " +
               std::to_string(k_max_thickness_points) + " points through the thickness");
    const Real t1 = t.real(0, "T1");
    // 0: the elements give their thicknesses (*ELEMENT_SHELL_THICKNESS), checked per part
    if (!(t1 >= 0)) t.fail("T1 must be a thickness >= 0");
    for (std::size_t k = 1; k < 4; ++k) {
        const Real tk = t.real(k, "T2, T3, T4");
        if (tk != 0 && tk != t1)
            t.fail(
                "a thickness that varies over the element (T1 to T4 not equal) is not "
                "supported");
    }
    if (t.real(4, "NLOC") != 0) t.fail("NLOC: only the mid-surface reference (0) is supported");
    const Real area_mass = t.real(5, "MAREA");  // non-structural mass per unit area
    if (area_mass < 0) t.fail("MAREA must be >= 0 (a mass per unit area)");
    if (const auto other = sections_.find(id); other != sections_.end())
        f.fail("section " + std::to_string(id) + " is defined twice (first at " +
               place(other->second.at) + ")");
    sections_[id] = {{&b, f.line()}, t1, static_cast<int>(nip), qr < 0 ? -qr : 0, area_mass};
    note(b, f.line(),
         fmt::format("ELFORM {} mapped to fpmshell's finite-particle triangle (CST membrane, "
                     "DKT bending; quadrangles split in two)",
                     elform));
    if (nip == 1 && qr == 0)
        note(b, f.line(),
             "NIP 1: one point at the mid-surface, so the section carries no bending moment (a "
             "membrane, as LS-DYNA's)");
}

/// *INTEGRATION_SHELL: IRID, NIP, ESOP, FAILOPT, then NIP cards S, WF, PID (ESOP 1: NIP layers of
/// equal thickness, their S and WF not read).
void DeckTranslator::integration_shell(const DeckBlock& b) {
    const Card f = required_card(b, 0, "IRID, NIP, ESOP, FAILOPT");
    const long long id = f.id(0, "IRID");
    const long long nip = f.id(1, "NIP");
    const long long esop = f.id(2, "ESOP");
    if (nip < 1 || nip > k_max_thickness_points)
        f.fail("NIP " + std::to_string(nip) + ": fpmshell takes rules of 1 to " +
               std::to_string(k_max_thickness_points) + " points through the thickness");
    if (esop != 0 && esop != 1) f.fail("ESOP must be 0 (points given) or 1 (equal layers)");
    IntegrationRuleDef rule{{&b, f.line()}, {}};
    const auto n = static_cast<std::size_t>(nip);
    Real sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (esop == 1 && i + 1 >= b.cards.size()) {
            // equal layers: the point cards only name parts, and may be left out
            rule.points.emplace_back(-1 + (2.0 * static_cast<Real>(i) + 1) / nip, 1.0 / nip);
            continue;
        }
        const Card p = required_card(b, i + 1, "S, WF, PID");
        if (p.id(2, "PID") != 0)
            p.fail(
                "PID: a layer of another part (a composite through the thickness) is not "
                "supported");
        if (esop == 1) {
            rule.points.emplace_back(-1 + (2.0 * static_cast<Real>(i) + 1) / nip, 1.0 / nip);
            continue;
        }
        const Real s = p.real(0, "S"), wf = p.real(1, "WF");
        if (s < -1 || s > 1) p.fail("S must lie in [-1, 1]");
        if (!(wf > 0)) p.fail("WF must be > 0 (the point's fraction of the thickness)");
        rule.points.emplace_back(s, wf);
        sum += wf;
    }
    if (esop == 0) {
        // the weights are fractions of the thickness; decks write them to 4 or 5 digits
        // (0.3333 x 3), so a sum within 1e-3 of 1 is scaled to 1 and noted
        if (std::abs(sum - 1) > 1e-3)
            f.fail(
                fmt::format("the weights WF sum to {}, not 1 (each is its point's fraction of "
                            "the thickness)",
                            sum));
        if (sum != 1) {
            for (auto& [s, wf] : rule.points) wf /= sum;
            note(b, f.line(), fmt::format("the weights WF sum to {}: scaled to sum to 1", sum));
        }
    }
    if (const auto other = integration_rules_.find(id); other != integration_rules_.end())
        f.fail("integration rule " + std::to_string(id) + " is defined twice (first at " +
               place(other->second.at) + ")");
    integration_rules_[id] = rule;
}

/// The section's `thickness_points` / `thickness_rule` keys, and notes on how it is read.
std::string DeckTranslator::thickness_rule_keys(const SectionDef& s, const MaterialDef& m,
                                                long long pid) {
    const DeckBlock& b = *s.at.block;
    if (s.user_rule != 0) {
        const auto r = integration_rules_.find(s.user_rule);
        if (r == integration_rules_.end())
            deck_fail(b, s.at.line,
                      "QR/IRID " + std::to_string(-s.user_rule) + ": no *INTEGRATION_SHELL " +
                          std::to_string(s.user_rule) + " defines the rule");
        std::string keys = "thickness_rule: [";
        for (std::size_t i = 0; i < r->second.points.size(); ++i)
            keys += (i ? ", " : "") + std::string("[") + num(r->second.points[i].first) + ", " +
                    num(r->second.points[i].second) + "]";
        return keys + "]";
    }
    // *CONTROL_SHELL INTGRD 1: Lobatto for 3 to 10 points; 1 or 2 stay Gauss (LS-DYNA: Lobatto
    // with 2 points is too inaccurate)
    const bool lobatto = lobatto_shells_.has_value() && s.points >= 3;
    if (m.plastic && s.points == 2)
        note(b, s.at.line,
             "NIP 2 with the plastic material of part " + std::to_string(pid) +
                 ": two Gauss points, as LS-DYNA integrates it (their fully plastic moment is "
                 "15 % above sigma_y h^2 / 4; NIP 5 integrates plasticity closer)");
    return "thickness_points: " + std::to_string(s.points) +
           ", thickness_rule: " + (lobatto ? "lobatto" : "gauss");
}

void DeckTranslator::write_sections(std::vector<Line>& out) {
    bool first = true;
    for (const auto& [pid, e] : element_parts_) {
        const auto p = parts_.find(pid);
        if (p == parts_.end())
            deck_fail(*e.first.block, e.first.line,
                      "an element of part " + std::to_string(pid) + ", which no *PART defines");
        const PartDef& part = p->second;
        const auto s = sections_.find(part.section);
        if (s == sections_.end())
            deck_fail(*part.at.block, part.at.line,
                      "SECID " + std::to_string(part.section) +
                          (solid_sections_.count(part.section)
                               ? ": a *SECTION_SOLID, but the part's elements are shells"
                               : ": no *SECTION_SHELL defines it"));
        const auto m = materials_.find(part.material);
        if (m == materials_.end())
            deck_fail(*part.at.block, part.at.line,
                      "MID " + std::to_string(part.material) + ": no *MAT card defines it");
        Real thickness = s->second.thickness;
        if (!e.thickness.empty()) thickness = *e.thickness.begin();
        if (!(thickness > 0))
            deck_fail(*s->second.at.block, s->second.at.line,
                      "T1 is 0 and the elements of part " + std::to_string(pid) +
                          " give no thickness of their own (*ELEMENT_SHELL_THICKNESS)");
        const std::string rule = thickness_rule_keys(s->second, m->second, pid);
        const std::string inertia = given_inertia(part, m->second);
        if (first) add(out, "sections:", part.at);
        first = false;
        add(out,
            "  - {elements: part_" + std::to_string(pid) + ", material: mat_" +
                std::to_string(part.material) + ", thickness: " + num(thickness) + ", " + rule +
                (inertia.empty() ? "" : ", " + inertia) +
                (s->second.area_mass > 0 ? ", area_mass: " + num(s->second.area_mass) : "") + "}",
            part.at);
    }
    for (const auto& [pid, e] : solid_parts_) write_solid_section(out, pid, e, first);
    for (const auto& [pid, p] : parts_)
        if (!element_parts_.count(pid) && !solid_parts_.count(pid))
            note(*p.at.block, p.at.line,
                 "part " + std::to_string(pid) + " has no shell elements: left out");
}

void DeckTranslator::section_solid(const DeckBlock& b) {
    const std::size_t first = b.keyword == "SECTION_SOLID_TITLE" ? 1 : 0;
    const Card f = required_card(b, first, "SECID, ELFORM, AET");
    const long long id = f.id(0, "SECID");
    if (const auto other = solid_sections_.find(id); other != solid_sections_.end())
        f.fail("section " + std::to_string(id) + " is defined twice (first at " +
               place(other->second) + ")");
    solid_sections_[id] = {&b, b.line};
}

void DeckTranslator::write_solid_section(std::vector<Line>& out, long long pid,
                                         const ElementPartInfo& e, bool& first) {
    const auto p = parts_.find(pid);
    if (p == parts_.end())
        deck_fail(*e.first.block, e.first.line,
                  "an element of part " + std::to_string(pid) + ", which no *PART defines");
    const PartDef& part = p->second;
    const auto s = solid_sections_.find(part.section);
    if (s == solid_sections_.end())
        deck_fail(*e.first.block, e.first.line,
                  "the solids of part " + std::to_string(pid) + " need a *SECTION_SOLID (SECID " +
                      std::to_string(part.section) + " is none)");
    const auto m = materials_.find(part.material);
    if (m == materials_.end())
        deck_fail(*part.at.block, part.at.line,
                  "MID " + std::to_string(part.material) + ": no *MAT card defines it");
    if (m->second.keyword != "MAT_RIGID")
        deck_fail(*s->second.block, s->second.line,
                  "part " + std::to_string(pid) + " is meshed with solids of " + "*" +
                      m->second.keyword +
                      ": fpmshell models shells only, and solids of rigid parts (*MAT_RIGID)");
    const std::string inertia = given_inertia(part, m->second);
    if (first) add(out, "sections:", part.at);
    first = false;
    add(out,
        "  - {elements: part_" + std::to_string(pid) + ", material: mat_" +
            std::to_string(part.material) + ", thickness: 0, " +
            (inertia.empty() ? "inertia: enclosed" : inertia) + "}",
        part.at);
    note(*e.first.block, e.first.line,
         fmt::format("the {} solids of rigid part {} are its outer faces (a contact surface "
                     "without thickness) and {}",
                     e.count, pid,
                     inertia.empty() ? "the mass and inertia of the solid they enclose"
                                     : "the mass and inertia its *PART_INERTIA gives"));
}

}  // namespace fpmshell::deck
