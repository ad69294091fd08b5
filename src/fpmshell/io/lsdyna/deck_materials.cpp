// Parts, materials, curves and tables of a deck, and their model keys.
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

namespace {

/// The plastic strain at failure of a plastic material's card (*MAT_003 FS, *MAT_018 EPSF,
/// *MAT_024 FAIL; theory.md §7.6): > 0 erodes the elements whose points reach it, 0 none.
void failure_strain(const Card& c, std::size_t k, const char* name, MaterialDef& m) {
    const Real strain = c.real(k, name);
    if (strain < 0)
        c.fail(std::string(name) +
               " < 0 (a user failure routine or a failure time) is not supported; give the "
               "plastic strain at failure (> 0) or 0 for none");
    if (strain > 0) m.keys.push_back("failure: {plastic_strain: " + num(strain) + "}");
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

void DeckTranslator::material(const DeckBlock& b) {
    static const std::map<std::string, std::string> aliases = {
        {"MAT_001", "MAT_ELASTIC"},
        {"MAT_003", "MAT_PLASTIC_KINEMATIC"},
        {"MAT_015", "MAT_JOHNSON_COOK"},
        {"MAT_018", "MAT_POWER_LAW_PLASTICITY"},
        {"MAT_024", "MAT_PIECEWISE_LINEAR_PLASTICITY"},
        {"MAT_037", "MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC"},
        {"MAT_020", "MAT_RIGID"}};
    std::string name = b.keyword;
    bool titled = false;
    if (name.size() > 6 && name.compare(name.size() - 6, 6, "_TITLE") == 0) {
        titled = true;
        name.resize(name.size() - 6);
    }
    if (const auto a = aliases.find(name); a != aliases.end()) name = a->second;
    const std::size_t first = titled ? 1 : 0;
    MaterialDef m;
    m.keyword = name;
    long long mid = 0;
    const auto elastic = [&](const Card& f, Real e, Real nu) {
        m.keys.push_back("density: " + num(f.real(1, "RO")));
        m.keys.push_back("youngs_modulus: " + num(e));
        m.keys.push_back("poisson_ratio: " + num(nu));
    };
    if (name == "MAT_ELASTIC") {
        const Card f = required_card(b, first, "MID, RO, E, PR");
        mid = f.id(0, "MID");
        m.keys.push_back("type: elastic");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        m.at = {&b, f.line()};
    } else if (name == "MAT_PLASTIC_KINEMATIC") {
        const Card f = required_card(b, first, "MID, RO, E, PR, SIGY, ETAN, BETA");
        const Card g = card(b, first + 1);
        mid = f.id(0, "MID");
        m.plastic = true;
        m.keys.push_back("type: j2_plastic");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        m.keys.push_back("yield_stress: " + num(f.real(4, "SIGY")));
        m.keys.push_back("tangent_modulus: " + num(f.real(5, "ETAN")));
        m.keys.push_back("hardening_mix: " + num(f.real(6, "BETA")));
        const Real src = g.real(0, "SRC"), srp = g.real(1, "SRP");
        if (src > 0 || srp > 0)
            m.keys.push_back("cowper_symonds: {D: " + num(src) + ", q: " + num(srp) + "}");
        failure_strain(g, 2, "FS", m);
        if (g.real(3, "VP") != 0)
            note(b, g.line(), "VP = 1 read as the scaled yield stress (VP = 0)");
        m.at = {&b, f.line()};
    } else if (name == "MAT_JOHNSON_COOK") {
        const Card f = required_card(b, first, "MID, RO, G, E, PR");
        const Card g = required_card(b, first + 1, "A, B, N, C, M, TM, TR, EPSO");
        const Card h = card(b, first + 2), i = card(b, first + 3);
        mid = f.id(0, "MID");
        m.plastic = true;
        Real e = f.real(3, "E");
        const Real shear = f.real(2, "G"), nu = f.real(4, "PR");
        if (e == 0) e = 2.0 * shear * (1.0 + nu);
        m.keys.push_back("type: johnson_cook");
        elastic(f, e, nu);
        if (f.real(7, "RATEOP") != 0)
            f.fail("RATEOP: only the log-linear rate term (0) is supported");
        if (f.real(6, "VP") != 0)
            note(b, f.line(), "VP = 1 read as the scaled yield stress (VP = 0)");
        const Real c = g.real(3, "C"), m_exp = g.real(4, "M"), tm = g.real(5, "TM");
        const Real eps0 = g.real(7, "EPSO");
        m.keys.push_back("A: " + num(g.real(0, "A")));
        m.keys.push_back("B: " + num(g.real(1, "B")));
        m.keys.push_back("n: " + num(g.real(2, "N")));
        if (c != 0) {
            if (!(eps0 > 0)) g.fail("EPSO must be > 0 with a rate term C");
            m.keys.push_back("C: " + num(c));
            m.keys.push_back("reference_strain_rate: " + num(eps0));
        }
        const Real cp = h.real(0, "CP"), tr = g.real(6, "TR");
        if (m_exp != 0 && tm != 0 && cp != 0) {  // theory.md eq. 7.4-2
            if (!(m_exp > 0)) g.fail("M must be > 0 (the exponent of the homologous temperature)");
            if (!(tm > tr)) g.fail("TM must be above TR (the melting and the room temperature)");
            if (!(cp > 0)) h.fail("CP must be > 0 (the specific heat)");
            m.keys.push_back("thermal_softening: {m: " + num(m_exp) +
                             ", melt_temperature: " + num(tm) + ", room_temperature: " + num(tr) +
                             ", specific_heat: " + num(cp) + "}");
            note(b, h.line(),
                 "thermal softening by adiabatic heating: 0.9 of the plastic work heats (the "
                 "Taylor-Quinney fraction; the card has no field for it)");
        } else if (m_exp != 0 || tm != 0) {
            note(b, g.line(), "isothermal: the temperature terms (M, TM, TR) need CP > 0 to act");
        }
        bool damage = false;
        for (std::size_t k = 4; k < 8; ++k) damage = damage || h.real(k, "D1..D4") != 0;
        damage = damage || i.real(0, "D5") != 0;
        if (damage) note(b, h.line(), "D1..D5: failure is not modelled (no element is deleted)");
        note(b, f.line(), "its *EOS is irrelevant: a shell is in plane stress");
        m.at = {&b, f.line()};
    } else if (name == "MAT_POWER_LAW_PLASTICITY") {
        const Card f = required_card(b, first, "MID, RO, E, PR, K, N, SRC, SRP");
        const Card g = card(b, first + 1);
        mid = f.id(0, "MID");
        m.plastic = true;
        m.keys.push_back("type: power_law");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        m.keys.push_back("k: " + num(f.real(4, "K")));
        m.keys.push_back("n: " + num(f.real(5, "N")));
        const Real src = f.real(6, "SRC"), srp = f.real(7, "SRP");
        if (src > 0 || srp > 0)
            m.keys.push_back("cowper_symonds: {D: " + num(src) + ", q: " + num(srp) + "}");
        // LS-DYNA takes SIGY as the initial yield stress only above 0.02, else the strain
        // at yield from the elastic line
        const Real sigy = g.real(0, "SIGY");
        if (sigy > 0.02) m.keys.push_back("yield_stress: " + num(sigy));
        if (g.real(1, "VP") != 0)
            note(b, g.line(), "VP = 1 read as the scaled yield stress (VP = 0)");
        failure_strain(g, 2, "EPSF", m);
        m.at = {&b, f.line()};
    } else if (name == "MAT_PIECEWISE_LINEAR_PLASTICITY") {
        const Card f = required_card(b, first, "MID, RO, E, PR, SIGY, ETAN, FAIL, TDEL");
        const Card g = card(b, first + 1);
        const Card eps = card(b, first + 2), es = card(b, first + 3);
        mid = f.id(0, "MID");
        m.plastic = true;
        m.at = {&b, f.line()};
        const Real c = g.real(0, "C"), p = g.real(1, "P");
        m.lcss = g.id(2, "LCSS");
        if (g.id(3, "LCSR") != 0) g.fail("LCSR (a strain-rate scaling curve) is not supported");
        if (g.real(4, "VP") != 0)
            note(b, g.line(), "VP = 1 read as the scaled yield stress (VP = 0)");
        failure_strain(f, 6, "FAIL", m);
        std::vector<Point2> points;
        for (std::size_t k = 0; k < 8; ++k) {
            const Real x = eps.real(k, "EPS1..EPS8"), y = es.real(k, "ES1..ES8");
            if (k == 0 || x != 0 || y != 0) points.push_back({x, y});
        }
        const bool tabulated = m.lcss != 0 || points.size() >= 2;
        m.keys.push_back(tabulated ? "type: tabulated" : "type: j2_plastic");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        if (!tabulated) {
            m.keys.push_back("yield_stress: " + num(f.real(4, "SIGY")));
            m.keys.push_back("tangent_modulus: " + num(f.real(5, "ETAN")));
        } else if (m.lcss == 0) {
            m.keys.push_back("flow_curve: " + points_text(points));
        }
        if (c > 0 || p > 0)
            m.keys.push_back("cowper_symonds: {D: " + num(c) + ", q: " + num(p) + "}");
    } else if (name == "MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC") {
        // Hill's normal anisotropy R (theory.md eq. 7.1-3) on a bilinear curve (SIGY, ETAN) or
        // the flow curve HLCID
        const Card f = required_card(b, first, "MID, RO, E, PR, SIGY, ETAN, R, HLCID");
        const Card g = card(b, first + 1);
        mid = f.id(0, "MID");
        m.plastic = true;
        m.at = {&b, f.line()};
        for (std::size_t k = 0; k < 5; ++k)
            if (g.real(k, "IDSCALE, EA, COE, ICFLD, STRAINLT") != 0)
                g.fail(
                    "IDSCALE, EA, COE, ICFLD, STRAINLT (a modulus that changes with plastic "
                    "strain, a forming limit) are not supported");
        Real r = f.real(6, "R");
        if (r < 0) {
            r = -r;
            note(b, f.line(), "R < 0 read as its magnitude " + num(r));
        }
        if (!(r > 0)) f.fail("R must be the sheet's Lankford ratio, not 0");
        if (f.real(5, "ETAN") < 0)
            f.fail("ETAN < 0 (through-thickness normal stresses) is not supported");
        m.lcss = f.id(7, "HLCID");
        m.keys.push_back(m.lcss != 0 ? "type: tabulated" : "type: j2_plastic");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        if (m.lcss == 0) {
            m.keys.push_back("yield_stress: " + num(f.real(4, "SIGY")));
            m.keys.push_back("tangent_modulus: " + num(f.real(5, "ETAN")));
        } else if (f.real(4, "SIGY") != 0 || f.real(5, "ETAN") != 0) {
            note(b, f.line(), "SIGY and ETAN ignored: the curve HLCID gives the flow stress");
        }
        m.keys.push_back("normal_anisotropy: " + num(r));
    } else if (name == "MAT_RIGID") {
        // a part of it moves as one rigid body (its section's particles, theory.md §6.11)
        const Card f = required_card(b, first, "MID, RO, E, PR, N, COUPLE, M, ALIAS");
        const Card g = card(b, first + 1);
        mid = f.id(0, "MID");
        m.keys.push_back("type: rigid");
        elastic(f, f.real(2, "E"), f.real(3, "PR"));
        const long long cmo = g.id(0, "CMO");
        if (cmo == -1)
            g.fail(
                "CMO -1: constraints in a local coordinate system are not supported (CMO 1 "
                "constrains the global directions)");
        if (cmo != 0 && cmo != 1) g.fail("CMO must be 0, 1 or -1");
        if (cmo == 1) {  // CON1, CON2: 1 x, 2 y, 3 z, 4 x y, 5 y z, 6 z x, 7 all
            static const char* const axes[8] = {"", "x", "y", "z", "xy", "yz", "zx", "xyz"};
            std::string fix;
            for (const auto& [field, prefix] : {std::pair{1, 'u'}, std::pair{2, 'r'}}) {
                const long long code =
                    g.id(static_cast<std::size_t>(field), field == 1 ? "CON1" : "CON2");
                if (code < 0 || code > 7)
                    g.fail(std::string(field == 1 ? "CON1" : "CON2") + " must be 0 to 7");
                for (const char* a = axes[code]; *a != '\0'; ++a)
                    fix += (fix.empty() ? "" : ", ") + std::string{prefix, *a};
            }
            if (!fix.empty()) m.keys.push_back("fix: [" + fix + "]");
        }
        m.at = {&b, f.line()};
    } else {
        refuse(b, unsupported_reason(b.keyword));
    }
    if (const auto other = materials_.find(mid); other != materials_.end())
        deck_fail(b, m.at.line,
                  "material " + std::to_string(mid) + " is defined twice (first at " +
                      place(other->second.at) + ")");
    materials_[mid] = m;
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
