// Parts, materials, curves and tables of a deck, and their model keys.
#include "fpmshell/failure/failure_criterion.hpp"
#include "fpmshell/io/lsdyna/deck_failure_card.hpp"
#include "fpmshell/io/lsdyna/deck_material_card.hpp"
#include "fpmshell/io/lsdyna/deck_translator.hpp"
#include "fpmshell/materials/material_law.hpp"

namespace fpmshell::deck {

namespace {
/// A *MAT_ keyword without its _TITLE option, and whether it had it (a title card first).
std::pair<std::string, bool> without_title(const std::string& keyword) {
    const bool titled = keyword.size() > 6 && keyword.compare(keyword.size() - 6, 6, "_TITLE") == 0;
    return {titled ? keyword.substr(0, keyword.size() - 6) : keyword, titled};
}
}  // namespace

/// Parts: a heading card and a data card each (one *PART may define several).
void DeckTranslator::part(const DeckBlock& b) {
    if (b.cards.size() < 2) required_card(b, 1, "PID, SECID, MID");
    for (std::size_t c = 0; c + 1 < b.cards.size(); c += 2) {
        const Card f = required_card(b, c + 1, "PID, SECID, MID");
        const long long pid = f.id(0, "PID");
        PartDef p{{&b, f.line()}, f.id(1, "SECID"), f.id(2, "MID")};
        if (f.id(3, "EOSID") != 0)
            note(b, f.line(),
                 "EOSID ignored: an equation of state has no part in a shell's plane stress");
        if (const auto other = parts_.find(pid); other != parts_.end())
            f.fail("part " + std::to_string(pid) + " is defined twice (first at " +
                   place(other->second.at) + ")");
        parts_[pid] = p;
    }
}

/// *PART_INERTIA: per part, a heading card, PID SECID MID ..., XC YC ZC TM IRCS NODEID,
/// IXX IXY IXZ IYY IYZ IZZ (global axes, about the centre), VTX VTY VTZ VRX VRY VRZ.
void DeckTranslator::part_inertia(const DeckBlock& b) {
    constexpr std::size_t k_cards = 5;
    if (b.cards.size() < k_cards) required_card(b, b.cards.size(), "the cards of *PART_INERTIA");
    for (std::size_t c = 0; c + k_cards <= b.cards.size(); c += k_cards) {
        const Card f = required_card(b, c + 1, "PID, SECID, MID");
        const Card g = required_card(b, c + 2, "XC, YC, ZC, TM, IRCS, NODEID");
        const Card h = required_card(b, c + 3, "IXX, IXY, IXZ, IYY, IYZ, IZZ");
        const Card v = required_card(b, c + 4, "VTX, VTY, VTZ, VRX, VRY, VRZ");
        const long long pid = f.id(0, "PID");
        if (g.id(4, "IRCS") != 0)
            g.fail(
                "IRCS 1: an inertia tensor in local axes is not supported (give it in global "
                "axes, IRCS 0)");
        if (g.id(5, "NODEID") != 0)
            g.fail("NODEID: a node as the centre of mass is not supported (give XC, YC, ZC)");
        const Real tm = g.real(3, "TM");
        if (!(tm > 0)) g.fail("TM must be the body's mass, > 0");
        const Real xc = g.real(0, "XC"), yc = g.real(1, "YC"), zc = g.real(2, "ZC");
        PartDef p{{&b, f.line()}, f.id(1, "SECID"), f.id(2, "MID")};
        p.inertia = "inertia: {mass: " + num(tm) + ", centre: " + vec(xc, yc, zc) + ", tensor: [" +
                    num(h.real(0, "IXX")) + ", " + num(h.real(1, "IXY")) + ", " +
                    num(h.real(2, "IXZ")) + ", " + num(h.real(3, "IYY")) + ", " +
                    num(h.real(4, "IYZ")) + ", " + num(h.real(5, "IZZ")) + "]}";
        p.inertia_at = {&b, g.line()};
        if (const auto other = parts_.find(pid); other != parts_.end())
            f.fail("part " + std::to_string(pid) + " is defined twice (first at " +
                   place(other->second.at) + ")");
        parts_[pid] = p;
        const Real vt[3] = {v.real(0, "VTX"), v.real(1, "VTY"), v.real(2, "VTZ")};
        const Real vr[3] = {v.real(3, "VRX"), v.real(4, "VRY"), v.real(5, "VRZ")};
        if (vt[0] != 0 || vt[1] != 0 || vt[2] != 0 || vr[0] != 0 || vr[1] != 0 || vr[2] != 0) {
            initial_bodies_.push_back({"  - {nodes: part_" + std::to_string(pid) +
                                           ", velocity: " + vec(vt[0], vt[1], vt[2]) +
                                           ", rotation: {centre: " + vec(xc, yc, zc) +
                                           ", angular_velocity: " + vec(vr[0], vr[1], vr[2]) + "}}",
                                       {&b, v.line()}});
            note(b, v.line(),
                 "VTX..VRZ: the rigid body's initial velocity, replacing those its nodes are "
                 "given elsewhere");
        }
    }
}

std::string DeckTranslator::given_inertia(const PartDef& part, const MaterialDef& m) {
    if (part.inertia.empty()) return "";
    if (m.keyword != "MAT_RIGID")
        deck_fail(*part.inertia_at.block, part.inertia_at.line,
                  "the inertia of a part is given for rigid parts (*MAT_RIGID) only, and this "
                  "part is of *" +
                      m.keyword);
    return part.inertia;
}

// The card's law (materials/material_laws.cpp) translates it (materials/<law>/).
void DeckTranslator::material(const DeckBlock& b) {
    const auto [name, titled] = without_title(b.keyword);
    const DeckMaterialCard* rule = nullptr;
    for (const MaterialLaw& law : material_laws())
        for (const DeckMaterialCard& c : law.deck_cards)
            for (const std::string& k : c.keywords)
                if (k == name) rule = &c;
    if (!rule) refuse(b, unsupported_reason(b.keyword));
    MaterialDef m;
    m.keyword = rule->keywords.front();
    MaterialCard card(*this, b, titled ? 1 : 0, m);
    rule->translate(card);
    if (const auto other = materials_.find(m.id); other != materials_.end())
        deck_fail(b, m.at.line,
                  "material " + std::to_string(m.id) + " is defined twice (first at " +
                      place(other->second.at) + ")");
    materials_[m.id] = m;
}

// The criterion whose deck cards hold the keyword translates it (failure/<criterion>/).
void DeckTranslator::add_failure_card(const DeckBlock& b) {
    const auto [name, titled] = without_title(b.keyword);
    for (const FailureCriterion& c : failure_criteria())
        for (const DeckFailureCard& d : c.deck_cards)
            for (const std::string& k : d.keywords)
                if (k == name) {
                    FailureCard card(*this, b, titled ? 1 : 0);
                    d.translate(card);
                    return;
                }
    refuse(b, unsupported_reason(b.keyword));
}

MaterialDef* DeckTranslator::material_def(long long mid) {
    const auto m = materials_.find(mid);
    return m == materials_.end() ? nullptr : &m->second;
}

const std::vector<Point2>* DeckTranslator::curve_points(long long id) const {
    const auto c = curves_.find(id);
    return c == curves_.end() ? nullptr : &c->second.points;
}

std::string DeckTranslator::points_text(const std::vector<Point2>& points) {
    std::string s = "[";
    for (std::size_t k = 0; k < points.size(); ++k)
        s += (k ? ", [" : "[") + num(points[k].x) + ", " + num(points[k].y) + "]";
    return s + "]";
}

void DeckTranslator::define_curve(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    for (const std::string& o : opt)
        if (o != "TITLE") refuse(b, "*DEFINE_CURVE_" + o + " is not supported");
    const std::size_t first = opt.count("TITLE") ? 1 : 0;
    const Card f = required_card(b, first, "LCID, SIDR, SFA, SFO, OFFA, OFFO");
    const long long id = f.id(0, "LCID");
    Real sfa = f.real(2, "SFA"), sfo = f.real(3, "SFO");
    if (sfa == 0) sfa = 1;
    if (sfo == 0) sfo = 1;
    const Real offa = f.real(4, "OFFA"), offo = f.real(5, "OFFO");
    CurveDef c{{&b, f.line()}, {}};
    for (std::size_t k = first + 1; k < b.cards.size(); ++k) {
        if (b.cards[k].blank()) continue;  // a blank line between points
        const Card p(deck_, b, b.cards[k], {20, 20});
        // abscissa SFA (a + OFFA), ordinate SFO (o + OFFO): the offsets first
        c.points.push_back({sfa * (p.real(0, "A1") + offa), sfo * (p.real(1, "O1") + offo)});
    }
    if (c.points.empty()) f.fail("curve " + std::to_string(id) + " has no points");
    if (const auto other = curves_.find(id); other != curves_.end())
        f.fail("curve " + std::to_string(id) + " is defined twice (first at " +
               place(other->second.at) + ")");
    curves_[id] = c;
    if (table_waiting_ > 0) {  // the curves of the last *DEFINE_TABLE follow it, in order
        tables_[last_table_].curves.push_back(id);
        --table_waiting_;
    }
}

void DeckTranslator::define_table(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    for (const std::string& o : opt)
        if (o != "TITLE") refuse(b, "*DEFINE_TABLE_" + o + " is not supported");
    const std::size_t first = opt.count("TITLE") ? 1 : 0;
    const Card f = required_card(b, first, "TBID, SFA, OFFA");
    const long long id = f.id(0, "TBID");
    Real sfa = f.real(1, "SFA");
    if (sfa == 0) sfa = 1;
    const Real offa = f.real(2, "OFFA");
    TableDef t{{&b, f.line()}, {}, {}};
    for (std::size_t k = first + 1; k < b.cards.size(); ++k) {
        if (b.cards[k].blank()) continue;  // a blank line between values
        const Card v(deck_, b, b.cards[k], {20, 20});
        t.values.push_back(sfa * (v.real(0, "VALUE") + offa));
        if (v.id(1, "LCID") != 0)
            f.fail("a curve id beside VALUE is not supported; let the curves follow the table");
    }
    if (t.values.empty()) f.fail("table " + std::to_string(id) + " has no values");
    if (t.values.front() < 0)  // LS-DYNA: then every value is the logarithm of a rate
        for (Real& v : t.values) v = std::exp(v);
    if (const auto other = tables_.find(id); other != tables_.end())
        f.fail("table " + std::to_string(id) + " is defined twice (first at " +
               place(other->second.at) + ")");
    tables_[id] = t;
    last_table_ = id;
    table_waiting_ = t.values.size();
}

void DeckTranslator::write_materials(std::vector<Line>& out) {
    std::set<long long> used;
    for (const auto& [pid, p] : parts_)
        if (element_parts_.count(pid) || solid_parts_.count(pid)) used.insert(p.material);
    bool first = true;
    for (const auto& [mid, m] : materials_) {
        if (!used.count(mid)) continue;
        if (first) add(out, "materials:", m.at);
        first = false;
        std::string keys;
        for (const std::string& k : m.keys) keys += (keys.empty() ? "" : ", ") + k;
        if (m.lcss != 0) keys += ", " + flow_curves(m);
        if (m.lcsr != 0) {
            const std::string scaling = rate_scaling(m);
            if (!scaling.empty()) keys += ", " + scaling;
        }
        std::vector<std::string> failure = m.failure;
        if (const std::string t = failure_curves(m); !t.empty()) failure.push_back(t);
        if (!failure.empty()) {  // every criterion of its card and of *MAT_ADD_... cards
            std::string f;
            for (const std::string& c : failure) f += (f.empty() ? "" : ", ") + c;
            if (!m.failure_points.empty()) f += ", " + m.failure_points;
            keys += ", failure: {" + f + "}";
        }
        add(out, "  mat_" + std::to_string(mid) + ": {" + keys + "}", m.at);
    }
}

/// The flow curve (or the curves per rate) of a *MAT_024's LCSS.
std::string DeckTranslator::flow_curves(const MaterialDef& m) {
    const DeckBlock& b = *m.at.block;
    if (const auto c = curves_.find(m.lcss); c != curves_.end())
        return "flow_curve: " + points_text(c->second.points);
    const auto t = tables_.find(m.lcss);
    if (t == tables_.end())
        deck_fail(
            b, m.at.line,
            "LCSS " + std::to_string(m.lcss) + " is neither a *DEFINE_CURVE nor a *DEFINE_TABLE");
    if (t->second.curves.size() != t->second.values.size())
        deck_fail(*t->second.at.block, t->second.at.line,
                  "the table lists " + std::to_string(t->second.values.size()) +
                      " strain rates but only " + std::to_string(t->second.curves.size()) +
                      " *DEFINE_CURVE follow it");
    for (const std::string& k : m.keys)
        if (starts_with(k, "cowper_symonds"))
            note(b, m.at.line, "C, P ignored: LCSS is a table of curves per strain rate");
    std::string s = "flow_curves: [";
    for (std::size_t k = 0; k < t->second.values.size(); ++k)
        s += std::string(k ? ", " : "") + "{strain_rate: " + num(t->second.values[k]) +
             ", points: " + points_text(curves_.at(t->second.curves[k]).points) + "}";
    return s + "]";
}

/// The rate factor of a *MAT_024's LCSR (theory.md eq. 7.4-3), "" where its LCSS is a table
/// (which gives the rates itself: LCSR ignored, noted).
std::string DeckTranslator::rate_scaling(const MaterialDef& m) {
    const DeckBlock& b = *m.at.block;
    if (tables_.count(m.lcss)) {
        note(b, m.at.line, "LCSR ignored: LCSS is a table of curves per strain rate");
        return "";
    }
    const auto c = curves_.find(m.lcsr);
    if (c == curves_.end())
        deck_fail(b, m.at.line, "LCSR " + std::to_string(m.lcsr) + ": no *DEFINE_CURVE defines it");
    return "rate_scaling: " + points_text(c->second.points);
}

/// *MAT_224's LCF, LCG, LCI (theory.md eq. 7.6-3): eps_f = f(eta) g(rate) i(size), a criterion
/// `tabulated` of exponent 1 (D = sum d alpha / eps_f, as MAT_224's); without LCF the failure
/// strain is the product of the others (LCI then the failure strain against the size).
std::string DeckTranslator::failure_curves(const MaterialDef& m) {
    if (m.failure_curve == 0 && m.failure_rate_curve == 0 && m.failure_size_curve == 0) return "";
    const DeckBlock& b = *m.at.block;
    const auto points = [&](long long id, const char* name) -> const std::vector<Point2>& {
        const auto c = curves_.find(id);
        if (c == curves_.end())
            deck_fail(b, m.at.line,
                      std::string(name) + " " + std::to_string(id) +
                          (tables_.count(id) ? ": a table (over the Lode angle, or the "
                                               "triaxiality) is not supported; give a curve"
                                             : ": no *DEFINE_CURVE defines it"));
        return c->second.points;
    };
    std::string t = "tabulated: {failure_strain: ";
    t += m.failure_curve != 0 ? points_text(points(m.failure_curve, "LCF")) : "[[0, 1]]";
    if (m.failure_rate_curve != 0) {
        const std::vector<Point2>& g = points(m.failure_rate_curve, "LCG");
        // a first rate < 0: the rates are their logarithms (as LS-DYNA reads LCG)
        t += std::string(!g.empty() && g.front().x < 0 ? ", log_rate_scaling: "
                                                       : ", rate_scaling: ") +
             points_text(g);
    }
    if (m.failure_size_curve != 0)
        t += ", regularization: " + points_text(points(m.failure_size_curve, "LCI"));
    return t + "}";
}

void DeckTranslator::write_curves(std::vector<Line>& out) {
    std::set<long long> done;
    bool first = true;
    for (const auto& [id, at] : used_curves_) {
        if (!done.insert(id).second) continue;
        const auto c = curves_.find(id);
        if (c == curves_.end())
            deck_fail(*at.block, at.line,
                      "LCID " + std::to_string(id) + ": no *DEFINE_CURVE defines it");
        if (first) add(out, "curves:", c->second.at);
        first = false;
        add(out, "  curve_" + std::to_string(id) + ": " + points_text(c->second.points),
            c->second.at);
    }
}

}  // namespace fpmshell::deck
