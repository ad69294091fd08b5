// LS-DYNA keyword shell-mesh reader (see lsdyna_reader.hpp).
#include "fpmshell/mesh/lsdyna_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "fpmshell/core/errors.hpp"
#include "fpmshell/core/text.hpp"
#include "fpmshell/mesh/keyword_deck.hpp"
#include "fpmshell/mesh/raw_mesh.hpp"
#include "fpmshell/mesh/solid_faces.hpp"

namespace fpmshell {
namespace {

using namespace text_mesh;

enum class Format { Standard, Long, WideId };  // no suffix, '+', '%'

std::vector<std::string> columns(const std::string& line, const std::vector<std::size_t>& widths) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    std::vector<std::string> out;
    out.reserve(widths.size());
    std::size_t pos = 0;
    for (const std::size_t w : widths) {
        // the column, trimmed in place (no copy of the untrimmed field)
        std::string_view f = pos < line.size() ? std::string_view(line).substr(pos, w) : "";
        while (!f.empty() && blank(f.front())) f.remove_prefix(1);
        while (!f.empty() && blank(f.back())) f.remove_suffix(1);
        out.emplace_back(f);
        pos += w;
    }
    return out;
}

bool blank_or_id(const std::string& f) {
    long long v = 0;
    return f.empty() || parse_whole(f, v);
}

bool blank_or_real(const std::string& f) {
    Real v = 0;
    return f.empty() || parse_real(f, v);
}

/// Fields of a card: split at commas when it has any; else the fixed columns when each field
/// passes `ok`; else the blank-separated tokens (hand-written files).
template <typename Ok>
std::vector<std::string> card_fields(const std::string& line,
                                     const std::vector<std::size_t>& widths, Ok ok) {
    if (line.find(',') != std::string::npos) return split_commas(line);
    auto fixed = columns(line, widths);
    bool good = true;
    for (std::size_t k = 0; k < fixed.size(); ++k) good = good && ok(k, fixed[k]);
    if (good) return fixed;
    return split_blanks(line);
}

enum class Block { Skip, Node, Shell, Solid, NodeSet, ShellSet, PartSet, Mass, MassSet };

class LsDynaReader {
public:
    explicit LsDynaReader(const std::string& path) : main_path_(path) { raw_.path = path; }

    MeshData read() {
        const KeywordDeck deck = read_keyword_deck(raw_.path);
        raw_.file_bytes = deck.bytes;
        for (const DeckBlock& block : deck.blocks) {
            raw_.path = block.file;
            start(block);
            for (const DeckCard& c : block.cards) card(c.text, c.line);
        }
        raw_.path = main_path_;
        add_solid_faces();
        // The triangles in element-number order, whatever order the cards and included files
        // come in (LS-DYNA reads a deck as a whole): a reordered deck is the same model.
        const auto by_id = [](const auto& a, const auto& b) { return a.id < b.id; };
        if (!std::is_sorted(raw_.shells.begin(), raw_.shells.end(), by_id))
            std::stable_sort(raw_.shells.begin(), raw_.shells.end(), by_id);
        for (const auto& [name, parts] : part_sets_) {  // the parts' elements, known by now
            auto& members = raw_.element_sets[name];
            for (const long long pid : parts) {
                const auto it = raw_.element_sets.find("part_" + std::to_string(pid));
                if (it != raw_.element_sets.end())
                    members.insert(members.end(), it->second.begin(), it->second.end());
            }
        }
        keep_mass_nodes();
        MeshData mesh = finish_raw_mesh(raw_);
        for (const SolidElement& e : solids_)
            for (const long long n : e.nodes)
                if (!std::binary_search(mesh.node_tag.begin(), mesh.node_tag.end(), n))
                    mesh.inner_node_tag.push_back(n);
        std::sort(mesh.inner_node_tag.begin(), mesh.inner_node_tag.end());
        mesh.inner_node_tag.erase(
            std::unique(mesh.inner_node_tag.begin(), mesh.inner_node_tag.end()),
            mesh.inner_node_tag.end());
        return mesh;
    }

private:
    std::size_t width(std::size_t standard) const {
        if (format_ == Format::Long) return 20;
        if (format_ == Format::WideId) return std::max<std::size_t>(standard, 10);
        return standard;
    }

    void start(const DeckBlock& block) {
        const std::string& name = block.keyword;
        const int number = block.line;
        format_ = block.format == DeckFormat::Long     ? Format::Long
                  : block.format == DeckFormat::WideId ? Format::WideId
                                                       : Format::Standard;
        block_ = Block::Skip;
        card_ = 0;
        std::vector<std::string> parts;
        for (std::size_t start = 0;;) {
            const auto u = name.find('_', start);
            parts.push_back(
                name.substr(start, u == std::string::npos ? std::string::npos : u - start));
            if (u == std::string::npos) break;
            start = u + 1;
        }
        if (name == "NODE") {
            block_ = Block::Node;
        } else if (name == "ELEMENT_MASS" || name == "ELEMENT_MASS_NODE_SET") {
            block_ = name == "ELEMENT_MASS" ? Block::Mass : Block::MassSet;
        } else if (name == "ELEMENT_SOLID") {
            block_ = Block::Solid;
            solid_waiting_ = false;
        } else if (name.rfind("ELEMENT_SHELL", 0) == 0) {
            block_ = Block::Shell;
            const std::set<std::string> options(parts.begin() + 2, parts.end());
            cards_per_element_ = 1;
            if (options.count("THICKNESS") || options.count("BETA") || options.count("MCID"))
                ++cards_per_element_;
            if (options.count("OFFSET")) ++cards_per_element_;
            for (const auto& o : options)
                if (o != "THICKNESS" && o != "BETA" && o != "MCID" && o != "OFFSET")
                    raw_.fail(number, "*" + name +
                                          " is not supported; use *ELEMENT_SHELL "
                                          "(optionally _THICKNESS, _BETA, _MCID, _OFFSET)");
        } else if (name.rfind("SET_NODE", 0) == 0 || name.rfind("SET_SHELL", 0) == 0 ||
                   name.rfind("SET_PART", 0) == 0) {
            block_ = parts[1] == "NODE"    ? Block::NodeSet
                     : parts[1] == "SHELL" ? Block::ShellSet
                                           : Block::PartSet;
            title_ = generate_ = false;
            for (std::size_t k = 2; k < parts.size(); ++k) {
                if (parts[k] == "TITLE") {
                    title_ = true;
                } else if (parts[k] == "GENERATE") {
                    generate_ = true;
                } else if (parts[k] != "LIST") {
                    raw_.fail(number, "*" + name +
                                          " is not supported; use *SET_NODE_LIST, "
                                          "*SET_SHELL_LIST or *SET_PART_LIST (optionally "
                                          "_TITLE, _GENERATE)");
                }
            }
            set_title_.clear();
        }
    }

    long long id(const std::string& field, int line, const char* what) const {
        long long v = 0;
        if (!parse_whole(field, v))
            raw_.fail(line, std::string("expected ") + what + ", got '" + field + "'");
        return v;
    }

    void card(const std::string& line, int number) {
        // A blank line between records is skipped; where a card's place gives its meaning (a
        // set's title, a shell's thickness card) it is a card of defaults.
        const bool record_start =
            block_ == Block::Node || (block_ == Block::Shell && card_ % cards_per_element_ == 0) ||
            (block_ == Block::Solid && !solid_waiting_) ||
            ((block_ == Block::NodeSet || block_ == Block::ShellSet || block_ == Block::PartSet) &&
             !(title_ && card_ == 0));
        if (record_start && std::all_of(line.begin(), line.end(),
                                        [](char c) { return c == ' ' || c == '\t' || c == '\r'; }))
            return;
        const int index = card_++;
        switch (block_) {
            case Block::Skip:
                return;
            case Block::Node: {
                const std::vector<std::size_t> widths = {width(8),  width(16), width(16),
                                                         width(16), width(8),  width(8)};
                const auto f = card_fields(line, widths, [](std::size_t k, const std::string& s) {
                    return k == 0 ? blank_or_id(s) && !s.empty() : k <= 3 ? blank_or_real(s) : true;
                });
                if (f.empty()) raw_.fail(number, "a *NODE card needs: NID, X, Y, Z");
                Vec3 x = Vec3::Zero();
                for (std::size_t k = 1; k <= 3 && k < f.size(); ++k)
                    if (!f[k].empty() && !parse_real(f[k], x[static_cast<Index>(k - 1)]))
                        raw_.fail(number, "coordinate '" + f[k] + "' is not a finite number");
                raw_.add_node(id(f[0], number, "a node number"), x, number);
                return;
            }
            case Block::Shell: {
                if (index % cards_per_element_ != 0) return;  // thickness/offset cards
                const auto f =
                    card_fields(line, std::vector<std::size_t>(10, width(8)),
                                [](std::size_t, const std::string& s) { return blank_or_id(s); });
                if (f.size() < 5)
                    raw_.fail(number, "an *ELEMENT_SHELL card needs: EID, PID, N1, N2, N3, N4");
                const long long e = id(f[0], number, "an element number");
                const long long pid = id(f[1], number, "a part number");
                std::vector<long long> nodes;
                for (std::size_t k = 2; k < 6; ++k) {
                    long long n = 0;
                    if (k < f.size() && !f[k].empty()) n = id(f[k], number, "a node number");
                    nodes.push_back(n);
                }
                for (std::size_t k = 6; k < f.size(); ++k) {
                    long long n = 0;
                    if (!f[k].empty() && parse_whole(f[k], n) && n != 0)
                        raw_.fail(number, "shells with more than 4 nodes are not supported");
                }
                if (nodes[3] == 0 || nodes[3] == nodes[2]) nodes.pop_back();
                for (const long long n : nodes)
                    if (n <= 0)
                        raw_.fail(number, "element " + std::to_string(e) +
                                              " needs at least 3 node numbers");
                raw_.add_shell(e, nodes, number);
                const std::string part = "part_" + std::to_string(pid);
                raw_.element_sets[part].push_back(e);
                raw_.set_lines.try_emplace(part, number);
                raw_.set_files.try_emplace(part, raw_.path);
                return;
            }
            case Block::Solid:
                solid_card(line, number);
                return;
            case Block::Mass:
            case Block::MassSet: {  // EID, NID or NSID, MASS, PID: a point mass (its node kept)
                const auto f =
                    card_fields(line, {width(8), width(8)},
                                [](std::size_t, const auto& s) { return blank_or_id(s); });
                long long n = 0;
                if (f.size() < 2 || !parse_whole(f[1], n) || n <= 0)
                    return;  // the translator says why
                (block_ == Block::Mass ? mass_nodes_ : mass_sets_)
                    .push_back({n, raw_.path, number});
                return;
            }
            case Block::NodeSet:
            case Block::ShellSet:
            case Block::PartSet: {
                if (title_ && index == 0) {
                    set_title_ = trim(line);
                    return;
                }
                const auto f =
                    card_fields(line, std::vector<std::size_t>(8, width(10)),
                                [](std::size_t, const std::string& s) { return blank_or_id(s); });
                if (index == (title_ ? 1 : 0)) {  // header card: SID, DA1..DA4, SOLVER
                    if (f.empty()) raw_.fail(number, "a set card needs its SID first");
                    const long long sid = id(f[0], number, "a set number (SID)");
                    const bool nodes = block_ == Block::NodeSet;
                    set_ = !set_title_.empty()
                               ? set_title_
                               : lsdyna_set_name(block_ == Block::NodeSet    ? "node"
                                                 : block_ == Block::ShellSet ? "shell"
                                                                             : "part",
                                                 sid);
                    auto& sets = nodes ? raw_.node_sets : raw_.element_sets;
                    (void)sets[set_];
                    if (nodes) node_set_names_[sid] = set_;
                    raw_.set_lines.try_emplace(set_, number);
                    raw_.set_files.try_emplace(set_, raw_.path);
                    return;
                }
                auto& members = block_ == Block::NodeSet    ? raw_.node_sets[set_]
                                : block_ == Block::ShellSet ? raw_.element_sets[set_]
                                                            : part_sets_[set_];
                std::vector<long long> ids;
                for (const std::string& s : f) {
                    long long v = 0;
                    if (s.empty()) {
                        ids.push_back(0);
                    } else if (parse_whole(s, v)) {
                        ids.push_back(v);
                    } else {
                        raw_.fail(number, "expected a number, got '" + s + "'");
                    }
                }
                if (!generate_) {
                    for (const long long v : ids)
                        if (v > 0) members.push_back(v);
                    return;
                }
                for (std::size_t k = 0; k + 1 < ids.size(); k += 2) {
                    const long long first = ids[k];
                    const long long last = ids[k + 1];
                    if (first == 0 && last == 0) continue;
                    if (first <= 0 || last < first)
                        raw_.fail(number, "a GENERATE range needs 0 < first <= last");
                    const long long count = last - first + 1;
                    raw_.add_generated(count, number);
                    for (long long m = 0; m < count; ++m) members.push_back(first + m);
                }
                return;
            }
        }
    }

    /// A card of *ELEMENT_SOLID: EID, PID, N1..N8; or EID and PID alone, the nodes N1..N8 on
    /// the next card (LS-DYNA's two-card form).
    void solid_card(const std::string& line, int number) {
        const auto f =
            card_fields(line, std::vector<std::size_t>(10, width(8)),
                        [](std::size_t, const std::string& s) { return blank_or_id(s); });
        std::vector<long long> v;
        for (const std::string& field : f) {
            long long n = 0;
            if (!field.empty() && !parse_whole(field, n))
                raw_.fail(number,
                          "expected a number in an *ELEMENT_SOLID card, got '" + field + "'");
            v.push_back(n);
        }
        std::size_t first_node = 2;
        if (!solid_waiting_) {
            if (v.size() < 2 || v[0] <= 0 || v[1] <= 0)
                raw_.fail(number, "an *ELEMENT_SOLID card needs: EID, PID, N1, ..., N8");
            solid_ = SolidElement{v[0], v[1], {}, number};
            if (v.size() < 3 || v[2] == 0) {  // the nodes follow on the next card
                solid_waiting_ = true;
                return;
            }
        } else {
            first_node = 0;
            solid_waiting_ = false;
        }
        std::size_t given = 0;
        for (std::size_t k = 0; k < 8; ++k) {
            const std::size_t at = first_node + k;
            solid_.nodes[k] = at < v.size() ? v[at] : 0;
            if (solid_.nodes[k] > 0) ++given;
        }
        if (given < 4 || solid_.nodes[0] <= 0 || solid_.nodes[1] <= 0 || solid_.nodes[2] <= 0 ||
            solid_.nodes[3] <= 0)
            raw_.fail(number, "solid " + std::to_string(solid_.id) +
                                  " needs at least its nodes N1 to N4 (a tetrahedron)");
        for (std::size_t k = 4; k < 8; ++k)  // blank N5..N8: a tetrahedron's repeated N4
            if (solid_.nodes[k] <= 0) solid_.nodes[k] = solid_.nodes[3];
        for (std::size_t at = first_node + 8; at < v.size(); ++at)
            if (v[at] != 0) raw_.fail(number, "solids with more than 8 nodes are not supported");
        solids_.push_back(solid_);
    }

    /// The outer faces of each part of solids, as its shells (numbered after every shell and
    /// solid of the file, in the solids' order).
    /// The nodes that carry a point mass (*ELEMENT_MASS, the sets of _NODE_SET) are particles,
    /// shells or not; one inside a rigid part of solids (on none of its outer faces, which carry
    /// the part's body) would be a particle apart from the body: refused.
    void keep_mass_nodes() {
        std::vector<MassCard> nodes = mass_nodes_;
        for (const MassCard& set : mass_sets_) {
            const auto name = node_set_names_.find(set.id);
            if (name == node_set_names_.end()) continue;  // the translator names the missing set
            for (const long long n : raw_.node_sets[name->second])
                nodes.push_back({n, set.file, set.line});
        }
        if (nodes.empty()) return;
        std::unordered_set<long long> on_shells, in_solids;
        for (const auto& e : raw_.shells) on_shells.insert(e.nodes.begin(), e.nodes.end());
        for (const SolidElement& e : solids_) in_solids.insert(e.nodes.begin(), e.nodes.end());
        for (const MassCard& m : nodes) {
            if (in_solids.count(m.id) != 0 && on_shells.count(m.id) == 0) {
                raw_.path = m.file;
                raw_.fail(m.line, "node " + std::to_string(m.id) +
                                      " carries a point mass inside a rigid part of solids (on "
                                      "none of its outer faces, which carry the part's body): put "
                                      "the mass on a node of the part's surface");
            }
            raw_.mass_nodes.push_back(m.id);
        }
    }

    void add_solid_faces() {
        if (solids_.empty()) return;
        std::unordered_map<long long, Vec3> at;
        long long next = 0;
        for (const SolidElement& e : solids_) {
            next = std::max(next, e.id);
            for (const long long n : e.nodes) {
                const auto it = raw_.nodes.find(n);
                if (it == raw_.nodes.end())
                    raw_.fail(e.line, "solid " + std::to_string(e.id) + " refers to node " +
                                          std::to_string(n) + ", which no *NODE card defines");
                at.emplace(n, it->second.x);
            }
        }
        for (const auto& shell : raw_.shells) next = std::max(next, shell.id);
        std::map<long long, int> first_line;
        for (const SolidElement& e : solids_) first_line.try_emplace(e.part, e.line);
        for (const SolidFace& face : outer_solid_faces(solids_, at)) {
            const long long id = ++next;
            raw_.add_shell(id, face.nodes, first_line[face.part]);
            const std::string part = "part_" + std::to_string(face.part);
            raw_.element_sets[part].push_back(id);
            raw_.set_lines.try_emplace(part, first_line[face.part]);
        }
    }

    RawMesh raw_;
    std::vector<SolidElement> solids_;
    SolidElement solid_;
    bool solid_waiting_ = false;
    Block block_ = Block::Skip;
    Format format_ = Format::Standard;
    int card_ = 0;
    int cards_per_element_ = 1;
    bool title_ = false;
    bool generate_ = false;
    std::string set_title_;
    std::string set_;
    std::string main_path_;
    std::map<std::string, std::vector<long long>> part_sets_;  // name -> part ids
    std::map<long long, std::string> node_set_names_;          // SID -> the node set's name
    struct MassCard {  ///< a point mass's node (*ELEMENT_MASS) or set (_NODE_SET), its card
        long long id = 0;
        std::string file;
        int line = 0;
    };
    std::vector<MassCard> mass_nodes_, mass_sets_;
};

}  // namespace

MeshData read_lsdyna(const std::string& path) { return LsDynaReader(path).read(); }

std::string lsdyna_set_name(const std::string& kind, long long sid) {
    return kind + "_set_" + std::to_string(sid);
}

}  // namespace fpmshell
