// Point masses of a deck (*ELEMENT_MASS, *ELEMENT_MASS_NODE_SET, *ELEMENT_MASS_PART, _PART_SET)
// -> the model's `masses` (model-format.md; theory.md §6.1: the mass lives on the particles, a
// lumped mass is more of it).
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

/// *ELEMENT_MASS (EID, NID, MASS, PID): each node gains MASS; the nodes of one mass value form
/// one set. *ELEMENT_MASS_NODE_SET (EID, NSID, MASS, PID): MASS shared equally by the set's
/// nodes. PID (a part for the mass's own output) is noted: the mass joins its node.
void DeckTranslator::element_mass(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    if (opt.count("PART")) return part_mass(b, opt);
    const bool node_set = opt == std::set<std::string>{"NODE", "SET"};
    if (!opt.empty() && !node_set)
        refuse(b,
               "fpmshell reads *ELEMENT_MASS, _NODE_SET, _PART and _PART_SET; this form of it is "
               "not supported");
    const std::size_t w = b.format == DeckFormat::WideId ? 10 : 8;
    const std::vector<std::size_t> widths{w, w, 16, w};
    bool part_given = false;
    for (std::size_t c = 0; c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;
        const Card f = card(b, c, widths);
        const long long id = f.id(1, node_set ? "NSID" : "NID");
        const Real mass = f.real(2, "MASS");
        if (!(mass > 0)) f.fail("MASS must be > 0");
        part_given = part_given || f.id(3, "PID") != 0;
        const Origin at{&b, f.line()};
        if (node_set) {
            masses_.push_back({"  - {nodes: " + yaml_name(set_name(f, "node", id)) +
                                   ", total: " + num(mass) + "}",
                               at});
        } else {
            const std::string text = "{nodes: NODES, mass: " + num(mass) + "}";
            auto& group = node_group_of_text_[text];  // the nodes of one mass value
            if (group.empty()) group = "mass_nodes_" + std::to_string(node_group_of_text_.size());
            add_node_to_group(group, id, text, at, masses_);
        }
    }
    if (part_given)
        note(b, b.line,
             "PID: the mass joins its node (a particle's mass); it makes no part of its own");
}

/// *ELEMENT_MASS_PART (PID, ADDMASS, FINMASS, LCID) and _PART_SET (PSID, ..., MWD): ADDMASS
/// spread over the part's shells by area (LS-DYNA's area-weighted distribution), or what
/// FINMASS > 0 leaves above their own mass.
void DeckTranslator::part_mass(const DeckBlock& b, const std::set<std::string>& opt) {
    const bool part_set = opt.count("SET") != 0;
    for (const std::string& o : opt)
        if (o != "PART" && o != "SET")
            refuse(b, "*ELEMENT_MASS_PART_" + o + " is not supported (_PART and _PART_SET)");
    const std::vector<std::size_t> widths{8, 16, 16, 16, 8};
    for (std::size_t c = 0; c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;
        const Card f = card(b, c, widths);
        const long long id = f.id(0, part_set ? "PSID" : "PID");
        const Real add = f.real(1, "ADDMASS"), final_mass = f.real(2, "FINMASS");
        if (f.id(3, "LCID") != 0)
            f.fail("LCID (a curve that scales the added mass) is not supported");
        if (part_set && f.id(4, "MWD") != 0)
            f.fail("MWD (a distribution weighted by the nodal masses) is not supported");
        const std::string elements =
            part_set ? yaml_name(set_name(f, "part", id)) : "part_" + std::to_string(id);
        if (final_mass > 0)
            masses_.push_back({"  - {elements: " + elements + ", final: " + num(final_mass) + "}",
                               {&b, f.line()}});
        else if (add > 0)
            masses_.push_back(
                {"  - {elements: " + elements + ", total: " + num(add) + "}", {&b, f.line()}});
        else
            f.fail("ADDMASS or FINMASS must be > 0");
    }
}

}  // namespace fpmshell::deck
