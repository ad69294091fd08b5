// Point masses of a deck (*ELEMENT_MASS, *ELEMENT_MASS_NODE_SET) -> the model's `masses`
// (model-format.md; theory.md §6.1: the mass lives on the particles, a point mass is more of it).
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

/// *ELEMENT_MASS (EID, NID, MASS, PID): each node gains MASS; the nodes of one mass value form
/// one set. *ELEMENT_MASS_NODE_SET (EID, NSID, MASS, PID): MASS shared equally by the set's
/// nodes. PID (a part for the mass's own output) is noted: the mass joins its node.
void DeckTranslator::element_mass(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const bool node_set = opt == std::set<std::string>{"NODE", "SET"};
    if (!opt.empty() && !node_set)
        refuse(b,
               "fpmshell reads *ELEMENT_MASS and *ELEMENT_MASS_NODE_SET (point masses on nodes); "
               "this form of it is not supported");
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

}  // namespace fpmshell::deck
