// LS-DYNA keyword deck -> YAML model (see lsdyna_deck.hpp). The deck is read once into what
// each card defines (parts, sections, materials, curves, conditions, controls), the references
// between them are checked, and the model is written key by key, each line with its card.
#include "fpmshell/io/lsdyna_deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include "fpmshell/core/text.hpp"
#include "fpmshell/io/model_reader.hpp"
#include "fpmshell/mesh/keyword_deck.hpp"
#include "fpmshell/mesh/lsdyna_reader.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"

namespace fpmshell {
namespace {

using text_mesh::upper;

/// The fields of one card with the deck's parameters substituted; each accessor names the
/// field (LS-DYNA's own name) in its message.
class Card {
public:
    Card(const KeywordDeck& deck, const DeckBlock& block, const DeckCard& card,
         const std::vector<std::size_t>& widths)
        : deck_(deck), block_(block), line_(card.line), fields_(deck_fields(block, card, widths)) {}
    /// A blank field is `fallback`.
    [[nodiscard]] Real real(std::size_t k, const char* name, Real fallback = 0) const {
        const std::string f = value(k);
        if (f.empty()) return fallback;
        Real v = 0;
        if (!text_mesh::parse_real(f, v))
            fail(std::string(name) + " '" + f + "' is not a finite number");
        return v;
    }
    [[nodiscard]] long long id(std::size_t k, const char* name, long long fallback = 0) const {
        const std::string f = value(k);
        if (f.empty()) return fallback;
        long long v = 0;
        Real r = 0;
        if (text_mesh::parse_id(f, v)) return v;
        if (text_mesh::parse_real(f, r) && r == std::round(r) && std::abs(r) < 1e15)
            return static_cast<long long>(r);  // "5." in a real-looking column
        fail(std::string(name) + " '" + f + "' is not a whole number");
    }
    [[nodiscard]] std::string text(std::size_t k) const { return value(k); }
    [[nodiscard]] std::size_t size() const { return fields_.size(); }
    [[nodiscard]] int line() const { return line_; }
    [[noreturn]] void fail(const std::string& message) const { deck_fail(block_, line_, message); }

private:
    /// The field, or the value of the parameter it names (&NAME, -&NAME).
    [[nodiscard]] std::string value(std::size_t k) const {
        if (k >= fields_.size()) return "";
        const std::string& f = fields_[k];
        const bool negative = f.rfind("-&", 0) == 0;
        if (f.empty() || (f[0] != '&' && !negative)) return f;
        const std::string name = upper(f.substr(negative ? 2 : 1));
        const auto it = deck_.parameters.find(name);
        if (it == deck_.parameters.end())
            fail("parameter '" + name + "' is not defined by a *PARAMETER card");
        const std::string v = it->second.substr(1);
        if (!negative) return v;
        return v.rfind('-', 0) == 0 ? v.substr(1) : "-" + v;
    }

    const KeywordDeck& deck_;
    const DeckBlock& block_;
    int line_;
    std::vector<std::string> fields_;
};

const std::vector<std::size_t> k_ten(8, 10);  // the usual card: 8 fields of 10 columns

/// A number as the model file writes it (shortest round-trip form).
std::string num(Real v) { return fmt::format("{}", v); }
std::string vec(Real x, Real y, Real z) {
    return "[" + num(x) + ", " + num(y) + ", " + num(z) + "]";
}

/// A YAML scalar for a name: plain when it is a word, else double-quoted.
std::string yaml_name(const std::string& s) {
    const bool plain = !s.empty() &&
                       std::all_of(s.begin(), s.end(),
                                   [](char c) {
                                       return std::isalnum(static_cast<unsigned char>(c)) ||
                                              c == '_' || c == '-' || c == '.';
                                   }) &&
                       !std::isdigit(static_cast<unsigned char>(s[0])) && s[0] != '-' &&
                       s[0] != '.';
    if (plain) return s;
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

/// The option words of a keyword after its base: ("RIGIDWALL_PLANAR_MOVING_ID", 2) -> MOVING, ID.
std::set<std::string> options_of(const std::string& keyword, std::size_t base_words) {
    std::set<std::string> out;
    std::size_t pos = 0;
    for (std::size_t k = 0; k < base_words && pos != std::string::npos; ++k) {
        pos = keyword.find('_', pos);
        if (pos != std::string::npos) ++pos;
    }
    while (pos != std::string::npos && pos < keyword.size()) {
        const auto u = keyword.find('_', pos);
        out.insert(keyword.substr(pos, u == std::string::npos ? std::string::npos : u - pos));
        pos = u == std::string::npos ? u : u + 1;
    }
    return out;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

struct Origin {
    const DeckBlock* block = nullptr;
    int line = 0;
};

struct Point2 {
    Real x = 0, y = 0;
};

struct CurveDef {
    Origin at;
    std::vector<Point2> points;  ///< scaled and offset
};

struct TableDef {
    Origin at;
    std::vector<Real> values;       ///< strain rates
    std::vector<long long> curves;  ///< the curve of each value
};

struct MaterialDef {
    Origin at;
    std::string keyword;
    std::vector<std::string> keys;  ///< "type: elastic", "density: 7850", ... (flow curves later)
    long long lcss = 0;             ///< *MAT_024: the curve or table of the flow stress
    bool plastic = false;
};

struct SectionDef {
    Origin at;
    Real thickness = 0;
    int points = 2;
};

struct PartDef {
    Origin at;
    long long section = 0, material = 0;
};

struct Segment {
    std::array<long long, 4> nodes{};  ///< N1 ... N4 (N4 = N3 or 0 for a triangle)
    Origin at;
};

struct SegmentLoad {
    std::string name;  ///< the segment set, or a name for a *LOAD_SEGMENT card
    std::vector<Segment> segments;
    Real sf = 1;
    std::string curve;
    Origin at;
    std::size_t slot = 0;  ///< its place among the loads (loads add up in the deck's order)
};

struct WallDef {
    Origin at;
    long long id = 0;
    std::string nodes;             ///< node set, "" for all
    std::array<Real, 3> normal{};  ///< a planar wall's head - tail (a moving one moves along it)
    Real mass = 0, speed = 0;      ///< moving walls: mass and the speed along the normal
    bool moving = false;
    Real friction = 0;  ///< a planar wall's FRIC: 0 frictionless, (0, 1) Coulomb, 1 no sliding
    /// the shape's keys of the model (model-format.md rigid_bodies): "shape: plane, point: ..."
    std::string geometry;
    /// a geometric wall's _MOTION: its curve (0: none), OPT (0 velocity, 1 displacement), the
    /// direction cosines, and the card
    long long motion_curve = 0, motion_opt = 0;
    std::array<Real, 3> motion_dir{};
    Origin motion_at;
};

/// One line of the model file and the card it comes from.
struct Line {
    std::string text;
    Origin at;
};

class DeckTranslator {
public:
    DeckTranslator(const std::string& path, std::string mesh_file)
        : path_(path), mesh_file_(std::move(mesh_file)), deck_(read_keyword_deck(path)) {}

    DeckTranslation translate() {
        for (const DeckBlock& b : deck_.blocks) read_block(b);
        return write();
    }

private:
    // ---- reading ----

    void note(const DeckBlock& b, int line, const std::string& what) {
        notes_.push_back(input_error_text(b.file, line, "", "*" + b.keyword + ": " + what));
    }
    [[noreturn]] static void refuse(const DeckBlock& b, const std::string& why) {
        deck_fail(b, b.line, why);
    }
    /// Card k of the block; an optional card left out reads as blank fields.
    Card card(const DeckBlock& b, std::size_t k, const std::vector<std::size_t>& widths = k_ten) {
        if (k >= b.cards.size())
            return Card(deck_, b, DeckCard{b.cards.empty() ? b.line : b.cards.back().line, ""},
                        widths);
        return Card(deck_, b, b.cards[k], widths);
    }
    Card required_card(const DeckBlock& b, std::size_t k, const char* what,
                       const std::vector<std::size_t>& widths = k_ten) {
        if (k >= b.cards.size()) deck_fail(b, b.line, std::string("needs its card of ") + what);
        return Card(deck_, b, b.cards[k], widths);
    }

    void read_block(const DeckBlock& b) {
        const std::string& k = b.keyword;
        if (k == "TITLE") {
            if (!b.cards.empty()) title_ = trim(b.cards[0].text);
        } else if (k == "NODE" || starts_with(k, "ELEMENT_SHELL")) {
            if (starts_with(k, "ELEMENT_SHELL")) element_shell(b);
        } else if (starts_with(k, "SET_NODE") || starts_with(k, "SET_SHELL") ||
                   starts_with(k, "SET_PART")) {
            set_header(b);
        } else if (k == "PART") {
            part(b);
        } else if (starts_with(k, "SECTION_SHELL")) {
            section_shell(b);
        } else if (starts_with(k, "MAT_")) {
            material(b);
        } else if (starts_with(k, "DEFINE_CURVE")) {
            define_curve(b);
        } else if (starts_with(k, "DEFINE_TABLE")) {
            define_table(b);
        } else if (starts_with(k, "BOUNDARY_SPC_")) {
            spc(b);
        } else if (starts_with(k, "BOUNDARY_PRESCRIBED_MOTION_")) {
            prescribed_motion(b);
        } else if (starts_with(k, "INITIAL_VELOCITY")) {
            initial_velocity(b);
        } else if (starts_with(k, "SET_SEGMENT")) {
            segment_set(b);
        } else if (starts_with(k, "LOAD_SEGMENT")) {
            segment_load(b);
        } else if (starts_with(k, "LOAD_NODE_") || starts_with(k, "LOAD_SHELL_SET")) {
            load(b);
        } else if (starts_with(k, "RIGIDWALL_PLANAR")) {
            rigid_wall(b);
        } else if (starts_with(k, "RIGIDWALL_GEOMETRIC")) {
            geometric_wall(b);
        } else if (starts_with(k, "CONTACT_AUTOMATIC_SINGLE_SURFACE") ||
                   starts_with(k, "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE") ||
                   starts_with(k, "CONTACT_AUTOMATIC_NODES_TO_SURFACE")) {
            contact(b);
        } else if (starts_with(k, "CONSTRAINED_NODAL_RIGID_BODY")) {
            nodal_rigid_body(b);
        } else if (starts_with(k, "CONSTRAINED_SPOTWELD")) {
            spot_weld(b);
        } else if (starts_with(k, "CONSTRAINED_GENERALIZED_WELD")) {
            generalized_spot_weld(b);
        } else if (starts_with(k, "CONTROL_") || k == "DAMPING_GLOBAL") {
            control(b);
        } else if (starts_with(k, "DATABASE_")) {
            database(b);
        } else if (starts_with(k, "EOS_") || k == "HOURGLASS" || starts_with(k, "SENSOR_") ||
                   k == "PART_CONTACT" || k == "COMMENT" || starts_with(k, "DEFINE_BOX") ||
                   starts_with(k, "DEFINE_COORDINATE")) {
            note(b, b.line, ignored_reason(k));
        } else {
            refuse(b, unsupported_reason(k));
        }
    }

    static std::string ignored_reason(const std::string& k) {
        if (starts_with(k, "EOS_"))
            return "ignored: an equation of state has no part in a shell's plane stress";
        if (k == "HOURGLASS") return "ignored: fpmshell's triangles have no hourglass modes";
        if (starts_with(k, "SENSOR_"))
            return "ignored: no control of this deck uses a sensor that fpmshell reads";
        if (k == "PART_CONTACT")
            return "ignored: contact parameters per part (fpmshell's contact takes each shell's "
                   "thickness)";
        return "ignored: only the cards that use it would need it, and fpmshell refuses those";
    }

    static std::string unsupported_reason(const std::string& k) {
        if (starts_with(k, "MAT_"))
            return "this material is not supported; fpmshell reads *MAT_ELASTIC (001), "
                   "*MAT_PLASTIC_KINEMATIC (003), *MAT_JOHNSON_COOK (015), "
                   "*MAT_POWER_LAW_PLASTICITY (018), *MAT_RIGID (020) and "
                   "*MAT_PIECEWISE_LINEAR_PLASTICITY (024)";
        if (starts_with(k, "ELEMENT_"))
            return "fpmshell models shells only (*ELEMENT_SHELL); this element kind would change "
                   "the model";
        if (starts_with(k, "CONSTRAINED_"))
            return "this constraint is not supported (fpmshell reads "
                   "*CONSTRAINED_NODAL_RIGID_BODY, *CONSTRAINED_SPOTWELD and "
                   "*CONSTRAINED_GENERALIZED_WELD_SPOT), and ignoring it would change the model";
        if (starts_with(k, "BOUNDARY_PRESCRIBED_MOTION"))
            return "fpmshell reads *BOUNDARY_PRESCRIBED_MOTION_NODE and _SET (with _ID); a "
                   "rigid part's motion cannot be prescribed";
        if (starts_with(k, "CONTACT_"))
            return "fpmshell reads *CONTACT_AUTOMATIC_SINGLE_SURFACE, _SURFACE_TO_SURFACE and "
                   "_NODES_TO_SURFACE (as its shell self-contact)";
        if (starts_with(k, "LOAD_"))
            return "fpmshell reads *LOAD_NODE_POINT, *LOAD_NODE_SET, *LOAD_SHELL_SET, "
                   "*LOAD_SEGMENT and *LOAD_SEGMENT_SET";
        return "this card is not supported by fpmshell, and ignoring it could change the model";
    }

    // -- mesh-side cards: what the translation needs of them

    void element_shell(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        const bool thickness = opt.count("THICKNESS") != 0;
        const std::size_t per_element =
            1 + (thickness || opt.count("BETA") || opt.count("MCID") ? 1 : 0) +
            (opt.count("OFFSET") ? 1 : 0);
        const std::size_t w = b.format == DeckFormat::WideId ? 10 : 8;
        for (std::size_t c = 0; c < b.cards.size(); c += per_element) {
            // EID and PID in columns, else (hand-written files) split at blanks, as the mesh
            // reader reads them
            std::vector<std::string> ids =
                deck_fields(b, b.cards[c], std::vector<std::size_t>(6, w));
            long long eid = 0, pid = 0;
            if (!text_mesh::parse_id(ids[0], eid) || !text_mesh::parse_id(ids[1], pid)) {
                ids = text_mesh::split_blanks(b.cards[c].text);
                ids.resize(std::max<std::size_t>(ids.size(), 6));
                if (!text_mesh::parse_id(ids[1], pid)) continue;  // the mesh reader says why
            }
            std::array<long long, 4> n{};
            bool numbered = true;
            for (std::size_t k = 0; k < 4; ++k)
                numbered =
                    numbered && (ids[2 + k].empty() || text_mesh::parse_id(ids[2 + k], n[k]));
            if (numbered) {
                if (n[3] != 0 && n[3] != n[2]) {
                    if (quadrangles_ == 0) first_quadrangle_ = {&b, b.cards[c].line};
                    ++quadrangles_;
                }
                shells_.push_back({eid, n});
            }
            auto& p = element_parts_[pid];
            if (p.count == 0) p.first = {&b, b.cards[c].line};
            ++p.count;
            if (thickness && c + 1 < b.cards.size()) {
                const Card t(deck_, b, b.cards[c + 1], std::vector<std::size_t>(4, 16));
                for (std::size_t k = 0; k < 4; ++k) {
                    const Real v = t.real(k, "THIC");
                    if (v != 0) p.thickness.insert(v);
                }
                if (p.thickness.size() > 1)
                    t.fail("the elements of part " + std::to_string(pid) +
                           " have different thicknesses; fpmshell takes one thickness per part");
            }
        }
    }

    void set_header(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        const bool titled = opt.count("TITLE") != 0;
        if (b.cards.size() < (titled ? 2U : 1U)) return;  // the mesh reader reports it
        const Card f = card(b, titled ? 1 : 0);
        const long long sid = f.id(0, "SID");
        const std::string kind = starts_with(b.keyword, "SET_NODE")    ? "node"
                                 : starts_with(b.keyword, "SET_SHELL") ? "shell"
                                                                       : "part";
        set_names_[kind][sid] = titled ? trim(b.cards[0].text) : lsdyna_set_name(kind, sid);
    }

    /// The name of set `sid` of `kind` (node, shell, part), which the deck must define.
    std::string set_name(const Card& f, const std::string& kind, long long sid) const {
        const auto& names =
            set_names_.count(kind) ? set_names_.at(kind) : std::map<long long, std::string>{};
        const auto it = names.find(sid);
        if (it == names.end())
            f.fail("no *SET_" + upper(kind) + "_LIST defines set " + std::to_string(sid) +
                   " (define sets before the cards that use them)");
        return it->second;
    }

    // -- constraints: nodal rigid bodies and spot welds (model-format.md `constraints`)

    /// *CONSTRAINED_NODAL_RIGID_BODY (_TITLE): the nodes of NSID move as one rigid body.
    void nodal_rigid_body(const DeckBlock& b) {
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
            {"  - {type: rigid, nodes: " + yaml_name(set_name(f, "node", nsid)) + "}",
             {&b, f.line()}});
        if (f.id(3, "PNODE") != 0)
            note(b, f.line(), "PNODE ignored: the body's motion is that of its nodes");
    }

    /// *CONSTRAINED_SPOTWELD (_ID): each weld's two nodes move as one rigid body; the failure
    /// data is noted (a weld never fails).
    void spot_weld(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        for (const std::string& o : opt)
            if (o != "ID")
                refuse(b, "*CONSTRAINED_SPOTWELD_" + o + " is not supported (plain and _ID)");
        const std::size_t per_weld = opt.count("ID") ? 2 : 1;
        if (b.cards.empty()) required_card(b, 0, "N1, N2, SN, SS, N, M, TF, EP");
        bool failure = false;
        for (std::size_t c = 0; c < b.cards.size(); c += per_weld) {
            const Card f = required_card(b, c + per_weld - 1, "N1, N2, SN, SS, N, M, TF, EP");
            weld_nodes(b, f, {f.id(0, "N1"), f.id(1, "N2")});
            failure = failure || f.real(2, "SN") != 0 || f.real(3, "SS") != 0 ||
                      (f.real(6, "TF") != 0 && f.real(6, "TF") < 1e20);
        }
        if (failure)
            note(b, b.line, "the welds' failure (SN, SS, TF) is not modelled: they never fail");
    }

    /// *CONSTRAINED_GENERALIZED_WELD_SPOT (_ID): the nodes of NSID move as one rigid body; the
    /// failure data is noted.
    void generalized_spot_weld(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 3);
        if (!opt.count("SPOT"))
            refuse(b,
                   "fpmshell reads *CONSTRAINED_GENERALIZED_WELD_SPOT only (fillet, butt and "
                   "combined welds are not supported)");
        for (const std::string& o : opt)
            if (o != "SPOT" && o != "ID")
                refuse(b, "*CONSTRAINED_GENERALIZED_WELD_SPOT_" + o + " is not supported");
        const std::size_t first = opt.count("ID") ? 1 : 0;
        const Card f = required_card(b, first, "NSID, CID, FILTER, WINDOW, NPR, NPRT");
        const Card g = required_card(b, first + 1, "TFAIL, EPSF, SN, SS, N, M");
        constraints_.push_back(
            {"  - {type: rigid, nodes: " + yaml_name(set_name(f, "node", f.id(0, "NSID"))) + "}",
             {&b, f.line()}});
        if ((g.real(0, "TFAIL") != 0 && g.real(0, "TFAIL") < 1e20) || g.real(1, "EPSF") != 0 ||
            g.real(2, "SN") != 0 || g.real(3, "SS") != 0)
            note(b, g.line(),
                 "the weld's failure (TFAIL, EPSF, SN, SS) is not modelled: it never fails");
    }

    /// A weld of the nodes `ids` as a rigid body of a set of its own (`spotweld_<k>`).
    void weld_nodes(const DeckBlock& b, const Card& f, const std::array<long long, 2>& ids) {
        if (ids[0] == ids[1]) f.fail("N1 and N2 are the same node " + std::to_string(ids[0]));
        const std::string group = "spotweld_" + std::to_string(++welds_);
        for (const long long id : ids)
            add_node_to_group(group, id, "{type: rigid, nodes: NODES}", {&b, f.line()},
                              constraints_);
    }

    // -- parts, sections, materials, curves

    /// Parts: a heading card and a data card each (one *PART may define several).
    void part(const DeckBlock& b) {
        if (b.cards.size() < 2) required_card(b, 1, "PID, SECID, MID");
        for (std::size_t c = 0; c + 1 < b.cards.size(); c += 2) {
            const Card f = required_card(b, c + 1, "PID, SECID, MID");
            const long long pid = f.id(0, "PID");
            PartDef p{{&b, f.line()}, f.id(1, "SECID"), f.id(2, "MID")};
            if (f.id(3, "EOSID") != 0)
                note(b, f.line(),
                     "EOSID ignored: an equation of state has no part in a shell's plane stress");
            if (parts_.count(pid)) f.fail("part " + std::to_string(pid) + " is defined twice");
            parts_[pid] = p;
        }
    }

    void section_shell(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        const std::size_t first = opt.count("TITLE") ? 1 : 0;
        for (const std::string& o : opt)
            if (o != "TITLE") refuse(b, "*SECTION_SHELL_" + o + " is not supported");
        const Card f = required_card(b, first, "SECID, ELFORM, SHRF, NIP, PROPT, QR");
        const Card t = required_card(b, first + 1, "T1, T2, T3, T4, NLOC");
        const long long id = f.id(0, "SECID");
        const long long elform = f.id(1, "ELFORM", 2);
        long long nip = f.id(3, "NIP", 2);
        if (nip == 0) nip = 2;
        const Real qr = f.real(5, "QR/IRID");
        if (f.id(6, "ICOMP") != 0) f.fail("ICOMP = 1 (composite layers) is not supported");
        if (nip != 2 && nip != 3 && nip != 5)
            f.fail("NIP " + std::to_string(nip) +
                   ": fpmshell integrates through the thickness with 2, 3 or 5 points");
        if (qr != 0) f.fail("QR/IRID: only the default rule (0) is supported");
        const Real t1 = t.real(0, "T1");
        if (!(t1 > 0)) t.fail("T1 must be a thickness > 0");
        for (std::size_t k = 1; k < 4; ++k) {
            const Real tk = t.real(k, "T2, T3, T4");
            if (tk != 0 && tk != t1)
                t.fail(
                    "a thickness that varies over the element (T1 to T4 not equal) is not "
                    "supported");
        }
        if (t.real(4, "NLOC") != 0) t.fail("NLOC: only the mid-surface reference (0) is supported");
        if (sections_.count(id)) f.fail("section " + std::to_string(id) + " is defined twice");
        sections_[id] = {{&b, f.line()}, t1, static_cast<int>(nip)};
        note(
            b, f.line(),
            fmt::format(
                "ELFORM {} mapped to fpmshell's finite-particle triangle (CST membrane, "
                "DKT bending; quadrangles split in two); NIP {}{}",
                elform, nip,
                nip == 2 ? " (Gauss)"
                         : " (fpmshell's rule is Lobatto, surfaces included; LS-DYNA's is Gauss)"));
    }

    void material(const DeckBlock& b) {
        static const std::map<std::string, std::string> aliases = {
            {"MAT_001", "MAT_ELASTIC"},
            {"MAT_003", "MAT_PLASTIC_KINEMATIC"},
            {"MAT_015", "MAT_JOHNSON_COOK"},
            {"MAT_018", "MAT_POWER_LAW_PLASTICITY"},
            {"MAT_024", "MAT_PIECEWISE_LINEAR_PLASTICITY"},
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
            if (g.real(2, "FS") != 0)
                note(b, g.line(), "FS: failure is not modelled (no element is deleted)");
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
            if (m_exp != 0 && tm != 0 && h.real(0, "CP") != 0)
                g.fail(
                    "thermal softening (M, TM with CP) is not modelled; set M = 0 for an "
                    "isothermal material");
            if (m_exp != 0 || tm != 0)
                note(b, g.line(), "isothermal: the temperature terms (M, TM, TR) are not modelled");
            bool damage = false;
            for (std::size_t k = 4; k < 8; ++k) damage = damage || h.real(k, "D1..D4") != 0;
            damage = damage || i.real(0, "D5") != 0;
            if (damage)
                note(b, h.line(), "D1..D5: failure is not modelled (no element is deleted)");
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
            if (g.real(2, "EPSF") != 0)
                note(b, g.line(), "EPSF: failure is not modelled (no element is deleted)");
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
            if (f.real(6, "FAIL") != 0)
                note(b, f.line(), "FAIL: failure is not modelled (no element is deleted)");
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
        } else if (name == "MAT_RIGID") {
            // a part of it moves as one rigid body (its section's particles, theory.md §6.11)
            const Card f = required_card(b, first, "MID, RO, E, PR, N, COUPLE, M, ALIAS");
            const Card g = card(b, first + 1);
            mid = f.id(0, "MID");
            m.keys.push_back("type: rigid");
            elastic(f, f.real(2, "E"), f.real(3, "PR"));
            if (g.real(0, "CMO") != 0)
                g.fail(
                    "CMO: constraints on a rigid part's motion are not supported (0 only: the "
                    "part moves freely)");
            m.at = {&b, f.line()};
        } else {
            refuse(b, unsupported_reason(b.keyword));
        }
        if (materials_.count(mid))
            refuse(b, "material " + std::to_string(mid) + " is defined twice");
        materials_[mid] = m;
    }

    static std::string points_text(const std::vector<Point2>& points) {
        std::string s = "[";
        for (std::size_t k = 0; k < points.size(); ++k)
            s += (k ? ", [" : "[") + num(points[k].x) + ", " + num(points[k].y) + "]";
        return s + "]";
    }

    void define_curve(const DeckBlock& b) {
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
            const Card p(deck_, b, b.cards[k], {20, 20});
            // abscissa SFA (a + OFFA), ordinate SFO (o + OFFO): the offsets first
            c.points.push_back({sfa * (p.real(0, "A1") + offa), sfo * (p.real(1, "O1") + offo)});
        }
        if (c.points.empty()) f.fail("curve " + std::to_string(id) + " has no points");
        if (curves_.count(id)) f.fail("curve " + std::to_string(id) + " is defined twice");
        curves_[id] = c;
        if (table_waiting_ > 0) {  // the curves of the last *DEFINE_TABLE follow it, in order
            tables_[last_table_].curves.push_back(id);
            --table_waiting_;
        }
    }

    void define_table(const DeckBlock& b) {
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
            const Card v(deck_, b, b.cards[k], {20, 20});
            t.values.push_back(sfa * (v.real(0, "VALUE") + offa));
            if (v.id(1, "LCID") != 0)
                f.fail("a curve id beside VALUE is not supported; let the curves follow the table");
        }
        if (t.values.empty()) f.fail("table " + std::to_string(id) + " has no values");
        if (t.values.front() < 0)  // LS-DYNA: then every value is the logarithm of a rate
            for (Real& v : t.values) v = std::exp(v);
        if (tables_.count(id)) f.fail("table " + std::to_string(id) + " is defined twice");
        tables_[id] = t;
        last_table_ = id;
        table_waiting_ = t.values.size();
    }

    // -- conditions

    /// The id card of the _ID options (ID, HEADING) comes first.
    static std::size_t first_data_card(const std::set<std::string>& opt) {
        return opt.count("ID") ? 1 : 0;
    }

    void spc(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        const bool single = opt.count("NODE") != 0;
        if (!single && !opt.count("SET")) refuse(b, unsupported_reason("BOUNDARY_SPC"));
        static const char* dofs[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
        for (std::size_t c = first_data_card(opt); c < b.cards.size(); ++c) {
            const Card f = card(b, c);
            const long long id = f.id(0, single ? "NID" : "NSID");
            if (f.id(1, "CID") != 0) f.fail("CID: only global directions (0) are supported");
            std::string fix, pattern;
            for (std::size_t d = 0; d < 6; ++d) {
                const long long on = f.id(2 + d, "DOF");
                if (on != 0 && on != 1) f.fail("a DOF flag must be 0 or 1");
                pattern += on ? '1' : '0';
                if (on) fix += std::string(fix.empty() ? "" : ", ") + dofs[d];
            }
            if (fix.empty()) continue;
            const Origin at{&b, f.line()};
            const std::string text = "{nodes: NODES, fix: [" + fix + "]}";
            if (single) {
                add_node_to_group("spc_" + pattern, id, text, at, boundary_);
            } else {
                boundary_.push_back({"  - " + replace_nodes(text, set_name(f, "node", id)), at});
            }
        }
    }

    /// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET: a velocity (VAD 0) or a displacement (VAD 2)
    /// along x, y or z (DOF 1, 2, 3), the curve times SF; the node's other directions stay free.
    void prescribed_motion(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 3);
        const bool single = opt.count("NODE") != 0;
        if (!single && !opt.count("SET")) refuse(b, unsupported_reason(b.keyword));
        for (const std::string& o : opt)
            if (o != "NODE" && o != "SET" && o != "ID")
                refuse(b, "*BOUNDARY_PRESCRIBED_MOTION_..._" + o + " is not supported");
        for (std::size_t c = first_data_card(opt); c < b.cards.size(); ++c) {
            const Card f = card(b, c);
            const long long id = f.id(0, single ? "NID" : "NSID");
            const long long dof = f.id(1, "DOF");
            const long long vad = f.id(2, "VAD");
            const Real sf = f.real(4, "SF", 1.0);
            if (dof < 1 || dof > 3)
                f.fail("DOF " + std::to_string(dof) +
                       ": fpmshell prescribes the translations along x, y or z (1, 2, 3)");
            if (vad != 0 && vad != 2)
                f.fail("VAD " + std::to_string(vad) +
                       ": fpmshell prescribes a velocity (0) or a displacement (2)");
            if (f.id(5, "VID") != 0) f.fail("VID: a direction vector is not supported (0 only)");
            const Real death = f.real(6, "DEATH");
            if (f.real(7, "BIRTH") != 0 || (death != 0 && death < 1e20))
                f.fail("BIRTH and DEATH are not supported (the motion is prescribed throughout)");
            const std::size_t axis = static_cast<std::size_t>(dof - 1);
            const std::string value =
                vec(axis == 0 ? sf : 0.0, axis == 1 ? sf : 0.0, axis == 2 ? sf : 0.0);
            static const char* names[3] = {"ux", "uy", "uz"};
            const std::string text = std::string("{nodes: NODES, prescribe: {") +
                                     (vad == 0 ? "velocity: " : "displacement: ") + value +
                                     ", curve: " + curve_ref(b, f, f.id(3, "LCID")) +
                                     ", components: [" + names[axis] + "]}}";
            if (single) {
                auto& group = node_group_of_text_[text];
                if (group.empty())
                    group = "prescribed_nodes_" + std::to_string(node_group_of_text_.size());
                add_node_to_group(group, id, text, {&b, f.line()}, boundary_);
            } else {
                boundary_.push_back(
                    {"  - " + replace_nodes(text, set_name(f, "node", id)), {&b, f.line()}});
            }
        }
    }

    // -- segments: sets of element faces given by their nodes, and pressures on them

    /// *SET_SEGMENT(_TITLE): a header card (SID), then one card per segment (N1 ... N4).
    void segment_set(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        for (const std::string& o : opt)
            if (o != "TITLE") refuse(b, "*SET_SEGMENT_" + o + " is not supported");
        const bool titled = opt.count("TITLE") != 0;
        const Card head = required_card(b, titled ? 1 : 0, "SID");
        const long long sid = head.id(0, "SID");
        const std::string name = titled ? trim(b.cards[0].text) : lsdyna_set_name("segment", sid);
        set_names_["segment"][sid] = name;
        auto& segments = segment_sets_[name];
        for (std::size_t c = titled ? 2 : 1; c < b.cards.size(); ++c)
            segments.push_back(segment(Card(deck_, b, b.cards[c], k_ten), 0, b));
    }

    /// The segment of nodes in fields first ... first + 3 of `f`.
    static Segment segment(const Card& f, std::size_t first, const DeckBlock& b) {
        Segment s{{}, {&b, f.line()}};
        for (std::size_t k = 0; k < 4; ++k) s.nodes[k] = f.id(first + k, "N1..N4");
        if (s.nodes[0] <= 0 || s.nodes[1] <= 0 || s.nodes[2] <= 0)
            f.fail("a segment needs at least three node numbers N1, N2, N3");
        return s;
    }

    /// *LOAD_SEGMENT_SET (SSID, LCID, SF, AT) and *LOAD_SEGMENT (LCID, SF, AT, N1 ... N4): a
    /// pressure along each segment's normal (by its node order), on the shell it covers.
    void segment_load(const DeckBlock& b) {
        const std::string& k = b.keyword;
        const bool set = k == "LOAD_SEGMENT_SET";
        if (!set && k != "LOAD_SEGMENT") refuse(b, unsupported_reason(k));
        for (const DeckCard& dc : b.cards) {
            const Card f(deck_, b, dc, k_ten);
            const std::size_t at = set ? 3 : 2;
            if (f.real(at, "AT") != 0) f.fail("AT (an arrival time) is not supported");
            SegmentLoad load;
            load.at = {&b, f.line()};
            load.sf = f.real(set ? 2 : 1, "SF", 1.0);
            load.curve = curve_ref(b, f, f.id(set ? 1 : 0, "LCID"));
            if (set) {
                load.name = set_name(f, "segment", f.id(0, "SSID"));
                load.segments = segment_sets_.at(load.name);
                if (load.segments.empty())
                    f.fail("segment set '" + load.name + "' lists no segment");
            } else {
                load.name = "load_segments_" + std::to_string(segment_loads_.size() + 1);
                load.segments.push_back(segment(f, 3, b));
            }
            load.slot = loads_.size();  // its pressures take this place among the loads
            loads_.push_back({"", load.at});
            segment_loads_.push_back(std::move(load));
        }
    }

    /// The element sets and pressures of the segment loads: each segment's shell (the one with
    /// its nodes), in a set of the shells whose normal the segment's node order follows and one
    /// (`<name>_reversed`, the pressure negated) of those it opposes.
    void write_segment_loads() {
        if (segment_loads_.empty()) return;
        std::vector<std::pair<std::array<long long, 4>, std::size_t>> by_nodes;
        by_nodes.reserve(shells_.size());
        for (std::size_t k = 0; k < shells_.size(); ++k)
            by_nodes.emplace_back(node_key(shells_[k].nodes), k);
        std::sort(by_nodes.begin(), by_nodes.end());
        std::map<std::size_t, std::vector<Line>> pressures;  // by the slot of their card
        for (const SegmentLoad& load : segment_loads_) {
            std::vector<long long> aligned, reversed;
            for (const Segment& seg : load.segments) {
                const auto key = node_key(seg.nodes);
                const auto it = std::lower_bound(by_nodes.begin(), by_nodes.end(),
                                                 std::make_pair(key, std::size_t{0}));
                if (it == by_nodes.end() || it->first != key)
                    deck_fail(*seg.at.block, seg.at.line,
                              "no shell element has the nodes of this segment; fpmshell loads "
                              "segments of its shells");
                const Shell& shell = shells_[it->second];
                (same_order(shell.nodes, seg.nodes) ? aligned : reversed).push_back(shell.id);
            }
            for (const bool flip : {false, true}) {
                const auto& ids = flip ? reversed : aligned;
                if (ids.empty()) continue;
                const std::string name = load.name + (flip ? "_reversed" : "");
                auto& group = element_groups_[name];
                if (group.ids.empty()) {
                    group.at = load.at;
                    group.ids = ids;
                }
                pressures[load.slot].push_back(
                    {"  - {type: pressure, elements: " + yaml_name(name) + ", value: " +
                         num(flip ? -load.sf : load.sf) + ", curve: " + load.curve + "}",
                     load.at});
            }
        }
        std::vector<Line> loads;
        for (std::size_t k = 0; k < loads_.size(); ++k) {
            const auto p = pressures.find(k);
            if (p == pressures.end())
                loads.push_back(loads_[k]);
            else
                loads.insert(loads.end(), p->second.begin(), p->second.end());
        }
        loads_ = std::move(loads);
    }

    /// The distinct node numbers of a shell or segment, sorted (a triangle's fourth is 0).
    static std::array<long long, 4> node_key(const std::array<long long, 4>& n) {
        std::array<long long, 4> key = n;
        if (key[3] == key[2]) key[3] = 0;
        std::sort(key.begin(), key.end());
        return key;
    }
    /// Whether segment s runs round its shell in the shell's own direction.
    static bool same_order(const std::array<long long, 4>& shell,
                           const std::array<long long, 4>& s) {
        const std::size_t count = (shell[3] == 0 || shell[3] == shell[2]) ? 3 : 4;
        const auto first = std::find(shell.begin(), shell.begin() + static_cast<long>(count), s[0]);
        const std::size_t at = static_cast<std::size_t>(first - shell.begin());
        return shell[(at + 1) % count] == s[1];
    }

    static std::string replace_nodes(std::string text, const std::string& set) {
        text.replace(text.find("NODES"), 5, yaml_name(set));
        return text;
    }

    /// Node `id` joins the set `group` (of node_ids); the first node writes `text` (with NODES
    /// for the set's name) into `lines`.
    void add_node_to_group(const std::string& group, long long id, const std::string& text,
                           const Origin& at, std::vector<Line>& lines) {
        auto& g = node_groups_[group];
        if (g.ids.empty()) {
            g.at = at;
            lines.push_back({"  - " + replace_nodes(text, group), at});
        }
        g.ids.push_back(id);
    }

    std::string nodes_of_velocity(const Card& f, long long id, long long styp) {
        if (id == 0) return "all";
        if (styp == 1) return set_name(f, "part", id);
        if (styp == 2) return "part_" + std::to_string(id);
        if (styp == 3) return set_name(f, "node", id);
        f.fail("STYP " + std::to_string(styp) + " is not 1 (part set), 2 (part) or 3 (node set)");
    }

    void initial_velocity(const DeckBlock& b) {
        const std::string& k = b.keyword;
        if (k == "INITIAL_VELOCITY") {
            const Card f = required_card(b, 0, "NSID, NSIDEX, BOXID, IRIGID, ICID");
            const Card v = required_card(b, 1, "VX, VY, VZ, VXR, VYR, VZR");
            const long long nsid = f.id(0, "NSID");
            if (f.id(1, "NSIDEX") != 0 || f.id(2, "BOXID") != 0 || f.id(4, "ICID") != 0)
                f.fail("NSIDEX, BOXID and ICID are not supported (0 only)");
            const std::string nodes = nsid == 0 ? "all" : set_name(f, "node", nsid);
            initial_.push_back({"  - {nodes: " + yaml_name(nodes) + ", velocity: " +
                                    vec(v.real(0, "VX"), v.real(1, "VY"), v.real(2, "VZ")) +
                                    ", angular_velocity: " +
                                    vec(v.real(3, "VXR"), v.real(4, "VYR"), v.real(5, "VZR")) + "}",
                                {&b, v.line()}});
        } else if (k == "INITIAL_VELOCITY_GENERATION") {
            // cards in pairs: the translation, then the axis of the rotation OMEGA
            for (std::size_t c = 0; c < b.cards.size(); c += 2) {
                const Card f = card(b, c);
                const Card g = card(b, c + 1);
                if (f.id(7, "ICID") != 0) f.fail("ICID: only global directions (0) are supported");
                if (f.id(6, "IVATN") != 0 || g.id(7, "IRIGID") != 0)
                    f.fail("IVATN and IRIGID are not supported (0 only)");
                const std::string nodes = nodes_of_velocity(f, f.id(0, "ID"), f.id(1, "STYP"));
                std::string text = "  - {nodes: " + yaml_name(nodes) + ", velocity: " +
                                   vec(f.real(3, "VX"), f.real(4, "VY"), f.real(5, "VZ"));
                if (const Real omega = f.real(2, "OMEGA"); omega != 0) {
                    std::array<Real, 3> axis{g.real(3, "NX"), g.real(4, "NY"), g.real(5, "NZ")};
                    if (axis == std::array<Real, 3>{})
                        g.fail("NX, NY, NZ: the axis of OMEGA must not be zero");
                    axis = unit(axis);
                    text += ", rotation: {centre: " +
                            vec(g.real(0, "XC"), g.real(1, "YC"), g.real(2, "ZC")) +
                            ", angular_velocity: " +
                            vec(omega * axis[0], omega * axis[1], omega * axis[2]) + "}";
                }
                initial_.push_back({text + "}", {&b, f.line()}});
            }
        } else {
            refuse(b, unsupported_reason(k));
        }
    }

    /// The model's name of load curve `lcid` (written out if some card uses it).
    std::string curve_ref(const DeckBlock& b, const Card& f, long long lcid) {
        if (lcid == 0) f.fail("LCID: a load needs a curve");
        used_curves_.push_back({lcid, {&b, f.line()}});
        return "curve_" + std::to_string(lcid);
    }

    void load(const DeckBlock& b) {
        const std::string& k = b.keyword;
        for (const DeckCard& dc : b.cards) {
            const Card f(deck_, b, dc, k_ten);
            if (k == "LOAD_SHELL_SET") {
                const long long ssid = f.id(0, "SSID");
                if (f.real(3, "AT") != 0) f.fail("AT (an arrival time) is not supported");
                loads_.push_back(
                    {"  - {type: pressure, elements: " + yaml_name(set_name(f, "shell", ssid)) +
                         ", value: " + num(f.real(2, "SF", 1.0)) +
                         ", curve: " + curve_ref(b, f, f.id(1, "LCID")) + "}",
                     {&b, f.line()}});
                continue;
            }
            const bool single = k == "LOAD_NODE_POINT";
            if (!single && k != "LOAD_NODE_SET") refuse(b, unsupported_reason(k));
            const long long id = f.id(0, single ? "NID" : "NSID");
            const long long dof = f.id(1, "DOF");
            const long long lcid = f.id(2, "LCID");
            const Real sf = f.real(3, "SF", 1.0);
            if (f.id(4, "CID") != 0) f.fail("CID: only global directions (0) are supported");
            if (dof < 1 || dof > 7 || dof == 4)
                f.fail("DOF " + std::to_string(dof) +
                       ": fpmshell loads nodes along x, y, z (1, 2, 3) or about them (5, 6, 7)");
            const bool moment = dof >= 5;
            const long long axis = moment ? dof - 5 : dof - 1;
            const std::string value =
                vec(axis == 0 ? sf : 0.0, axis == 1 ? sf : 0.0, axis == 2 ? sf : 0.0);
            const std::string text = std::string("{type: ") + (moment ? "moment" : "force") +
                                     ", nodes: NODES, value: " + value +
                                     ", curve: " + curve_ref(b, f, lcid) + "}";
            if (single) {
                auto& group = node_group_of_text_[text];  // the nodes of one load and curve
                if (group.empty())
                    group = "load_nodes_" + std::to_string(node_group_of_text_.size());
                add_node_to_group(group, id, text, {&b, f.line()}, loads_);
            } else
                loads_.push_back(
                    {"  - " + replace_nodes(text, set_name(f, "node", id)), {&b, f.line()}});
        }
    }

    void rigid_wall(const DeckBlock& b) {
        const std::set<std::string> opt = options_of(b.keyword, 2);
        for (const std::string& o : opt)
            if (o != "ID" && o != "MOVING" && o != "FORCES")
                refuse(b, "*RIGIDWALL_PLANAR_" + o +
                              " is not supported; fpmshell's walls are infinite planes "
                              "(_ID, _MOVING, _FORCES)");
        std::size_t c = 0;
        WallDef w;
        w.id = static_cast<long long>(walls_.size()) + 1;
        if (opt.count("ID")) w.id = required_card(b, c++, "RWID, HEADING").id(0, "RWID");
        const Card f = required_card(b, c++, "NSID, NSIDEX, BOXID, OFFSET, BIRTH, DEATH");
        const Card g = required_card(b, c++, "XT, YT, ZT, XH, YH, ZH, FRIC, WVEL");
        const long long nsid = f.id(0, "NSID");
        if (f.id(1, "NSIDEX") != 0 || f.id(2, "BOXID") != 0)
            f.fail("NSIDEX and BOXID are not supported (0 only)");
        if (f.real(3, "OFFSET") != 0) f.fail("OFFSET is not supported (0 only)");
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

    void add_wall(const WallDef& w, const Card& f) {
        for (const WallDef& other : walls_)
            if (other.id == w.id)
                f.fail("rigid wall " + std::to_string(w.id) + " is defined twice");
        walls_.push_back(w);
    }

    static std::array<Real, 3> unit(const std::array<Real, 3>& v) {
        const Real len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return {v[0] / len, v[1] / len, v[2] / len};
    }
    static std::string unit_text(const std::array<Real, 3>& v) {
        const std::array<Real, 3> n = unit(v);
        return vec(n[0], n[1], n[2]);
    }

    /// *RIGIDWALL_GEOMETRIC_FLAT (a rectangle), _CYLINDER, _SPHERE: a fixed rigid body of that
    /// shape (model/rigid_face.hpp) the nodes stay outside of; _ID and _DISPLAY (its card
    /// skipped) read, _MOTION refused.
    void geometric_wall(const DeckBlock& b) {
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
        if (shape.empty())
            refuse(b, "fpmshell reads *RIGIDWALL_GEOMETRIC_FLAT, _CYLINDER and _SPHERE");
        std::size_t c = 0;
        WallDef w;
        w.id = static_cast<long long>(walls_.size()) + 1;
        if (opt.count("ID")) w.id = required_card(b, c++, "RWID, HEADING").id(0, "RWID");
        const Card f = required_card(b, c++, "NSID, NSIDEX, BOXID, BIRTH, DEATH");
        const Card g = required_card(b, c++, "XT, YT, ZT, XH, YH, ZH");
        const Card s = required_card(b, c++, "the shape's card");
        const long long nsid = f.id(0, "NSID");
        if (f.id(1, "NSIDEX") != 0 || f.id(2, "BOXID") != 0)
            f.fail("NSIDEX and BOXID are not supported (0 only)");
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
    void contact(const DeckBlock& b) {
        const bool single = starts_with(b.keyword, "CONTACT_AUTOMATIC_SINGLE_SURFACE");
        const std::set<std::string> opt = options_of(b.keyword, single ? 4 : 5);
        for (const std::string& o : opt)
            if (o != "ID" && o != "MPP" && o != "TITLE")
                refuse(b, "*" + b.keyword + ": the option _" + o + " is not supported");
        std::size_t c = (opt.count("ID") || opt.count("TITLE")) ? 1 : 0;
        if (opt.count("MPP")) {
            ++c;
            if (c < b.cards.size() && trim(b.cards[c].text).rfind('&', 0) == 0) ++c;
        }
        const Card f = required_card(b, c, "SSID, MSID, SSTYP, MSTYP");
        const Card g = card(b, c + 1);
        if (f.id(4, "SBOXID") != 0 || f.id(5, "MBOXID") != 0)
            f.fail("SBOXID and MBOXID are not supported (0 only)");
        if (g.real(0, "FS") != 0 || g.real(1, "FD") != 0)
            g.fail(
                "FS, FD: fpmshell's shell self-contact is frictionless (friction is modelled "
                "against rigid walls, their FRIC); set them to 0 to run frictionless");
        if (g.real(6, "BT") != 0 || (g.real(7, "DT") != 0 && g.real(7, "DT") < 1e20))
            g.fail("BT and DT are not supported (contact acts from start to end)");
        if (g.real(4, "VDC") != 0)
            note(b, g.line(),
                 "VDC ignored: the contact is enforced by Lagrange multipliers, without "
                 "viscous damping");
        std::vector<std::string> sides{contact_side(f, f.id(0, "SSID"), f.id(2, "SSTYP"), "SSTYP")};
        if (!single) sides.push_back(contact_side(f, f.id(1, "MSID"), f.id(3, "MSTYP"), "MSTYP"));
        std::string elements;
        if (std::find(sides.begin(), sides.end(), "all") != sides.end()) {
            elements = "all";
        } else if (sides.size() == 1 || sides[0] == sides[1]) {
            elements = yaml_name(sides[0]);
        } else {
            elements = "[" + yaml_name(sides[0]) + ", " + yaml_name(sides[1]) + "]";
        }
        contact_.push_back({"  - {type: self, elements: " + elements + "}", {&b, f.line()}});
        // its number in RCFORC's columns: CID of _ID or _TITLE, else its place among the cards
        const long long cid = opt.count("ID") || opt.count("TITLE") ? card(b, 0).id(0, "CID") : 0;
        contact_ids_.push_back(
            {cid > 0 ? cid : static_cast<long long>(contact_ids_.size()) + 1, {&b, f.line()}});
        note(b, f.line(),
             std::string(single ? "as fpmshell's shell self-contact"
                                : "as fpmshell's shell self-contact over both sides together "
                                  "(each side is kept from itself too)") +
                 " (Lagrange multipliers, each shell's thickness as its contact thickness)");
    }

    /// The element set of one side of a contact: SID of type TYP (1 shell set, 2 part set,
    /// 3 part, 5 all; SID 0 is all).
    std::string contact_side(const Card& f, long long sid, long long typ, const char* name) {
        if (typ == 5 || sid == 0) return "all";
        if (typ == 1) return set_name(f, "shell", sid);
        if (typ == 2) return set_name(f, "part", sid);
        if (typ == 3) return "part_" + std::to_string(sid);
        f.fail(std::string(name) + " " + std::to_string(typ) +
               " is not supported: 1 (shell set), 2 (part set), 3 (part) or 5 (all); give a node "
               "set's shells as a part or shell set");
    }

    void control(const DeckBlock& b) {
        const std::string& k = b.keyword;
        const Card f = card(b, 0);
        const Origin at{&b, f.line()};
        if (k == "CONTROL_TERMINATION") {
            end_time_ = Line{num(f.real(0, "ENDTIM")), at};
            if (f.id(1, "ENDCYC") != 0 || f.real(2, "DTMIN") != 0 || f.real(3, "ENDENG") != 0 ||
                f.real(4, "ENDMAS") != 0)
                note(b, f.line(), "only ENDTIM is read (ENDCYC, DTMIN, ENDENG, ENDMAS ignored)");
        } else if (k == "CONTROL_TIMESTEP") {
            Real tssfac = f.real(1, "TSSFAC");
            if (tssfac == 0) tssfac = 0.9;
            control_.push_back({"  time_step_scale: " + num(tssfac), at});
            const Real dt2ms = f.real(4, "DT2MS");
            if (f.id(5, "LCTM") != 0) f.fail("LCTM (a curve of the largest step) is not supported");
            if (dt2ms > 0)
                f.fail(
                    "DT2MS > 0 is not supported; DT2MS < 0 (mass added where the step is "
                    "below TSSFAC x |DT2MS|) is");
            if (dt2ms < 0)
                control_.push_back(
                    {"  mass_scaling: {time_step: " + num(tssfac * -dt2ms) + "}", at});
            if (f.id(2, "ISDO") != 0 || f.real(3, "TSLIMT") != 0)
                note(b, f.line(), "ISDO and TSLIMT ignored (fpmshell's own element step)");
        } else if (k == "CONTROL_SHELL") {
            const long long istupd = f.id(3, "ISTUPD");
            if (istupd == 1 || istupd == 4) control_.push_back({"  thickness_update: true", at});
            note(b, f.line(), "only ISTUPD is read (fpmshell's element has no other options here)");
        } else if (k == "DAMPING_GLOBAL") {
            if (f.id(0, "LCID") != 0) f.fail("LCID: damping that varies in time is not supported");
            bool scaled = false;
            for (std::size_t s = 2; s < 8; ++s) {
                const Real v = f.real(s, "STX..SRZ");
                scaled = scaled || (v != 0 && v != 1);
            }
            if (scaled) f.fail("STX..SRZ: damping scaled per direction is not supported");
            damping_ = Line{"damping: {mass: " + num(f.real(1, "VALDMP")) + "}", at};
        } else if (k == "CONTROL_OUTPUT" || k == "CONTROL_ENERGY" || k == "CONTROL_HOURGLASS" ||
                   k == "CONTROL_BULK_VISCOSITY" || k == "CONTROL_CONTACT" ||
                   k == "CONTROL_ACCURACY" || k == "CONTROL_CPU" || k == "CONTROL_PARALLEL" ||
                   starts_with(k, "CONTROL_MPP")) {
            note(b, b.line,
                 "ignored (output, hourglass, bulk viscosity or solver settings that "
                 "fpmshell's shells do not use)");
        } else {
            refuse(b, unsupported_reason(k));
        }
    }

    void database(const DeckBlock& b) {
        const std::string& k = b.keyword;
        if (starts_with(k, "DATABASE_HISTORY_NODE")) {
            const bool with_id = k == "DATABASE_HISTORY_NODE_ID";
            if (!with_id && k != "DATABASE_HISTORY_NODE")
                refuse(b, "this history request is not supported");
            for (const DeckCard& dc : b.cards) {
                const Card f(deck_, b, dc, with_id ? std::vector<std::size_t>{10} : k_ten);
                for (std::size_t n = 0; n < f.size(); ++n) {
                    const long long id = f.id(n, "NID");
                    if (id > 0) history_nodes_.push_back({id, {&b, f.line()}});
                }
            }
            return;
        }
        const Card f = card(b, 0);
        const Real dt = f.real(0, "DT");
        if (k == "DATABASE_BINARY_D3PLOT") {
            const long long npltc = f.id(3, "NPLTC");
            if (npltc > 0)
                fields_every_npltc_ = npltc;
            else
                fields_every_ = Line{num(dt), {&b, f.line()}};
            return;
        }
        if (k == "DATABASE_GLSTAT" || k == "DATABASE_NODOUT" || k == "DATABASE_RWFORC" ||
            k == "DATABASE_RCFORC") {
            if (dt > 0 && (!every_ || dt < every_value_)) {
                every_value_ = dt;
                every_ = Line{num(dt), {&b, f.line()}};
            }
            if (k == "DATABASE_RWFORC") wall_forces_ = true;
            if (k == "DATABASE_RCFORC") contact_forces_ = true;
            return;
        }
        note(b, b.line,
             "ignored: an output fpmshell does not write (it writes history.csv, "
             "energy.csv and VTU frames)");
    }

    // ---- writing ----

    void add(std::vector<Line>& out, const std::string& text, const Origin& at) {
        out.push_back({text, at});
    }

    DeckTranslation write() {
        write_segment_loads();
        std::vector<Line> out;
        const Origin top{deck_.blocks.empty() ? nullptr : &deck_.blocks.front(), 0};
        const std::string title =
            title_.empty() ? std::filesystem::path(path_).stem().string() : title_;
        add(out, "title: " + yaml_name(title), top);
        add(out, "mesh: {file: " + yaml_name(mesh_file_) + "}", top);
        write_sets(out);
        write_materials(out);
        write_sections(out);
        write_curves(out);
        write_list(out, "boundary", boundary_);
        write_list(out, "loads", loads_);
        write_list(out, "initial_conditions", initial_);
        write_list(out, "constraints", constraints_);
        write_walls(out);
        write_list(out, "contact", contact_);
        if (damping_) out.push_back(*damping_);
        write_control(out);
        write_output(out);

        DeckTranslation t;
        for (const Line& l : out) {
            t.yaml += l.text + "\n";
            t.origins.push_back(l.at.block == nullptr ? SourceLine{path_, 0, ""}
                                                      : SourceLine{l.at.block->file, l.at.line,
                                                                   "*" + l.at.block->keyword});
        }
        if (quadrangles_ > 0)
            note(*first_quadrangle_.block, first_quadrangle_.line,
                 fmt::format("{} quadrangles split into two triangles each (along the shorter "
                             "diagonal): {} triangles in all",
                             quadrangles_, total_triangles()));
        t.notes = std::move(notes_);
        return t;
    }

    void write_list(std::vector<Line>& out, const char* key, const std::vector<Line>& items) {
        if (items.empty()) return;
        add(out, std::string(key) + ":", items.front().at);
        out.insert(out.end(), items.begin(), items.end());
    }

    void write_sets(std::vector<Line>& out) {
        for (const auto& [id, at] : history_nodes_) {
            auto& g = node_groups_["node_" + std::to_string(id)];
            if (g.ids.empty()) {
                g.at = at;
                g.ids.push_back(id);
            }
        }
        if (node_groups_.empty() && element_groups_.empty()) return;
        add(out, "sets:",
            node_groups_.empty() ? element_groups_.begin()->second.at
                                 : node_groups_.begin()->second.at);
        for (const auto* groups : {&node_groups_, &element_groups_})
            for (const auto& [name, g] : *groups) {
                std::string ids;
                for (const long long id : g.ids)
                    ids += (ids.empty() ? "" : ", ") + std::to_string(id);
                add(out,
                    "  " + yaml_name(name) +
                        (groups == &node_groups_ ? ": {node_ids: [" : ": {element_ids: [") + ids +
                        "]}",
                    g.at);
            }
    }

    void write_materials(std::vector<Line>& out) {
        std::set<long long> used;
        for (const auto& [pid, p] : parts_)
            if (element_parts_.count(pid)) used.insert(p.material);
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
    std::string flow_curves(const MaterialDef& m) {
        const DeckBlock& b = *m.at.block;
        if (const auto c = curves_.find(m.lcss); c != curves_.end())
            return "flow_curve: " + points_text(c->second.points);
        const auto t = tables_.find(m.lcss);
        if (t == tables_.end())
            deck_fail(b, m.at.line,
                      "LCSS " + std::to_string(m.lcss) +
                          " is neither a *DEFINE_CURVE nor a *DEFINE_TABLE");
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

    void write_sections(std::vector<Line>& out) {
        bool first = true;
        for (const auto& [pid, e] : element_parts_) {
            const auto p = parts_.find(pid);
            if (p == parts_.end())
                deck_fail(*e.first.block, e.first.line,
                          "an element of part " + std::to_string(pid) + ", which no *PART defines");
            const PartDef& part = p->second;
            const auto s = sections_.find(part.section);
            if (s == sections_.end())
                deck_fail(
                    *part.at.block, part.at.line,
                    "SECID " + std::to_string(part.section) + ": no *SECTION_SHELL defines it");
            const auto m = materials_.find(part.material);
            if (m == materials_.end())
                deck_fail(*part.at.block, part.at.line,
                          "MID " + std::to_string(part.material) + ": no *MAT card defines it");
            Real thickness = s->second.thickness;
            if (!e.thickness.empty()) thickness = *e.thickness.begin();
            int points = s->second.points;
            if (m->second.plastic && points == 2)
                deck_fail(*s->second.at.block, s->second.at.line,
                          "NIP 2 with the plastic material of part " + std::to_string(pid) +
                              ": fpmshell integrates plastic sections with 3 or 5 points");
            if (first) add(out, "sections:", part.at);
            first = false;
            add(out,
                "  - {elements: part_" + std::to_string(pid) + ", material: mat_" +
                    std::to_string(part.material) + ", thickness: " + num(thickness) +
                    ", thickness_points: " + std::to_string(points) + "}",
                part.at);
        }
        for (const auto& [pid, p] : parts_)
            if (!element_parts_.count(pid))
                note(*p.at.block, p.at.line,
                     "part " + std::to_string(pid) + " has no shell elements: left out");
    }

    void write_curves(std::vector<Line>& out) {
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

    void write_walls(std::vector<Line>& out) {
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
            contacts.push_back({"  - {type: rigid, body: rigidwall" + std::to_string(w.id) +
                                    (w.nodes.empty() ? "" : ", nodes: " + yaml_name(w.nodes)) +
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
    std::string wall_velocity(const WallDef& w) {
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

    void write_control(std::vector<Line>& out) {
        if (!end_time_)
            throw InputError(input_error_text(path_, 0, "",
                                              "the deck has no *CONTROL_TERMINATION; its ENDTIM "
                                              "is the end time of the run"));
        add(out, "control:", end_time_->at);
        add(out, "  end_time: " + end_time_->text, end_time_->at);
        out.insert(out.end(), control_.begin(), control_.end());
    }

    void write_output(std::vector<Line>& out) {
        std::vector<Line> o;
        if (every_) o.push_back({"  every: " + every_->text, every_->at});
        if (fields_every_npltc_ > 0)
            o.push_back({"  fields_every: " + num(std::stod(end_time_->text) /
                                                  static_cast<Real>(fields_every_npltc_)),
                         end_time_->at});
        else if (fields_every_)
            o.push_back({"  fields_every: " + fields_every_->text, fields_every_->at});
        std::vector<Line> h;
        std::set<long long> seen;
        for (const auto& [id, at] : history_nodes_) {
            if (!seen.insert(id).second) continue;
            for (const char* q : {"ux", "uy", "uz", "vx", "vy", "vz", "ax", "ay", "az"})
                h.push_back({fmt::format("    - {{name: node{}_{}, nodes: node_{}, quantity: {}}}",
                                         id, q, id, q),
                             at});
        }
        if (wall_forces_)
            for (const WallDef& w : walls_)
                for (const char* c : {"x", "y", "z"})
                    h.push_back({fmt::format("    - {{name: rigidwall{}_force_{}, quantity: "
                                             "rigid_rigidwall{}_force_{}}}",
                                             w.id, c, w.id, c),
                                 w.at});
        // the contact definitions come after the walls' in the model (write_walls)
        if (contact_forces_)
            for (std::size_t k = 0; k < contact_ids_.size(); ++k)
                for (const char* c : {"x", "y", "z"})
                    h.push_back({fmt::format("    - {{name: contact{}_force_{}, quantity: "
                                             "contact_{}_force_{}}}",
                                             contact_ids_[k].first, c, walls_.size() + k + 1, c),
                                 contact_ids_[k].second});
        if (!h.empty()) {
            o.push_back({"  histories:", h.front().at});
            o.insert(o.end(), h.begin(), h.end());
        }
        if (o.empty()) return;
        add(out, "output:", o.front().at);
        out.insert(out.end(), o.begin(), o.end());
    }

    [[nodiscard]] long long total_triangles() const {
        long long shells = 0;
        for (const auto& [pid, p] : element_parts_) shells += p.count;
        return shells + quadrangles_;
    }

    struct ElementPart {
        Origin first;
        long long count = 0;
        std::set<Real> thickness;
    };
    struct NodeGroup {
        Origin at;
        std::vector<long long> ids;
    };

    std::string path_, mesh_file_;
    KeywordDeck deck_;
    std::vector<std::string> notes_;
    std::string title_;
    std::map<long long, ElementPart> element_parts_;
    long long quadrangles_ = 0;
    Origin first_quadrangle_;
    std::map<std::string, std::map<long long, std::string>> set_names_;
    std::map<long long, PartDef> parts_;
    std::map<long long, SectionDef> sections_;
    std::map<long long, MaterialDef> materials_;
    std::map<long long, CurveDef> curves_;
    std::map<long long, TableDef> tables_;
    long long last_table_ = 0;
    std::size_t table_waiting_ = 0;
    std::vector<std::pair<long long, Origin>> used_curves_;
    std::map<std::string, NodeGroup> node_groups_;
    std::map<std::string, NodeGroup> element_groups_;  // element sets by number (segment loads)
    struct Shell {
        long long id = 0;
        std::array<long long, 4> nodes{};
    };
    std::vector<Shell> shells_;  // every shell's number and nodes (for segments)
    std::map<std::string, std::vector<Segment>> segment_sets_;
    std::vector<SegmentLoad> segment_loads_;
    /// the model line of a load or prescribed motion on single nodes -> the set of its nodes
    std::map<std::string, std::string> node_group_of_text_;
    std::vector<Line> boundary_, loads_, initial_, contact_, control_, constraints_;
    long long welds_ = 0;  ///< spot welds read (their sets are numbered by it)
    std::vector<WallDef> walls_;
    std::optional<Line> end_time_, damping_, every_, fields_every_;
    Real every_value_ = 0;
    long long fields_every_npltc_ = 0;
    bool wall_forces_ = false;
    bool contact_forces_ = false;  ///< *DATABASE_RCFORC: a history of each contact's force
    std::vector<std::pair<long long, Origin>> contact_ids_;  ///< per contact card: its number
    std::vector<std::pair<long long, Origin>> history_nodes_;
};

}  // namespace

bool is_keyword_deck(const std::string& path) {
    const std::string ext = upper(std::filesystem::path(path).extension().string());
    return ext == ".K" || ext == ".KEY" || ext == ".DYN" || ext == ".KW";
}

DeckTranslation translate_lsdyna_deck(const std::string& deck_path, const std::string& mesh_file) {
    return DeckTranslator(deck_path, mesh_file).translate();
}

Model read_lsdyna_deck(const std::string& deck_path,
                       const std::vector<std::string>& set_overrides) {
    DeckTranslation t =
        translate_lsdyna_deck(deck_path, std::filesystem::path(deck_path).filename().string());
    Model model = read_model_text(t.yaml, std::move(t.origins), deck_path, set_overrides);
    model.notes = std::move(t.notes);
    return model;
}

}  // namespace fpmshell
