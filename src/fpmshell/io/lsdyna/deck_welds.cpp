// The spot welds of a deck, and their failure (theory.md eqs. 6.11-13 to 6.11-15):
// *CONSTRAINED_SPOTWELD and *CONSTRAINED_GENERALIZED_WELD_SPOT.
#include <cmath>
#include <tuple>

#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

/// The `failure` keys of a weld from SN, SS, N, M (fields sn ... sn + 3 of `f`), TF (field tf)
/// and the plastic strain EP or EPSF (field ep, named ep_name; 0 or 1e20 and above: none), or
/// "" when it cannot fail. A blank exponent of a force given is taken as 2 (`defaulted` set).
std::string DeckTranslator::weld_failure(const Card& f, std::size_t sn, std::size_t tf,
                                         std::size_t ep, const char* ep_name, bool& defaulted) {
    const Real normal = f.real(sn, "SN"), shear = f.real(sn + 1, "SS");
    if (normal < 0 || shear < 0)
        f.fail(
            "SN or SS < 0 (a curve of the nodal temperature) is not supported: fpmshell has no "
            "temperature; give the forces");
    const Real time = f.real(tf, "TF", 1e20);
    const bool timed = time > 0 && time < 1e20;
    const Real strain = f.real(ep, ep_name, 1e20);
    if (strain < 0)
        f.fail(std::string(ep_name) +
               " must be >= 0 (the sheets' plastic strain at which the "
               "weld tears out)");
    const bool ductile = strain > 0 && strain < 1e20;
    if (normal == 0 && shear == 0 && !timed && !ductile) return "";
    std::string keys;
    if (normal > 0) keys += ", normal_force: " + num(normal);
    if (shear > 0) keys += ", shear_force: " + num(shear);
    for (const auto& [k, name, key] :
         {std::tuple{sn + 2, "N", "normal_exponent"}, std::tuple{sn + 3, "M", "shear_exponent"}}) {
        const Real e = f.real(k, name);
        if (e > 0) {
            keys += std::string(", ") + key + ": " + num(e);
        } else if (e < 0) {
            f.fail(std::string(name) + " must be > 0 (the exponent of the weld's force)");
        } else if ((k == sn + 2 ? normal : shear) > 0) {
            defaulted = true;
        }
    }
    if (timed) keys += ", time: " + num(time);
    if (ductile) keys += ", plastic_strain: " + num(strain);
    return ", failure: {" + keys.substr(2) + "}";
}

/// *CONSTRAINED_SPOTWELD (_ID): each weld's two nodes move as one rigid body until the weld
/// fails by its forces SN, SS (exponents N, M), its time TF (eq. 6.11-13) or the sheets'
/// plastic strain EP at one of its nodes (eq. 6.11-15).
void DeckTranslator::spot_weld(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    for (const std::string& o : opt)
        if (o != "ID")
            refuse(b, "*CONSTRAINED_SPOTWELD_" + o + " is not supported (plain and _ID)");
    const std::size_t per_weld = opt.count("ID") ? 2 : 1;
    if (b.cards.empty()) required_card(b, 0, "N1, N2, SN, SS, N, M, TF, EP");
    bool defaulted = false;
    for (std::size_t c = 0; c < b.cards.size(); c += per_weld) {
        while (c < b.cards.size() && b.cards[c].blank()) ++c;  // blank lines between welds
        if (c >= b.cards.size()) break;
        const Card f = required_card(b, c + per_weld - 1, "N1, N2, SN, SS, N, M, TF, EP");
        const std::array<long long, 2> ids{f.id(0, "N1"), f.id(1, "N2")};
        if (ids[0] == ids[1]) f.fail("N1 and N2 are the same node " + std::to_string(ids[0]));
        const std::string group = "spotweld_" + std::to_string(++welds_);
        const std::string text =
            "{type: rigid, nodes: NODES" + weld_failure(f, 2, 6, 7, "EP", defaulted) + "}";
        for (const long long id : ids)
            add_node_to_group(group, id, text, {&b, f.line()}, constraints_);
    }
    if (defaulted) note(b, b.line, "N or M blank: the exponent 2 is taken");
}

/// *CONSTRAINED_GENERALIZED_WELD_SPOT (_ID): the nodes of NSID move as one rigid body, which
/// fails by TFAIL, SN, SS (exponents N, M) or EPSF: two nodes as *CONSTRAINED_SPOTWELD's, more
/// each node by the force onto it (theory.md eqs. 6.11-14, 6.11-15).
void DeckTranslator::generalized_spot_weld(const DeckBlock& b) {
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
    const long long nsid = f.id(0, "NSID");
    bool defaulted = false;
    const std::string failure = weld_failure(g, 2, 0, 1, "EPSF", defaulted);
    if (defaulted) note(b, g.line(), "N or M blank: the exponent 2 is taken");
    if (f.id(2, "FILTER") > 1)
        note(b, f.line(), "FILTER: the weld's forces are judged unfiltered, every step");
    constraints_.push_back(
        {"  - {type: rigid, nodes: " + yaml_name(set_name(f, "node", nsid)) + failure + "}",
         {&b, f.line()}});
}

}  // namespace fpmshell::deck
