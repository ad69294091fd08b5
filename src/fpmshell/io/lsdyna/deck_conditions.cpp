// Constraints on nodes (SPC, prescribed motion), loads on nodes, shells and segments, and
// initial velocities of a deck.
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

/// The id card of the _ID options (ID, HEADING) comes first.
std::size_t DeckTranslator::first_data_card(const std::set<std::string>& opt) {
    return opt.count("ID") ? 1 : 0;
}

void DeckTranslator::spc(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const bool single = opt.count("NODE") != 0;
    if (!single && !opt.count("SET")) refuse(b, unsupported_reason("BOUNDARY_SPC"));
    static const char* dofs[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
    for (std::size_t c = first_data_card(opt); c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;  // a blank line between records
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

/// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET: a velocity (VAD 0), an acceleration (VAD 1) or a
/// displacement (VAD 2)
/// along x, y or z (DOF 1, 2, 3), the curve times SF; the node's other directions stay free.
void DeckTranslator::prescribed_motion(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 3);
    const bool single = opt.count("NODE") != 0;
    if (opt.count("RIGID")) return prescribed_rigid_motion(b, opt);
    if (!single && !opt.count("SET")) refuse(b, unsupported_reason(b.keyword));
    for (const std::string& o : opt)
        if (o != "NODE" && o != "SET" && o != "ID")
            refuse(b, "*BOUNDARY_PRESCRIBED_MOTION_..._" + o + " is not supported");
    for (std::size_t c = first_data_card(opt); c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;  // a blank line between records
        const Card f = card(b, c);
        const long long id = f.id(0, single ? "NID" : "NSID");
        const long long dof = f.id(1, "DOF");
        const long long vad = f.id(2, "VAD");
        const Real sf = f.real(4, "SF", 1.0);
        if (dof < 1 || dof > 3)
            f.fail("DOF " + std::to_string(dof) +
                   ": fpmshell prescribes the translations along x, y or z (1, 2, 3)");
        if (vad != 0 && vad != 1 && vad != 2)
            f.fail("VAD " + std::to_string(vad) +
                   ": fpmshell prescribes a velocity (0), an acceleration (1) or a displacement "
                   "(2)");
        if (f.id(5, "VID") != 0) f.fail("VID: a direction vector is not supported (0 only)");
        const Real death = f.real(6, "DEATH");
        if (f.real(7, "BIRTH") != 0 || (death != 0 && death < 1e20))
            f.fail("BIRTH and DEATH are not supported (the motion is prescribed throughout)");
        const std::size_t axis = static_cast<std::size_t>(dof - 1);
        const std::string value =
            vec(axis == 0 ? sf : 0.0, axis == 1 ? sf : 0.0, axis == 2 ? sf : 0.0);
        static const char* names[3] = {"ux", "uy", "uz"};
        const std::string text = std::string("{nodes: NODES, prescribe: {") +
                                 (vad == 0   ? "velocity: "
                                  : vad == 1 ? "acceleration: "
                                             : "displacement: ") +
                                 value + ", curve: " + curve_ref(b, f, f.id(3, "LCID")) +
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

/// *BOUNDARY_PRESCRIBED_MOTION_RIGID: the velocity (VAD 0), acceleration (1) or displacement (2) of
/// a rigid part's centre of mass along x, y or z (DOF 1-3), or its angular velocity about x, y or z
/// (DOF 5-7, VAD 0), the curve times SF; the body's other components stay free (theory.md eq.
/// 6.11-7: `boundary` entries of type rigid_body).
void DeckTranslator::prescribed_rigid_motion(const DeckBlock& b, const std::set<std::string>& opt) {
    for (const std::string& o : opt)
        if (o != "RIGID" && o != "ID")
            refuse(b, "*BOUNDARY_PRESCRIBED_MOTION_RIGID_" + o + " is not supported");
    for (std::size_t c = first_data_card(opt); c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;  // a blank line between records
        const Card f = card(b, c);
        const long long pid = f.id(0, "PID");
        const long long dof = f.id(1, "DOF");
        const long long vad = f.id(2, "VAD");
        const Real sf = f.real(4, "SF", 1.0);
        const bool rotation = dof >= 5 && dof <= 7;
        if (!(dof >= 1 && dof <= 3) && !rotation)
            f.fail("DOF " + std::to_string(dof) +
                   ": fpmshell prescribes a rigid part's translation along x, y or z (1, 2, 3) "
                   "or its rotation about x, y or z (5, 6, 7)");
        if (vad != 0 && !((vad == 1 || vad == 2) && !rotation))
            f.fail("VAD " + std::to_string(vad) +
                   (rotation ? ": fpmshell prescribes a rigid part's rotation as an angular "
                               "velocity (VAD 0)"
                             : ": fpmshell prescribes a velocity (0), an acceleration (1) or a "
                               "displacement (2)"));
        if (f.id(5, "VID") != 0)
            f.fail("VID: a direction vector or local system is not supported (0 only)");
        const Real death = f.real(6, "DEATH");
        if (f.real(7, "BIRTH") != 0 || (death != 0 && death < 1e20))
            f.fail("BIRTH and DEATH are not supported (the motion is prescribed throughout)");
        const std::size_t axis = static_cast<std::size_t>(rotation ? dof - 5 : dof - 1);
        const std::string value =
            vec(axis == 0 ? sf : 0.0, axis == 1 ? sf : 0.0, axis == 2 ? sf : 0.0);
        static const char* translations[3] = {"ux", "uy", "uz"};
        static const char* rotations[3] = {"rx", "ry", "rz"};
        const char* kind = rotation   ? "angular_velocity: "
                           : vad == 0 ? "velocity: "
                           : vad == 1 ? "acceleration: "
                                      : "displacement: ";
        boundary_.push_back({"  - {rigid_body: part_" + std::to_string(pid) + ", prescribe: {" +
                                 kind + value + ", curve: " + curve_ref(b, f, f.id(3, "LCID")) +
                                 ", components: [" +
                                 (rotation ? rotations[axis] : translations[axis]) + "]}}",
                             {&b, f.line()}});
    }
}

std::string DeckTranslator::replace_nodes(std::string text, const std::string& set) {
    text.replace(text.find("NODES"), 5, yaml_name(set));
    return text;
}

/// Node `id` joins the set `group` (of node_ids); the first node writes `text` (with NODES
/// for the set's name) into `lines`.
void DeckTranslator::add_node_to_group(const std::string& group, long long id,
                                       const std::string& text, const Origin& at,
                                       std::vector<Line>& lines) {
    auto& g = node_groups_[group];
    if (g.ids.empty()) {
        g.at = at;
        lines.push_back({"  - " + replace_nodes(text, group), at});
    }
    g.ids.push_back(id);
}

std::string DeckTranslator::nodes_of_velocity(const Card& f, long long id, long long styp) {
    if (id == 0) return "all";
    if (styp == 1) return set_name(f, "part", id);
    if (styp == 2) return "part_" + std::to_string(id);
    if (styp == 3) return set_name(f, "node", id);
    f.fail("STYP " + std::to_string(styp) + " is not 1 (part set), 2 (part) or 3 (node set)");
}

/// The initial velocities, from the most general card to the most specific: *INITIAL_VELOCITY
/// (a set, all nodes, an exempted set with its own velocities), then _GENERATION, then _NODE;
/// a later entry of the model replaces an earlier one on the nodes they share
/// (model-format.md), so a node given its own velocity keeps it whatever the card order.
void DeckTranslator::initial_velocity(const DeckBlock& b) {
    const std::string& k = b.keyword;
    if (k == "INITIAL_VELOCITY") {
        const Card f = required_card(b, 0, "NSID, NSIDEX, BOXID, IRIGID, ICID");
        const Card v = required_card(b, 1, "VX, VY, VZ, VXR, VYR, VZR");
        const long long nsid = f.id(0, "NSID"), nsidex = f.id(1, "NSIDEX");
        if (f.id(2, "BOXID") != 0) f.fail("BOXID is not supported (0 only)");
        const long long icid = f.id(4, "ICID");
        const std::string nodes = nsid == 0 ? "all" : set_name(f, "node", nsid);
        initial_sets_.push_back(
            {"  - {nodes: " + yaml_name(nodes) + ", " + velocities(v, 0, icid) + "}",
             {&b, v.line()}});
        if (nsidex != 0) {  // the exempted nodes take the velocities of the third card
            const Card e = card(b, 2);
            initial_sets_.push_back({"  - {nodes: " + yaml_name(set_name(f, "node", nsidex)) +
                                         ", " + velocities(e, 0, icid) + "}",
                                     {&b, e.line()}});
        }
    } else if (k == "INITIAL_VELOCITY_NODE") {
        // one card per node; the nodes of one velocity make one set
        for (const DeckCard& dc : b.cards) {
            if (dc.blank()) continue;
            const Card f(deck_, b, dc, k_ten);
            const std::string text = "{nodes: NODES, " + velocities(f, 1, f.id(7, "ICID")) + "}";
            auto& group = node_group_of_text_[text];
            if (group.empty())
                group = "velocity_nodes_" + std::to_string(node_group_of_text_.size());
            add_node_to_group(group, f.id(0, "NID"), text, {&b, f.line()}, initial_nodes_);
        }
    } else if (k == "INITIAL_VELOCITY_GENERATION") {
        // cards in pairs: the translation, then the axis of the rotation OMEGA
        for (std::size_t c = 0; c < b.cards.size(); c += 2) {
            while (c < b.cards.size() && b.cards[c].blank()) ++c;  // blank lines between pairs
            if (c >= b.cards.size()) break;
            const Card f = card(b, c);
            const Card g = card(b, c + 1);
            // ICID: VX, VY, VZ and the axis NX, NY, NZ in the local system (XC, YC, ZC global)
            const long long icid = f.id(7, "ICID");
            if (f.id(6, "IVATN") != 0 || g.id(7, "IRIGID") != 0)
                f.fail("IVATN and IRIGID are not supported (0 only)");
            const std::string nodes = nodes_of_velocity(f, f.id(0, "ID"), f.id(1, "STYP"));
            const std::array<Real, 3> v =
                to_global(f, icid, {f.real(3, "VX"), f.real(4, "VY"), f.real(5, "VZ")});
            std::string text =
                "  - {nodes: " + yaml_name(nodes) + ", velocity: " + vec(v[0], v[1], v[2]);
            if (const Real omega = f.real(2, "OMEGA"); omega != 0) {
                std::array<Real, 3> axis{g.real(3, "NX"), g.real(4, "NY"), g.real(5, "NZ")};
                if (axis == std::array<Real, 3>{})
                    g.fail("NX, NY, NZ: the axis of OMEGA must not be zero");
                axis = unit(to_global(f, icid, axis));
                text += ", rotation: {centre: " +
                        vec(g.real(0, "XC"), g.real(1, "YC"), g.real(2, "ZC")) +
                        ", angular_velocity: " +
                        vec(omega * axis[0], omega * axis[1], omega * axis[2]) + "}";
            }
            initial_generated_.push_back({text + "}", {&b, f.line()}});
        }
    } else if (k == "INITIAL_VELOCITY_RIGID_BODY") {
        // PID, VX, VY, VZ, VXR, VYR, VZR, ICID: the rigid part's translation (a part-level
        // velocity, as _GENERATION's) and its spin about its centre of mass
        for (const DeckCard& dc : b.cards) {
            if (dc.blank()) continue;
            const Card f(deck_, b, dc, k_ten);
            const long long icid = f.id(7, "ICID");
            const long long pid = f.id(0, "PID");
            require_rigid_part(f, pid, "PID");
            const std::array<Real, 3> v =
                to_global(f, icid, {f.real(1, "VX"), f.real(2, "VY"), f.real(3, "VZ")});
            const std::array<Real, 3> w =
                to_global(f, icid, {f.real(4, "VXR"), f.real(5, "VYR"), f.real(6, "VZR")});
            const Real wx = w[0], wy = w[1], wz = w[2];
            initial_generated_.push_back(
                {"  - {nodes: part_" + std::to_string(pid) +
                     ", velocity: " + vec(v[0], v[1], v[2]) +
                     (wx != 0 || wy != 0 || wz != 0
                          ? ", rotation: {centre: mass, angular_velocity: " + vec(wx, wy, wz) + "}"
                          : std::string()) +
                     "}",
                 {&b, f.line()}});
        }
    } else {
        refuse(b, unsupported_reason(k));
    }
}

/// "velocity: [VX, VY, VZ], angular_velocity: [VXR, VYR, VZR]" from fields first ... first + 5.
std::string DeckTranslator::velocities(const Card& f, std::size_t first, long long cid) const {
    const std::array<Real, 3> v =
        to_global(f, cid, {f.real(first, "VX"), f.real(first + 1, "VY"), f.real(first + 2, "VZ")});
    const std::array<Real, 3> w = to_global(
        f, cid, {f.real(first + 3, "VXR"), f.real(first + 4, "VYR"), f.real(first + 5, "VZR")});
    return "velocity: " + vec(v[0], v[1], v[2]) + ", angular_velocity: " + vec(w[0], w[1], w[2]);
}

/// The model's name of load curve `lcid` (written out if some card uses it).
std::string DeckTranslator::curve_ref(const DeckBlock& b, const Card& f, long long lcid) {
    if (lcid == 0) f.fail("LCID: a load needs a curve");
    used_curves_.push_back({lcid, {&b, f.line()}});
    return "curve_" + std::to_string(lcid);
}

void DeckTranslator::load(const DeckBlock& b) {
    const std::string& k = b.keyword;
    for (const DeckCard& dc : b.cards) {
        if (dc.blank()) continue;  // a blank line between records
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
            if (group.empty()) group = "load_nodes_" + std::to_string(node_group_of_text_.size());
            add_node_to_group(group, id, text, {&b, f.line()}, loads_);
        } else
            loads_.push_back(
                {"  - " + replace_nodes(text, set_name(f, "node", id)), {&b, f.line()}});
    }
}

/// *LOAD_SEGMENT_SET (SSID, LCID, SF, AT) and *LOAD_SEGMENT (LCID, SF, AT, N1 ... N4): a
/// pressure along each segment's normal (by its node order), on the shell it covers.
void DeckTranslator::segment_load(const DeckBlock& b) {
    const std::string& k = b.keyword;
    const bool set = k == "LOAD_SEGMENT_SET";
    if (!set && k != "LOAD_SEGMENT") refuse(b, unsupported_reason(k));
    for (const DeckCard& dc : b.cards) {
        if (dc.blank()) continue;  // a blank line between records
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
            if (load.segments.empty()) f.fail("segment set '" + load.name + "' lists no segment");
        } else {
            load.name = "load_segments_" + std::to_string(segment_loads_.size() + 1);
            load.segments.push_back(segment(f, 3, b));
        }
        load.slot = loads_.size();  // its pressures take this place among the loads
        loads_.push_back({"", load.at});
        segment_loads_.push_back(std::move(load));
    }
}

/// *LOAD_BODY_X, _Y, _Z: LCID, SF, LCIDDR, XC, YC, ZC, CID. A base acceleration along the axis
/// (theory.md eq. 6.7-4): the inertial load pulls the other way, so the curve's value a gives
/// `gravity` -a SF along it. *LOAD_BODY_PARTS: PSID, the parts every body load acts on.
void DeckTranslator::body_load(const DeckBlock& b) {
    const std::string& k = b.keyword;
    const bool parts = k == "LOAD_BODY_PARTS";
    const int axis = k == "LOAD_BODY_X" ? 0 : k == "LOAD_BODY_Y" ? 1 : k == "LOAD_BODY_Z" ? 2 : -1;
    if (!parts && axis < 0) refuse(b, unsupported_reason(k));
    for (const DeckCard& dc : b.cards) {
        if (dc.blank()) continue;
        const Card f(deck_, b, dc, k_ten);
        if (parts) {
            if (body_parts_)
                f.fail(
                    "a second *LOAD_BODY_PARTS (the deck names the parts of its body loads once)");
            body_parts_ = {yaml_name(set_name(f, "part", f.id(0, "PSID"))), {&b, f.line()}};
            continue;
        }
        if (f.id(6, "CID") != 0) f.fail("CID: only global directions (0) are supported");
        if (f.id(2, "LCIDDR") != 0)
            note(b, f.line(),
                 "LCIDDR ignored: the body load acts by LCID throughout (a dynamic relaxation "
                 "runs with it too)");
        const Real sf = f.real(1, "SF", 1.0);
        std::array<Real, 3> g{0.0, 0.0, 0.0};
        g[static_cast<std::size_t>(axis)] = -sf;
        body_loads_.push_back(
            {loads_.size(), "  - {type: gravity, value: " + vec(g[0], g[1], g[2]) +
                                ", curve: " + curve_ref(b, f, f.id(0, "LCID"))});
        loads_.push_back({"", {&b, f.line()}});
    }
}

void DeckTranslator::write_body_loads() {
    for (const auto& [slot, text] : body_loads_)
        loads_[slot].text =
            text + (body_parts_ ? ", elements: " + body_parts_->first : std::string()) + "}";
    if (body_parts_ && body_loads_.empty())
        note(*body_parts_->second.block, body_parts_->second.line,
             "*LOAD_BODY_PARTS without a *LOAD_BODY_X, _Y or _Z: nothing to load");
}

/// *PART_MOVE: PID XMOV YMOV ZMOV CID IFSET (I8, 3 x E16, I8, I8), one part per card.
void DeckTranslator::part_move(const DeckBlock& b) {
    for (const DeckCard& dc : b.cards) {
        if (dc.blank()) continue;
        const Card f(deck_, b, dc, {8, 16, 16, 16, 8, 8});
        const long long pid = f.id(0, "PID");
        if (f.id(4, "CID") != 0)
            f.fail(
                "CID: a move in a local coordinate system is not supported (give it in global "
                "axes, CID 0)");
        const long long ifset = f.id(5, "IFSET");
        if (ifset != 0 && ifset != 1) f.fail("IFSET must be 0 (a part) or 1 (a part set)");
        const std::string nodes =
            ifset == 1 ? set_name(f, "part", pid) : "part_" + std::to_string(pid);
        moves_.push_back({"  - {nodes: " + yaml_name(nodes) + ", by: " +
                              vec(f.real(1, "XMOV"), f.real(2, "YMOV"), f.real(3, "ZMOV")) + "}",
                          {&b, f.line()}});
    }
}

}  // namespace fpmshell::deck
