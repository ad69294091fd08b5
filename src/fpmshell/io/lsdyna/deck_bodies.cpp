// Rigid walls (planar and geometric), contacts and nodal rigid bodies of a deck.
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

/// *CONSTRAINED_NODAL_RIGID_BODY (_TITLE): the nodes of NSID move as one rigid body.
void DeckTranslator::nodal_rigid_body(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 4);
    for (const std::string& o : opt)
        if (o != "TITLE")
            refuse(b, "*CONSTRAINED_NODAL_RIGID_BODY_" + o +
                          " is not supported (its inertia or constraints would change the "
                          "model); fpmshell reads the plain card and _TITLE");
    const std::size_t first = opt.count("TITLE") ? 1 : 0;
    const Card f = required_card(b, first, "PID, CID, NSID, PNODE, IPRT, DRFLAG, RRFLAG");
    const long long nsid = f.id(2, "NSID");
    if (f.id(5, "DRFLAG") != 0 || f.id(6, "RRFLAG") != 0)
        f.fail("DRFLAG and RRFLAG (released degrees of freedom) are not supported (0 only)");
    constraints_.push_back(
        {"  - {type: rigid, nodes: " + yaml_name(set_name(f, "node", nsid)) + "}", {&b, f.line()}});
    if (f.id(3, "PNODE") != 0)
        note(b, f.line(), "PNODE ignored: the body's motion is that of its nodes");
}

/// Part `pid` of card f: it must exist and be of *MAT_RIGID (`what` names the card's field).
void DeckTranslator::require_rigid_part(const Card& f, long long pid, const char* what) {
    const auto p = parts_.find(pid);
    if (p == parts_.end())
        f.fail(std::string(what) + " " + std::to_string(pid) + ": no *PART defines it");
    const auto m = materials_.find(p->second.material);
    if (m == materials_.end() || std::find(m->second.keys.begin(), m->second.keys.end(),
                                           "type: rigid") == m->second.keys.end())
        f.fail(std::string(what) + " " + std::to_string(pid) +
               ": the part is not of *MAT_RIGID (the card joins rigid bodies)");
}

/// *CONSTRAINED_RIGID_BODIES: each card's constrained part PIDC joins the lead part PIDL in
/// one rigid body (a `constraints` entry over both parts' nodes).
void DeckTranslator::rigid_bodies_joined(const DeckBlock& b) {
    if (b.keyword != "CONSTRAINED_RIGID_BODIES") refuse(b, unsupported_reason(b.keyword));
    if (b.cards.empty()) required_card(b, 0, "PIDL, PIDC, IFLAG");
    for (std::size_t c = 0; c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;
        const Card f = card(b, c);
        const long long lead = f.id(0, "PIDL"), joined = f.id(1, "PIDC");
        require_rigid_part(f, lead, "PIDL");
        require_rigid_part(f, joined, "PIDC");
        constraints_.push_back({"  - {type: rigid, nodes: [part_" + std::to_string(lead) +
                                    ", part_" + std::to_string(joined) + "]}",
                                {&b, f.line()}});
        if (f.id(2, "IFLAG") != 0)
            note(b, f.line(),
                 "IFLAG ignored: the joined body's mass and inertia are those of all its "
                 "particles");
    }
}

/// *CONSTRAINED_EXTRA_NODES_NODE / _SET: nodes that move with the rigid part PID (a
/// `constraints` entry over the part's nodes and them).
void DeckTranslator::extra_nodes(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 3);
    const bool single = opt.count("NODE") != 0;
    if (opt.size() != 1 || (!single && !opt.count("SET")))
        refuse(b, "fpmshell reads *CONSTRAINED_EXTRA_NODES_NODE and _SET");
    if (b.cards.empty()) required_card(b, 0, single ? "PID, NID, IFLAG" : "PID, NSID, IFLAG");
    for (std::size_t c = 0; c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;
        const Card f = card(b, c);
        const long long pid = f.id(0, "PID"), id = f.id(1, single ? "NID" : "NSID");
        require_rigid_part(f, pid, "PID");
        if (f.id(2, "IFLAG") != 0)
            note(b, f.line(),
                 "IFLAG ignored: the body's mass and inertia are those of all its particles");
        const std::string part = "part_" + std::to_string(pid);
        if (single)
            add_node_to_group("extra_nodes_" + std::to_string(pid), id,
                              "{type: rigid, nodes: [" + part + ", NODES]}", {&b, f.line()},
                              constraints_);
        else
            constraints_.push_back({"  - {type: rigid, nodes: [" + part + ", " +
                                        yaml_name(set_name(f, "node", id)) + "]}",
                                    {&b, f.line()}});
    }
}

void DeckTranslator::rigid_wall(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    for (const std::string& o : opt)
        if (o != "ID" && o != "MOVING" && o != "FORCES")
            refuse(b, "*RIGIDWALL_PLANAR_" + o +
                          " is not supported; fpmshell's walls are infinite planes "
                          "(_ID, _MOVING, _FORCES)");
    std::size_t c = 0;
    WallDef w;
    w.id = reading_number(b);  // LS-DYNA numbers a wall without _ID by its place
    if (opt.count("ID")) w.id = required_card(b, c++, "RWID, HEADING").id(0, "RWID");
    const Card f = required_card(b, c++, "NSID, NSIDEX, BOXID, OFFSET, BIRTH, DEATH");
    const Card g = required_card(b, c++, "XT, YT, ZT, XH, YH, ZH, FRIC, WVEL");
    const long long nsid = f.id(0, "NSID");
    if (f.id(2, "BOXID") != 0) f.fail("BOXID is not supported (0 only)");
    if (const long long nsidex = f.id(1, "NSIDEX"); nsidex != 0)
        w.except_nodes = set_name(f, "node", nsidex);
    if (f.real(3, "OFFSET") != 0)
        note(b, f.line(),
             "OFFSET: every node of NSID is tracked (LS-DYNA tracks those within OFFSET of the "
             "wall, a subset)");
    if (f.real(4, "BIRTH") != 0 || (f.real(5, "DEATH") != 0 && f.real(5, "DEATH") < 1e20))
        f.fail("BIRTH and DEATH are not supported (the wall acts from start to end)");
    w.friction = g.real(6, "FRIC");
    if (!(w.friction >= 0 && w.friction <= 1))
        g.fail(
            "FRIC must be from 0 to 1 (0 frictionless, a Coulomb coefficient below 1, 1 no "
            "sliding)");
    w.nodes = nsid == 0 ? "" : set_name(f, "node", nsid);
    std::array<Real, 3> tail{};
    Real len = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        tail[k] = g.real(k, "XT, YT, ZT");
        w.normal[k] = g.real(3 + k, "XH, YH, ZH") - tail[k];
        len += w.normal[k] * w.normal[k];
    }
    if (!(len > 0)) g.fail("the head (XH, YH, ZH) must differ from the tail (XT, YT, ZT)");
    if (opt.count("MOVING")) {
        const Card m = required_card(b, c++, "MASS, V0");
        w.moving = true;
        w.mass = m.real(0, "MASS");
        w.speed = m.real(1, "V0");
        if (!(w.mass > 0)) m.fail("MASS must be > 0");
    }
    w.geometry = "shape: plane, point: " + vec(tail[0], tail[1], tail[2]) +
                 ", normal: " + unit_text(w.normal);
    w.at = {&b, g.line()};
    add_wall(w, f);
}

void DeckTranslator::add_wall(const WallDef& w, const Card& f) {
    for (const WallDef& other : walls_)
        if (other.id == w.id)
            f.fail("rigid wall " + std::to_string(w.id) + " is defined twice (first at " +
                   place(other.at) + ")");
    walls_.push_back(w);
}

std::array<Real, 3> DeckTranslator::unit(const std::array<Real, 3>& v) {
    const Real len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / len, v[1] / len, v[2] / len};
}

std::string DeckTranslator::unit_text(const std::array<Real, 3>& v) {
    const std::array<Real, 3> n = unit(v);
    return vec(n[0], n[1], n[2]);
}

/// *RIGIDWALL_GEOMETRIC_FLAT (a rectangle), _CYLINDER, _SPHERE: a fixed rigid body of that
/// shape (model/rigid_face.hpp) the nodes stay outside of; _ID and _DISPLAY (its card
/// skipped) read, _MOTION refused.
void DeckTranslator::geometric_wall(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    std::string shape;
    for (const std::string& o : opt) {
        if (o == "FLAT" || o == "CYLINDER" || o == "SPHERE")
            shape = o;
        else if (o != "ID" && o != "DISPLAY" && o != "MOTION")
            refuse(b, "*" + b.keyword + ": the option _" + o +
                          " is not supported (fpmshell reads _FLAT, _CYLINDER, _SPHERE with "
                          "_ID, _MOTION, _DISPLAY)");
    }
    if (shape.empty()) refuse(b, "fpmshell reads *RIGIDWALL_GEOMETRIC_FLAT, _CYLINDER and _SPHERE");
    std::size_t c = 0;
    WallDef w;
    w.id = reading_number(b);  // LS-DYNA numbers a wall without _ID by its place
    if (opt.count("ID")) w.id = required_card(b, c++, "RWID, HEADING").id(0, "RWID");
    const Card f = required_card(b, c++, "NSID, NSIDEX, BOXID, BIRTH, DEATH");
    const Card g = required_card(b, c++, "XT, YT, ZT, XH, YH, ZH");
    const Card s = required_card(b, c++, "the shape's card");
    const long long nsid = f.id(0, "NSID");
    if (f.id(2, "BOXID") != 0) f.fail("BOXID is not supported (0 only)");
    if (const long long nsidex = f.id(1, "NSIDEX"); nsidex != 0)
        w.except_nodes = set_name(f, "node", nsidex);
    if (f.real(3, "BIRTH") != 0 || (f.real(4, "DEATH") != 0 && f.real(4, "DEATH") < 1e20))
        f.fail("BIRTH and DEATH are not supported (the wall acts from start to end)");
    w.nodes = nsid == 0 ? "" : set_name(f, "node", nsid);
    std::array<Real, 3> tail{}, dir{};
    for (std::size_t k = 0; k < 3; ++k) {
        tail[k] = g.real(k, "XT, YT, ZT");
        dir[k] = g.real(3 + k, "XH, YH, ZH") - tail[k];
    }
    const bool has_dir = dir[0] != 0 || dir[1] != 0 || dir[2] != 0;
    const std::string point = vec(tail[0], tail[1], tail[2]);
    if (shape == "SPHERE") {
        w.geometry = "shape: sphere, point: " + point + ", radius: " + num(s.real(0, "RADSPH"));
    } else if (!has_dir) {
        g.fail("the head (XH, YH, ZH) must differ from the tail (XT, YT, ZT)");
    } else if (shape == "CYLINDER") {
        w.geometry = "shape: cylinder, point: " + point + ", axis: " + unit_text(dir) +
                     ", radius: " + num(s.real(0, "RADCYL")) +
                     ", length: " + num(s.real(1, "LENCYL"));
    } else {
        const Real l = s.real(3, "LENL"), m = s.real(4, "LENM");
        w.geometry = "shape: plane, point: " + point + ", normal: " + unit_text(dir);
        if (l > 0 || m > 0)
            w.geometry +=
                ", edge: " + vec(s.real(0, "XHEV"), s.real(1, "YHEV"), s.real(2, "ZHEV")) +
                ", size: [" + num(l) + ", " + num(m) + "]";
    }
    if (opt.count("MOTION")) {
        const Card mo = required_card(b, c++, "LCID, OPT, VX, VY, VZ");
        w.motion_curve = mo.id(0, "LCID");
        w.motion_opt = mo.id(1, "OPT");
        if (w.motion_curve == 0) mo.fail("LCID: the motion needs a curve");
        if (w.motion_opt != 0 && w.motion_opt != 1)
            mo.fail("OPT must be 0 (velocity) or 1 (displacement)");
        for (std::size_t k = 0; k < 3; ++k) w.motion_dir[k] = mo.real(2 + k, "VX, VY, VZ");
        if (w.motion_dir == std::array<Real, 3>{})
            mo.fail("VX, VY, VZ: the direction must not be zero");
        w.motion_dir = unit(w.motion_dir);
        w.motion_at = {&b, mo.line()};
    }
    w.at = {&b, g.line()};
    add_wall(w, f);
    note(b, g.line(),
         "a rigid " +
             std::string(shape == "FLAT"     ? "rectangle"
                         : shape == "SPHERE" ? "sphere"
                                             : "cylinder") +
             " of infinite mass the nodes stay outside of (frictionless, Lagrange "
             "multipliers)");
}

/// *CONTACT_AUTOMATIC_SINGLE_SURFACE: self-contact over its side; _SURFACE_TO_SURFACE and
/// _NODES_TO_SURFACE: self-contact over the union of both sides, which keeps the two
/// apart (and each side from itself too: noted).
namespace {

/// The contact cards read as fpmshell's shell self-contact: the keyword, its words before the
/// options, whether it has one side, and how the mapping is not one-to-one (null: it is).
struct ContactForm {
    const char* keyword;
    std::size_t words;
    bool single;
    const char* differs;
};
const ContactForm k_contact_forms[] = {
    {"CONTACT_AUTOMATIC_SINGLE_SURFACE", 4, true, nullptr},
    {"CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", 5, false, nullptr},
    {"CONTACT_AUTOMATIC_NODES_TO_SURFACE", 5, false, nullptr},
    {"CONTACT_AUTOMATIC_GENERAL", 3, true,
     "LS-DYNA's general contact also checks beam and shell edges against each other; fpmshell's "
     "checks particles against faces"},
    {"CONTACT_SINGLE_SURFACE", 3, true,
     "the older single-surface contact, read as the automatic one (both sides of each shell, "
     "its thickness as the contact thickness)"},
    {"CONTACT_SURFACE_TO_SURFACE", 4, false,
     "a one-sided contact (the side its segments' normals point to), read as the automatic, "
     "two-sided one"},
    {"CONTACT_NODES_TO_SURFACE", 4, false,
     "a one-sided contact (the side its segments' normals point to), read as the automatic, "
     "two-sided one"},
    {"CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE", 7, false,
     "a forming contact (a sheet against its tools, the tools' side only), read as the "
     "automatic, two-sided one"},
    {"CONTACT_FORMING_SURFACE_TO_SURFACE", 5, false,
     "a forming contact (a sheet against its tools), read as the automatic, two-sided one"},
    {"CONTACT_FORMING_NODES_TO_SURFACE", 5, false,
     "a forming contact (a sheet's nodes against its tools), read as the automatic, two-sided "
     "one"},
    // the eroding forms: fpmshell's self-contact is eroding already (theory.md §7.6: an eroded
    // element's faces leave it, its particles stay as contact nodes)
    {"CONTACT_ERODING_SINGLE_SURFACE", 4, true, nullptr},
    {"CONTACT_ERODING_SURFACE_TO_SURFACE", 5, false,
     "a one-sided contact (the side its segments' normals point to), read as the automatic, "
     "two-sided one"},
    {"CONTACT_ERODING_NODES_TO_SURFACE", 5, false,
     "a one-sided contact (the side its segments' normals point to), read as the automatic, "
     "two-sided one"},
};

}  // namespace

/// A *CONTACT_ card of k_contact_forms as fpmshell's shell self-contact: single-surface forms
/// over their side, two-sided forms over the union of both sides, which keeps the two apart
/// (and each side from itself too: noted).
void DeckTranslator::contact(const DeckBlock& b) {
    const ContactForm* form = nullptr;
    for (const ContactForm& f : k_contact_forms)
        if (b.keyword == f.keyword ||
            starts_with(b.keyword, (std::string(f.keyword) + "_").c_str()))
            form = &f;
    if (form == nullptr) refuse(b, unsupported_reason(b.keyword));
    const bool single = form->single;
    const std::set<std::string> opt = options_of(b.keyword, form->words);
    for (const std::string& o : opt)
        if (o != "ID" && o != "MPP" && o != "TITLE" && o != "MORTAR")
            refuse(b, "*" + b.keyword + ": the option _" + o + " is not supported");
    if (form->differs != nullptr) note(b, b.line, form->differs);
    if (opt.count("MORTAR"))
        note(b, b.line,
             "_MORTAR: the segment-to-segment penalty contact read as fpmshell's particle-to-face "
             "contact with Lagrange multipliers");
    std::size_t c = (opt.count("ID") || opt.count("TITLE")) ? 1 : 0;
    if (opt.count("MPP")) {
        ++c;
        if (c < b.cards.size() && trim(b.cards[c].text).rfind('&', 0) == 0) ++c;
    }
    const Card f = required_card(b, c, "SSID, MSID, SSTYP, MSTYP");
    const Card g = card(b, c + 1);
    if (f.id(4, "SBOXID") != 0 || f.id(5, "MBOXID") != 0)
        f.fail("SBOXID and MBOXID are not supported (0 only)");
    const std::string friction = contact_friction(g);
    if (g.real(6, "BT") != 0 || (g.real(7, "DT") != 0 && g.real(7, "DT") < 1e20))
        g.fail("BT and DT are not supported (contact acts from start to end)");
    if (g.real(4, "VDC") != 0)
        note(b, g.line(),
             "VDC ignored: the contact is enforced by Lagrange multipliers, without "
             "viscous damping");
    if (starts_with(b.keyword, "CONTACT_ERODING_")) eroding_contact_card(b, c + 3);
    // a node set on the slave side of a nodes-to-surface form: those nodes alone against the
    // master side's faces (one-way, as LS-DYNA's)
    const bool node_set =
        f.id(2, "SSTYP") == 4 && b.keyword.find("NODES_TO_SURFACE") != std::string::npos;
    std::string elements, nodes;
    if (node_set) {
        nodes = ", nodes: " + yaml_name(set_name(f, "node", f.id(0, "SSID")));
        elements = yaml_name(contact_side(f, f.id(1, "MSID"), f.id(3, "MSTYP"), "MSTYP"));
    } else {
        std::vector<std::string> sides{contact_side(f, f.id(0, "SSID"), f.id(2, "SSTYP"), "SSTYP")};
        if (!single) sides.push_back(contact_side(f, f.id(1, "MSID"), f.id(3, "MSTYP"), "MSTYP"));
        if (std::find(sides.begin(), sides.end(), "all") != sides.end())
            elements = "all";
        else if (sides.size() == 1 || sides[0] == sides[1])
            elements = yaml_name(sides[0]);
        else
            elements = "[" + yaml_name(sides[0]) + ", " + yaml_name(sides[1]) + "]";
    }
    contact_.push_back(
        {"  - {type: self, elements: " + elements + nodes + friction + "}", {&b, f.line()}});
    // its number in RCFORC's columns: CID of _ID or _TITLE, else its place among the cards
    const long long cid = opt.count("ID") || opt.count("TITLE") ? card(b, 0).id(0, "CID") : 0;
    contact_ids_.push_back({cid > 0 ? cid : reading_number(b), {&b, f.line()}});
    note(b, f.line(),
         std::string(node_set ? "as fpmshell's contact of the node set's particles against the "
                                "master side's faces (one-way)"
                     : single ? "as fpmshell's shell self-contact"
                              : "as fpmshell's shell self-contact over both sides together "
                                "(each side is kept from itself too)") +
             " (Lagrange multipliers, each shell's thickness as its contact thickness)");
}

/// The fourth card of the *CONTACT_ERODING_ forms (LS-DYNA requires it): ISYM, EROSOP, IADJ.
/// fpmshell's self-contact erodes as LS-DYNA's does with EROSOP 1: an eroded element's faces
/// leave it and its nodes stay in it (theory.md §7.6); a shell has no interior faces that
/// erosion would expose, nor solids beside it (IADJ), nor faces on symmetry planes to drop
/// (ISYM, which concerns the faces of solids).
void DeckTranslator::eroding_contact_card(const DeckBlock& b, std::size_t index) {
    const Card e = required_card(b, index, "ISYM, EROSOP, IADJ");
    const long long isym = e.id(0, "ISYM"), erosop = e.id(1, "EROSOP"), iadj = e.id(2, "IADJ");
    if (isym != 0 && isym != 1) e.fail("ISYM must be 0 or 1");
    if (erosop != 0 && erosop != 1) e.fail("EROSOP must be 0 or 1");
    if (iadj != 0 && iadj != 1) e.fail("IADJ must be 0 or 1");
    note(b, e.line(),
         "an eroding contact: an eroded element's faces leave fpmshell's self-contact and its "
         "particles stay in it as nodes with their mass (LS-DYNA's EROSOP 1 with *CONTROL_CONTACT "
         "ENMASS 2; a shell exposes no inner faces, so EROSOP 0 is the same here); ISYM and IADJ "
         "concern solids and are not used");
}

/// Coulomb friction of a contact's second card: FS, FD, DC as `friction`, `friction_dynamic`,
/// `friction_decay` (mu = FD + (FS - FD) exp(-DC |v_rel|), theory.md eq. 8.4-5); "" for none.
std::string DeckTranslator::contact_friction(const Card& g) {
    const Real fs = g.real(0, "FS"), fd = g.real(1, "FD"), dc = g.real(2, "DC");
    if (fs < 0)
        g.fail(
            "FS < 0 (a friction table of *DEFINE_FRICTION or a part-pair friction) is not "
            "supported; give FS, FD and DC");
    if (fd < 0 || dc < 0) g.fail("FD and DC must be >= 0");
    if (g.real(3, "VC") != 0)
        note(g.block(), g.line(),
             "VC ignored: the friction force is not limited by VC x the contact area (Coulomb's "
             "law alone)");
    if (fs == 0) {
        if (fd != 0)
            note(g.block(), g.line(),
                 "FD without FS: frictionless (LS-DYNA's coefficient FD + (FS - FD) exp(-DC v) "
                 "starts from FS = 0)");
        return "";
    }
    std::string keys = ", friction: " + num(fs);
    if (dc > 0) keys += ", friction_dynamic: " + num(fd) + ", friction_decay: " + num(dc);
    return keys;
}

/// *CONTACT_TIED_NODES_TO_SURFACE, _SHELL_EDGE_TO_SURFACE, _SURFACE_TO_SURFACE (_OFFSET,
/// _CONSTRAINED_OFFSET, _ID, _TITLE, _MPP): a `constraints` entry of type tied, the slave side's
/// nodes tied to the master side's faces (theory.md §6.12).
void DeckTranslator::tied_contact(const DeckBlock& b) {
    const bool edge = starts_with(b.keyword, "CONTACT_TIED_SHELL_EDGE_TO_SURFACE");
    const bool tiebreak = starts_with(b.keyword, "CONTACT_TIEBREAK_NODES_TO_SURFACE");
    const bool tiebreak_surface = starts_with(b.keyword, "CONTACT_TIEBREAK_SURFACE_TO_SURFACE");
    const std::set<std::string> opt = options_of(b.keyword, edge ? 6 : 5);
    for (const std::string& o : opt)
        if (o != "ID" && o != "TITLE" && o != "MPP" && o != "OFFSET" && o != "CONSTRAINED")
            refuse(b, "*" + b.keyword + ": the option _" + o +
                          " is not supported (_OFFSET, _CONSTRAINED_OFFSET, _ID, _TITLE)");
    std::size_t c = (opt.count("ID") || opt.count("TITLE")) ? 1 : 0;
    if (opt.count("MPP")) {
        ++c;
        if (c < b.cards.size() && trim(b.cards[c].text).rfind('&', 0) == 0) ++c;
    }
    const Card f = required_card(b, c, "SSID, MSID, SSTYP, MSTYP");
    if (f.id(4, "SBOXID") != 0 || f.id(5, "MBOXID") != 0)
        f.fail("SBOXID and MBOXID are not supported (0 only)");
    const long long ssid = f.id(0, "SSID"), msid = f.id(1, "MSID");
    const long long sstyp = f.id(2, "SSTYP"), mstyp = f.id(3, "MSTYP");
    std::string slaves;
    if (sstyp == 4)
        slaves = set_name(f, "node", ssid);
    else if (sstyp == 2)
        slaves = set_name(f, "part", ssid);
    else if (sstyp == 3)
        slaves = "part_" + std::to_string(ssid);
    else
        f.fail("SSTYP " + std::to_string(sstyp) +
               " is not supported for a tied contact: 4 (node set), 2 (part set) or 3 (part)");
    std::string masters;
    if (mstyp == 2)
        masters = set_name(f, "part", msid);
    else if (mstyp == 3)
        masters = "part_" + std::to_string(msid);
    else
        f.fail("MSTYP " + std::to_string(mstyp) +
               " is not supported for a tied contact: 2 (part set) or 3 (part); give the "
               "master faces as a part or part set");
    std::string failure;
    if (tiebreak) {
        // the fourth card: NFLF, SFLF (the forces at which a tie lets go), NEN, MES (exponents)
        const Card g = required_card(b, c + 3, "NFLF, SFLF, NEN, MES");
        const Real nflf = g.real(0, "NFLF"), sflf = g.real(1, "SFLF");
        Real nen = g.real(2, "NEN", 2.0), mes = g.real(3, "MES", 2.0);
        if (nen == 0) nen = 2;  // LS-DYNA's default for a 0
        if (mes == 0) mes = 2;
        if (nflf < 0 || sflf < 0) g.fail("NFLF and SFLF must be >= 0");
        if (!(nen > 0) || !(mes > 0)) g.fail("NEN and MES must be > 0");
        if (nflf > 0 || sflf > 0)
            failure = ", failure: {normal_force: " + num(nflf) + ", shear_force: " + num(sflf) +
                      ", normal_exponent: " + num(nen) + ", shear_exponent: " + num(mes) + "}";
        else
            note(b, g.line(), "NFLF and SFLF are 0: the ties never let go");
    }
    if (tiebreak_surface) {
        // the fourth card: NFLS, SFLS (the stresses at which a tie lets go, eq. 6.12-3: times
        // each slave node's area), TBLCID, THKOFF
        const Card g = required_card(b, c + 3, "NFLS, SFLS, TBLCID, THKOFF");
        const Real nfls = g.real(0, "NFLS"), sfls = g.real(1, "SFLS");
        if (g.id(2, "TBLCID") != 0)
            g.fail("TBLCID: a table of the failure stresses is not supported (NFLS, SFLS)");
        if (g.id(3, "THKOFF") != 0)
            g.fail("THKOFF: thickness offsets of the tie are not supported (0 only)");
        if (nfls < 0 || sfls < 0) g.fail("NFLS and SFLS must be >= 0");
        if (nfls > 0 || sfls > 0)
            failure =
                ", failure: {normal_stress: " + num(nfls) + ", shear_stress: " + num(sfls) + "}";
        else
            note(b, g.line(), "NFLS and SFLS are 0: the ties never let go");
        note(b, g.line(),
             "once a tie lets go its faces are free of each other unless another contact "
             "covers them (LS-DYNA's tiebreak goes on as a surface-to-surface contact)");
    }
    constraints_.push_back({"  - {type: tied, nodes: " + yaml_name(slaves) +
                                ", elements: " + yaml_name(masters) + failure + "}",
                            {&b, f.line()}});
    if (!opt.count("OFFSET"))
        note(b, f.line(),
             "the slave nodes keep their offset from the master faces (LS-DYNA moves them onto "
             "the faces first)");
    if (edge) note(b, f.line(), "the shell edges' rotations are not tied (their translations are)");
    note(b, f.line(),
         "as a tie of each slave node to its closest master face within the larger of their "
         "thicknesses (SST, MST and the friction fields not used)");
}

/// The element set of one side of a contact: SID of type TYP (1 shell set, 2 part set,
/// 3 part, 5 all; SID 0 is all).
std::string DeckTranslator::contact_side(const Card& f, long long sid, long long typ,
                                         const char* name) {
    if (typ == 5 || sid == 0) return "all";
    if (typ == 0) {  // a segment set: the shells its segments cover (write_segment_loads)
        const std::string group = "contact_segments_" + std::to_string(sid);
        segment_sides_.push_back({group, sid, {&f.block(), f.line()}});
        return group;
    }
    if (typ == 1) return set_name(f, "shell", sid);
    if (typ == 2) return set_name(f, "part", sid);
    if (typ == 3) return "part_" + std::to_string(sid);
    f.fail(std::string(name) + " " + std::to_string(typ) +
           " is not supported: 0 (segment set), 1 (shell set), 2 (part set), 3 (part) or 5 (all), "
           "and 4 (node set) for the slave side of a nodes-to-surface contact");
}

void DeckTranslator::write_walls(std::vector<Line>& out) {
    if (walls_.empty()) return;
    add(out, "rigid_bodies:", walls_.front().at);
    for (const WallDef& w : walls_) {
        std::string s = "  - {name: rigidwall" + std::to_string(w.id) + ", " + w.geometry;
        if (w.moving) {
            const std::array<Real, 3> n = unit(w.normal);
            s += ", mass: " + num(w.mass) +
                 ", velocity: " + vec(w.speed * n[0], w.speed * n[1], w.speed * n[2]);
        } else {
            s += ", fixed: true";
            if (w.motion_curve != 0) s += ", velocity: " + wall_velocity(w);
        }
        add(out, s + "}", w.at);
    }
    std::vector<Line> contacts;
    for (const WallDef& w : walls_)
        // LS-DYNA's walls act on the nodes themselves, not on their shells' thickness: offset 0;
        // the nodes that start behind a wall are released from it (noted by the model reader)
        contacts.push_back(
            {"  - {type: rigid, body: rigidwall" + std::to_string(w.id) +
                 (w.nodes.empty() ? "" : ", nodes: " + yaml_name(w.nodes)) +
                 (w.except_nodes.empty() ? "" : ", except_nodes: " + yaml_name(w.except_nodes)) +
                 ", offset: 0, initially_inside: release" +
                 (w.friction == 0   ? ""
                  : w.friction == 1 ? ", friction: stick"
                                    : ", friction: " + num(w.friction)) +
                 "}",
             w.at});
    contact_.insert(contact_.begin(), contacts.begin(), contacts.end());
}

/// The constant velocity of a geometric wall's _MOTION: a flat velocity curve (OPT 0) or a
/// straight displacement curve from 0 at t = 0 (OPT 1), along the direction; fpmshell's
/// fixed bodies move at a constant velocity, so any other curve is refused.
std::string DeckTranslator::wall_velocity(const WallDef& w) {
    const DeckBlock& b = *w.motion_at.block;
    const auto c = curves_.find(w.motion_curve);
    if (c == curves_.end())
        deck_fail(b, w.motion_at.line,
                  "LCID " + std::to_string(w.motion_curve) + ": no *DEFINE_CURVE defines it");
    const std::vector<Point2>& p = c->second.points;
    Real speed = p.front().y;
    bool constant = true;
    if (w.motion_opt == 1) {
        speed = p.size() > 1 ? (p.back().y - p.front().y) / (p.back().x - p.front().x) : 0.0;
        constant = p.size() > 1 && std::isfinite(speed);
        for (const Point2& q : p)  // on the line through the origin of slope `speed`
            constant = constant && std::abs(q.y - speed * q.x) <=
                                       1e-9 * (std::abs(speed * q.x) + std::abs(q.y) + 1e-300);
    } else {
        for (const Point2& q : p) constant = constant && q.y == speed;
    }
    if (!constant)
        deck_fail(b, w.motion_at.line,
                  "the motion of curve " + std::to_string(w.motion_curve) +
                      " is not a constant velocity (a flat velocity curve, or a straight "
                      "displacement curve from 0 at t = 0), which is what a geometric wall "
                      "of fpmshell can do");
    note(b, w.motion_at.line,
         "_MOTION: the wall moves at " + num(speed) +
             " along its direction throughout (past the curve's end too)");
    return vec(speed * w.motion_dir[0], speed * w.motion_dir[1], speed * w.motion_dir[2]);
}

}  // namespace fpmshell::deck
