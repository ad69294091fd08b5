// The mesh-side cards of a deck as the translation needs them: the shells (their parts,
// thicknesses and nodes), the sets' names, and the segments with the pressures on them.
#include "fpmshell/io/lsdyna/deck_translator.hpp"

namespace fpmshell::deck {

void DeckTranslator::element_solid(const DeckBlock& b) {
    const std::size_t w = b.format == DeckFormat::WideId ? 10 : 8;
    for (std::size_t c = 0; c < b.cards.size(); ++c) {
        if (b.cards[c].blank()) continue;
        std::vector<std::string> ids = deck_fields(b, b.cards[c], std::vector<std::size_t>(3, w));
        long long eid = 0, pid = 0, n1 = 0;
        if (!text_mesh::parse_whole(ids[0], eid) || !text_mesh::parse_whole(ids[1], pid)) {
            ids = text_mesh::split_blanks(b.cards[c].text);
            ids.resize(std::max<std::size_t>(ids.size(), 3));
            if (!text_mesh::parse_whole(ids[1], pid)) continue;  // the mesh reader says why
        }
        // EID and PID alone: the nodes are on the next card (LS-DYNA's two-card form)
        if (ids[2].empty() || !text_mesh::parse_whole(ids[2], n1) || n1 == 0) ++c;
        auto& p = solid_parts_[pid];
        if (p.count == 0)
            p.first = {&b, b.line};  // the card's block (the mesh reader checks cards)
        ++p.count;
    }
}

void DeckTranslator::element_shell(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const bool thickness = opt.count("THICKNESS") != 0;
    const std::size_t per_element = 1 +
                                    (thickness || opt.count("BETA") || opt.count("MCID") ? 1 : 0) +
                                    (opt.count("OFFSET") ? 1 : 0);
    const std::size_t w = b.format == DeckFormat::WideId ? 10 : 8;
    for (std::size_t c = 0; c < b.cards.size(); c += per_element) {
        while (c < b.cards.size() && b.cards[c].blank()) ++c;  // blank lines between elements
        if (c >= b.cards.size()) break;
        // EID and PID in columns, else (hand-written files) split at blanks, as the mesh
        // reader reads them
        std::vector<std::string> ids = deck_fields(b, b.cards[c], std::vector<std::size_t>(6, w));
        long long eid = 0, pid = 0;
        if (!text_mesh::parse_whole(ids[0], eid) || !text_mesh::parse_whole(ids[1], pid)) {
            ids = text_mesh::split_blanks(b.cards[c].text);
            ids.resize(std::max<std::size_t>(ids.size(), 6));
            if (!text_mesh::parse_whole(ids[1], pid)) continue;  // the mesh reader says why
        }
        std::array<long long, 4> n{};
        bool numbered = true;
        for (std::size_t k = 0; k < 4; ++k)
            numbered = numbered && (ids[2 + k].empty() || text_mesh::parse_whole(ids[2 + k], n[k]));
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

void DeckTranslator::set_header(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    const bool titled = opt.count("TITLE") != 0;
    if (b.cards.size() < (titled ? 2U : 1U)) return;  // the mesh reader reports it
    const Card f = card(b, titled ? 1 : 0);
    const long long sid = f.id(0, "SID");
    const std::string kind = starts_with(b.keyword, "SET_NODE")    ? "node"
                             : starts_with(b.keyword, "SET_SHELL") ? "shell"
                                                                   : "part";
    const std::string title = titled ? trim(b.cards[0].text) : "";
    define_set(f, kind, sid, !title.empty() ? title : lsdyna_set_name(kind, sid));
}

/// Set `sid` of `kind` is called `name`; a set number defined twice is refused.
void DeckTranslator::define_set(const Card& f, const std::string& kind, long long sid,
                                const std::string& name) {
    const auto [it, fresh] = set_places_[kind].try_emplace(sid, Origin{&f.block(), f.line()});
    if (!fresh)
        f.fail("*SET_" + upper(kind) + " " + std::to_string(sid) + " is defined twice (first at " +
               place(it->second) + ")");
    set_names_[kind][sid] = name;
}

/// The name of set `sid` of `kind` (node, shell, part), which the deck must define.
std::string DeckTranslator::set_name(const Card& f, const std::string& kind, long long sid) const {
    const auto& names =
        set_names_.count(kind) ? set_names_.at(kind) : std::map<long long, std::string>{};
    const auto it = names.find(sid);
    if (it == names.end())
        f.fail("no *SET_" + upper(kind) + "_LIST defines set " + std::to_string(sid) +
               " anywhere in the deck");
    return it->second;
}

/// *SET_SEGMENT(_TITLE): a header card (SID), then one card per segment (N1 ... N4).
void DeckTranslator::segment_set(const DeckBlock& b) {
    const std::set<std::string> opt = options_of(b.keyword, 2);
    for (const std::string& o : opt)
        if (o != "TITLE") refuse(b, "*SET_SEGMENT_" + o + " is not supported");
    const bool titled = opt.count("TITLE") != 0;
    const Card head = required_card(b, titled ? 1 : 0, "SID");
    const long long sid = head.id(0, "SID");
    const std::string title = titled ? trim(b.cards[0].text) : "";
    const std::string name = !title.empty() ? title : lsdyna_set_name("segment", sid);
    define_set(head, "segment", sid, name);
    auto& segments = segment_sets_[name];
    for (std::size_t c = titled ? 2 : 1; c < b.cards.size(); ++c)
        if (!b.cards[c].blank())
            segments.push_back(segment(Card(deck_, b, b.cards[c], k_ten), 0, b));
}

/// The segment of nodes in fields first ... first + 3 of `f`.
Segment DeckTranslator::segment(const Card& f, std::size_t first, const DeckBlock& b) {
    Segment s{{}, {&b, f.line()}};
    for (std::size_t k = 0; k < 4; ++k) s.nodes[k] = f.id(first + k, "N1..N4");
    if (s.nodes[0] <= 0 || s.nodes[1] <= 0 || s.nodes[2] <= 0)
        f.fail("a segment needs at least three node numbers N1, N2, N3");
    return s;
}

/// The element sets and pressures of the segment loads: each segment's shell (the one with
/// its nodes), in a set of the shells whose normal the segment's node order follows and one
/// (`<name>_reversed`, the pressure negated) of those it opposes. The contacts' segment sets:
/// the set of the shells their segments cover.
void DeckTranslator::write_segment_loads() {
    if (segment_loads_.empty() && segment_sides_.empty()) return;
    std::vector<std::pair<std::array<long long, 4>, std::size_t>> by_nodes;
    by_nodes.reserve(shells_.size());
    for (std::size_t k = 0; k < shells_.size(); ++k)
        by_nodes.emplace_back(node_key(shells_[k].nodes), k);
    std::sort(by_nodes.begin(), by_nodes.end());
    const auto shell_of = [&](const Segment& seg, const char* what) -> const Shell& {
        const auto key = node_key(seg.nodes);
        const auto it =
            std::lower_bound(by_nodes.begin(), by_nodes.end(), std::make_pair(key, std::size_t{0}));
        if (it == by_nodes.end() || it->first != key)
            deck_fail(
                *seg.at.block, seg.at.line,
                std::string("no shell element has the nodes of this segment; fpmshell ") + what);
        return shells_[it->second];
    };
    for (const SegmentSide& side : segment_sides_) {
        const auto& names = set_names_["segment"];
        const auto name = names.find(side.set_id);
        if (name == names.end())
            deck_fail(*side.at.block, side.at.line,
                      "no *SET_SEGMENT defines set " + std::to_string(side.set_id) +
                          " anywhere in the deck");
        auto& group = element_groups_[side.group];
        if (!group.ids.empty()) continue;  // (the same set on another contact)
        group.at = side.at;
        for (const Segment& seg : segment_sets_.at(name->second)) {
            const long long id = shell_of(seg, "takes the segments of its shells in contact").id;
            if (std::find(group.ids.begin(), group.ids.end(), id) == group.ids.end())
                group.ids.push_back(id);
        }
        if (group.ids.empty())
            deck_fail(*side.at.block, side.at.line,
                      "segment set " + std::to_string(side.set_id) + " lists no segment");
    }
    std::map<std::size_t, std::vector<Line>> pressures;  // by the slot of their card
    for (const SegmentLoad& load : segment_loads_) {
        std::vector<long long> aligned, reversed;
        for (const Segment& seg : load.segments) {
            const Shell& shell = shell_of(seg, "loads segments of its shells");
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
            if (!load.blast.empty())  // a blast: the faces' normal as the segments'
                pressures[load.slot].push_back({"  - {type: blast, elements: " + yaml_name(name) +
                                                    ", " + load.blast +
                                                    (flip ? ", reversed: true}" : "}"),
                                                load.at});
            else
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
std::array<long long, 4> DeckTranslator::node_key(const std::array<long long, 4>& n) {
    std::array<long long, 4> key = n;
    if (key[3] == key[2]) key[3] = 0;
    std::sort(key.begin(), key.end());
    return key;
}

/// Whether segment s runs round its shell in the shell's own direction.
bool DeckTranslator::same_order(const std::array<long long, 4>& shell,
                                const std::array<long long, 4>& s) {
    const std::size_t count = (shell[3] == 0 || shell[3] == shell[2]) ? 3 : 4;
    const auto first = std::find(shell.begin(), shell.begin() + static_cast<long>(count), s[0]);
    const std::size_t at = static_cast<std::size_t>(first - shell.begin());
    return shell[(at + 1) % count] == s[1];
}

}  // namespace fpmshell::deck
