// *LOAD_BLAST_ENHANCED (a charge: BID M XBO YBO ZBO TBO UNIT BLAST / CFM CFL CFT CFP NIDBO DEATH
// NEGPHS) and *LOAD_BLAST_SEGMENT (BID N1 N2 N3 N4 ALEPID SFNRB SCALEP) or _SET (BID SSID ALEPID
// SFNRB SCALEP): the faces the charge loads, as `loads: - {type: blast, ...}` (theory.md §6.13).
// Each segment's normal is the one its node order gives, as LS-DYNA takes it.
#include <cmath>
#include <map>
#include <utility>

#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

namespace {

/// LS-DYNA's UNIT of the blast: the deck's length, mass and time units in metres, kilograms
/// and seconds (a consistent set, whose pressure unit is the one the card names).
struct BlastUnits {
    Real length, mass, time;
};

BlastUnits blast_units(const Card& f, long long unit, const Card* user) {
    constexpr Real foot = 0.3048, pound = 0.45359237, psi = 6894.757293168361;
    switch (unit) {
        case 2:
            return {1, 1, 1};  // m, kg, s, Pa
        case 3:
            return {0.0254, 12 * 14.593902937, 1};  // in, dozens of slugs, s, psi
        case 4:
            return {0.01, 1e-3, 1e-6};  // cm, g, microsecond, Mbar
        case 6:
            return {1e-3, 1, 1e-3};  // mm, kg, ms, GPa
        case 7:
            return {1e-3, 1e3, 1};  // mm, tonne, s, MPa
        case 8:
            return {1e-3, 1e-3, 1e-3};  // mm, g, ms, MPa
        case 5: {                       // the user's factors (card 2)
            const BlastUnits u{user->real(1, "CFL") * foot, user->real(0, "CFM") * pound,
                               user->real(2, "CFT") * 1e-3};
            if (!(u.length > 0 && u.mass > 0 && u.time > 0))
                user->fail("CFM, CFL, CFT: UNIT 5 needs each conversion factor > 0");
            // the pressure unit of those three, against the CFP given (within 1 %)
            const Real pascals = u.mass / (u.length * u.time * u.time);
            const Real cfp = user->real(3, "CFP");
            if (!(cfp > 0) || std::abs(cfp * psi / pascals - 1.0) > 0.01)
                user->fail("CFP: the pressure unit must be that of CFM, CFL and CFT (" +
                           num(pascals / psi) + " psi), fpmshell's units being consistent");
            return u;
        }
        case 1:
            f.fail(
                "UNIT 1 (feet, pound-mass, seconds, psi) is not a consistent set of units: "
                "give UNIT 5 with the deck's own factors");
        default:
            f.fail("UNIT " + std::to_string(unit) + " is not one of 1 to 8");
    }
}

}  // namespace

void DeckTranslator::blast_source(const DeckBlock& b) {
    std::vector<const DeckCard*> cards;
    for (const DeckCard& dc : b.cards)
        if (!dc.blank()) cards.push_back(&dc);
    if (cards.empty()) deck_fail(b, b.line, "*LOAD_BLAST_ENHANCED: no card");
    const Card f(deck_, b, *cards[0], k_ten);
    const Card g(deck_, b, cards.size() > 1 ? *cards[1] : *cards[0], k_ten);
    const bool second = cards.size() > 1;
    if (cards.size() > 2)
        deck_fail(b, cards[2]->line, "*LOAD_BLAST_ENHANCED has two cards per charge");
    const long long bid = f.id(0, "BID");
    if (blast_sources_.count(bid)) f.fail("BID " + std::to_string(bid) + " is defined twice");
    const Real mass = f.real(1, "M");
    if (!(mass > 0)) f.fail("M: the charge's TNT-equivalent mass must be > 0");
    const long long blast = f.id(7, "BLAST", 2);
    if (blast != 1 && blast != 2)
        f.fail("BLAST " + std::to_string(blast) +
               ": fpmshell models the hemispherical surface burst (1) and the spherical "
               "free-air burst (2)");
    const long long unit = f.id(6, "UNIT", 2);
    if (unit == 5 && !second) f.fail("UNIT 5 needs card 2 (CFM, CFL, CFT, CFP)");
    const BlastUnits u = blast_units(f, unit, &g);
    std::string keys = "charge_mass: " + num(mass);
    const long long nidbo = second ? g.id(4, "NIDBO") : 0;
    if (nidbo != 0) {  // the charge at a node (its initial position)
        const std::string group = "blast_centre_" + std::to_string(bid);
        auto& node = node_groups_[group];
        node.at = {&b, g.line()};
        node.ids = {nidbo};
        keys += ", centre: " + yaml_name(group);
    } else {
        keys += ", centre: " + vec(f.real(2, "XBO"), f.real(3, "YBO"), f.real(4, "ZBO"));
    }
    keys += std::string(", burst: ") + (blast == 1 ? "surface" : "free_air");
    if (const Real tbo = f.real(5, "TBO"); tbo != 0) keys += ", detonation_time: " + num(tbo);
    if (second) {
        const Real death = g.real(5, "DEATH", 1e20);
        if (!(death > 0)) g.fail("DEATH must be > 0");
        if (death < 1e20) keys += ", death_time: " + num(death);
        const long long negphs = g.id(6, "NEGPHS");
        if (negphs != 0 && negphs != 1 && negphs != 10 && negphs != 11)
            g.fail("NEGPHS " + std::to_string(negphs) + " is not 0, 1, 10 or 11");
        // 0 and 10: the Friedlander curve continued (eq. 6.13-5); 1 and 11: the positive
        // phase only. The duration is the Kingery-Bulmash (ConWep) one for all four.
        if (negphs == 0 || negphs == 10) keys += ", negative_phase: true";
    } else {
        keys += ", negative_phase: true";  // NEGPHS 0, LS-DYNA's default
    }
    if (unit != 2)
        keys += ", units: {length: " + num(u.length) + ", mass: " + num(u.mass) +
                ", time: " + num(u.time) + "}";
    blast_sources_[bid] = {keys, {&b, f.line()}};
}

void DeckTranslator::blast_segment_load(const DeckBlock& b) {
    const std::string& k = b.keyword;
    const bool set = k == "LOAD_BLAST_SEGMENT_SET";
    if (!set && k != "LOAD_BLAST_SEGMENT") refuse(b, unsupported_reason(k));
    // the single segments of one charge and scale in this block: one load
    std::map<std::pair<long long, Real>, std::size_t> gathered;
    for (const DeckCard& dc : b.cards) {
        if (dc.blank()) continue;
        const Card f(deck_, b, dc, k_ten);
        const long long bid = f.id(0, "BID");
        const auto source = blast_sources_.find(bid);
        if (source == blast_sources_.end())
            f.fail("BID " + std::to_string(bid) + ": no *LOAD_BLAST_ENHANCED defines it");
        const std::size_t ale = set ? 2 : 5;
        if (f.id(ale, "ALEPID") != 0)
            f.fail(
                "ALEPID: the blast coupled to an ALE air domain is not supported (fpmshell "
                "loads the faces by the Kingery-Bulmash fits alone)");
        const Real scale = f.real(ale + 2, "SCALEP", 1.0);
        if (!(scale > 0)) f.fail("SCALEP must be > 0");
        SegmentLoad load;
        load.at = {&b, f.line()};
        load.blast = source->second.first + (scale != 1.0 ? ", scale: " + num(scale) : "");
        if (set) {
            load.name = set_name(f, "segment", f.id(1, "SSID"));
            load.segments = segment_sets_.at(load.name);
            if (load.segments.empty()) f.fail("segment set '" + load.name + "' lists no segment");
        } else {
            const auto [at, first] = gathered.try_emplace({bid, scale}, segment_loads_.size());
            if (!first) {
                segment_loads_[at->second].segments.push_back(segment(f, 1, b));
                continue;
            }
            load.name = "blast_segments_" + std::to_string(segment_loads_.size() + 1);
            load.segments.push_back(segment(f, 1, b));
        }
        load.slot = loads_.size();
        loads_.push_back({"", load.at});
        segment_loads_.push_back(std::move(load));
    }
}

}  // namespace fpmshell::deck
